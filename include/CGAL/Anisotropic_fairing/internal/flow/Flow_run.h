// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One run of a Time_stepper, read as an ODE integrator's loop: each step is proposed with the
// controller's fraction of the time step (Step_control.h), solved, turned into a candidate surface,
// judged (Step_safety.h), and accepted, rejected and retried shorter, or retaken to end where the noise
// level is reached or to keep a deviation bound; after each accepted step the stop rules are asked in
// order: the noise level, the noise removed (fourth order), the deviation bound's level, a cramped flow,
// then the paper's criteria and the steady state (Stopping_monitor.h) and the caller. At the end, a run
// whose surface has more folded edges than its input falls back to the last one that had no more.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_FLOW_RUN_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_FLOW_RUN_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Deviation_bound.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Local_time_scale.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Output_fidelity.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Ride_along_probe.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_control.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_safety.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_solver.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_units.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stopping_monitor.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The loop of Time_stepper::run and run_on_fixed_surface. Z: what moves (X itself, or on a fixed
/// surface the attributes' columns); `fixed`: the surface of X's first 3 columns does not move.
template <typename Stepper, typename Tensor, typename Callback>
class Flow_run
{
  enum class Outcome { NEXT, RETRY, ENDED, FAILED };

public:
  Flow_run(Stepper& t, const Control_matrix& X, Control_matrix& Z, int metric_columns, const Tensor& tensor,
           const Stepper_settings& s, Callback& callback, bool fixed)
    : t_(t), X_(X), Z_(Z), metric_columns_(metric_columns), tensor_(tensor), s_(s), callback_(callback), fixed_(fixed) {}

  Fairing_report run()
  {
    total_.start();
    if(!start()) return report_;
    for(std::size_t step = 1; step <= s_.maximum_steps && nfree_ > 0 && report_.stop_reason != Stop_reason::NOISE_LEVEL;)
    {
      const Outcome o = attempt(step);
      if(o == Outcome::FAILED) return report_;
      if(o == Outcome::ENDED) break;
      if(o == Outcome::RETRY) continue;
      control_.grow();
      ++step;
    }
    finish();
    return report_;
  }

private:
  typedef typename Stepper::Cache_type Cache;

  // the units, the input's operator, the criteria's measures and the soundness and noise level of the start
  bool start()
  {
    report_.vertices = std::size_t(Z_.rows());
    report_.constrained_vertices = std::size_t(Z_.rows()) - t_.block_.size();
    t_.measure_limit_surface_ = s_.measure_limit_surface;
    clock_.start();
    Assembly_statistics a;
    if(!t_.set_units(X_, metric_columns_, s_, tensor_, report_, a, total_)) return false;
    assemble_seconds_ = clock_.time();
    Z0_ = Z_;
    // automatic isotropic runs: a time step that follows the mesh's density (Local_time_scale.h)
    if(s_.local_time_scale && !fixed_)
      mass_weight_ = mass_weights(local_time_scale(*t_.layer_.topology, t_.layer_.real_faces, Z0_, t_.components_, t_.component_edge_));
    // (on a fixed surface the attributes are solved in their own units)
    unknown_scale_ = fixed_ ? &no_scale_ : &t_.unknown_scale_;
    time_unit_ = s_.stopping.relative_units ? std::pow(report_.scale, s_.order) : 1.0;   // (28), steady speed
    start_criteria(a);
    start_surface(a);
    start_solver();
    if(nfree_ == 0) report_.stop_reason = Stop_reason::NO_FREE_VERTEX;
    else if(noise_stop_ && first_discrepancy_ >= target_)
    {
      // the input's own limit surface is already off it by more than the noise: the result lies between
      // the two, where the noise level is reached
      report_.stop_reason = Stop_reason::NOISE_LEVEL;
      t_.limit_weight_ = first_discrepancy_ > 0 ? target_ / first_discrepancy_ : 0.0;
      report_.noise_displacement = target_;
    }
    return true;
  }

