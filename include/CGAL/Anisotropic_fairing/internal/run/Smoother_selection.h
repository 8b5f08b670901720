// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default run's choice among its candidate flows (Flow_candidates.h): each is judged by the same risk
// estimate (Tensor_selection.h) and the lowest kept. A candidate that ends short of the noise level (steps
// rejected, budget spent, steady state) is estimated at the state it reached and kept only when none reached
// the noise level: its flow could not go on, and on noise that is not Gaussian its estimate can be far too
// low. Probes ride along their candidate's run (Ride_along_probe.h), and a run is dropped once its estimate
// rises above the leader's (Candidate_drop.h). A candidate whose carried estimate is only a lower bound is
// estimated anew only when that bound could be the lowest: the anisotropic flow's probe replaying its run's
// steps on an operator of its own (Probe_flow.h), the isotropic flow run again on the probed input (taking its
// steps when it stopped early). The figures behind these rules: the manual's Validation page.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_SMOOTHER_SELECTION_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_SMOOTHER_SELECTION_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Noise_model.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/run/Candidate_drop.h>
#include <CGAL/Anisotropic_fairing/internal/run/Flow_candidates.h>
#include <CGAL/Anisotropic_fairing/internal/run/Normal_error_estimate.h>
#include <CGAL/Anisotropic_fairing/internal/run/Tensor_selection.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The estimate the comparison chooses by: SURE of the positions (the default run's), or the face normals'
/// error (Normal_error_estimate.h), which the benchmarks measure: read on the prefiltered input with a probe
/// along A u, or with the probe along the noise and read again on the result kept (`FACE_NORMALS_ON_RESULT`).
enum class Risk_kind { POSITIONS, FACE_NORMALS, FACE_NORMALS_ON_RESULT };

/// `model`: the noise model (Noise_model.h) the face normals' error is estimated with: its deviation along the
/// normals and across them at each vertex, `sigma` scaled by the model's local factors (none: `sigma` along the
/// normals only). `part`: the part of the mesh a process holds (the face normals' error, which the benchmarks
/// measure, reads the whole mesh).
inline std::unique_ptr<Risk_estimate> make_risk_estimate(Risk_kind kind, const Ghost_layer& layer,
                                                         const Control_matrix& y, const Control_matrix& surface,
                                                         const std::vector<double>& sigma, const std::vector<double>& b,
                                                         const Noise_model* model = nullptr,
                                                         const Part_view& part = whole_mesh_view())
{
  if(kind == Risk_kind::POSITIONS)
    return std::make_unique<Position_error_estimate>(*layer.topology, layer.real_faces, y, surface, sigma, b, part);
  std::vector<double> along = sigma, across;
  if(model && model->normal > 0)
  {
    across.assign(sigma.size(), 0.0);
    for(std::size_t i = 0; i < sigma.size(); ++i)
    {
      along[i] = sigma[i] * model->normal_at(i) / model->normal;
      across[i] = sigma[i] * model->tangential_at(i) / model->normal;
    }
  }
  const Normal_error_probe probe =
    kind == Risk_kind::FACE_NORMALS ? Normal_error_probe::STIFFNESS : Normal_error_probe::NOISE;
  return std::make_unique<Normal_error_estimate>(*layer.topology, layer.real_faces, y, surface, along, b, probe,
                                                 across);
}

/// What the comparison reads besides its candidates.
struct Selection_context
{
  const Ghost_layer& layer;
  const Control_matrix& input;          // the start of every candidate
  const std::vector<double>& sigma;     // the noise's deviation at each vertex (0: none to estimate)
  const std::vector<double>& probe;     // the estimate's probe, in units of sigma (Tensor_selection.h)
  const Control_matrix& surface;        // the surface the estimate measures on, made by the first run (empty: none)
  const Part_view* part = nullptr;      // the part of the mesh a process holds (none: the whole mesh)
  Risk_kind kind = Risk_kind::POSITIONS;
  const Noise_model* model = nullptr;   // the noise model the face normals' error is estimated with (none: sigma)
  // benchmarks: what sees the candidates once estimated, and the estimate
  std::function<void(const Candidate_list&, const Risk_estimate&)> observe = nullptr;
};

