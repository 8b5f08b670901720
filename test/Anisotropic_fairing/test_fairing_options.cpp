// The parameters as one value (Fairing_options, named parameter fairing_options).
//
// Truth: the same run asked for by named parameters. A value holding them gives the very same surface and
// report, bit for bit (the default run, a run with a time step, an anisotropic tensor, attributes in the
// coupled mode); a named parameter beside the value replaces the value's; whether the run is automatic is
// read from the value when the run starts; a pair given twice (one in the value, one beside it) and a value
// out of range are refused before anything is touched, with a message naming the parameter.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include "test_support/check.h"
#include "test_support/mesh_generators.h"

#include <cstdio>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace AF = CGAL::Anisotropic_fairing;

namespace {

Mesh noisy_sphere()
{
  AF_test::Triangle_soup soup = AF_test::icosphere_soup(3);
  AF_test::perturb_soup(soup, 0.01, 7);
  Mesh mesh;
  AF_test::soup_to_mesh(soup, mesh);
  return mesh;
}

std::vector<K::Point_3> points(const Mesh& m) { return std::vector<K::Point_3>(m.points().begin(), m.points().end()); }

// the two runs wrote the same points and reported the same steps (timings aside)
void check_same(const Mesh& a, const Mesh& b, const AF::Fairing_report& ra, const AF::Fairing_report& rb, const std::string& what)
{
  AF_CHECK(ra.succeeded() && rb.succeeded(), what + ": both runs succeed");
  AF_CHECK(points(a) == points(b), what + ": the same points, bit for bit");
  bool same_steps = ra.steps.size() == rb.steps.size();
  for(std::size_t i = 0; same_steps && i < ra.steps.size(); ++i)
    same_steps = ra.steps[i].time == rb.steps[i].time && ra.steps[i].area == rb.steps[i].area;
  AF_CHECK(same_steps && ra.stop_reason == rb.stop_reason && ra.choices == rb.choices && ra.selected_tensor == rb.selected_tensor,
           what + ": the same steps, stop and choices");
}

// `call` is refused with INVALID_PARAMETER, a message naming `name`, and the mesh left as it was
template <typename Call>
void check_refused(Mesh& mesh, const Call& call, const std::string& name, const std::string& what)
{
  const std::vector<K::Point_3> before = points(mesh);
  bool refused = false;
  try
  {
    call(mesh);
  }
  catch(const AF::Input_error& e)
  {
    refused = e.kind() == AF::Input_error::INVALID_PARAMETER && std::string(e.what()).find(name) != std::string::npos;
    std::printf("  %s: %s\n", what.c_str(), e.what());
  }
  AF_CHECK(refused, what + ": refused, naming " + name);
  AF_CHECK(points(mesh) == before, what + ": the mesh is left as it was");
}

} // namespace

int main()
{
  const Mesh input = noisy_sphere();
  const auto solver = AF::Linear_solver::CONJUGATE_GRADIENT;   // (the automatic choice times the solvers)

  {
    Mesh a = input, b = input;
    const AF::Fairing_report ra = AF::anisotropic_fairing(a, AF::parameters::linear_solver(solver));
    AF::Fairing_options o;
    o.linear_solver = solver;
    const AF::Fairing_report rb = AF::anisotropic_fairing(b, AF::parameters::fairing_options(o));
    check_same(a, b, ra, rb, "the default run");
    AF_CHECK(ra.automatic_parameters && rb.automatic_parameters && !rb.selected_tensor.empty(),
             "an empty value is the default run, with its comparison of flows");
  }
  {
    Mesh a = input, b = input;
    const AF::Anisotropic_diffusion_tensor tensor = AF::Anisotropic_diffusion_tensor().set_lambda(4).set_epsilon(2e-3);
    const AF::Fairing_report ra = AF::anisotropic_fairing(
      a, AF::parameters::relative_time_step(1e-3).number_of_iterations(4).diffusion_tensor(tensor).linear_solver(solver)
           .relative_fidelity_weight(5.0).stopping_criteria(AF::Stopping_criteria::none()));
    AF::Fairing_options o;
    o.relative_time_step = 1e-3;
    o.number_of_iterations = 4;
    o.diffusion_tensor = tensor;
    o.linear_solver = solver;
    o.relative_fidelity_weight = 5.0;
    o.stopping_criteria = AF::Stopping_criteria::none();
    const AF::Fairing_report rb = AF::anisotropic_fairing(b, AF::parameters::fairing_options(o));
    check_same(a, b, ra, rb, "an anisotropic run with a time step");
    AF_CHECK(!rb.automatic_parameters && rb.steps.size() == 4, "a value with a time step is not the default run");

    // a named parameter beside the value applies on top of it
    Mesh c = input, d = input;
    const AF::Fairing_report rc = AF::anisotropic_fairing(c, AF::parameters::fairing_options(o).relative_time_step(3e-3));
    o.relative_time_step = 3e-3;
    const AF::Fairing_report rd = AF::anisotropic_fairing(d, AF::parameters::fairing_options(o));
    check_same(c, d, rc, rd, "a named parameter beside the value");
    AF_CHECK(points(c) != points(a), "the parameter beside the value changed the run");
  }
  {
    // attributes, coupled: the value and the named parameters fair the function alike
    Mesh a = input, b = input;
    auto qa = a.add_property_map<Vertex, double>("v:q", 0.0).first;
    auto qb = b.add_property_map<Vertex, double>("v:q", 0.0).first;
    for(Vertex v : a.vertices()) qa[v] = qb[v] = a.point(v).z() > 0 ? 1.0 : 0.0;
    const AF::Fairing_report ra = AF::anisotropic_fairing(
      a, a.points(), qa, AF::parameters::relative_time_step(1e-3).number_of_iterations(3).attribute_mode(AF::Attribute_mode::COUPLED)
                           .attribute_weight(0.5).linear_solver(solver));
    AF::Fairing_options o;
    o.relative_time_step = 1e-3;
    o.number_of_iterations = 3;
    o.attribute_mode = AF::Attribute_mode::COUPLED;
    o.attribute_weight = 0.5;
    o.linear_solver = solver;
    const AF::Fairing_report rb = AF::anisotropic_fairing(b, b.points(), qb, AF::parameters::fairing_options(o));
    check_same(a, b, ra, rb, "coupled attributes");
    bool same_values = true;
    for(Vertex v : a.vertices()) same_values = same_values && qa[v] == qb[v];
    AF_CHECK(same_values, "coupled attributes: the same values, bit for bit");
  }
  {
    Mesh mesh = input;
    AF::Fairing_options o;
    o.time_step = 1e-4;
    check_refused(mesh, [&](Mesh& m) { AF::anisotropic_fairing(m, AF::parameters::fairing_options(o).relative_time_step(1e-3)); },
                  "give either time_step or relative_time_step", "a pair given in the value and beside it");
    AF::Fairing_options bad;
    bad.relative_time_step = -1;
    check_refused(mesh, [&](Mesh& m) { AF::anisotropic_fairing(m, AF::parameters::fairing_options(bad)); }, "relative_time_step",
                  "a value out of range");
    AF::Fairing_options bounds;
    bounds.relative_maximum_deviation = 0.01;
    bounds.absolute_maximum_deviation = 0.01;
    check_refused(mesh, [&](Mesh& m) { AF::anisotropic_fairing(m, AF::parameters::fairing_options(bounds)); },
                  "absolute_maximum_deviation", "both bounds in the value");
  }
  return AF_test::report();
}