  // what the criteria measure: int |H|^2 and the motion in lengths; on a fixed surface the attributes'
  // Dirichlet energy and their motion in units of their spread, and (29) does not apply
  void start_criteria(const Assembly_statistics& a)
  {
    measured_columns_ = fixed_ ? int(Z_.cols()) : metric_columns_;
    row_unit_ = t_.units_.length;
    Stopping_criteria criteria = s_.stopping;
    if(fixed_)
    {
      report_.initial.energy = dirichlet_energy(t_.operator_.pattern(), t_.operator_.L(), Z_);
      double spread = 0;
      const Eigen::RowVectorXd mean = Z0_.colwise().mean();
      for(Eigen::Index i = 0; i < Z0_.rows(); ++i) spread += (Z0_.row(i) - mean).squaredNorm();
      spread = Z0_.rows() > 0 ? std::sqrt(spread / double(Z0_.rows())) : 0.0;
      row_unit_.assign(std::size_t(Z0_.rows()), spread > 0 ? spread : 1.0);
      criteria.displacement = 0;
    }
    monitor_.emplace(criteria, fixed_ ? report_.initial.energy : a.H_integral);
  }

  // the folds of the input, the user's bound on the written positions and the noise level's distance
  void start_surface(const Assembly_statistics& a)
  {
    // the noise criterion: stop once the written surface moved off the input by the noise
    noise_stop_ = !fixed_ && s_.noise && s_.stopping.noise_discrepancy > 0;
    initial_ = Surface_soundness();
    initial_.statistics = a;
    if(!fixed_)
    {
      t_.measured_positions(Z_, Y_);
      count_folds(t_.layer_, Cache::has_second_derivatives, t_.components_.of_face, t_.component_edge_, Z_, initial_);
      input_folds_ = count_folded_edges(*t_.layer_.topology, t_.layer_.real_faces, Z0_, t_.components_.of_face, t_.component_edge_,
                                        turn_120, nullptr, &input_fold_edges_);
    }
    // the user's bound on the written positions (Deviation_bound.h), held by the vertices' own fidelity
    bound_.emplace(t_.make_bound(s_, Z_, fixed_, !noise_stop_, report_));
    fidelity_.emplace(*t_.layer_.topology, s_.limit_written);
    anchor_ = bound_->active() ? written(Z_) : Control_matrix();
    bound_->set_start(anchor_, Z0_);
    accepted_ = initial_;
    lowest_H_.emplace(a);
    target_ = noise_stop_ ? s_.stopping.noise_discrepancy * s_.strength * s_.noise->relative_sigma() : 0.0;
    discrepancy_ = noise_stop_ ? s_.noise->relative_displacement(Y_, Z0_, {}) : 0.0;
    report_.noise_displacement = discrepancy_;
    // before the first step, the limit surface of the input may round its creases by more than the
    // noise while leaving most vertices in place: a clean mesh, whatever the typical vertex says
    first_discrepancy_ = noise_stop_ ? std::max(discrepancy_, s_.noise->relative_displacement(Y_, Z0_, {}, true)) : 0.0;
    // the last surface with no more folded edges than the input mesh (or its limit surface): what the
    // run falls back to if the surface it ends on has more
    allowed_folds_ = std::max(input_folds_, initial_.folded_edges);
    if(!fixed_) Z_unfolded_ = Z_;
  }

  // the probe, carried along where the steps are linear in the positions (without the bound's own
  // fidelities), and the solver of the steps
  void start_solver()
  {
    nfree_ = Eigen::Index(t_.block_.size());
    if(t_.probe_maker_ && !fixed_ && !bound_->active())
      t_.probe_.start(t_.probe_maker_(t_.operator_.prefiltered() ? *t_.operator_.prefiltered() : Z0_));
    if(fixed_ || bound_->active()) t_.probe_ = Ride_along_probe();
    const Eigen::Index solved_columns = Z_.cols() * (t_.probe_.active() ? 2 : 1);
    solver_.emplace(t_.operator_.pattern(), t_.block_, s_, solved_columns, fixed_, bound_->active() ? &*fidelity_ : nullptr, &anchor_);
  }

