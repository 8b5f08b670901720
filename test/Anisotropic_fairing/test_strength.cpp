// The named parameter strength (issue 51): the default run asked for a little more or less smoothing.
//
// Truth, on the Fandisk0.3 pair (a CAD part and a copy with Gaussian noise of 0.3 mean edge lengths along the
// normals, same connectivity): with strength 0.5, 1 and 2 the surface moves off the input by about half, once
// and twice what it moves at 1, measured here along the input's own vertex normals (not the package's
// measure) and as the mean distance each vertex moved; the flow kept is the crease-preserving anisotropic one
// at every strength (chosen automatically, not given); the noise being known, stopping at the noise itself
// gives the lowest mean face-normal error to the noise-free part (the discrepancy principle), 0.5 and 2 worse;
// strength 1 is the default run bit for bit; the report and its choices say the strength.
// On a noisy sphere and a noisy bumpy shape: a tensor given, the fourth-order flow and a time step with the noise
// criterion scale their target alike (the package's own displacement measure ends at strength x the noise), the
// fourth-order flow in about as many steps at 2 as at 1; the default run keeps the flow it keeps at 1. Refused before anything is touched, naming strength: 0, a negative value,
// NaN and infinity (as a named parameter and in Fairing_options), and any strength but 1 where no run stops at
// the noise level (a time step with the paper's criteria, the attributes-only mode).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include "test_support/check.h"
#include "test_support/denoising_pair.h"
#include "test_support/mesh_generators.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace AF = CGAL::Anisotropic_fairing;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

std::vector<K::Point_3> points(const Mesh& m) { return std::vector<K::Point_3>(m.points().begin(), m.points().end()); }

using AF_test::face_normal;
using AF_test::mean_normal_angle;
using AF_test::read_obj_in_order;

double mean_edge_length(const Mesh& m)
{
  double sum = 0;
  for(auto e : m.edges()) sum += std::sqrt(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1))));
  return sum / double(num_edges(m));
}

// how far `m` moved off `input`: the mean distance per vertex, and the robust deviation (1.4826 x the median
// of the absolute values) of the motion along the input's area-weighted vertex normals, both in units of the
// input's mean edge length
struct Motion { double mean = 0, normal = 0; };
Motion motion(const Mesh& m, const Mesh& input)
{
  std::vector<K::Vector_3> n(num_vertices(input), K::Vector_3(0, 0, 0));
  for(Mesh::Face_index f : input.faces())
    for(Vertex v : vertices_around_face(input.halfedge(f), input)) n[std::size_t(v)] = n[std::size_t(v)] + face_normal(input, f);
  const double h = mean_edge_length(input);
  Motion r;
  std::vector<double> along;
  for(Vertex v : input.vertices())
  {
    const K::Vector_3 d = m.point(v) - input.point(v);
    r.mean += std::sqrt(d.squared_length());
    const double len = std::sqrt(n[std::size_t(v)].squared_length());
    if(len > 0) along.push_back(std::abs(d * n[std::size_t(v)]) / len);
  }
  r.mean /= double(num_vertices(input)) * h;
  std::nth_element(along.begin(), along.begin() + std::ptrdiff_t(along.size() / 2), along.end());
  r.normal = 1.4826 * along[along.size() / 2] / h;
  return r;
}

// `call` is refused with INVALID_PARAMETER, a message naming strength, and the mesh left as it was
template <typename Call>
void check_refused(Mesh& mesh, const Call& call, const std::string& what)
{
  const std::vector<K::Point_3> before = points(mesh);
  bool refused = false;
  try
  {
    call(mesh);
  }
  catch(const AF::Input_error& e)
  {
    refused = e.kind() == AF::Input_error::INVALID_PARAMETER && std::string(e.what()).find("strength") != std::string::npos;
    std::printf("  %s: %s\n", what.c_str(), e.what());
  }
  AF_CHECK(refused, what + ": refused, naming strength");
  AF_CHECK(points(mesh) == before, what + ": the mesh is left as it was");
}

