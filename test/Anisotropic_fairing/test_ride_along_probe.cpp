// The risk estimate's probe carried along a run (internal/flow/Ride_along_probe.h) takes exactly the run's
// steps with the run's operators: it is an affine map of its start, and it follows the run through every
// shortened, rewound and retried step. Checked on a noisy icosphere with the default run's own settings
// (noise stop, automatic time steps), for the uniform fourth-order flow (whose probe rides along in the
// default run) and the anisotropic flow (tangential motion removed, steps located at the noise level):
//  - a probe started from the input translated by c ends at the run's result translated by c, exactly
//    (the stiffness annihilates constants, so its columns solve the run's own system);
//  - a probe started from the input plus e d and one from the input plus 2 e d differ from the run's
//    result by a difference and its double (linear in the start, unlike a run of its own);
//  - under a deviation bound (vertex fidelities that change with the state) the probe does not ride along;
//  - the anisotropic flow's probe replaying the run's steps on an operator of its own surface
//    (internal/flow/Probe_flow.h) ends where a run of its own from the probed start ends, taking the same
//    steps: the whole map, the operator's dependence on the data included, which the carried probe misses;
//    and on the run's own path, with the noise stop's last step cut where the run's was.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Anisotropic_fairing/internal/run/Fairing_driver.h>

#include "test_support/check.h"
#include "test_support/mesh_generators.h"

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace AF = CGAL::Anisotropic_fairing;
namespace AFI = CGAL::Anisotropic_fairing::internal;

namespace {

struct Setup
{
  AFI::Locality_ordering ordering;
  AFI::Mesh_components components;
  std::vector<double> component_edge;
  double mean_edge = 0;
  AFI::Control_matrix X;   // the noisy input in the private numbering
};

struct Result
{
  AF::Fairing_report report;
  AFI::Control_matrix Y, probe;
  AFI::Probe_schedule schedule;
  AFI::Stepper_settings settings;
};

template <typename Tensor>
Result run(const Setup& m, const AFI::Ghosted_patch_cache& cache, const AFI::Noise_estimate& noise, const Tensor& tensor, int order,
           const AFI::Control_matrix* probe, double deviation = 0, std::size_t fixed_steps = 0)
{
  AFI::Stepper_settings s;
  s.order = order;
  s.time_unit = AFI::Length_unit::EDGE;
  s.time_step = order == 4 ? AFI::Automatic_parameters().time_step4 : AFI::Automatic_parameters().time_step;
  s.local_time_scale = true;
  s.maximum_steps = 200;
  s.stopping = AF::Stopping_criteria::automatic();
  s.noise = &noise;
  s.measure_limit_surface = s.limit_written = true;
  s.maximum_deviation = deviation;
  if(fixed_steps > 0)
  {
    s.maximum_steps = fixed_steps;
    s.stopping = AF::Stopping_criteria::none();
  }
  const std::size_t n = std::size_t(m.X.rows());
  const std::vector<bool> constrained(n, false), border(n, false);
  const auto callback = [](const AF::Fairing_step&) { return true; };
  auto cb = callback;
  const AFI::Flow_context<AFI::Ghosted_patch_cache> context{ cache, m.ordering, m.components, m.component_edge, m.mean_edge,
                                                            AF::Attribute_mode::GEOMETRY_ONLY, constrained, border };
  AFI::Probe_plan plan;
  plan.start = probe;
  AFI::Stepper_outcome o = AFI::run_stepper(context, tensor, s, m.X, plan, cb);
  Result r;
  r.report = o.report;
  r.Y = o.Y;
  r.probe = o.probe;
  r.schedule = o.schedule;
  r.settings = s;
  return r;
}

// the probe from P replaying the steps of run r on an operator of its own
template <typename Tensor>
AFI::Control_matrix replay(const Setup& m, const AFI::Ghosted_patch_cache& cache, const Tensor& tensor, const Result& r,
                           const AFI::Control_matrix& P)
{
  const std::vector<bool> constrained(P.rows(), false), border(P.rows(), false);
  const AFI::Flow_context<AFI::Ghosted_patch_cache> context{ cache, m.ordering, m.components, m.component_edge, m.mean_edge,
                                                            AF::Attribute_mode::GEOMETRY_ONLY, constrained, border };
  return AFI::replayed_probe(context, tensor, r.settings, P, r.schedule).Y;
}

double largest(const AFI::Control_matrix& A) { return A.cwiseAbs().maxCoeff(); }

} // namespace

