// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The flow loop of every run, on one process or several (Flow_operator.h), read as an ODE integrator's:
// each step is proposed with the controller's fraction of the time step (Step_control.h), solved, turned into
// a candidate surface, judged (Step_safety.h), and accepted, rejected and retried shorter, or retaken to end
// where the noise level is reached or to keep a deviation bound; after each accepted step the stop rules are
// asked in their order (stop/Stop_rules.h), then the caller. At the end, a run whose surface has more folded
// edges than its input falls back to the last one that had no more (stop/New_folds.h).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_FLOW_LOOP_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_FLOW_LOOP_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Deviation_bound.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Flow_units.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Output_fidelity.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Probe_schedule.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Ride_along_probe.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Run_report.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_control.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_safety.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>
#include <CGAL/Anisotropic_fairing/internal/flow/stop/New_folds.h>
#include <CGAL/Anisotropic_fairing/internal/flow/stop/Stop_rules.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The risk estimate's probe a run carries along (Ride_along_probe.h): its start (empty: none).
struct Probe_request
{
  Control_matrix start;
  // after each accepted step that no rule ends, with the run's and the probe's control points: false ends
  // the run (Stop_reason::DROPPED: the comparison has a better candidate)
  std::function<bool(const Control_matrix&, const Control_matrix&)> keep_going;
};

/// What a run returns besides the moved rows.
struct Flow_result
{
  Fairing_report report;
  Control_matrix probe;      // where the probe ended (empty: none carried)
  Probe_schedule schedule;   // the steps it took, for a probe to replay on an operator of its own (Probe_flow.h)
  double limit_weight = 1;   // 1, or how far from the input to its limit points the result lies (a run that
                             // ended before its first step: the limit surface alone moved by more than the noise)
};

/// One run. X: the surface's control points (its first `metric_columns` columns); Z: what moves, X itself, or
/// on a fixed surface (`fixed`: X's first 3 columns do not move) the attributes' columns.
template <typename Operator, typename Tensor, typename Callback>
class Flow_loop
{
  enum class Outcome { NEXT, RETRY, ENDED, FAILED };

public:
  Flow_loop(Operator& op, const Control_matrix& X, Control_matrix& Z, int metric_columns, const Tensor& tensor,
            const Stepper_settings& s, Callback& callback, bool fixed, Probe_request probe = Probe_request())
    : op_(op), X_(X), Z_(Z), metric_columns_(metric_columns), tensor_(tensor), s_(s), callback_(callback),
      fixed_(fixed), probe_request_(std::move(probe))
  {}

  Flow_result run()
  {
    total_.start();
    if(start())
    {
      for(std::size_t step = 1;
          step <= s_.maximum_steps && nfree_ > 0 && report_.stop_reason != Stop_reason::NOISE_LEVEL;)
      {
        const Outcome o = attempt(step);
        if(o == Outcome::FAILED) return result();
        if(o == Outcome::ENDED) break;
        if(o == Outcome::RETRY) continue;
        control_.grow();
        ++step;
      }
      finish();
    }
    return result();
  }

private:
  Flow_result result()
  {
    Flow_result r;
    r.report = std::move(report_);
    r.probe = probe_.result();
    r.schedule = std::move(schedule_);
    r.limit_weight = limit_weight_;
    return r;
  }

  // the units, the input's operator, the criteria's measures and the soundness and noise level of the start
  bool start()
  {
    report_.vertices = op_.vertex_count();
    nfree_ = op_.free_count();
    report_.constrained_vertices = report_.vertices - nfree_;
    const std::string unsupported = op_.unsupported(s_, fixed_);
    if(!unsupported.empty()) { fail(report_, Fairing_status::SOLVER_FAILED, unsupported, total_); return false; }
    op_.begin_run(s_, fixed_);
    clock_.start();
    Z0_ = Z_;
    start_noise_measures();
    // a run that takes no step (a clean mesh at the noise stop) never uses its tensor's operator
    const bool takes_steps = s_.maximum_steps > 0 && nfree_ > 0 &&
                             !(noise_stop_ && Noise_level::before_first_step(first_discrepancy_, target_));
    Assembly_statistics a;
    if(!start_units(op_, X_, metric_columns_, s_, tensor_, report_, a, total_, takes_steps)) return false;
    assemble_seconds_ = clock_.time();
    time_unit_ = s_.stopping.relative_units ? std::pow(report_.scale, s_.order) : 1.0;   // (28), steady speed
    start_surface(a);
    if(takes_steps) start_solver();
    rules_.emplace(Stop_rule_setup{ s_, fixed_, noise_stop_, bound_->active(),
                                    fixed_ ? report_.initial.energy : a.H_integral, op_.mesh().mean_edge });
    const std::optional<double> before = Noise_level::before_first_step(first_discrepancy_, target_);
    if(nfree_ == 0) report_.stop_reason = Stop_reason::NO_FREE_VERTEX;
    else if(noise_stop_ && before)
    {
      // the input's own limit surface is already off it by more than the noise: the result lies between
      // the two, where the noise level is reached
      report_.stop_reason = Stop_reason::NOISE_LEVEL;
      limit_weight_ = *before;
      report_.noise_displacement = target_;
    }
    return true;
  }

