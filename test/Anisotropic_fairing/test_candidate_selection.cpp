// The default run's choice among its candidates (internal/run/Smoother_selection.h, select_smoother) cannot be
// fooled by a candidate that stops early: every candidate is judged by the same risk estimate, at a state
// its own estimate can be compared at, and one that ended short of the noise level is judged, not preferred.
//
// Constructed case: a noisy icosphere and stand-in flows whose results are known exactly. The truth is
// the unit sphere; "isotropic" returns it (projection onto the sphere: error about 0, divergence 0),
// "uniform" returns its input unchanged (error 0 along the normals but divergence N: risk 1 per vertex,
// the noise itself), and the anisotropic candidate is forced to stop early, as a run whose later steps
// are rejected does: it moves a tenth of the way toward the sphere and reports STEP_REJECTED. Kept must be
// the isotropic result, with the risks in `choices`. A first run the callback ends is kept alone.
// Then the early candidate is made the truth itself: still not kept while another reached the noise level,
// kept when none did. The normals are known before the candidates run (the input's prefiltered surface), so
// every stand-in carries its probe along, as the flows do; the uniform candidate's carried estimate is its
// estimate, and it is never run again; the others' are lower bounds, and a run on the probed input is made
// only for one that could be the lowest: the anisotropic flow's probe replaying its run's steps on an
// operator of its own (Probe_flow.h), the isotropic flow run again (taking its steps when it stopped early).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Anisotropic_fairing/internal/run/Fairing_driver.h>

#include "test_support/check.h"
#include "test_support/mesh_generators.h"
#include "test_support/unit_sphere.h"

#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace AF = CGAL::Anisotropic_fairing;
namespace AFI = CGAL::Anisotropic_fairing::internal;

namespace {

using AF_test::toward_sphere;

struct Stand_in_flows
{
  AF::Stop_reason anisotropic_stop;
  double anisotropic_weight = 0.1, isotropic_weight = 1.0;   // how far each moves onto the sphere
  std::vector<std::string> calls;
  AF::Stop_reason others_stop = AF::Stop_reason::NOISE_LEVEL;   // how the isotropic and the uniform stand-in end

  std::size_t steps_left() const { return 100; }

  AFI::Flow_outcome run(const AFI::Flow_request& request)
  {
    const bool probe = request.probe_start != nullptr;
    calls.push_back(request.name + (request.fixed_steps > 0 ? " (fixed)" : "") + (probe ? " (probe along)" : "") +
                    (request.replay ? " (replay)" : ""));
    const bool isotropic = request.flow.tensor == AFI::Candidate_tensor::ISOTROPIC;
    const bool uniform = request.flow.tensor == AFI::Candidate_tensor::UNIFORM;
    const double weight = uniform ? 0.0 : isotropic ? isotropic_weight : anisotropic_weight;
    AFI::Flow_outcome out;
    AF::Fairing_report& r = out.report;
    r.steps.resize(3);
    out.Y = toward_sphere(request.start, weight);   // the uniform stand-in stays, and so does its probe
    r.stop_reason = isotropic || uniform ? others_stop : anisotropic_stop;
    if(probe) out.probe = toward_sphere(*request.probe_start, weight);
    if(request.may_be_kept) out.Z = out.Y;
    return out;
  }

