// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default run's choice among its flows: the anisotropic result is compared with the isotropic and
// the uniform fourth-order flow's by the risk estimate of Tensor_selection.h, and the lowest kept.
// Every candidate is judged by the same estimate. One that ends at the noise level is estimated as it
// runs (its stopping rule is part of the estimator); one that ends short of it (its later steps rejected,
// the budget spent, a steady state) is estimated at the state it reached: its probe run replays the
// same number of steps with no stopping rule, since a probe that stopped elsewhere would measure the
// stopping rule's jump instead of the flow. A candidate that stops early is judged, never preferred: it
// is kept only when no candidate reached the noise level, and only then is its estimate made. Its flow
// could not go on without folding the surface (or ran out of steps), and on noise that is not Gaussian
// (quantised coordinates) its estimate came out far below the others' while its error was three times theirs.
// Every probe rides along its candidate's run (Ride_along_probe.h), one solve with more columns instead
// of a second run, once the normals are known: the anisotropic run makes them first, from its input's
// prefiltered surface. The uniform flow's stiffness depends on the connectivity alone, so its steps are
// linear in the data but for the mass matrix, and its carried estimate is its estimate (within 0.022 per
// vertex of a run of its own on 26 cases, median 0.004, the same choices). The other two flows' operators
// follow the surface, and that dependence is part of their divergence: carried along, their estimates
// came out lower than by a run of their own, by 0.046 per vertex (median, up to 0.09: the anisotropic
// flow) and 0.010 (up to 0.04: the isotropic). So they are run again on the probed input only when their
// carried estimate is below the lowest estimate so far.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_SMOOTHER_SELECTION_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_SMOOTHER_SELECTION_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/Uniform_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/run/Tensor_selection.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// Whether a run ended where its own stopping rule wanted it: at the noise level.
inline bool ended_at_noise_level(const Fairing_report& r)
{
  return r.succeeded() && (r.stop_reason == Stop_reason::NOISE_LEVEL || r.stop_reason == Stop_reason::NOISE_REMOVED ||
                           r.stop_reason == Stop_reason::DEVIATION_BOUND);
}

/// Whether a run is judged: it ran to its end, whatever stopped it, but the user's callback.
inline bool judged_run(const Fairing_report& r) { return r.succeeded() && r.stop_reason != Stop_reason::CALLBACK; }

/// One flow of the comparison, its result and its estimates.
struct Smoother_candidate
{
  const char* name; const char* label; const char* flow;
  Fairing_report report;
  Control_matrix Y, Z, probe;   // probe: the result of the probed input, when it rode along
  double risk = std::nan(""), carried = std::nan("");   // the estimate, and the one its probe carried along gave

  /// Compared: judged, and at the noise level unless none of the candidates reached it.
  bool compared(bool any_at_noise) const { return judged_run(report) && (ended_at_noise_level(report) || !any_at_noise); }
};

/// A failed report for a run the step budget cannot pay for: never kept.
inline Fairing_report run_not_made()
{
  Fairing_report r;
  r.status = Fairing_status::SOLVER_FAILED;
  r.stop_reason = Stop_reason::FAILURE;
  r.message = "not run: the call's step budget (number_of_iterations) was spent";
  return r;
}

/// True, and why in `choices`, when the anisotropic run leaves nothing to compare.
inline bool nothing_to_compare(const Fairing_report& report, std::size_t steps_left, std::string& choices)
{
  if(report.succeeded() && report.stop_reason == Stop_reason::CALLBACK)
  {
    choices += "; kept the anisotropic result (the callback ended the run)";
    return true;
  }
  if(report.succeeded() && report.stop_reason == Stop_reason::NOISE_LEVEL && report.steps.empty())
  {
    // every flow stops there before its first step, with the same result: nothing to compare
    choices += "; kept the anisotropic result (the input's limit surface is at the noise level already: every flow stops before its first step)";
    return true;
  }
  if(steps_left == 0)
  {
    if(report.succeeded()) choices += "; kept the anisotropic result (the step budget, number_of_iterations, is spent: no other flow runs)";
    return true;
  }
  return false;
}

/// The sum of the risk terms of result Y whose probed input ended at Yp (Tensor_selection.h).
inline double risk_of(const Control_matrix& input, const Control_matrix& Y, const Control_matrix& Yp, const Control_matrix& N,
                      const std::vector<double>& sigma, const std::vector<double>& b)
{
  double risk = 0;
  for(double x : risk_terms(input, Y, Yp, N, sigma, b)) risk += x;
  return risk;
}

