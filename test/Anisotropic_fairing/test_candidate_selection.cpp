// The default run's choice among its candidates (internal/run/Smoother_selection.h, select_smoother) cannot be
// fooled by a candidate that stops early: every candidate is judged by the same risk estimate, at a state
// its own estimate can be compared at, and one that ended short of the noise level is judged, not preferred.
//
// Constructed case: a noisy icosphere and stand-in flows whose results are known exactly. The truth is
// the unit sphere; "isotropic" returns it (projection onto the sphere: error about 0, divergence 0),
// "uniform" returns its input unchanged (error 0 along the normals but divergence N: risk 1 per vertex,
// the noise itself), and the anisotropic candidate is forced to stop early, as a run whose later steps
// are rejected does: it moves a tenth of the way toward the sphere and reports STEP_REJECTED. Kept must be
// the isotropic result, with the risks in `choices`; a candidate stopped by the callback is not compared.
// Then the early candidate is made the truth itself: still not kept (nor estimated) while another reached
// the noise level, kept when none did, its probe run then replaying its steps. The uniform stand-in carries
// its probe along, as the uniform flow does; the others are probed by runs of their own. With the normals
// known before the candidates run (the anisotropic run's prefiltered input), every probe rides along and a
// run of its own is made only for a candidate whose carried estimate is below the lowest estimate so far.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Anisotropic_fairing/internal/run/Fairing_driver.h>

#include "test_support/check.h"
#include "test_support/mesh_generators.h"
#include "test_support/unit_sphere.h"

#include <cmath>
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
  bool all_ride = false;   // every stand-in carries its probe along (else only the uniform one)

  std::size_t steps_left() const { return 100; }

  AFI::Flow_outcome run(const AFI::Flow_request& request)
  {
    const bool probe = request.probe_start != nullptr || request.make_probe;
    calls.push_back(request.name + (request.fixed_steps > 0 ? " (fixed)" : "") + (probe ? " (probe along)" : ""));
    const bool isotropic = request.flow.tensor == AFI::Candidate_tensor::ISOTROPIC;
    const bool uniform = request.flow.tensor == AFI::Candidate_tensor::UNIFORM;
    AFI::Flow_outcome out;
    AF::Fairing_report& r = out.report;
    r.steps.resize(3);
    if(isotropic) { out.Y = toward_sphere(request.start, isotropic_weight); r.stop_reason = others_stop; }
    else if(uniform) { out.Y = request.start; r.stop_reason = others_stop; }   // the probe stays
    else { out.Y = toward_sphere(request.start, anisotropic_weight); r.stop_reason = anisotropic_stop; }
    if(request.probe_start && uniform) out.probe = *request.probe_start;
    else if(request.probe_start && all_ride)
      out.probe = toward_sphere(*request.probe_start, isotropic ? isotropic_weight : anisotropic_weight);
    // else only the uniform flow's rides along
    if(request.may_be_kept) out.Z = out.Y;
    return out;
  }
};

// The default run's first run (the stand-in anisotropic flow), then its choice.
struct Selection
{
  AF::Fairing_report report;
  AFI::Control_matrix X, control;
  std::string choices;
};