Mesh noisy_sphere()
{
  AF_test::Triangle_soup soup = AF_test::icosphere_soup(4);
  AF_test::perturb_soup(soup, 0.03, 51);   // about 0.23 mean edge lengths along the normals
  Mesh mesh;
  AF_test::soup_to_mesh(soup, mesh);
  return mesh;
}

} // namespace

int main(int argc, char** argv)
{
  const std::string dir = argc > 1 ? argv[1] : "data";
  const auto solver = AF::Linear_solver::CONJUGATE_GRADIENT;   // (the automatic choice times the solvers)

  // ---- the default run at strength 0.5, 1 and 2 on a CAD part with known noise
  Mesh noisy, original;
  if(!AF_CHECK(read_obj_in_order(dir + "/fandisk0.3_noisy.obj", noisy) && read_obj_in_order(dir + "/fandisk0.3_original.obj", original),
               "the Fandisk0.3 pair is read"))
    return AF_test::report();
  Mesh by_default = noisy;
  const AF::Fairing_report r_default = AF::anisotropic_fairing(by_default, AF::parameters::linear_solver(solver));
  const double strengths[3] = { 0.5, 1, 2 };
  Mesh faired[3];
  AF::Fairing_report r[3];
  Motion moved[3];
  double error[3];
  std::string last_run[3];
  for(int k = 0; k < 3; ++k)
  {
    faired[k] = noisy;
    r[k] = AF::anisotropic_fairing(faired[k], AF::parameters::strength(strengths[k]).linear_solver(solver).callback(
                                                [&](const AF::Fairing_step& s) { last_run[k] = s.run_name; return true; }));
    moved[k] = motion(faired[k], noisy);
    error[k] = mean_normal_angle(faired[k], original);
    std::printf("strength %g: %s, kept %s, %zu steps (%s), moved %.4f h along the input's normals, %.4f h mean; "
                "noise %.4f h, package's displacement %.4f h; mean normal error %.2f deg\n  choices: %s\n",
                strengths[k], AF::to_string(r[k].status), r[k].selected_tensor.c_str(), r[k].steps.size(), AF::to_string(r[k].stop_reason),
                moved[k].normal, moved[k].mean, r[k].noise_level, r[k].noise_displacement, error[k], r[k].choices.c_str());
    AF_CHECK(r[k].succeeded(), "the run at each strength succeeds");
    AF_CHECK(r[k].selected_tensor == "anisotropic", "the CAD part keeps the anisotropic flow at every strength, chosen automatically");
    AF_CHECK(r[k].automatic_parameters && r[k].strength == strengths[k], "the report gives the strength");
  }
  AF_CHECK(points(faired[1]) == points(by_default) && r[1].steps.size() == r_default.steps.size() &&
           r[1].choices == r_default.choices && r[1].stop_reason == r_default.stop_reason &&
           r[1].selected_tensor == r_default.selected_tensor && r[1].noise_displacement == r_default.noise_displacement,
           "strength 1 is the default run, bit for bit");
  AF_CHECK(r_default.choices.find("strength") == std::string::npos, "the default run's choices do not mention a strength");
  AF_CHECK(r[0].choices.find("strength 0.5") != std::string::npos && r[2].choices.find("strength 2") != std::string::npos,
           "the choices name the strength");
  AF_CHECK(last_run[2] == "anisotropic flow at strength 2",
           "after the comparison the flow kept runs again to the strength's target (the callback sees it)");
  AF_CHECK(moved[0].normal < moved[1].normal && moved[1].normal < moved[2].normal && moved[0].mean < moved[1].mean &&
           moved[1].mean < moved[2].mean, "strength 2 moves the surface farther off the input than 1, and 1 than 0.5");
  AF_CHECK(std::abs(moved[2].normal / moved[1].normal - 2) < 0.3 && std::abs(moved[0].normal / moved[1].normal - 0.5) < 0.15,
           "measured along the input's normals, the motion scales with the strength");
  AF_CHECK(std::abs(r[2].noise_displacement / (2 * r[2].noise_level) - 1) < 0.02 && r[2].stop_reason == AF::Stop_reason::NOISE_LEVEL,
           "at strength 2 the run ends at twice the noise");
  AF_CHECK(std::abs(r[0].noise_displacement / (0.5 * r[0].noise_level) - 1) < 0.02 && r[0].limit_weight < 1,
           "at strength 0.5 the result lies between the input and its limit surface, at half the noise");
  AF_CHECK(error[1] < error[0] && error[1] < error[2] && error[1] < 4.0,
           "the noise known, stopping at the noise itself is the most accurate (discrepancy principle)");

  // ---- a tensor given, the fourth-order flow, a time step with the noise criterion: the target scales alike
  const Mesh sphere = noisy_sphere();
  const auto ends_at = [](const AF::Fairing_report& x, double strength, const std::string& what) {
    std::printf("%s: %s, %zu steps (%s), displacement %.4f h, noise %.4f h\n", what.c_str(), AF::to_string(x.status), x.steps.size(),
                AF::to_string(x.stop_reason), x.noise_displacement, x.noise_level);
    AF_CHECK(x.succeeded() && x.stop_reason == AF::Stop_reason::NOISE_LEVEL &&
             std::abs(x.noise_displacement / (strength * x.noise_level) - 1) < 0.025, what + ": ends at strength x the noise");
  };
  {
    Mesh a = sphere, b = sphere;
    const auto np = AF::parameters::diffusion_tensor(AF::Isotropic_diffusion_tensor()).linear_solver(solver);
    const AF::Fairing_report ra = AF::anisotropic_fairing(a, np), rb = AF::anisotropic_fairing(b, np.strength(2));
    ends_at(ra, 1, "isotropic tensor given, strength 1");
    ends_at(rb, 2, "isotropic tensor given, strength 2");
    AF_CHECK(rb.selected_tensor.empty() && rb.choices.find("moved by 2 x the noise (strength 2)") != std::string::npos,
             "a tensor given runs alone, to the strength's target: " + rb.choices);
    AF_CHECK(motion(b, sphere).normal > 1.5 * motion(a, sphere).normal, "and moves farther");
  }
  {
    // an organic shape with detail at a few edge lengths (on a sphere the fourth-order flow has no shape to move:
    // its displacement levels off at the noise, noise_removed, whatever the strength)
    Mesh bumpy;
    if(AF_CHECK(CGAL::IO::read_polygon_mesh(dir + "/bumpy.off", bumpy), "bumpy.off is read"))
    {
      AF_test::perturb_vertices(bumpy, 0.4 * mean_edge_length(bumpy), 51);   // about 0.23 h along the normals
      Mesh a = bumpy, b = bumpy;
      const auto np = AF::parameters::diffusion_tensor(AF::Uniform_diffusion_tensor()).flow_order(4).linear_solver(solver);
      const AF::Fairing_report ra = AF::anisotropic_fairing(a, np), rb = AF::anisotropic_fairing(b, np.strength(2));
      ends_at(ra, 1, "uniform fourth-order flow on a noisy bumpy shape, strength 1");
      ends_at(rb, 2, "uniform fourth-order flow on a noisy bumpy shape, strength 2");
      AF_CHECK(rb.steps.size() <= 2 * ra.steps.size() + 2, "the fourth-order flow reaches twice the noise in about as many steps");
      AF_CHECK(motion(b, bumpy).normal > 1.5 * motion(a, bumpy).normal, "and moves farther");
      // the default run: the same flow kept as at strength 1, then run to twice the noise
      Mesh c = bumpy, d = bumpy;
      std::string last;
      const AF::Fairing_report rc = AF::anisotropic_fairing(c, AF::parameters::linear_solver(solver));
      const AF::Fairing_report rd = AF::anisotropic_fairing(d, AF::parameters::strength(2).linear_solver(solver).callback(
                                                                  [&](const AF::Fairing_step& s) { last = s.run_name; return true; }));
      std::printf("default run on the noisy bumpy shape: kept %s, then %s\n", rc.selected_tensor.c_str(), last.c_str());
      ends_at(rd, 2, "the default run on a noisy bumpy shape, strength 2");
      AF_CHECK(rc.succeeded() && rd.selected_tensor == rc.selected_tensor &&
               last == (rc.selected_tensor == "uniform" ? "uniform fourth-order" : rc.selected_tensor) + " flow at strength 2",
               "the flow kept is the one the default run keeps");
      AF_CHECK(motion(d, bumpy).normal > 1.5 * motion(c, bumpy).normal, "and it moves farther");
    }
  }
  {
    Mesh a = sphere, b = sphere;
    const auto np = AF::parameters::relative_time_step(2e-4).number_of_iterations(100).linear_solver(solver)
                      .stopping_criteria(AF::Stopping_criteria::automatic());
    const AF::Fairing_report ra = AF::anisotropic_fairing(a, np), rb = AF::anisotropic_fairing(b, np.strength(2));
    ends_at(ra, 1, "a time step with the noise criterion, strength 1");
    ends_at(rb, 2, "a time step with the noise criterion, strength 2");
    AF_CHECK(!rb.automatic_parameters && rb.strength == 2, "not the default run, and the report gives the strength");
  }
  {
    // the default run on the sphere, strength 1 against 2, and the same through Fairing_options
    Mesh a = sphere, b = sphere;
    AF::Fairing_options o;
    o.strength = 2;
    o.linear_solver = solver;
    const AF::Fairing_report ra = AF::anisotropic_fairing(a, AF::parameters::strength(2).linear_solver(solver));
    const AF::Fairing_report rb = AF::anisotropic_fairing(b, AF::parameters::fairing_options(o));
    AF_CHECK(ra.succeeded() && points(a) == points(b) && ra.choices == rb.choices, "Fairing_options::strength is the named parameter");
  }

  // ---- refused, naming strength, before anything is touched
  Mesh mesh = sphere;
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for(double bad : { 0.0, -1.0, nan, inf, -inf })
  {
    char what[64];
    std::snprintf(what, sizeof what, "strength %g", bad);
    check_refused(mesh, [&](Mesh& m) { AF::anisotropic_fairing(m, AF::parameters::strength(bad)); }, what);
    AF::Fairing_options o;
    o.strength = bad;
    check_refused(mesh, [&](Mesh& m) { AF::anisotropic_fairing(m, AF::parameters::fairing_options(o)); }, std::string(what) + " in Fairing_options");
  }
  check_refused(mesh, [&](Mesh& m) { AF::anisotropic_fairing(m, AF::parameters::relative_time_step(1e-3).strength(2)); },
                "strength 2 with a time step (the paper's criteria)");
  check_refused(mesh, [&](Mesh& m) {
    AF::anisotropic_fairing(m, AF::parameters::strength(0.5).stopping_criteria(AF::Stopping_criteria::none()));
  }, "strength 0.5 with no stopping criterion");
  auto q = mesh.add_property_map<Vertex, double>("v:q", 0.0).first;
  check_refused(mesh, [&](Mesh& m) {
    AF::anisotropic_fairing(m, m.points(), q, AF::parameters::strength(2).attribute_mode(AF::Attribute_mode::ATTRIBUTES_ONLY));
  }, "strength 2 in the attributes-only mode");
  {
    Mesh m = sphere;
    const AF::Fairing_report x = AF::anisotropic_fairing(m, AF::parameters::relative_time_step(1e-3).number_of_iterations(2).strength(1));
    AF_CHECK(x.succeeded() && x.steps.size() == 2, "strength 1 is accepted with any stopping rule");
  }
  return AF_test::report();
}