  // the written positions of control points W: the limit points or W itself (what the bound holds)
  const Control_matrix& written(const Control_matrix& W)
  {
    if(fixed_ || s_.limit_written != t_.measure_limit_surface_)
    {
      if(s_.limit_written) limit_points(t_.layer_, W, Yb_);
      else Yb_ = W;
      return Yb_;
    }
    t_.measured_positions(W, Y_);
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
    double theta = -1;   // >= 0: the run ends this far into the step, where the noise level is reached
    if(noise_stop_ && finite && !bound_->active())
    {
      t_.measured_positions(Zc_, Y_);
      if(Y_.allFinite())
      {
        candidate_discrepancy_ = s_.noise->relative_displacement(Y_, Z0_, {});
        if(control_.retake_for_noise_level(discrepancy_, candidate_discrepancy_, target_)) return Outcome::RETRY;
        if(candidate_discrepancy_ >= target_)
        {
          // the surface the run ends on is the one judged, and it needs no matrices
          theta = fraction_reaching(discrepancy_, candidate_discrepancy_, target_);
          if(theta < 1) { Zc_ = Z_ + theta * (Zc_ - Z_); t_.measured_positions(Zc_, Y_); t_.probe_.shorten(theta); }
          last_step = true;
        }
      }
    }
    const Outcome judged = judge(step, finite, last_step);
    if(judged != Outcome::NEXT) return judged;
    // a written position carried past the user's bound: the step again, those vertices held harder
    if(bound_->active() && finite && bound_retakes_ < step_control::maximum_bound_retakes)
      if(bound_->exceeded_and_raised(written(Zc_), Z0_, t_.block_.free, scaled_tau(control_.factor())))
      {
        restore_accepted();
        ++bound_retakes_;
        ++report_.bound_retaken_steps;
        return Outcome::RETRY;
      }
    bound_retakes_ = 0;
    if(noise_stop_ && bound_->active())
    {
      candidate_discrepancy_ = s_.noise->relative_displacement(Y_, Z0_, {});
      if(control_.retake_for_noise_level(discrepancy_, candidate_discrepancy_, target_)) { restore_accepted(); return Outcome::RETRY; }
    }
    return accept(st, theta);
  }