/// What the comparison gives back: the candidate kept, whose report's selected_tensor names it, and what
/// the report's `choices` adds.
struct Smoother_choice
{
  Flow_candidate kept;
  std::string choices;
  std::vector<std::pair<std::size_t, double>> estimates;   // each estimated candidate's run and estimate
};

/// Where the estimate measures (its normals and stiffness): the input's prefiltered surface (`given`), else
/// the result of the candidate that gives it, else the first sound result, else the input.
inline const Control_matrix& estimate_surface(const Candidate_list& c, const Selection_context& context)
{
  if(context.surface.size() > 0) return context.surface;
  const Flow_candidate* base = nullptr;
  for(const Flow_candidate& x : c)
    if(x.made && x.gives_normals && x.result.report.succeeded()) base = &x;
  for(const Flow_candidate& x : c)
    if(!base && x.made && x.result.report.succeeded()) base = &x;
  return base ? base->result.Y : context.input;
}

/// Why the first run's result is kept with nothing compared (empty when its failed run says why itself), or
/// nothing when the other candidates are to run.
inline std::optional<std::string> nothing_to_compare(const Flow_candidate& own, std::size_t steps_left)
{
  const Fairing_report& r = own.result.report;
  const std::string kept = std::string("; kept the ") + own.name + " result (";
  if(r.succeeded() && r.stop_reason == Stop_reason::CALLBACK) return kept + "the callback ended the run)";
  // every flow stops there before its first step, with the same result: nothing to compare
  if(r.succeeded() && r.stop_reason == Stop_reason::NOISE_LEVEL && r.steps.empty())
    return kept + "the input's limit surface is at the noise level already: every flow stops before its first step)";
  if(steps_left == 0)
    return r.succeeded() ? kept + "the step budget, number_of_iterations, is spent: no other flow runs)"
                         : std::string();
  return std::nullopt;
}

/// A failed outcome for a run the step budget cannot pay for: never kept.
inline Flow_outcome run_not_made()
{
  Flow_outcome o;
  o.report.status = Fairing_status::SOLVER_FAILED;
  o.report.stop_reason = Stop_reason::FAILURE;
  o.report.message = "not run: the call's step budget (number_of_iterations) was spent";
  return o;
}

/// What the estimates read: the estimate the comparison chooses by.
struct Estimate_context
{
  const Risk_estimate& estimate;
  const Control_matrix& probed() const { return estimate.probed(); }
  double risk_of(const Control_matrix& Y, const Control_matrix& Yp) const { return estimate.relative(Y, Yp); }
};

/// The order in which candidates are estimated: those whose carried estimate is their estimate first, then
/// the others, the lower carried estimate first (the list's order between those that do not compare).
inline std::vector<std::size_t> estimate_order(const Candidate_list& c)
{
  std::vector<std::size_t> order, rest;
  for(std::size_t k = 0; k < c.size(); ++k) (c[k].carried_is_estimate ? order : rest).push_back(k);
  for(std::size_t i = 1; i < rest.size(); ++i)
    for(std::size_t j = i; j > 0 && c[rest[j]].carried < c[rest[j - 1]].carried; --j) std::swap(rest[j], rest[j - 1]);
  order.insert(order.end(), rest.begin(), rest.end());
  return order;
}

/// The lowest estimate among the candidates that ended as `x` did (at the noise level or short of it).
inline double lowest_estimate_like(const Candidate_list& c, const Flow_candidate& x)
{
  const bool at_noise = ended_at_noise_level(x.result.report);
  double lowest = std::nan("");
  for(const Flow_candidate& y : c)
    if(std::isfinite(y.risk) && ended_at_noise_level(y.result.report) == at_noise && !(y.risk >= lowest))
      lowest = y.risk;
  return lowest;
}