  // what the criteria measure: int |H|^2 and the motion in lengths; on a fixed surface the attributes'
  // Dirichlet energy and their motion in units of their spread (the root mean square of Z0 - mean(Z0))
  void start_measures()
  {
    measured_columns_ = fixed_ ? int(Z_.cols()) : metric_columns_;
    row_unit_ = op_.units().length;
    if(!fixed_) return;
    report_.initial.energy = op_.dirichlet_energy(Z_);
    const double spread = row_spread(Z0_);
    row_unit_.assign(std::size_t(Z0_.rows()), spread > 0 ? spread : 1.0);
  }

  // the noise criterion (stop once the written surface moved off the input by the noise): the noise level's
  // distance and the input's own, which need no assembly
  void start_noise_measures()
  {
    noise_stop_ = !fixed_ && s_.noise && s_.stopping.noise_discrepancy > 0;
    if(!fixed_) op_.measured_positions(Z_, Y_);
    target_ = noise_stop_ ? s_.stopping.noise_discrepancy * s_.strength * s_.noise->relative_sigma() : 0.0;
    discrepancy_ = noise_stop_ ? s_.noise->relative_displacement(Y_, Z0_, {}) : 0.0;
    report_.noise_displacement = discrepancy_;
    first_discrepancy_ = noise_stop_ ? Noise_level::at_start(*s_.noise, Y_, Z0_) : 0.0;
  }

  // the folds of the input and the user's bound on the written positions
  void start_surface(const Assembly_statistics& a)
  {
    start_measures();
    initial_ = Surface_soundness();
    initial_.statistics = a;
    Surface_soundness input;
    if(!fixed_)
    {
      op_.count_folds(Z_, initial_);
      op_.input_folds(Z0_, input);
    }
    input_folds_ = input.folded_edges;
    input_fold_edges_ = std::move(input.folded_edge_list);
    // the user's bound on the written positions (Deviation_bound.h), held by the vertices' own fidelity
    bound_.emplace(make_bound());
    fidelity_.emplace(*op_.mesh().layer.topology, s_.limit_written);
    anchor_ = bound_->active() ? written(Z_) : Control_matrix();
    bound_->set_start(anchor_, Z0_);
    accepted_ = initial_;
    lowest_H_.emplace(a);
    // the last surface with no more folded edges than the input mesh (or its limit surface): what the
    // run falls back to if the surface it ends on has more
    allowed_folds_ = std::max(input_folds_, initial_.folded_edges);
    if(!fixed_) Z_unfolded_ = Z_;
  }

  // the bounds of the settings on Z's columns: the geometry (the first 3, not on a fixed surface) and the
  // attributes (the others, all of them on a fixed surface)
  Deviation_bound make_bound()
  {
    if(s_.maximum_deviation > 0)
    {
      report_.absolute_maximum_deviation =
        s_.relative_deviation ? s_.maximum_deviation * op_.units().scale : s_.maximum_deviation;
      report_.maximum_deviation = report_.absolute_maximum_deviation;   // its deprecated name, still filled
    }
    const auto bounds = user_bounds(Z_.cols(), !fixed_, fixed_ ? 0 : 3, report_.absolute_maximum_deviation,
                                    s_.attribute_maximum_deviation);
    return Deviation_bound(bounds[0], bounds[1], std::size_t(Z_.rows()), !noise_stop_,
                           [this](double x) { return op_.largest(x); });
  }