  // the step's system and right-hand side at Z_n (divided so that a huge tau cannot overflow), solved
  bool solve(Fairing_step& st, bool& finite)
  {
    clock_.reset();
    const double factor = control_.factor();
    const auto prepare = [&](const Control_matrix& Z, const Control_matrix& Z0) {
      solver_->prepare(t_.operator_.M(), t_.operator_.L(), t_.units_, mass_weight_, *unknown_scale_, factor,
                       system_scale(t_.units_, t_.block_.free, factor, s_.order, t_.mean_edge_), Z, Z0, bound_->weights());
    };
    if(t_.probe_.active())
    {
      // [Z | probe], [Z0 | its start]: freed before the solve, which no longer reads them
      Control_matrix ZZ, ZZ0;
      t_.probe_.augment(Z_, Z0_, ZZ, ZZ0);
      prepare(ZZ, ZZ0);
    }
    else prepare(Z_, Z0_);
    Zc_.resize(0, 0);   // the last candidate, accepted or not, is not needed while this step is solved
    const Solve_statistics sol = solver_->solve(st.direct_solve);
    st.solve_seconds = solver_->solve_seconds();
    st.assemble_seconds = assemble_seconds_ + clock_.time() - st.solve_seconds;
    assemble_seconds_ = 0;
    report_.used_cholesky = report_.used_cholesky || st.direct_solve;
    st.solver_iterations = sol.iterations;
    st.residual = sol.residual;
    finite = solver_->displacement().allFinite() && std::isfinite(sol.residual);
    if(!finite && fixed_)
    {
      fail(report_, Fairing_status::NON_FINITE_VALUE, "step " + std::to_string(st.step) + ": the solution is not finite", total_);
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
    Control_matrix dZ_run;   // the run's own columns of a solve that carried the probe along
    if(t_.probe_.active()) dZ_run = solver_->displacement().leftCols(Z_.cols());
    const Control_matrix& dZ = t_.probe_.active() ? dZ_run : solver_->displacement();
    const Control_matrix& tangent_surface = t_.operator_.prefiltered() ? *t_.operator_.prefiltered() : Z_;
    t_.probe_.make_candidate(solver_->displacement(), t_.block_.free, t_.tangential_filter_, tangent_surface, metric_columns_);
    if(t_.tangential_filter_)
    {
      // dZ itself stays the solution: the next step's CG starts from it. The tangent plane is that of
      // M_eps when the tensor reads its curvature there: on noise, the current surface's normal is mostly
      // noise, and removing motion in its tangent plane would keep the noise
      t_.normal_dZ_ = dZ;
      t_.tangential_filter_->remove(tangent_surface, metric_columns_, t_.block_.free, t_.normal_dZ_);
      t_.move_free_rows(Zc_, t_.normal_dZ_, Z0_, measured_columns_, row_unit_, st);
      t_.normal_dZ_.resize(0, 0);
    }
    else t_.move_free_rows(Zc_, dZ, Z0_, measured_columns_, row_unit_, st);
  }

  // back to the accepted surface's operator after a candidate was assembled (a fixed surface has one)
  void restore_accepted()
  {
    if(!fixed_) t_.operator_.restore(Z_, metric_columns_, tensor_);
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
      candidate_.finite = finite && Zc_.allFinite();
      // the folded edges first: they need no assembly, and a candidate they reject costs none
      if(candidate_.finite)
        count_folds(t_.layer_, Cache::has_second_derivatives, t_.components_.of_face, t_.component_edge_, Zc_, candidate_);
      const Known_fold_places known = [this](const Surface_soundness& c) {
        return folds_at_known_places(*t_.layer_.topology, t_.layer_.real_faces, accepted_, input_fold_edges_, allowed_folds_, c);
      };
      if(candidate_.finite && edges_folded(accepted_, input_folds_, candidate_, why, known)) verdict = Step_verdict::UNSOUND;
      else
      {
        t_.operator_.save();
        saved = true;
        if(candidate_.finite)
        {
          candidate_.statistics = t_.operator_.assemble(Zc_, metric_columns_, tensor_, !last_step);  // the last: statistics only
          if(!t_.operator_.error().empty())
          {
            fail(report_, Fairing_status::SOLVER_FAILED, "after step " + std::to_string(step) + ": " + t_.operator_.error(), total_);
            return Outcome::FAILED;
          }
          t_.measured_positions(Zc_, Y_);
          candidate_.finite = Y_.allFinite();
        }
        verdict = judge_step(initial_, accepted_, input_folds_, *lowest_H_, candidate_, why, known);
      }
      assemble_seconds_ = clock_.time();
    }
    if(verdict == Step_verdict::COLLAPSED)
    {
      fail(report_, Fairing_status::COLLAPSED, "step " + std::to_string(step) + ": " + why +
           ": mean-curvature flow shrinks closed surfaces to points; use fewer steps or a larger fidelity weight", total_);
      return Outcome::FAILED;
    }
    if(verdict != Step_verdict::UNSOUND) return Outcome::NEXT;
    if(saved) restore_accepted();
    ++report_.rejected_steps;
    last_why_ = why;
    if(s_.verbose) std::cerr << "step " << step << " rejected (" << why << "); retrying with a quarter of the time step\n";
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
    std::vector<double> tau(t_.units_.tau);
    for(double& x : tau) x *= f;
    return tau;
  }