  bool ran(const std::string& call) const
  {
    for(const std::string& c : calls)
      if(c.find(call) == 0) return true;
    return false;
  }
};

// The default run's choice, the estimate's surface (the truth's normals) known before the first run.
struct Selection
{
  AF::Fairing_report report;
  AFI::Control_matrix X, control;
  std::string choices;
};

// The estimate `choices` gives the uniform stand-in (printed to 4 digits; NaN: none).
double uniform_estimate(const std::string& choices)
{
  const std::string name = "uniform fourth-order ";
  const std::size_t at = choices.find(name);
  return at == std::string::npos ? std::nan("") : std::strtod(choices.c_str() + at + name.size(), nullptr);
}

// SURE per vertex of a result equal to its input: no error, a divergence of b_i^2 at vertex i (the probe moves the
// result as it moves the input), so 2 mean(b^2) - 1, about 1 (the noise itself).
double identity_estimate(Eigen::Index n)
{
  double square = 0;
  for(double b : AFI::risk_probe_values(std::size_t(n))) square += b * b;
  return 2 * square / double(n) - 1;
}

Selection select(Stand_in_flows& flows, const AFI::Ghost_layer& layer, const AFI::Control_matrix& input,
                 const std::vector<double>& sigmas)
{
  const std::vector<double> b = AFI::risk_probe_values(std::size_t(input.rows()));
  const AFI::Control_matrix surface = toward_sphere(input, 1.0);
  AFI::Smoother_choice choice = AFI::select_smoother(AFI::default_candidates(2),
                                                     AFI::Selection_context{ layer, input, sigmas, b, surface }, flows);
  Selection s;
  s.report = choice.kept.result.report;
  s.X = choice.kept.result.Y;
  s.control = choice.kept.result.Z;
  s.choices = choice.choices;
  std::printf("kept the %s result; runs:", s.report.selected_tensor.c_str());
  for(const std::string& c : flows.calls) std::printf(" [%s]", c.c_str());
  std::printf("\n  choices%s\n", s.choices.c_str());
  return s;
}

// An estimate whose terms are the first column of the result: what the drop test reads (Candidate_drop.h).
struct Column_estimate : AFI::Risk_estimate
{
  AFI::Control_matrix none;
  const AFI::Control_matrix& probed() const override { return none; }
  std::vector<double> terms(const AFI::Control_matrix& f, const AFI::Control_matrix&) const override
  {
    std::vector<double> t(std::size_t(f.rows()));
    for(Eigen::Index i = 0; i < f.rows(); ++i) t[std::size_t(i)] = f(i, 0);
    return t;
  }
  double relative(const AFI::Control_matrix& f, const AFI::Control_matrix& p) const override
  {
    double sum = 0;
    for(double t : terms(f, p)) sum += t;
    return sum / double(f.rows()) - 1;
  }
  double relative_loss(const AFI::Control_matrix&, const AFI::Control_matrix&) const override { return 0; }
  const char* description() const override { return "the first column"; }
};

// A candidate dropped against a leader whose terms are all 1 (estimate 0): its estimate per step is the
// mean of its terms less 1, their spread `spread` around it (alternating signs: a standard error of spread
// / sqrt(n - 1) for n terms).
void check_drop_test()
{
  const std::size_t n = 400;
  const std::vector<double> leader(n, 1.0);
  const auto state = [n](double estimate, double spread) {
    AFI::Control_matrix Y = AFI::Control_matrix::Zero(Eigen::Index(n), 3);
    for(std::size_t i = 0; i < n; ++i) Y(Eigen::Index(i), 0) = 1 + estimate + (i % 2 ? spread : -spread);
    return Y;
  };
  const Column_estimate e;
  std::vector<double> t = e.terms(state(0.3, 2.0), AFI::Control_matrix());
  AF_CHECK(!AFI::mean_difference({ 1.0 }, { 0.0 }), "no standard error of one difference");
  const std::pair<double, double> d = *AFI::mean_difference(t, leader);
  AF_CHECK(std::abs(d.first - 0.3) < 1e-12 && std::abs(d.second - 2.0 / std::sqrt(double(n - 1))) < 1e-12,
           "the mean difference and its standard error");
  double last = 0;
  const auto keep_going = AFI::drop_test(e, leader, last);
  // falling (kept), rising but within 2 standard errors (0.25 against 2 x 0.15: kept), rising by more (dropped)
  const AFI::Control_matrix none;
  const bool first = keep_going(state(0.5, 0.1), none), second = keep_going(state(0.2, 0.1), none);
  const bool third = keep_going(state(0.25, 3.0), none), fourth = keep_going(state(0.3, 0.1), none);
  std::printf("drop test: %d %d %d %d, last estimate %.3g\n", first, second, third, fourth, last);
  AF_CHECK(first && second, "a falling estimate is kept, however far above the leader");
  AF_CHECK(third, "a rising one within twice the standard error of the difference is kept");
  AF_CHECK(!fourth && std::abs(last - 0.3) < 1e-12, "a rising one above it by more is dropped, at its estimate");
}

} // namespace