// `surface` not empty: the estimate's surface, known before the first run, which carries its probe along its
// normals.
Selection select(Stand_in_flows& flows, const AFI::Ghost_layer& layer, const AFI::Control_matrix& input,
                 const std::vector<double>& sigmas, const AFI::Control_matrix& surface = AFI::Control_matrix())
{
  AFI::Candidate_list candidates = AFI::default_candidates(2);
  const std::vector<double> b = AFI::risk_probe_values(std::size_t(input.rows()));
  AFI::Control_matrix probe;
  if(surface.size() > 0)
    probe = AFI::probed_input(input, AFI::vertex_normals(*layer.topology, layer.real_faces, surface), sigmas, b);
  AFI::Flow_request first{ candidates[0].settings, "", input };
  first.probe_start = surface.size() > 0 ? &probe : nullptr;
  candidates[0].result = flows.run(first);
  candidates[0].made = true;
  AFI::Smoother_choice choice =
    AFI::select_smoother(std::move(candidates), AFI::Selection_context{ layer, input, sigmas, b, surface }, flows);
  Selection s;
  s.report = choice.kept.result.report;
  s.X = choice.kept.result.Y;
  s.control = choice.kept.result.Z;
  s.choices = choice.choices;
  return s;
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

  for(const AF::Stop_reason stop : {AF::Stop_reason::STEP_REJECTED, AF::Stop_reason::MAXIMUM_STEPS, AF::Stop_reason::CALLBACK})
  {
    Stand_in_flows flows{stop, 0.1, 1.0, {}};
    const Selection chosen = select(flows, layer, input, sigmas);
    const AF::Fairing_report& report = chosen.report;
    const AFI::Control_matrix &X = chosen.X, &control = chosen.control;
    const std::string& choices = chosen.choices;
    std::printf("anisotropic candidate stopped by %s: kept the %s result; runs:", AF::to_string(stop), report.selected_tensor.c_str());
    for(const std::string& c : flows.calls) std::printf(" [%s]", c.c_str());
    std::printf("\n  choices%s\n", choices.c_str());
    const double moved_to_sphere = (X - toward_sphere(input, 1.0)).norm();
    if(stop == AF::Stop_reason::CALLBACK)
    {
      // the user ended the run: nothing else is run, the anisotropic result is kept
      AF_CHECK(report.selected_tensor == "anisotropic", "a run the callback ended is kept as it is");
      AF_CHECK(flows.calls.size() == 1, "and no other candidate runs");
      continue;
    }
    AF_CHECK(report.selected_tensor == "isotropic", std::string("the candidate that stopped early (") + AF::to_string(stop) +
                                                      ") is judged, not preferred: the isotropic result is kept");
    AF_CHECK(moved_to_sphere < 1e-12 && (control - X).norm() < 1e-12, "X and the control points are the kept candidate's");
    AF_CHECK(choices.find(std::string("anisotropic not estimated (stopped early: ") + AF::to_string(stop) + ")") != std::string::npos,
             "choices names the candidate that stopped early");
    // no probe run for a candidate that cannot be kept; the uniform probe rode along its run
    bool probed_early = false, uniform_along = false, uniform_probe_run = false;
    for(const std::string& c : flows.calls)
    {
      probed_early = probed_early || c.find("anisotropic flow on the probed input") == 0;
      uniform_along = uniform_along || c == "uniform fourth-order flow (probe along)";
      uniform_probe_run = uniform_probe_run || c.find("uniform fourth-order flow on the probed input") == 0;
    }
    AF_CHECK(!probed_early, "the early candidate is not probed while another reached the noise level");
    AF_CHECK(uniform_along && !uniform_probe_run, "the uniform candidate's probe rides along its run");
    AF_CHECK(choices.find("uniform fourth-order not") == std::string::npos, "and it is estimated: " + choices);
  }

  // judged, not preferred, however low its estimate: w = 1 (the truth) has the lowest estimate, below
  // that of w = 0.5 at the noise level.
  // Kept only when no candidate reached the noise level: then the lowest estimate among those that stopped.
  const struct { AF::Stop_reason others; const char* kept; } cases[] = { {AF::Stop_reason::NOISE_LEVEL, "isotropic"},
                                                                          {AF::Stop_reason::MAXIMUM_STEPS, "anisotropic"} };
  for(const auto& m : cases)
  {
    Stand_in_flows flows{AF::Stop_reason::STEP_REJECTED, 1.0, 0.5, {}, m.others};
    const Selection chosen = select(flows, layer, input, sigmas);
    std::printf("stopped early at w = 1, the others at w = 0.5 (%s): kept the %s result%s\n", AF::to_string(m.others),
                chosen.report.selected_tensor.c_str(), chosen.choices.c_str());
    AF_CHECK(chosen.report.selected_tensor == m.kept, std::string("kept the ") + m.kept + " result");
    AF_CHECK(chosen.choices.find("(stopped early: step_rejected)") != std::string::npos &&
             chosen.choices.find("anisotropic not compared") == std::string::npos, "it is named: " + chosen.choices);
    if(m.others == AF::Stop_reason::NOISE_LEVEL) continue;
    // estimated, since none reached the noise level: its probe run replays its steps (no stopping rule of
    // its own)
    bool replayed = false;
    for(const std::string& c : flows.calls) replayed = replayed || c == "anisotropic flow on the probed input (fixed)";
    AF_CHECK(replayed, "the early candidate's probe run takes the same steps");
    AF_CHECK(chosen.choices.find("anisotropic not estimated") == std::string::npos, "and its estimate is shown: " + chosen.choices);
  }

  // the estimate's surface known first: the isotropic stand-in (the truth, its estimate about 0) and the
  // anisotropic one (a tenth of the way: a hundredth of the noise's square left and a divergence of 0.9 per
  // vertex, about 0.8) both carry their probes, below the uniform one's 1; the isotropic, the lower, is run again
  // first, and the anisotropic is then above its estimate and is not
  {
    Stand_in_flows flows{AF::Stop_reason::NOISE_LEVEL, 0.1, 1.0, {}};
    flows.all_ride = true;
    const Selection chosen = select(flows, layer, input, sigmas, toward_sphere(input, 1.0));
    std::printf("normals known first: kept the %s result; runs:", chosen.report.selected_tensor.c_str());
    for(const std::string& c : flows.calls) std::printf(" [%s]", c.c_str());
    std::printf("\n  choices%s\n", chosen.choices.c_str());
    bool isotropic_again = false, anisotropic_again = false;
    for(const std::string& c : flows.calls)
    {
      isotropic_again = isotropic_again || c == "isotropic flow on the probed input";
      anisotropic_again = anisotropic_again || c.find("anisotropic flow on the probed input") == 0;
    }
    AF_CHECK(chosen.report.selected_tensor == "isotropic", "the lowest estimate is kept");
    AF_CHECK(isotropic_again && !anisotropic_again, "only the candidate whose carried estimate could be the lowest runs again");
    AF_CHECK(chosen.choices.find("anisotropic 0.") != std::string::npos && chosen.choices.find("or more (carried along") != std::string::npos,
             "the other's carried estimate is shown as a lower bound: " + chosen.choices);
  }
  return AF_test::report();
}