/// The estimates: the uniform flow's carried one is its own; the other two are run again on the `probed`
/// input (lowest carried estimate first) only when theirs is below the lowest estimate of their kind so far.
/// `run_candidate(k, Y, start, Z, steps, name)` runs candidate k.
template <typename RunCandidate>
void estimate_risks(std::vector<Smoother_candidate>& c, const RunCandidate& run_candidate, const Control_matrix& input,
                    const Control_matrix& probed, const Control_matrix& N, const std::vector<double>& sigma,
                    const std::vector<double>& b, const std::size_t& steps_left, bool any_at_noise)
{
  for(Smoother_candidate& x : c)
    if(x.compared(any_at_noise) && x.probe.size() > 0) x.carried = risk_of(input, x.Y, x.probe, N, sigma, b);
  c[2].risk = c[2].carried;
  std::vector<std::size_t> order{ 2, 0, 1 };
  if(c[1].carried < c[0].carried) std::swap(order[1], order[2]);
  for(std::size_t k : order)
  {
    if(!c[k].compared(any_at_noise) || std::isfinite(c[k].risk)) continue;
    const bool at_noise = ended_at_noise_level(c[k].report);
    double lowest = std::nan("");
    for(const Smoother_candidate& x : c)
      if(std::isfinite(x.risk) && ended_at_noise_level(x.report) == at_noise && !(x.risk >= lowest)) lowest = x.risk;
    if(c[k].carried >= lowest || steps_left == 0) continue;
    // a candidate that ended short of the noise level: its probe takes exactly its steps
    const std::size_t replay = at_noise ? 0 : c[k].report.steps.size();
    if(!at_noise && replay == 0) continue;   // it took no step: nothing to estimate
    const std::string probe_name = std::string(c[k].flow) + " on the probed input";
    Control_matrix Yp;
    const Fairing_report rp = run_candidate(k, Yp, probed, nullptr, replay, probe_name.c_str());
    if(!rp.succeeded() || (rp.stop_reason == Stop_reason::MAXIMUM_STEPS && steps_left == 0 && replay == 0)) continue;   // cut short by the budget
    if(replay > 0 && rp.steps.size() != replay) continue;   // the probe could not take the same steps
    c[k].risk = risk_of(input, c[k].Y, Yp, N, sigma, b);
  }
}

/// The candidate kept: the lowest estimate among the runs that reached the noise level, among those that
/// stopped early only when none reached it; c.size() when none has an estimate.
inline std::size_t lowest_estimate(const std::vector<Smoother_candidate>& c)
{
  const auto lowest_of = [&c](bool at_noise) {
    std::size_t best = c.size();
    for(std::size_t k = 0; k < c.size(); ++k)
      if(std::isfinite(c[k].risk) && ended_at_noise_level(c[k].report) == at_noise && (best == c.size() || c[k].risk < c[best].risk)) best = k;
    return best;
  };
  const std::size_t kept = lowest_of(true);
  return kept < c.size() ? kept : lowest_of(false);
}

/// What `choices` says of the comparison that kept candidate `kept`, the estimates per vertex in units of the noise.
inline std::string describe_choice(const std::vector<Smoother_candidate>& c, std::size_t kept, bool any_at_noise, Eigen::Index rows)
{
  std::string list;
  for(const Smoother_candidate& x : c)
  {
    char text[160];
    if(std::isfinite(x.risk))
      std::snprintf(text, sizeof text, "%s %.4g%s", x.label, x.risk / double(rows) - 1,
                    ended_at_noise_level(x.report) ? "" : (std::string(" (stopped early: ") + to_string(x.report.stop_reason) + ")").c_str());
    else if(std::isfinite(x.carried))
      std::snprintf(text, sizeof text, "%s %.4g or more (carried along: it cannot be the lowest)", x.label, x.carried / double(rows) - 1);
    else if(judged_run(x.report) && !ended_at_noise_level(x.report) && any_at_noise)
      std::snprintf(text, sizeof text, "%s not estimated (stopped early: %s)", x.label, to_string(x.report.stop_reason));
    else
      std::snprintf(text, sizeof text, "%s not compared (%s)", x.label,
                    x.report.succeeded() ? to_string(x.report.stop_reason) : to_string(x.report.status));
    list += (list.empty() ? "" : ", ") + std::string(text);
  }
  bool lowest = true;
  for(const Smoother_candidate& x : c)
    lowest = lowest && !(x.risk < c[kept].risk) && !(judged_run(x.report) && !ended_at_noise_level(x.report) && any_at_noise);
  return std::string("; kept the ") + c[kept].name +
         (lowest ? " result, whose estimated error is the lowest" : " result, whose estimated error is the lowest of the runs that "
          "reached the noise level; a run that stopped early is not preferred to them") +
         " (Stein's unbiased risk estimate per vertex, in units of the noise: " + list + ")";
}