  // the candidate becomes the surface; its step recorded, then the stop rules asked in order
  Outcome accept(Fairing_step& st, double theta)
  {
    control_.accept();
    Z_previous_.swap(Z_);
    Z_.swap(Zc_);
    t_.probe_.accept();
    accepted_ = candidate_;
    if(!fixed_ && candidate_.folded_edges <= allowed_folds_)
    {
      Z_unfolded_ = Z_;
      unfolded_steps_ = report_.steps.size() + 1;
      t_.probe_.mark_unfolded();
    }
    lowest_H_->add(candidate_.statistics);
    time_ += st.time_step;
    st.time = time_;
    st.area = accepted_.statistics.area; st.energy = accepted_.statistics.energy; st.H_integral = accepted_.statistics.H_integral;
    if(fixed_) st.energy = dirichlet_energy(t_.operator_.pattern(), t_.operator_.L(), Z_);
    if(st.step == s_.maximum_steps) st.assemble_seconds += assemble_seconds_;   // the final surface's statistics
    const double previous_discrepancy = discrepancy_;
    if(noise_stop_) discrepancy_ = candidate_discrepancy_;
    st.noise_displacement = discrepancy_;
    ask_noise_rules(st, theta, previous_discrepancy);
    if(!fixed_) report_.noise_displacement = st.noise_displacement;
    if(bound_->active())
    {
      const double next = control_.next_factor();
      bound_->accept(written(Z_), Z0_, t_.block_.free, scaled_tau(next), control_.factor() / next);
    }
    report_.steps.push_back(st);
    if(s_.verbose) print(st);
    if(report_.stop_reason == Stop_reason::NOISE_LEVEL || report_.stop_reason == Stop_reason::NOISE_REMOVED ||
       report_.stop_reason == Stop_reason::DEVIATION_BOUND)
    {
      callback_(report_.steps.back());
      return Outcome::ENDED;
    }
    if(control_.cramped())
    {
      report_.stop_reason = Stop_reason::STEP_REJECTED;
      report_.message = "steps " + std::to_string(st.step - 3) + " to " + std::to_string(st.step) + " went on only with 1/16 of the time "
                        "step or less (" + last_why_ + " otherwise); the run ends on the last sound surface (step " +
                        std::to_string(st.step) + ")";
      callback_(report_.steps.back());
      return Outcome::ENDED;
    }
    // stopping criteria (27)-(29) and the steady state, then the caller
    bool stop = monitor_->should_stop(st.step, st.time_step / time_unit_, fixed_ ? st.energy : st.H_integral, t_.max_relative_,
                                      t_.moved_relative_, report_.stop_reason);
    if(!callback_(report_.steps.back()) && !stop) { report_.stop_reason = Stop_reason::CALLBACK; stop = true; }
    return stop ? Outcome::ENDED : Outcome::NEXT;
  }

  // the noise level reached within this step (the run ends on the surface where it is reached exactly:
  // without a bound that surface was made and judged already), the noise removed, or held by the bound
  void ask_noise_rules(Fairing_step& st, double theta, double previous_discrepancy)
  {
    const auto end_within_step = [&](double theta_reached) {
      st.time = time_ - (1 - theta_reached) * st.time_step;
      st.max_displacement = 0;
      for(Eigen::Index i = 0; i < Z_.rows(); ++i)
        st.max_displacement = std::max(st.max_displacement, (Z_.row(i) - Z0_.row(i)).head(metric_columns_).norm());
      t_.measured_positions(Z_, Y_);
      st.noise_displacement = s_.noise->relative_displacement(Y_, Z0_, {});
      report_.stop_reason = Stop_reason::NOISE_LEVEL;
    };
    if(theta >= 0) end_within_step(theta);
    else if(noise_stop_ && discrepancy_ >= target_)
    {
      theta = fraction_reaching(previous_discrepancy, discrepancy_, target_);
      if(theta < 1)
      {
        Z_ = Z_previous_ + theta * (Z_ - Z_previous_);
        t_.probe_.rewind(theta);
        const Assembly_statistics b = t_.operator_.assemble(Z_, metric_columns_, tensor_, false);
        st.area = b.area; st.energy = b.energy; st.H_integral = b.H_integral;
      }
      end_within_step(theta);
    }
    if(noise_stop_ && s_.order == 4 && report_.stop_reason != Stop_reason::NOISE_LEVEL &&
       noise_removed(previous_discrepancy, discrepancy_, st.time_step, t_.mean_edge_, s_.strength))
      report_.stop_reason = Stop_reason::NOISE_REMOVED;
    if(noise_stop_ && bound_->active() && report_.stop_reason != Stop_reason::NOISE_LEVEL &&
       held_by_bound(previous_discrepancy, discrepancy_))
      report_.stop_reason = Stop_reason::DEVIATION_BOUND;
  }