/// The estimate of candidate `x` by a run of its own on the probed input (NaN when it cannot be made); one
/// that ended short of the noise level has its probe take exactly its steps, and one whose probe replays
/// (Probe_flow.h) the very steps of its run.
template <typename Runner>
double estimate_by_probe_run(Flow_candidate& x, const Estimate_context& e, Runner& runner)
{
  const bool at_noise = ended_at_noise_level(x.result.report);
  const std::size_t replay = at_noise ? 0 : x.result.report.steps.size();
  if(!at_noise && replay == 0) return std::nan("");   // it took no step: nothing to estimate
  Flow_request request{ x.settings, std::string(x.flow) + " on the probed input", e.probed() };
  request.may_be_kept = false;
  request.fixed_steps = replay;
  request.replay = x.probe_replays ? &x.result.schedule : nullptr;
  const Flow_outcome probe = runner.run(request);
  const Fairing_report& rp = probe.report;
  const bool budget_spent = !request.replay && rp.stop_reason == Stop_reason::MAXIMUM_STEPS && runner.steps_left() == 0;
  if(!rp.succeeded() || (budget_spent && replay == 0)) return std::nan("");   // cut short by the budget
  if(replay > 0 && rp.steps.size() != replay) return std::nan("");   // the probe could not take the same steps
  x.probe_end = probe.Y;
  return e.risk_of(x.result.Y, probe.Y);
}

/// The estimates: a carried one is the candidate's own when its flow says so; the others are run again on
/// the probed input (lowest carried estimate first) only when theirs is below the lowest estimate so far.
template <typename Runner>
void estimate_risks(Candidate_list& c, const Estimate_context& e, Runner& runner, bool any_at_noise)
{
  for(Flow_candidate& x : c)
  {
    if(x.compared(any_at_noise) && x.result.probe.size() > 0) x.carried = e.risk_of(x.result.Y, x.result.probe);
    if(x.carried_is_estimate) x.risk = x.carried;
  }
  for(std::size_t k : estimate_order(c))
  {
    Flow_candidate& x = c[k];
    // (a candidate whose carried probe is its estimate is never run again)
    if(!x.compared(any_at_noise) || std::isfinite(x.risk) || x.carried_is_estimate) continue;
    if(x.carried >= lowest_estimate_like(c, x) || runner.steps_left() == 0) continue;
    x.risk = estimate_by_probe_run(x, e, runner);
  }
}

/// The candidate kept: the lowest estimate among the runs that reached the noise level, among those that
/// stopped early only when none reached it; c.size() when none has an estimate.
inline std::size_t lowest_estimate(const Candidate_list& c)
{
  const auto lowest_of = [&c](bool at_noise) {
    std::size_t best = c.size();
    for(std::size_t k = 0; k < c.size(); ++k)
      if(std::isfinite(c[k].risk) && ended_at_noise_level(c[k].result.report) == at_noise &&
         (best == c.size() || c[k].risk < c[best].risk))
        best = k;
    return best;
  };
  const std::size_t kept = lowest_of(true);
  return kept < c.size() ? kept : lowest_of(false);
}

/// One candidate's entry in the list of estimates (in the estimate's unit).
inline std::string described_estimate(const Flow_candidate& x, bool any_at_noise)
{
  const Fairing_report& r = x.result.report;
  char text[200];
  const std::string early = std::string(" (stopped early: ") + to_string(r.stop_reason) + ")";
  if(r.succeeded() && r.stop_reason == Stop_reason::DROPPED)
    std::snprintf(text, sizeof text, "%s %.4g at step %zu, rising (dropped: above the lowest by more than %g standard "
                  "errors)", x.label, x.dropped_at, r.steps.size(), drop_standard_errors);
  else if(std::isfinite(x.risk))
    std::snprintf(text, sizeof text, "%s %.4g%s", x.label, x.risk, ended_at_noise_level(r) ? "" : early.c_str());
  else if(std::isfinite(x.carried))
    std::snprintf(text, sizeof text, "%s %.4g or more (carried along: it cannot be the lowest)", x.label, x.carried);
  else if(judged_run(r) && !ended_at_noise_level(r) && any_at_noise)
    std::snprintf(text, sizeof text, "%s not estimated (stopped early: %s)", x.label, to_string(r.stop_reason));
  else
    std::snprintf(text, sizeof text, "%s not compared (%s)", x.label,
                  r.succeeded() ? to_string(r.stop_reason) : to_string(r.status));
  return text;
}