int main()
{
  Mesh mesh;
  AF_test::soup_to_mesh(AF_test::icosphere_soup(3), mesh);
  std::mt19937 rng(11);
  std::normal_distribution<double> gauss(0.0, 0.02);
  for(auto v : vertices(mesh))
  {
    const K::Point_3 p = mesh.point(v);
    const double f = 1 + gauss(rng);
    mesh.point(v) = K::Point_3(p.x() * f, p.y() * f, p.z() * f);
  }
  const AFI::Indexed_mesh<Mesh> im(mesh, AFI::Borders::GHOSTED, true);
  Setup m{ AFI::make_locality_ordering(im.ghost_layer()), {}, {}, 0, {} };
  const AFI::Ghost_layer& layer = m.ordering.layer;
  const std::size_t n = im.number_of_vertices();
  m.components = AFI::make_mesh_components(*layer.topology, n, layer.real_faces);
  const AFI::Control_matrix P = im.read_points(get(CGAL::vertex_point, mesh));
  m.X.resize(Eigen::Index(n), 3);
  for(std::size_t i = 0; i < n; ++i) m.X.row(Eigen::Index(i)) = P.row(m.ordering.old_of_new_vertex[i]);
  m.mean_edge = AFI::component_mean_edges(*layer.topology, layer.real_faces, m.components, m.X, m.component_edge);
  const AFI::Ghosted_patch_cache cache(layer, AFI::Quadrature_spec());
  const AFI::Noise_estimate noise(*layer.topology, m.X, std::vector<bool>(n, true));

  AF::Anisotropic_diffusion_tensor anisotropic = AF::Anisotropic_diffusion_tensor::automatic();
  AFI::choose_tensor(anisotropic, AFI::Automatic_parameters().lambda, AFI::Automatic_parameters().epsilon);
  AFI::Control_matrix shifted = m.X, d(Eigen::Index(n), 3);
  const Eigen::RowVector3d c(0.3, -0.2, 0.1);
  for(Eigen::Index i = 0; i < m.X.rows(); ++i) shifted.row(i) += c;
  for(Eigen::Index i = 0; i < d.rows(); ++i) d.row(i) << gauss(rng), gauss(rng), gauss(rng);
  const double e = 0.05;
  const AFI::Control_matrix once = m.X + e * d, twice = m.X + 2 * e * d;

  for(int flow = 0; flow < 2; ++flow)
  {
    const char* name = flow == 0 ? "uniform fourth-order" : "anisotropic";
    const auto go = [&](const AFI::Control_matrix* probe) {
      return flow == 0 ? run(m, cache, noise, AF::Uniform_diffusion_tensor(), 4, probe) : run(m, cache, noise, anisotropic, 2, probe);
    };
    const Result plain = go(nullptr), moved = go(&shifted), a = go(&once), b = go(&twice);
    std::printf("%s flow: %zu steps, stopped by %s; with probes %zu %zu %zu steps\n", name, plain.report.steps.size(),
                AF::to_string(plain.report.stop_reason), moved.report.steps.size(), a.report.steps.size(), b.report.steps.size());
    AF_CHECK(plain.report.succeeded() && plain.report.steps.size() >= 2, std::string(name) + ": the run takes steps");
    AF_CHECK(largest(moved.Y - plain.Y) == 0.0 && largest(a.Y - plain.Y) == 0.0,
             std::string(name) + ": carrying a probe leaves the run's own result as it is");
    AFI::Control_matrix expected = plain.Y;   // control points of the run, translated
    for(Eigen::Index i = 0; i < expected.rows(); ++i) expected.row(i) += c;
    const double translation = largest(moved.probe - expected);
    const double linear = largest((b.probe - plain.Y) - 2 * (a.probe - plain.Y)), size = largest(a.probe - plain.Y);
    std::printf("  translated probe off the translated result by %.3g; second difference %.3g of a difference of %.3g\n",
                translation, linear, size);
    // exact but for the solver: each column's CG stops within 1e-8 of its right-hand side, a step's motion
    // is about 0.02 here, and the columns of a translated start differ by rounding alone
    AF_CHECK(moved.probe.size() == plain.Y.size() && translation < 1e-9, std::string(name) + ": the translated start ends translated");
    AF_CHECK(size > 1e-8 && linear < 1e-4 * size, std::string(name) + ": the probe is linear in its start");
  }
  // the anisotropic probe replayed on its own operator: as a run of its own from the probed start, 3 steps
  {
    const std::size_t k = 3;
    const Result plain = run(m, cache, noise, anisotropic, 2, &once, 0, k);
    AFI::Control_matrix input = once;
    m.X.swap(input);   // the run of its own, from the probed start
    const Result from_probe = run(m, cache, noise, anisotropic, 2, nullptr, 0, k);
    m.X.swap(input);
    const AFI::Control_matrix own = replay(m, cache, anisotropic, plain, once);
    const double own_off = largest(own - from_probe.Y), carried_off = largest(plain.probe - from_probe.Y);
    const double moved = largest(from_probe.Y - once);
    std::printf("anisotropic flow, %zu steps: the probe replayed on its own operator off a run from the probed start "
                "by %.3g, the carried one by %.3g (the steps moved it %.3g)\n", k, own_off, carried_off, moved);
    AF_CHECK(plain.report.steps.size() == k && from_probe.report.steps.size() == k && plain.schedule.steps.size() == k,
             "the runs take the same steps, and the schedule has them");
    AF_CHECK(own.size() == plain.Y.size() && own_off < 1e-9 * moved, "the replayed probe is the run of its own");
    AF_CHECK(carried_off > 1e3 * own_off, "the carried probe is not: it leaves the operator's change out");
    // the default run's noise stop: the last step cut at the noise level, replayed cut as well
    const Result noisy = run(m, cache, noise, anisotropic, 2, &once);
    const AFI::Control_matrix cut = replay(m, cache, anisotropic, noisy, once);
    bool was_cut = false;
    for(const auto& step : noisy.schedule.steps) was_cut = was_cut || (step.cut >= 0 && step.cut < 1);
    std::printf("  noise stop: %zu steps, the last cut: %d; replayed off the carried probe by %.3g\n",
                noisy.schedule.steps.size(), int(was_cut), largest(cut - noisy.probe));
    AF_CHECK(was_cut && largest(cut - noisy.probe) < 0.1 * largest(noisy.probe - once),
             "a cut path is replayed cut: near the carried probe, not a step beyond");
  }
  const Result bounded = run(m, cache, noise, AF::Uniform_diffusion_tensor(), 4, &once, 0.01);
  AF_CHECK(bounded.report.succeeded() && bounded.probe.size() == 0, "under a deviation bound the probe does not ride along");
  return AF_test::report();
}