  // the probe, carried along where the steps are linear in the positions (without the bound's own
  // fidelities), and the solver of the steps
  void start_solver()
  {
    if(!fixed_ && !bound_->active() && probe_request_.start.size() > 0) probe_.start(probe_request_.start);
    keep_going_ = std::move(probe_request_.keep_going);
    probe_request_ = Probe_request();
    const Eigen::Index solved_columns = Z_.cols() * (probe_.active() ? 2 : 1);
    op_.start_solver(s_, solved_columns, fixed_, bound_->active() ? &*fidelity_ : nullptr, &anchor_, Z0_);
  }

  // the written positions of control points W: the limit points or W itself (what the bound holds)
  const Control_matrix& written(const Control_matrix& W)
  {
    if(fixed_ || s_.limit_written != s_.measure_limit_surface)
    {
      if(s_.limit_written) op_.limit_points(W, Yb_);
      else Yb_ = W;
      return Yb_;
    }
    op_.measured_positions(W, Y_);
    return Y_;
  }

  // one try at step `step`: solved, made a candidate, judged, then accepted or taken again
  Outcome attempt(std::size_t step)
  {
    Fairing_step st;
    st.step = step;
    st.time_step = control_.factor() * report_.time_step;
    bool finite = false;
    if(!solve(st, finite)) return Outcome::FAILED;
    make_candidate(st, finite);
    // the noise level passed within this step: take it again, shorter, so that it ends there. Judged
    // before the candidate is assembled, which a retaken step does not need; with a bound on the written
    // positions, after the bound's retakes
    candidate_discrepancy_ = 0;
    bool last_step = step == s_.maximum_steps;
    double cut_at = -1;   // >= 0: the run ends this far into the step, where the noise level is reached
    if(noise_stop_ && finite && !bound_->active())
    {
      op_.measured_positions(Zc_, Y_);
      if(op_.all_finite(Y_))
      {
        candidate_discrepancy_ = s_.noise->relative_displacement(Y_, Z0_, {});
        const auto verdict =
          Noise_level::judge_candidate(control_, discrepancy_, candidate_discrepancy_, target_, cut_at);
        if(verdict == Noise_level::Candidate::RETAKE) return Outcome::RETRY;
        if(verdict == Noise_level::Candidate::CUT)
        {
          // the surface the run ends on is the one judged, and it needs no matrices
          if(cut_at < 1) { Zc_ = Z_ + cut_at * (Zc_ - Z_); op_.measured_positions(Zc_, Y_); probe_.shorten(cut_at); }
          last_step = true;
        }
      }
    }
    const Outcome judged = judge(step, finite, last_step);
    if(judged != Outcome::NEXT) return judged;
    if(retake_for_bound(finite)) return Outcome::RETRY;
    schedule_.steps.push_back({ control_.factor(), cut_at });
    return accept(st, cut_at);
  }

  // a written position carried past the user's bound: the step again, those vertices held harder; or the
  // noise level passed under the bound: the step again, shorter
  bool retake_for_bound(bool finite)
  {
    if(bound_->active() && finite && bound_retakes_ < step_control::maximum_bound_retakes)
      if(bound_->exceeded_and_raised(written(Zc_), Z0_, op_.free_rows(), scaled_tau(control_.factor())))
      {
        restore_accepted();
        ++bound_retakes_;
        ++report_.bound_retaken_steps;
        return true;
      }
    bound_retakes_ = 0;
    if(noise_stop_ && bound_->active())
    {
      candidate_discrepancy_ = s_.noise->relative_displacement(Y_, Z0_, {});
      double unused = 0;
      if(Noise_level::judge_candidate(control_, discrepancy_, candidate_discrepancy_, target_, unused) ==
         Noise_level::Candidate::RETAKE)
      {
        restore_accepted();
        return true;
      }
    }
    return false;
  }