/// What `choices` says of the comparison that kept candidate `kept`.
inline std::string describe_choice(const Candidate_list& c, std::size_t kept, bool any_at_noise,
                                   const Risk_estimate& estimate)
{
  std::string list;
  for(const Flow_candidate& x : c) list += (list.empty() ? "" : ", ") + described_estimate(x, any_at_noise);
  bool lowest = true;
  for(const Flow_candidate& x : c)
    lowest = lowest && !(x.risk < c[kept].risk) &&
             !(judged_run(x.result.report) && !ended_at_noise_level(x.result.report) && any_at_noise &&
               x.result.report.stop_reason != Stop_reason::DROPPED);
  return std::string("; kept the ") + c[kept].name +
         (lowest ? " result, whose estimated error is the lowest"
                 : " result, whose estimated error is the lowest of the runs that reached the noise level; a run that "
                   "stopped early is not preferred to them") +
         " (" + estimate.description() + ": " + list + ")";
}

/// The estimate once the surface it measures on is known.
struct Estimate_basis
{
  std::unique_ptr<Risk_estimate> estimate;

  bool made() const { return bool(estimate); }
  void make(const Control_matrix& surface, const Selection_context& context, const std::vector<double>& b)
  {
    estimate = make_risk_estimate(context.kind, context.layer, context.input, surface, context.sigma, b, context.model,
                                  context.part ? *context.part : whole_mesh_view());
  }
};

/// A candidate whose carried probe is its estimate, once its run reached the noise level: its estimate and
/// the estimate's terms (what later candidates are dropped against).
inline void estimate_at_end(Flow_candidate& x, const Risk_estimate& e)
{
  if(!x.carried_is_estimate || !ended_at_noise_level(x.result.report) || x.result.probe.size() == 0) return;
  x.terms = e.terms(x.result.Y, x.result.probe);
  x.risk = e.relative(x.result.Y, x.result.probe);
}

/// The candidate the next run is dropped against: the lowest estimate with terms so far (null: none).
inline const Flow_candidate* leader(const Candidate_list& c)
{
  const Flow_candidate* lead = nullptr;
  for(const Flow_candidate& x : c)
    if(!x.terms.empty() && std::isfinite(x.risk) && (!lead || x.risk < lead->risk)) lead = &x;
  return lead;
}

/// The runs' order: the candidates made already, then the others in the list's order.
inline std::vector<std::size_t> run_order(const Candidate_list& c)
{
  std::vector<std::size_t> order;
  for(int made = 1; made >= 0; --made)
    for(std::size_t k = 0; k < c.size(); ++k)
      if(c[k].made == bool(made)) order.push_back(k);
  return order;
}