  // the end: never a surface with more folded edges than the input
  void finish()
  {
    Surface_soundness last;
    if(!fixed_) count_folds(t_.layer_, Cache::has_second_derivatives, t_.components_.of_face, t_.component_edge_, Z_, last);
    const std::size_t folds = last.folded_edges;
    if(folds > allowed_folds_ && report_.succeeded())
    {
      // every accepted step folded the surface: nothing sound was gained, and an unmoved result is no success
      if(unfolded_steps_ == 0)
      {
        fail(report_, Fairing_status::FOLDED, "the surface folded at " + std::to_string(folds) + " edges (the input at " +
             std::to_string(allowed_folds_) + ") from the first step on, even with smaller time steps", total_);
        return;
      }
      Z_ = Z_unfolded_;
      t_.probe_.fall_back();
      report_.steps.resize(unfolded_steps_);
      report_.stop_reason = Stop_reason::STEP_REJECTED;
      report_.message = "the surface folded at " + std::to_string(folds) + " edges (the input at " + std::to_string(allowed_folds_) +
                        "); the run ends on the last surface without new folds (step " + std::to_string(unfolded_steps_) + ")";
      if(noise_stop_) { t_.measured_positions(Z_, Y_); report_.noise_displacement = s_.noise->relative_displacement(Y_, Z0_, {}); }
    }
    report_.bound_fidelity_weight = bound_->largest_weight();
    report_.bound_held_vertices = bound_->held_rows();
    report_.bound_uniform_weight = bound_->uniform_weight();
    report_.total_seconds = total_.time();
  }

  Stepper& t_;
  const Control_matrix& X_;
  Control_matrix& Z_;
  const int metric_columns_;
  Tensor tensor_;
  const Stepper_settings& s_;
  Callback& callback_;
  const bool fixed_;

  CGAL::Real_timer total_, clock_;
  Fairing_report report_;
  double assemble_seconds_ = 0, time_unit_ = 1, time_ = 0;
  Control_matrix Z0_, Y_, Yb_, anchor_, Zc_, Z_previous_, Z_unfolded_;
  std::vector<double> mass_weight_, row_unit_;
  const std::vector<double> no_scale_;
  const std::vector<double>* unknown_scale_ = &no_scale_;   // the stepper's, per row (Time_stepper::unknown_scale_)
  int measured_columns_ = 0;
  std::optional<Stopping_monitor> monitor_;
  bool noise_stop_ = false;
  Surface_soundness initial_, accepted_, candidate_;
  std::size_t input_folds_ = 0, allowed_folds_ = 0, unfolded_steps_ = 0;
  std::vector<int> input_fold_edges_;   // the input mesh's folded edges (a halfedge of each)
  std::optional<Deviation_bound> bound_;
  std::optional<Output_fidelity> fidelity_;
  int bound_retakes_ = 0;
  std::optional<Lowest_curvature> lowest_H_;
  double target_ = 0, discrepancy_ = 0, first_discrepancy_ = 0, candidate_discrepancy_ = 0;
  Eigen::Index nfree_ = 0;
  std::optional<Step_solver> solver_;
  Step_controller control_;
  std::string last_why_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_FLOW_RUN_H