  // the step's system and right-hand side at Z_n, solved
  bool solve(Fairing_step& st, bool& finite)
  {
    clock_.reset();
    Solve_statistics sol;
    Zc_.resize(0, 0);   // the last candidate, accepted or not, is not needed while this step is solved
    if(probe_.active())
    {
      // [Z | probe], [Z0 | its start]: one solve for both
      Control_matrix ZZ, ZZ0;
      probe_.augment(Z_, Z0_, ZZ, ZZ0);
      sol = op_.solve(control_.factor(), ZZ, ZZ0, bound_->weights(), st.direct_solve);
    }
    else sol = op_.solve(control_.factor(), Z_, Z0_, bound_->weights(), st.direct_solve);
    st.solve_seconds = op_.solve_seconds();
    st.assemble_seconds = assemble_seconds_ + clock_.time() - st.solve_seconds;
    assemble_seconds_ = 0;
    report_.used_cholesky = report_.used_cholesky || st.direct_solve;
    st.solver_iterations = sol.iterations;
    st.residual = sol.residual;
    finite = op_.solution_finite(sol);
    if(!finite && fixed_)
    {
      fail(report_, Fairing_status::NON_FINITE_VALUE,
           "step " + std::to_string(st.step) + ": the solution is not finite", total_);
      return false;
    }
    if(!sol.ok && finite)
    {
      fail(report_, Fairing_status::SOLVER_FAILED, "step " + std::to_string(st.step) + ": " + sol.message, total_);
      return false;
    }
    return true;
  }

  // Zc = Z + the solution (its normal part for the anisotropic flow); the probe's candidate likewise
  void make_candidate(Fairing_step& st, bool finite)
  {
    Zc_ = Z_;
    if(!finite) return;
    const Control_matrix& solution = op_.displacement();
    // the tangent planes are those of M_eps when the tensor reads its curvature there: on noise, the current
    // surface's normal is mostly noise, and removing motion in its tangent plane would keep the noise
    const Control_matrix& tangent_surface = op_.prefiltered() ? *op_.prefiltered() : Z_;
    if(probe_.active())
    {
      Control_matrix d = solution.rightCols(Z_.cols());
      op_.normal_part(tangent_surface, metric_columns_, d);
      probe_.make_candidate([&](Control_matrix& P) { op_.add(P, d); });
    }
    Step_motion m;
    if(op_.moves_normally() || probe_.active())
    {
      // the solution itself stays as it is: the next step's CG starts from it
      Control_matrix dZ = probe_.active() ? Control_matrix(solution.leftCols(Z_.cols())) : solution;
      op_.normal_part(tangent_surface, metric_columns_, dZ);
      m = op_.move(Zc_, dZ, Z0_, measured_columns_, row_unit_);
    }
    else m = op_.move(Zc_, solution, Z0_, measured_columns_, row_unit_);
    st.step_displacement = m.step;
    st.max_displacement = m.total;
    moved_relative_ = m.step_relative;
    max_relative_ = m.total_relative;
  }

  // back to the accepted surface's operator after a candidate was assembled (a fixed surface has one)
  void restore_accepted()
  {
    if(!fixed_) op_.restore(Z_, metric_columns_, tensor_);
  }

  // the candidate judged (Step_safety.h): NEXT when sound, else failed, retried shorter or the run ended
  Outcome judge(std::size_t step, bool finite, bool last_step)
  {
    candidate_ = accepted_;
    std::string why;
    Step_verdict verdict = Step_verdict::SOUND;
    bool saved = false;   // the accepted surface's operator kept aside while the candidate's is assembled
    if(!fixed_)
    {
      clock_.reset();
      candidate_ = Surface_soundness();
      candidate_.finite = finite && op_.all_finite(Zc_);
      // the folded edges first: they need no assembly, and a candidate they reject costs none
      if(candidate_.finite) op_.count_folds(Zc_, candidate_);
      const Known_fold_places known = [this](const Surface_soundness& c) {
        const Ghost_layer& layer = op_.mesh().layer;
        return op_.everywhere(
          folds_at_known_places(*layer.topology, layer.real_faces, accepted_, input_fold_edges_, allowed_folds_, c));
      };
      if(candidate_.finite && edges_folded(accepted_, input_folds_, candidate_, why, known))
        verdict = Step_verdict::UNSOUND;
      else
      {
        op_.save();
        saved = true;
        if(candidate_.finite && !assemble_candidate(step, last_step)) return Outcome::FAILED;
        verdict = judge_step(initial_, accepted_, input_folds_, *lowest_H_, candidate_, why, known);
      }
      assemble_seconds_ = clock_.time();
    }
    if(verdict == Step_verdict::COLLAPSED)
    {
      fail(report_, Fairing_status::COLLAPSED,
           "step " + std::to_string(step) + ": " + why +
             ": mean-curvature flow shrinks closed surfaces to points; use fewer steps or a larger fidelity weight",
           total_);
      return Outcome::FAILED;
    }
    if(verdict != Step_verdict::UNSOUND) return Outcome::NEXT;
    if(saved) restore_accepted();
    return rejected(step, why);
  }

