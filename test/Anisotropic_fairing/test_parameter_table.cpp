// The parameter table (internal/parameter_table.h) against what is not made from it.
//
// Truth: the manual's list of the named parameters (doc/Anisotropic_fairing/Parameters.txt, the table that
// starts "| parameter | meaning |") has a row for every row of the parameter table, and no row for a name
// that is neither in it nor one of the named parameters outside it (maps, callback, the value of them all);
// a named parameter given alone is read into the Fairing_options member of its name.

#include <CGAL/Anisotropic_fairing/internal/run/Fairing_parameters.h>

#include "test_support/check.h"

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace AF = CGAL::Anisotropic_fairing;

namespace {

// the names of the parameter table's rows that are named parameters (not the tensor's settings)
std::vector<std::string> table_names()
{
  std::vector<std::string> names;
#define AF_PARAMETER(name, ...) names.push_back(#name);
#define AF_TENSOR_SETTING(...)
#include <CGAL/Anisotropic_fairing/internal/parameter_table.h>
#undef AF_PARAMETER
#undef AF_TENSOR_SETTING
  return names;
}

// the names in the first column of the manual's table of named parameters
std::set<std::string> manual_names(const std::string& path)
{
  std::ifstream in(path);
  AF_CHECK(bool(in), "the manual's page " + path + " can be read");
  std::set<std::string> names;
  std::string line;
  bool in_table = false;
  const std::regex row("^\\| `(\\w+)` \\|");
  while(std::getline(in, line))
  {
    if(line.rfind("| parameter | meaning |", 0) == 0) in_table = true;
    else if(in_table && line.empty()) break;
    std::smatch m;
    if(in_table && std::regex_search(line, m, row)) names.insert(m[1]);
  }
  return names;
}

// a value of each kind of member, given as a named parameter alone, is read into the member
void check_read()
{
  namespace P = AF::parameters;
  using AF::internal::read_fairing_options;
  AF_CHECK(read_fairing_options(P::solver_tolerance(0.25)).solver_tolerance == 0.25, "solver_tolerance is read");
  AF_CHECK(read_fairing_options(P::relative_time_step(2e-3)).relative_time_step == 2e-3, "relative_time_step is read");
  AF_CHECK(read_fairing_options(P::number_of_iterations(7)).number_of_iterations == 7u,
           "number_of_iterations (CGAL's) is read");
  AF_CHECK(read_fairing_options(P::verbose(true)).verbose, "verbose (CGAL's) is read");
  const auto vertices = AF::Boundary_handling::HOLD_BOUNDARY_VERTICES;
  AF_CHECK(read_fairing_options(P::boundary_handling(vertices)).boundary_handling == vertices,
           "boundary_handling is read");
  AF_CHECK(read_fairing_options(P::diffusion_tensor(AF::Uniform_diffusion_tensor())).diffusion_tensor.has_value(),
           "a tensor of the package's is read into the value");
  // the plain ones are checked by the table's column `check`, the message naming the parameter
  for(const auto& [name, bad] : std::vector<std::pair<std::string, AF::Fairing_options>>{
        {"solver_tolerance", [] { AF::Fairing_options o; o.solver_tolerance = 1; return o; }()},
        {"solver_maximum_iterations", [] { AF::Fairing_options o; o.solver_maximum_iterations = 0; return o; }()},
        {"attribute_maximum_deviation", [] { AF::Fairing_options o; o.attribute_maximum_deviation = -1; return o; }()}})
  {
    std::string message;
    try
    {
      AF::internal::resolve_fairing_parameters(bad, false);
    }
    catch(const AF::Input_error& e)
    {
      message = e.what();
    }
    AF_CHECK(message.find(name) != std::string::npos, name + " out of range is refused, naming it: " + message);
  }
}

} // namespace

int main(int argc, char** argv)
{
  const std::string data = argc > 1 ? argv[1] : "data";
  const std::string page = data + "/../../../doc/Anisotropic_fairing/Parameters.txt";
  const std::set<std::string> manual = manual_names(page);
  std::set<std::string> known = {"fairing_options", "callback", "vertex_point_map", "vertex_is_constrained_map",
                                 "attribute_control_map", "control_point_map", "sparse_linear_solver"};
  for(const std::string& name : table_names())
  {
    AF_CHECK(manual.count(name) == 1, "the parameter " + name + " of the parameter table has a row in " + page);
    known.insert(name);
  }
  for(const std::string& name : manual)
    AF_CHECK(known.count(name) == 1,
             "the row " + name + " of " + page + " is a parameter of the parameter table or a known one");
  check_read();
  return AF_test::report();
}