/// Runs the isotropic and the uniform fourth-order flow too (`run(name, tensor, Y, order, start, Z, steps,
/// probe)` runs from `start` and writes Y, and its control points in *Z unless null; `steps` > 0: exactly
/// that many steps, no stopping rule; `probe` not null: carries that start along and replaces it by where
/// it ends, written as Y is, or by nothing when it cannot ride along) and keeps, in X, *control and
/// `report`, the result whose estimated error is lowest, or the first that succeeded. `steps_left` is the
/// call's step budget: a run it cannot pay for is not made. `sigma`: the noise's deviation at each vertex
/// (0 where there is none to estimate). `normals`: those the estimate measures along, when the anisotropic
/// run made them (empty: the isotropic result's), and `anisotropic_probe` the probe it carried along them.
/// Says which in `choices`. (The user's callback sees every run.)
template <typename Run, typename Tensor>
void select_smoother(Run& run, const Tensor& tensor, const Ghost_layer& layer, const Control_matrix& input,
                     const std::vector<double>& sigma, Control_matrix& X, Control_matrix* control, Fairing_report& report,
                     std::string& choices, const std::size_t& steps_left, const Control_matrix& normals = Control_matrix(),
                     const Control_matrix& anisotropic_probe = Control_matrix())
{
  report.selected_tensor = "anisotropic";
  if(nothing_to_compare(report, steps_left, choices)) return;
  std::vector<Smoother_candidate> c(3);
  c[0].name = c[0].label = "anisotropic"; c[0].flow = "anisotropic flow"; c[0].report = report;
  c[0].Y.swap(X);   // the anisotropic result (and its control points): c[0]'s until the choice is made
  c[0].probe = anisotropic_probe;
  if(control) c[0].Z.swap(*control);
  c[1].name = c[1].label = "isotropic"; c[1].flow = "isotropic flow";
  c[2].name = "uniform"; c[2].label = "uniform fourth-order"; c[2].flow = "uniform fourth-order flow";
  const auto run_candidate = [&](std::size_t k, Control_matrix& Y, const Control_matrix& start, Control_matrix* Z, std::size_t steps,
                                 const char* name, Control_matrix* probe = nullptr) {
    if(k == 0) return run(name, tensor, Y, c[0].report.flow_order, start, Z, steps, probe);
    if(k == 1) return run(name, Isotropic_diffusion_tensor(), Y, 2, start, Z, steps, probe);
    return run(name, Uniform_diffusion_tensor(), Y, 4, start, Z, steps, probe);
  };
  // the normals of the risk: the anisotropic run's (its prefiltered input's), else the isotropic result's,
  // or the first sound one's
  const std::vector<double> b = risk_probe_values(std::size_t(input.rows()));
  const bool known = normals.size() > 0;
  if(known) c[1].probe = probed_input(input, normals, sigma, b);
  c[1].report = steps_left > 0 ? run_candidate(1, c[1].Y, input, control ? &c[1].Z : nullptr, 0, c[1].flow, known ? &c[1].probe : nullptr)
                               : run_not_made();
  const Smoother_candidate* base = c[1].report.succeeded() ? &c[1] : &c[0];
  Control_matrix made_normals;
  if(!known) made_normals = vertex_normals(*layer.topology, layer.real_faces, base->report.succeeded() ? base->Y : input);
  const Control_matrix& N = known ? normals : made_normals;
  const Control_matrix probed = probed_input(input, N, sigma, b);
  c[2].probe = probed;
  c[2].report = steps_left > 0 ? run_candidate(2, c[2].Y, input, control ? &c[2].Z : nullptr, 0, c[2].flow, &c[2].probe) : run_not_made();
  // a candidate that stopped early is estimated only when none reached the noise level
  bool any_at_noise = false;
  for(const Smoother_candidate& x : c) any_at_noise = any_at_noise || (judged_run(x.report) && ended_at_noise_level(x.report));
  estimate_risks(c, run_candidate, input, probed, N, sigma, b, steps_left, any_at_noise);
  std::size_t kept = lowest_estimate(c);
  if(kept < c.size()) choices += describe_choice(c, kept, any_at_noise, input.rows());
  else
  {
    // nothing to compare: the first result that succeeded
    for(std::size_t k = 0; k < c.size() && kept == c.size(); ++k)
      if(c[k].report.succeeded()) kept = k;
    if(kept == c.size())   // all failed: the anisotropic report says why
    {
      X.swap(c[0].Y);
      if(control) control->swap(c[0].Z);
      return;
    }
    choices += std::string("; kept the ") + c[kept].name + " result (no other could be compared)";
  }
  X.swap(c[kept].Y);
  if(control) control->swap(c[kept].Z);
  if(kept == 0) return;
  report = c[kept].report;
  report.selected_tensor = c[kept].name;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_SMOOTHER_SELECTION_H