  // the candidate's operator (the last step's: its statistics only) and measured positions
  bool assemble_candidate(std::size_t step, bool last_step)
  {
    candidate_.statistics = op_.assemble(Zc_, metric_columns_, tensor_, !last_step);
    if(!op_.error().empty())
    {
      fail(report_, Fairing_status::SOLVER_FAILED, "after step " + std::to_string(step) + ": " + op_.error(), total_);
      return false;
    }
    op_.measured_positions(Zc_, Y_);
    candidate_.finite = op_.all_finite(Y_);
    return true;
  }

  // a rejected candidate: retried shorter, or the run ends on the last sound surface (or fails before any)
  Outcome rejected(std::size_t step, const std::string& why)
  {
    ++report_.rejected_steps;
    last_why_ = why;
    if(s_.verbose)
      std::cerr << "step " << step << " rejected (" << why << "); retrying with a quarter of the time step\n";
    if(control_.reject(s_.maximum_rejections)) return Outcome::RETRY;
    const std::string what = "step " + std::to_string(step) + ": " + why + " even with 1/" +
                             std::to_string(1 << (2 * s_.maximum_rejections)) + " of the time step";
    if(report_.steps.empty())
    {
      fail(report_, !candidate_.finite ? Fairing_status::NON_FINITE_VALUE : Fairing_status::FOLDED, what, total_);
      return Outcome::FAILED;
    }
    report_.stop_reason = Stop_reason::STEP_REJECTED;
    report_.message = what + "; the run ends on the last sound surface (step " + std::to_string(step - 1) + ")";
    return Outcome::ENDED;
  }

  // every component's time step times f
  std::vector<double> scaled_tau(double f) const
  {
    std::vector<double> tau(op_.units().tau);
    for(double& x : tau) x *= f;
    return tau;
  }

  // the candidate becomes the surface; its step recorded, then the stop rules asked in order, then the caller
  Outcome accept(Fairing_step& st, double cut_at)
  {
    control_.accept();
    Z_previous_.swap(Z_);
    Z_.swap(Zc_);
    probe_.accept();
    accepted_ = candidate_;
    if(!fixed_ && candidate_.folded_edges <= allowed_folds_)
    {
      Z_unfolded_ = Z_;
      unfolded_steps_ = report_.steps.size() + 1;
      probe_.mark_unfolded();
    }
    lowest_H_->add(candidate_.statistics);
    time_ += st.time_step;
    st.time = time_;
    st.area = accepted_.statistics.area;
    st.energy = fixed_ ? op_.dirichlet_energy(Z_) : accepted_.statistics.energy;
    st.H_integral = accepted_.statistics.H_integral;
    if(st.step == s_.maximum_steps) st.assemble_seconds += assemble_seconds_;   // the final surface's statistics
    const double previous_discrepancy = discrepancy_;
    if(noise_stop_) discrepancy_ = candidate_discrepancy_;
    st.noise_displacement = discrepancy_;
    const double value = fixed_ ? st.energy : st.H_integral;
    const Step_progress progress{ st, st.time_step / time_unit_, value, max_relative_, moved_relative_,
                                  previous_discrepancy, discrepancy_, target_, cut_at, control_, last_why_ };
    const std::optional<Stop> stop = rules_->after_step(progress);
    if(stop && stop->at >= 0) end_within_step(st, *stop);
    if(!fixed_) report_.noise_displacement = st.noise_displacement;
    if(bound_->active())
    {
      const double next = control_.next_factor();
      bound_->accept(written(Z_), Z0_, op_.free_rows(), scaled_tau(next), control_.factor() / next);
    }
    report_.steps.push_back(st);
    if(s_.verbose) print(st);
    if(stop)
    {
      report_.stop_reason = stop->reason;
      if(!stop->message.empty()) report_.message = stop->message;
    }
    if(!callback_(report_.steps.back()) && !stop) report_.stop_reason = Stop_reason::CALLBACK;
    else if(!stop && probe_.active() && keep_going_ && !keep_going_(Z_, probe_.result()))
      report_.stop_reason = Stop_reason::DROPPED;
    else if(!stop) return Outcome::NEXT;
    return Outcome::ENDED;
  }