/// Runs the candidates not made yet, in the list's order, from the input. A candidate's probe rides along
/// once the estimate's surface is known (given, or made after the candidate that gives it), and it is dropped
/// against the leader so far (Candidate_drop.h). The first run alone is kept when nothing is to be compared
/// after it (nothing_to_compare): its index and what `choices` says, else nothing.
template <typename Runner>
std::optional<std::pair<std::size_t, std::string>> run_candidates(Candidate_list& c, const Selection_context& context,
                                                                  const std::vector<double>& b, Runner& runner,
                                                                  Estimate_basis& basis)
{
  if(context.surface.size() > 0) basis.make(context.surface, context, b);
  bool first = true;
  for(std::size_t k : run_order(c))
  {
    Flow_candidate& x = c[k];
    if(!x.made)
    {
      Flow_request request{ x.settings, x.flow, context.input };
      request.probe_start = basis.made() ? &basis.estimate->probed() : nullptr;
      request.estimate = basis.estimate.get();
      const Flow_candidate* lead = basis.made() ? leader(c) : nullptr;
      if(lead) request.keep_going = drop_test(*basis.estimate, lead->terms, x.dropped_at);
      x.result = runner.steps_left() > 0 ? runner.run(request) : run_not_made();
      x.made = true;
    }
    if(basis.made()) estimate_at_end(x, *basis.estimate);
    const std::optional<std::string> alone = first ? nothing_to_compare(x, runner.steps_left()) : std::nullopt;
    if(alone) return std::make_pair(k, *alone);
    first = false;
    if(!basis.made() && x.gives_normals) basis.make(estimate_surface(c, context), context, b);
  }
  if(!basis.made()) basis.make(estimate_surface(c, context), context, b);
  return std::nullopt;
}

/// The candidate kept when none has an estimate: the run's own if it succeeded, else the first that did (the
/// run's own when all failed), and what `choices` says of it.
inline std::pair<std::size_t, std::string> first_sound(const Candidate_list& c, std::size_t own)
{
  std::size_t kept = own;
  for(std::size_t k = 0; k < c.size() && !c[kept].result.report.succeeded(); ++k) kept = k;
  if(!c[kept].result.report.succeeded()) return { own, std::string() };   // all failed: the own report says why
  return { kept, std::string("; kept the ") + c[kept].name + " result (no other could be compared)" };
}

/// Runs the candidates of `c` not made yet (the run's own flow may be, on an input at the noise level) through
/// `runner` (`run(Flow_request)`, `steps_left()`: the call's step budget; a run it cannot pay for is not made)
/// and keeps the one whose estimated error is lowest, or the first that succeeded. (The user's callback sees
/// every run.)
template <typename Runner>
Smoother_choice select_smoother(Candidate_list c, const Selection_context& context, Runner& runner)
{
  const std::size_t own = own_candidate(c);
  std::string choices;
  const std::vector<double>& b = context.probe;
  Estimate_basis basis;
  const std::optional<std::pair<std::size_t, std::string>> alone = run_candidates(c, context, b, runner, basis);
  if(alone)
  {
    c[alone->first].result.report.selected_tensor = c[alone->first].name;
    return { std::move(c[alone->first]), alone->second };
  }
  // a candidate that stopped early is estimated only when none reached the noise level
  bool any_at_noise = false;
  for(const Flow_candidate& x : c) any_at_noise = any_at_noise || ended_at_noise_level(x.result.report);
  estimate_risks(c, Estimate_context{ *basis.estimate }, runner, any_at_noise);
  std::size_t kept = lowest_estimate(c);
  // an estimate that can measure on a denoised surface does, on the result kept, twice, and chooses again
  for(int again = 0; again < 2 && kept < c.size() && basis.estimate->measure_on_result(c[kept].result.Y); ++again)
  {
    for(Flow_candidate& x : c)
      if(!x.carried_is_estimate && std::isfinite(x.risk)) x.risk = basis.estimate->relative(x.result.Y, x.probe_end);
    // the carried estimates anew, and a run on the probed input for one that could now be the lowest
    estimate_risks(c, Estimate_context{ *basis.estimate }, runner, any_at_noise);
    kept = lowest_estimate(c);
  }
  if(context.observe) context.observe(c, *basis.estimate);
  if(kept < c.size()) choices = describe_choice(c, kept, any_at_noise, *basis.estimate);
  else std::tie(kept, choices) = first_sound(c, own);
  c[kept].result.report.selected_tensor = c[kept].name;
  std::vector<std::pair<std::size_t, double>> estimates;
  for(const Flow_candidate& x : c)
    if(std::isfinite(x.risk)) estimates.emplace_back(x.result.run, x.risk);
  return { std::move(c[kept]), choices, std::move(estimates) };
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_SMOOTHER_SELECTION_H
