// The memory check before a run (issue 55): a run predicted to need more memory than the process may take is
// refused before its set-up, with both numbers, the mesh untouched; memory_limit overrides the check.
//
// Truth: the limits themselves. A memory_limit below the run's need refuses it (INSUFFICIENT_MEMORY, the
// mesh's coordinates the same bytes); infinity runs it. An address-space limit (setrlimit RLIMIT_AS, what
// `ulimit -v` sets) half the run's need above the process's address space (/proc/self/statm) refuses it too
// and names that limit. The prediction grows with the vertices: a mesh refined once (four times the faces) is
// predicted about four times the memory. An automatic factorisation is made only where its factor fits.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include "test_support/check.h"
#include "test_support/mesh_coordinates.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#if defined(__linux__)
#include <sys/resource.h>
#include <unistd.h>
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace AF = CGAL::Anisotropic_fairing;

namespace {

const double MB = 1024.0 * 1024.0;

void check_memory_limit(const Mesh& input)
{
  Mesh m = input;
  const AF::Fairing_report r = AF::anisotropic_fairing(m, AF::parameters::memory_limit(1e6));
  AF_CHECK(r.status == AF::Fairing_status::INSUFFICIENT_MEMORY, "a run needing more than memory_limit is refused");
  AF_CHECK(r.steps.empty() && r.runs.empty(), "refused before any run");
  AF_CHECK(AF_test::coordinates(m) == AF_test::coordinates(input), "the refused run leaves the mesh untouched");
  AF_CHECK(r.available_memory == 1e6 && r.memory_limited_by == "the memory_limit given",
           "the report gives the limit and what set it");
  AF_CHECK(r.predicted_memory > 1e6, "the report gives the prediction that exceeded it");
  AF_CHECK(r.message.find(AF::internal::megabytes(r.predicted_memory)) != std::string::npos &&
             r.message.find("1 MB are available") != std::string::npos,
           "the message names both numbers: " + r.message);
  AF_CHECK(std::string(AF::to_string(r.status)) == "insufficient_memory", "the status's name");

  Mesh n = input;
  const AF::Fairing_report off =
    AF::anisotropic_fairing(n, AF::parameters::memory_limit(std::numeric_limits<double>::infinity()));
  AF_CHECK(off.succeeded() && !off.steps.empty(), "memory_limit infinity runs without the check");
  AF_CHECK(off.predicted_memory == r.predicted_memory, "the same prediction either way");

  bool refused = false;
  try { Mesh e = input; AF::anisotropic_fairing(e, AF::parameters::memory_limit(-1.0)); }
  catch(const AF::Input_error& e) { refused = std::string(e.what()).find("memory_limit") != std::string::npos; }
  AF_CHECK(refused, "a negative memory_limit is refused, naming it");
}

// the prediction follows the vertices: one Loop refinement, four times the faces, four times the memory
void check_growth(const Mesh& input)
{
  Mesh fine = input;
  CGAL::Subdivision_method_3::Loop_subdivision(fine, CGAL::parameters::number_of_iterations(1));
  Mesh a = input, b = fine;
  const auto np = AF::parameters::memory_limit(0.0).relative_time_step(1e-3);   // one flow, taking its steps
  const double coarse_need = AF::anisotropic_fairing(a, np).predicted_memory;
  const double fine_need = AF::anisotropic_fairing(b, np).predicted_memory;
  const double ratio = fine_need / coarse_need, vertices = double(fine.number_of_vertices()) / input.number_of_vertices();
  AF_CHECK(std::abs(ratio / vertices - 1) < 0.05,
           "the prediction grows as the vertices: " + std::to_string(ratio) + " for " + std::to_string(vertices));
}

// A factorisation only where its factor fits beside the run: the attributes-only mode factorises its fixed
// surface's constant system once (at most 50,000 vertices); with room for the run but not for the factor it
// iterates, to the same result within the solver's tolerance
void check_factor_budget(const Mesh& input)
{
  Mesh m = input;
  auto f = m.add_property_map<Mesh::Vertex_index, double>("v:f", 0.0).first;
  for(auto v : m.vertices()) f[v] = std::sin(10 * m.point(v).x()) + 0.05 * std::cos(1e3 * m.point(v).y());
  const auto np = AF::parameters::relative_time_step(1e-3).number_of_iterations(3u)
                    .attribute_mode(AF::Attribute_mode::ATTRIBUTES_ONLY)
                    .stopping_criteria(AF::Stopping_criteria::none());
  Mesh a = m, b = m;
  auto fa = a.property_map<Mesh::Vertex_index, double>("v:f").first;
  auto fb = b.property_map<Mesh::Vertex_index, double>("v:f").first;
  const AF::Fairing_report with = AF::anisotropic_fairing(a, a.points(), fa, np);
  const double factor = AF::internal::Solver_choice::factor_memory(m.number_of_vertices());
  const double tight = with.predicted_memory - factor + factor / 2;   // the run without its factor, and half of it
  const AF::Fairing_report without = AF::anisotropic_fairing(b, b.points(), fb, np.memory_limit(tight));
  AF_CHECK(with.succeeded() && !with.steps.empty() && with.steps.back().direct_solve,
           "with room, the constant system is factorised");
  AF_CHECK(without.succeeded() && without.steps.size() == with.steps.size() && !without.steps.back().direct_solve,
           "without room for the factor, it is iterated: " + without.message);
  AF_CHECK(std::abs(without.predicted_memory + factor - with.predicted_memory) < 1,
           "the prediction has the factor where it is made, and not where it is not");
  double largest = 0;
  for(auto v : m.vertices()) largest = std::max(largest, std::abs(fa[v] - fb[v]));
  AF_CHECK(largest < 1e-6, "the same values within the solver's tolerance: " + std::to_string(largest));
}

#if defined(__linux__) && !defined(__SANITIZE_ADDRESS__)
double address_space()
{
  std::ifstream statm("/proc/self/statm");
  double pages = 0;
  statm >> pages;
  return pages * double(sysconf(_SC_PAGESIZE));
}

// ulimit -v: the process may take its limit less its address space (at the check, once the run's choices are
// made). The limit leaves half the run's need: room for its preparation, not for the run.
void check_address_space_limit(const Mesh& input)
{
  rlimit old;
  AF_CHECK(getrlimit(RLIMIT_AS, &old) == 0, "getrlimit");
  if(old.rlim_max != RLIM_INFINITY)
  {
    std::printf("the hard address-space limit is set: the ulimit -v part is not run\n");
    return;
  }
  Mesh probe = input;
  const double need = AF::anisotropic_fairing(probe, AF::parameters::memory_limit(0.0)).predicted_memory;
  rlimit tight = old;
  tight.rlim_cur = rlim_t(address_space() + need / 2);
  Mesh m = input;
  AF_CHECK(setrlimit(RLIMIT_AS, &tight) == 0, "setrlimit");
  const AF::Fairing_report r = AF::anisotropic_fairing(m);
  setrlimit(RLIMIT_AS, &old);
  AF_CHECK(r.status == AF::Fairing_status::INSUFFICIENT_MEMORY, "refused under ulimit -v: " + r.message);
  AF_CHECK(r.memory_limited_by == "the address-space limit (ulimit -v)", "names ulimit -v: " + r.memory_limited_by);
  AF_CHECK(r.available_memory <= need / 2 && r.predicted_memory == need,
           "available: the limit less the address space (" + std::to_string(r.available_memory / MB) + " MB of " +
             std::to_string(need / 2 / MB) + ")");
  AF_CHECK(r.memory_in_use > 0, "the memory in use is read");
  AF_CHECK(r.message.find("ulimit -v") != std::string::npos, "the message names the limit: " + r.message);
  AF_CHECK(AF_test::coordinates(m) == AF_test::coordinates(input), "the refused run leaves the mesh untouched");
}
#endif

} // namespace

int main(int argc, char** argv)
{
  const std::string data = argc > 1 ? argv[1] : "data";
  Mesh fandisk;
  AF_CHECK(CGAL::IO::read_polygon_mesh(data + "/fandisk0.3_noisy.obj", fandisk), "read fandisk0.3_noisy.obj");
  check_memory_limit(fandisk);
  check_growth(fandisk);
  check_factor_budget(fandisk);
#if defined(__linux__) && !defined(__SANITIZE_ADDRESS__)
  Mesh fine = fandisk;   // 26,000 vertices: a need well above what the run's preparation takes
  CGAL::Subdivision_method_3::Loop_subdivision(fine, CGAL::parameters::number_of_iterations(1));
  check_address_space_limit(fine);
#endif
  return AF_test::report();
}