  // the run ends `stop.at` into the step just accepted (the noise level): the surface taken back there if it
  // was not cut there before, and the step's measures at that surface
  void end_within_step(Fairing_step& st, const Stop& stop)
  {
    if(stop.rewind)
    {
      Z_ = Z_previous_ + stop.at * (Z_ - Z_previous_);
      probe_.rewind(stop.at);
      schedule_.rewind = stop.at;
      const Assembly_statistics b = op_.assemble(Z_, metric_columns_, tensor_, false);
      st.area = b.area; st.energy = b.energy; st.H_integral = b.H_integral;
    }
    st.time = time_ - (1 - stop.at) * st.time_step;
    st.max_displacement = 0;
    for(Eigen::Index i = 0; i < Z_.rows(); ++i)
      st.max_displacement = std::max(st.max_displacement, (Z_.row(i) - Z0_.row(i)).head(metric_columns_).norm());
    st.max_displacement = op_.largest(st.max_displacement);
    op_.measured_positions(Z_, Y_);
    st.noise_displacement = s_.noise->relative_displacement(Y_, Z0_, {});
  }

  // the end: never a surface with more folded edges than the input (stop/New_folds.h)
  void finish()
  {
    Surface_soundness last;
    if(!fixed_) op_.count_folds(Z_, last);
    const std::optional<Fold_verdict> folds =
      report_.succeeded() ? new_folds(last.folded_edges, allowed_folds_, unfolded_steps_) : std::nullopt;
    if(folds && folds->fails) { fail(report_, Fairing_status::FOLDED, folds->message, total_); return; }
    if(folds)
    {
      Z_ = Z_unfolded_;
      probe_.fall_back();
      schedule_.fall_back = unfolded_steps_;
      report_.steps.resize(unfolded_steps_);
      report_.stop_reason = Stop_reason::STEP_REJECTED;
      report_.message = folds->message;
      if(noise_stop_)
      {
        op_.measured_positions(Z_, Y_);
        report_.noise_displacement = s_.noise->relative_displacement(Y_, Z0_, {});
      }
    }
    report_.bound_fidelity_weight = bound_->largest_weight();
    report_.bound_held_vertices = std::size_t(op_.total(double(bound_->held_rows())));
    report_.bound_uniform_weight = bound_->uniform_weight();
    report_.total_seconds = total_.time();
  }

  Operator& op_;
  const Control_matrix& X_;
  Control_matrix& Z_;
  const int metric_columns_;
  Tensor tensor_;
  const Stepper_settings& s_;
  Callback& callback_;
  const bool fixed_;
  Probe_request probe_request_;

  CGAL::Real_timer total_, clock_;
  Fairing_report report_;
  Ride_along_probe probe_;
  Probe_schedule schedule_;
  std::function<bool(const Control_matrix&, const Control_matrix&)> keep_going_;
  double limit_weight_ = 1;
  double assemble_seconds_ = 0, time_unit_ = 1, time_ = 0;
  Control_matrix Z0_, Y_, Yb_, anchor_, Zc_, Z_previous_, Z_unfolded_;
  std::vector<double> row_unit_;
  int measured_columns_ = 0;
  double moved_relative_ = 0, max_relative_ = 0;   // the last candidate's motion in row units
  std::optional<Stop_rules> rules_;
  bool noise_stop_ = false;
  Surface_soundness initial_, accepted_, candidate_;
  std::size_t input_folds_ = 0, allowed_folds_ = 0, unfolded_steps_ = 0;
  std::vector<int> input_fold_edges_;   // the input mesh's folded edges (a halfedge of each)
  std::optional<Deviation_bound> bound_;
  std::optional<Output_fidelity> fidelity_;
  int bound_retakes_ = 0;
  std::optional<Lowest_curvature> lowest_H_;
  double target_ = 0, discrepancy_ = 0, first_discrepancy_ = 0, candidate_discrepancy_ = 0;
  std::size_t nfree_ = 0;
  Step_controller control_;
  std::string last_why_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_FLOW_LOOP_H