int main()
{
  Mesh mesh;
  AF_test::soup_to_mesh(AF_test::icosphere_soup(3), mesh);   // 642 vertices on the unit sphere
  const AFI::Indexed_mesh<Mesh> im(mesh, AFI::Borders::GHOSTED, true);
  const AFI::Ghost_layer& layer = im.ghost_layer();
  const double sigma = 0.02;
  AFI::Control_matrix input = im.read_points(get(CGAL::vertex_point, mesh));
  std::mt19937 rng(7);
  std::normal_distribution<double> gauss(0.0, sigma);
  for(Eigen::Index i = 0; i < input.rows(); ++i) input.row(i) *= 1 + gauss(rng);
  const std::vector<double> sigmas(std::size_t(input.rows()), sigma);

  for(const AF::Stop_reason stop : {AF::Stop_reason::STEP_REJECTED, AF::Stop_reason::MAXIMUM_STEPS})
  {
    Stand_in_flows flows{stop};
    std::printf("anisotropic candidate stopped by %s: ", AF::to_string(stop));
    const Selection chosen = select(flows, layer, input, sigmas);
    AF_CHECK(chosen.report.selected_tensor == "isotropic", std::string("the candidate that stopped early (") +
                                                             AF::to_string(stop) + ") is judged, not preferred");
    AF_CHECK((chosen.X - toward_sphere(input, 1.0)).norm() < 1e-12 && (chosen.control - chosen.X).norm() < 1e-12,
             "X and the control points are the kept candidate's");
    AF_CHECK(chosen.choices.find(std::string("anisotropic not estimated (stopped early: ") + AF::to_string(stop) + ")") !=
               std::string::npos, "choices names the candidate that stopped early: " + chosen.choices);
    AF_CHECK(flows.ran("uniform fourth-order flow (probe along)") && flows.ran("anisotropic flow (probe along)"),
             "every candidate carries its probe");
    AF_CHECK(!flows.ran("uniform fourth-order flow on the probed input") && !flows.ran("anisotropic flow on the probed input"),
             "neither the candidate whose carried probe is its estimate nor the one that stopped early is run again");
    AF_CHECK(flows.ran("isotropic flow on the probed input"), "the isotropic one is, its carried estimate being the lowest");
    AF_CHECK(std::abs(uniform_estimate(chosen.choices) - identity_estimate(input.rows())) < 5e-4,
             "the uniform one is estimated at 2 mean(b^2) - 1 (about 1): its divergence is the probe's square");
  }

  // the first run ended by the user's callback: kept alone, nothing else runs
  {
    Stand_in_flows flows{AF::Stop_reason::NOISE_LEVEL};
    flows.others_stop = AF::Stop_reason::CALLBACK;
    std::printf("first run ended by the callback: ");
    const Selection chosen = select(flows, layer, input, sigmas);
    AF_CHECK(chosen.report.selected_tensor == "uniform" && flows.calls.size() == 1,
             "a first run the callback ended is kept as it is, and no other candidate runs");
  }

  // judged, not preferred, however low its estimate: w = 1 (the truth) has the lowest estimate, below
  // that of w = 0.5 at the noise level.
  // Kept only when no candidate reached the noise level: then the lowest estimate among those that stopped.
  const struct { AF::Stop_reason others; const char* kept; } cases[] = { {AF::Stop_reason::NOISE_LEVEL, "isotropic"},
                                                                          {AF::Stop_reason::MAXIMUM_STEPS, "anisotropic"} };
  for(const auto& m : cases)
  {
    Stand_in_flows flows{AF::Stop_reason::STEP_REJECTED, 1.0, 0.5, {}, m.others};
    std::printf("stopped early at w = 1, the others at w = 0.5 (%s): ", AF::to_string(m.others));
    const Selection chosen = select(flows, layer, input, sigmas);
    AF_CHECK(chosen.report.selected_tensor == m.kept, std::string("kept the ") + m.kept + " result");
    AF_CHECK(chosen.choices.find("(stopped early: step_rejected)") != std::string::npos &&
             chosen.choices.find("anisotropic not compared") == std::string::npos, "it is named: " + chosen.choices);
    if(m.others == AF::Stop_reason::NOISE_LEVEL) continue;
    // estimated, since none reached the noise level: its probe replays its steps
    AF_CHECK(flows.ran("anisotropic flow on the probed input (fixed) (replay)"), "the early candidate's probe replays its steps");
    AF_CHECK(chosen.choices.find("anisotropic not estimated") == std::string::npos, "its estimate is shown: " + chosen.choices);
    // the isotropic candidate's carried bound is above the anisotropic estimate: it is not run again
    AF_CHECK(!flows.ran("isotropic flow on the probed input"), "nor is a candidate whose carried bound is not the lowest");
  }

  // none at the noise level, the isotropic stand-in the truth: its carried bound is the lowest, and it is
  // estimated by a run on the probed input replaying its steps (no stopping rule)
  {
    Stand_in_flows flows{AF::Stop_reason::STEP_REJECTED, 0.5, 1.0, {}, AF::Stop_reason::MAXIMUM_STEPS};
    std::printf("none at the noise level, the isotropic stand-in the truth: ");
    const Selection chosen = select(flows, layer, input, sigmas);
    AF_CHECK(chosen.report.selected_tensor == "isotropic", "the lowest estimate among the early runs is kept");
    AF_CHECK(flows.ran("isotropic flow on the probed input (fixed)"), "an early candidate's probe run takes its steps");
  }

  // the anisotropic stand-in the truth at the noise level, the isotropic one half way: the anisotropic carried
  // estimate (about 0) is the lowest, its probe replays its steps and its estimate is kept; the isotropic one,
  // whose carried estimate is above it, is not run again: its carried estimate is shown as a lower bound
  {
    Stand_in_flows flows{AF::Stop_reason::NOISE_LEVEL, 1.0, 0.5, {}};
    std::printf("the anisotropic stand-in the truth: ");
    const Selection chosen = select(flows, layer, input, sigmas);
    AF_CHECK(chosen.report.selected_tensor == "anisotropic", "the lowest estimate is kept");
    AF_CHECK(!flows.ran("isotropic flow on the probed input") && flows.ran("anisotropic flow on the probed input (replay)") &&
             flows.calls.size() == 4, "only the anisotropic probe replays");
    AF_CHECK(chosen.choices.find("isotropic 0.") != std::string::npos &&
             chosen.choices.find("or more (carried along") != std::string::npos,
             "the isotropic carried estimate is shown as a lower bound: " + chosen.choices);
  }
  check_drop_test();
  return AF_test::report();
}
