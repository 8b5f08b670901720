// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The semi-implicit step ((1 + tau w) M + tau L(D)) X_{n+1} = M (X_n + tau w X_0) of Bajaj & Xu
// (eq. 26 with the fidelity term written consistently, doc/Anisotropic_fairing/design/loop-fem-flow.md section 8), repeated until a
// stopping criterion holds, controlled as an ODE integrator would be: a step that leaves an unsound
// surface (Step_safety.h) is rejected and retried with a quarter of the time step; when even
// 1/1024 of it fails, the run ends on the last sound surface. It knows nothing of the element: any
// cache the Fem_assembler accepts will do (Loop patches or P1 faces).
//
// Constrained vertices are eliminated: the unknowns are the displacements of the free vertices,
//   A_FF dX_F = tau (w M (X_0 - X_n) - L X_n)_F,
// so the system stays symmetric positive definite and its right-hand side does not depend on the
// model's position in space. The pieces: the operator on the current surface (Surface_operator.h), the
// step's system and solver (Step_solver.h), the judgement of a candidate surface (Step_safety.h) and the
// stopping criteria (Stopping_monitor.h); one loop runs them for the surface and for attributes on a
// fixed surface.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TIME_STEPPER_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TIME_STEPPER_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Mesh_components.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Deviation_bound.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Local_time_scale.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Noise_estimate.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Normal_motion.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Ride_along_probe.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_safety.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_solver.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_units.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stopping_monitor.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Surface_operator.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Tensor_hooks.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Free_block.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

template <typename Cache>
class Time_stepper
{
public:
  /// `constrained[i]` holds vertex i fixed. `layer`: the mesh (with its ghosts); `components`: its
  /// connected components, `component_edge[c]` the mean edge length of component c, `mean_edge` of all.
  Time_stepper(const Cache& cache, std::size_t n, const std::vector<bool>& constrained, const Ghost_layer& layer,
               const Mesh_components& components, const std::vector<double>& component_edge, double mean_edge)
    : operator_(cache, n), block_(operator_.pattern(), constrained), layer_(layer), components_(components),
      component_edge_(component_edge), mean_edge_(mean_edge)
  {
    operator_.assembler().use_components(&components_.of_face, components_.count);
    // the curvature a component's edges can show: |H| up to 2 / h (a sphere of diameter h)
    for(double h : component_edge_) curvature_bound_.push_back(2 / h);
    operator_.assembler().set_curvature_bounds(&curvature_bound_);
  }

  /// Each step's displacement of the surface's columns then loses its tangential part (null: kept).
  void set_tangential_filter(const Tangential_motion_filter* f) { tangential_filter_ = f; }
  /// The next run carries the probed start P along (Ride_along_probe.h), unless it holds a deviation bound.
  void set_probe(const Control_matrix& P) { probe_.start(P); }
  /// Or makes it, P = make(M_eps), once the run has its start's prefiltered surface (else its start).
  void set_probe_maker(std::function<Control_matrix(const Control_matrix&)> make) { probe_maker_ = std::move(make); }
  /// After a run: where its probe ended (empty: it carried none).
  const Control_matrix& probe_result() const { return probe_.result(); }
  Fem_assembler<Cache>& assembler() { return operator_.assembler(); }
  /// 1, or the fraction of the way from the input to the limit points of the result to write (a run
  /// that ended before its first step because the limit surface alone moved by more than the noise)
  double limit_weight() const { return limit_weight_; }

  /// Runs the flow from X (n x kappa; the first `metric_columns` columns define the surface, the
  /// others are carried along with the same operator). On success X holds the faired control points.
  /// On failure X is unspecified and the report says why.
  template <typename Tensor, typename Callback>
  Fairing_report run(Control_matrix& X, int metric_columns, const Tensor& tensor, const Stepper_settings& s, Callback& callback)
  {
    return flow(X, X, metric_columns, tensor, s, callback, false);
  }

  /// Attributes only (Bajaj & Xu's case c): the surface of the first 3 columns of X is fixed, so M
  /// and L are assembled once, the system matrix is constant (factorised once when factorised at all)
  /// and every step is one solve for the other columns. The stopping criteria read the attributes'
  /// Dirichlet energy trace(A^T L A) in place of int |H|^2 (27, 28), and the steady-state speed in units
  /// of the attributes' spread, the root mean square of A_0 - mean(A_0). (29) bounds how far the surface
  /// moves; with the surface fixed it does not apply (noisy values move by about the noise in one step),
  /// nor does the noise criterion, which measures the surface.
  template <typename Tensor, typename Callback>
  Fairing_report run_on_fixed_surface(Control_matrix& X, const Tensor& tensor, const Stepper_settings& s, Callback& callback)
  {
    Control_matrix F = X.rightCols(X.cols() - 3);
    const Fairing_report report = flow(X, F, 3, tensor, s, callback, true);
    X.rightCols(F.cols()) = F;
    return report;
  }

private:
  // The loop of both runs. Z: what moves, X itself, or on a fixed surface (the first 3 columns of X)
  // the attributes' columns.
  template <typename Tensor, typename Callback>
  Fairing_report flow(const Control_matrix& X, Control_matrix& Z, int metric_columns, const Tensor& tensor_in,
                      const Stepper_settings& s, Callback& callback, bool fixed)
  {
    CGAL::Real_timer total;
    total.start();
    Fairing_report report;
    report.vertices = std::size_t(Z.rows());
    report.constrained_vertices = std::size_t(Z.rows()) - block_.size();
    limit_output_ = s.limit_output;
    CGAL::Real_timer clock;
    clock.start();
    Tensor tensor = tensor_in;
    Assembly_statistics a;
    if(!set_units(X, metric_columns, s, tensor, report, a, total)) return report;
    double assemble_seconds = clock.time();
    const Control_matrix Z0 = Z;
    // automatic isotropic runs: a time step that follows the mesh's density (Local_time_scale.h)
    const std::vector<double> none, mass_weight = s.local_time_scale && !fixed
      ? mass_weights(local_time_scale(*layer_.topology, layer_.real_faces, Z0, components_, component_edge_)) : none;
    const std::vector<double>& unknown_scale = fixed ? none : unknown_scale_;
    const double time_unit = s.stopping.relative_units ? std::pow(report.scale, s.order) : 1.0;   // (28), steady speed

    // what the criteria measure: int |H|^2 and the motion in lengths; on a fixed surface the attributes'
    // Dirichlet energy and their motion in units of their spread, and (29) does not apply
    const int measured_columns = fixed ? int(Z.cols()) : metric_columns;
    std::vector<double> row_unit = units_.length;
    Stopping_criteria criteria = s.stopping;
    if(fixed)
    {
      report.initial.energy = dirichlet_energy(operator_.pattern(), operator_.L(), Z);
      double spread = 0;
      const Eigen::RowVectorXd mean = Z0.colwise().mean();
      for(Eigen::Index i = 0; i < Z0.rows(); ++i) spread += (Z0.row(i) - mean).squaredNorm();
      spread = Z0.rows() > 0 ? std::sqrt(spread / double(Z0.rows())) : 0.0;
      row_unit.assign(std::size_t(Z0.rows()), spread > 0 ? spread : 1.0);
      criteria.displacement = 0;
    }
    Stopping_monitor monitor(criteria, fixed ? report.initial.energy : a.H_integral);

    // the noise criterion: stop once the written surface moved off the input by the noise
    const bool noise_stop = !fixed && s.noise && s.stopping.noise_discrepancy > 0;
    Control_matrix Y;
    Surface_soundness initial{ a, 0, 0, true };
    std::size_t input_folds = 0;
    if(!fixed)
    {
      output_positions(Z, Y);
      count_folds(layer_, Cache::has_second_derivatives, components_.of_face, component_edge_, Z, initial);
      input_folds = count_folded_edges(*layer_.topology, layer_.real_faces, Z0, components_.of_face, component_edge_);
    }
    // the user's bound on the written positions (Deviation_bound.h), Yb, held by the vertices' own fidelity
    Deviation_bound bound = make_bound(s, Z, fixed, !noise_stop, report);
    const Output_fidelity fidelity(*layer_.topology, s.limit_written);
    Control_matrix Yb;
    auto written = [&](const Control_matrix& W) -> const Control_matrix& {
      if(fixed || s.limit_written != limit_output_) { if(s.limit_written) limit_points(layer_, W, Yb); else Yb = W; return Yb; }
      output_positions(W, Y);
      return Y;
    };
    const Control_matrix anchor = bound.active() ? written(Z) : Control_matrix();
    bound.set_start(anchor, Z0);
    int bound_retries = 0;
    const int maximum_bound_retries = 4;
    Surface_soundness accepted = initial;
    Lowest_curvature lowest_H(a);
    const double target = noise_stop ? s.stopping.noise_discrepancy * s.noise->relative_sigma() : 0.0;
    double discrepancy = noise_stop ? s.noise->relative_displacement(Y, Z0, {}) : 0.0;
    report.noise_displacement = discrepancy;
    // before the first step, the limit surface of the input may round its creases by more than the
    // noise while leaving most vertices in place: a clean mesh, whatever the typical vertex says
    const double first_discrepancy = noise_stop ? std::max(discrepancy, s.noise->relative_displacement(Y, Z0, {}, true)) : 0.0;

    const Eigen::Index nfree = Eigen::Index(block_.size());
    // the probe rides along where the steps are linear in the positions: without the bound's own fidelities
    if(probe_maker_ && !fixed && !bound.active()) probe_.start(probe_maker_(operator_.prefiltered() ? *operator_.prefiltered() : Z0));
    if(fixed || bound.active()) probe_ = Ride_along_probe();
    const Eigen::Index solved_columns = Z.cols() * (probe_.active() ? 2 : 1);
    Step_solver solver(operator_.pattern(), block_, s, solved_columns, fixed, bound.active() ? &fidelity : nullptr, &anchor);
    Control_matrix ZZ, ZZ0, dZ_run;
    Control_matrix Zc, Z_previous;
    // the last surface with no more folded edges than the input mesh (or its limit surface): what the
    // run falls back to if the surface it ends on has more
    const std::size_t allowed_folds = std::max(input_folds, initial.folded_edges);
    Control_matrix Z_unfolded = fixed ? Control_matrix() : Z;
    std::size_t unfolded_steps = 0;
    double factor = 1, time = 0;
    int rejections = 0, cramped = 0;   // cramped: steps in a row accepted only with <= 1/16 of the time step
    int locating = 0;                  // retries of this step to end it where the noise level is reached
    const double noise_tolerance = 0.02;   // how close to the noise level a run ends
    const int maximum_locating = 4;
    std::string last_why;
    if(nfree == 0) report.stop_reason = Stop_reason::NO_FREE_VERTEX;
    else if(noise_stop && first_discrepancy >= target)
    {
      // the input's own limit surface is already off it by more than the noise: the result lies between
      // the two, where the noise level is reached
      report.stop_reason = Stop_reason::NOISE_LEVEL;
      limit_weight_ = first_discrepancy > 0 ? target / first_discrepancy : 0.0;
      report.noise_displacement = target;
    }
    for(std::size_t step = 1; step <= s.maximum_steps && nfree > 0 && report.stop_reason != Stop_reason::NOISE_LEVEL;)
    {
      Fairing_step st;
      st.step = step;
      st.time_step = factor * report.time_step;
      // system and right-hand side at Z_n, divided by sys so that a huge tau cannot overflow
      clock.reset();
      if(probe_.active()) probe_.augment(Z, Z0, ZZ, ZZ0);
      const Solve_statistics sol = solver.solve(operator_.M(), operator_.L(), units_, mass_weight, unknown_scale, factor,
                                                system_scale(units_, block_.free, factor, s.order, mean_edge_), probe_.active() ? ZZ : Z,
                                                probe_.active() ? ZZ0 : Z0, bound.weights(), st.direct_solve);
      st.solve_seconds = solver.solve_seconds();
      st.assemble_seconds = assemble_seconds + clock.time() - st.solve_seconds;
      assemble_seconds = 0;
      report.used_cholesky = report.used_cholesky || st.direct_solve;
      st.solver_iterations = sol.iterations;
      st.residual = sol.residual;
      if(probe_.active()) dZ_run = solver.displacement().leftCols(Z.cols());
      const Control_matrix& dZ = probe_.active() ? dZ_run : solver.displacement();
      const bool finite = solver.displacement().allFinite() && std::isfinite(sol.residual);
      if(!finite && fixed)
        return fail(report, Fairing_status::NON_FINITE_VALUE, "step " + std::to_string(step) + ": the solution is not finite", total);
      if(!sol.ok && finite) return fail(report, Fairing_status::SOLVER_FAILED, "step " + std::to_string(step) + ": " + sol.message, total);

      // the candidate surface: its matrices (for the next step) and its soundness
      Zc = Z;
      if(finite)
      {
        const Control_matrix& tangent_surface = operator_.prefiltered() ? *operator_.prefiltered() : Z;
        probe_.make_candidate(solver.displacement(), block_.free, tangential_filter_, tangent_surface, metric_columns);
        if(tangential_filter_)
        {
          // dZ itself stays the solution: the next step's CG starts from it. The tangent plane is that
          // of M_eps when the tensor reads its curvature there: on noise, the current surface's normal
          // is mostly noise, and removing motion in its tangent plane would keep the noise
          normal_dZ_ = dZ;
          tangential_filter_->remove(tangent_surface, metric_columns, block_.free, normal_dZ_);
          move_free_rows(Zc, normal_dZ_, Z0, measured_columns, row_unit, st);
        }
        else move_free_rows(Zc, dZ, Z0, measured_columns, row_unit, st);
      }
      // the noise level passed within this step: take it again, shorter, so that it ends there (the
      // displacement grows fastest at first, so the secant undershoots the time and each retry comes
      // closer). Judged before the candidate is assembled, which a retaken step does not need; with a
      // bound on the written positions, after the bound's retakes
      double candidate_discrepancy = 0;
      const auto locate = [&]() {
        if(!(candidate_discrepancy > target * (1 + noise_tolerance)) || locating >= maximum_locating) return false;
        ++locating;
        factor *= std::max(0.05, (target - discrepancy) / (candidate_discrepancy - discrepancy));
        return true;
      };
      bool last_step = step == s.maximum_steps;
      double theta = -1;   // >= 0: the run ends this far into the step, where the noise level is reached
      if(noise_stop && finite && !bound.active())
      {
        output_positions(Zc, Y);
        if(Y.allFinite())
        {
          candidate_discrepancy = s.noise->relative_displacement(Y, Z0, {});
          if(locate()) continue;
          if(candidate_discrepancy >= target)
          {
            // the surface the run ends on is the one judged, and it needs no matrices
            theta = std::min(1.0, std::max(0.0, (target - discrepancy) / (candidate_discrepancy - discrepancy)));
            if(theta < 1) { Zc = Z + theta * (Zc - Z); output_positions(Zc, Y); probe_.shorten(theta); }
            last_step = true;
          }
        }
      }
      Surface_soundness candidate = accepted;
      std::string why;
      Step_verdict verdict = Step_verdict::SOUND;
      bool saved = false;   // the accepted surface's operator kept aside while the candidate's is assembled
      if(!fixed)
      {
        clock.reset();
        candidate = Surface_soundness();
        candidate.finite = finite && Zc.allFinite();
        // the folded edges first: they need no assembly, and a candidate they reject costs none
        if(candidate.finite) count_folds(layer_, Cache::has_second_derivatives, components_.of_face, component_edge_, Zc, candidate);
        if(candidate.finite && edges_folded(accepted, input_folds, candidate, why)) verdict = Step_verdict::UNSOUND;
        else
        {
          operator_.save();
          saved = true;
          if(candidate.finite)
          {
            candidate.statistics = operator_.assemble(Zc, metric_columns, tensor, !last_step);  // the last: statistics only
            if(!operator_.error().empty())
              return fail(report, Fairing_status::SOLVER_FAILED, "after step " + std::to_string(step) + ": " + operator_.error(), total);
            output_positions(Zc, Y);
            candidate.finite = Y.allFinite();
          }
          verdict = judge_step(initial, accepted, input_folds, lowest_H, candidate, why);
        }
        assemble_seconds = clock.time();
      }
      if(verdict == Step_verdict::COLLAPSED)
        return fail(report, Fairing_status::COLLAPSED, "step " + std::to_string(step) + ": " + why +
                    ": mean-curvature flow shrinks closed surfaces to points; use fewer steps or a larger fidelity weight", total);
      if(verdict == Step_verdict::UNSOUND)
      {
        if(saved) operator_.restore();
        ++report.rejected_steps;
        last_why = why;
        if(s.verbose) std::cerr << "step " << step << " rejected (" << why << "); retrying with a quarter of the time step\n";
        if(++rejections <= s.maximum_rejections) { factor /= 4; continue; }
        const std::string what = "step " + std::to_string(step) + ": " + why + " even with 1/" +
                                 std::to_string(1 << (2 * s.maximum_rejections)) + " of the time step";
        if(report.steps.empty())
          return fail(report, !candidate.finite ? Fairing_status::NON_FINITE_VALUE : Fairing_status::FOLDED, what, total);
        report.stop_reason = Stop_reason::STEP_REJECTED;
        report.message = what + "; the run ends on the last sound surface (step " + std::to_string(step - 1) + ")";
        break;
      }

      // a written position carried past the user's bound: the step again, those vertices held harder
      if(bound.active() && finite && bound_retries < maximum_bound_retries)
      {
        std::vector<double> tau(units_.tau);
        for(double& t : tau) t *= factor;
        if(bound.exceeded_and_raised(written(Zc), Z0, block_.free, tau))
        {
          if(!fixed) operator_.restore();
          ++bound_retries;
          ++report.bound_retaken_steps;
          continue;
        }
      }
      bound_retries = 0;

      if(noise_stop && bound.active())
      {
        candidate_discrepancy = s.noise->relative_displacement(Y, Z0, {});
        if(locate()) { operator_.restore(); continue; }
      }
      locating = 0;

      // accepted; a flow that only crawls on with a sliver of its time step is heading into a fold
      cramped = factor <= 1.0 / 16 ? cramped + 1 : 0;
      rejections = 0;
      Z_previous.swap(Z);
      Z.swap(Zc);
      probe_.accept();
      accepted = candidate;
      if(!fixed && candidate.folded_edges <= allowed_folds) { Z_unfolded = Z; unfolded_steps = report.steps.size() + 1; probe_.mark_unfolded(); }
      lowest_H.add(candidate.statistics);
      time += st.time_step;
      st.time = time;
      st.area = accepted.statistics.area; st.energy = accepted.statistics.energy; st.H_integral = accepted.statistics.H_integral;
      if(fixed) st.energy = dirichlet_energy(operator_.pattern(), operator_.L(), Z);
      if(step == s.maximum_steps) st.assemble_seconds += assemble_seconds;   // the final surface's statistics
      const double previous_discrepancy = discrepancy;
      if(noise_stop) discrepancy = candidate_discrepancy;
      st.noise_displacement = discrepancy;
      // the noise level is reached within this step: end on the surface where it is reached exactly (without
      // a bound, that surface was made and judged above)
      const auto end_within_step = [&](double theta_reached) {
        st.time = time - (1 - theta_reached) * st.time_step;
        st.max_displacement = 0;
        for(Eigen::Index i = 0; i < Z.rows(); ++i)
          st.max_displacement = std::max(st.max_displacement, (Z.row(i) - Z0.row(i)).head(metric_columns).norm());
        output_positions(Z, Y);
        st.noise_displacement = s.noise->relative_displacement(Y, Z0, {});
        report.stop_reason = Stop_reason::NOISE_LEVEL;
      };
      if(theta >= 0) end_within_step(theta);
      else if(noise_stop && discrepancy >= target)
      {
        theta = std::min(1.0, std::max(0.0, (target - previous_discrepancy) / (discrepancy - previous_discrepancy)));
        if(theta < 1)
        {
          Z = Z_previous + theta * (Z - Z_previous);
          probe_.rewind(theta);
          const Assembly_statistics b = operator_.assemble(Z, metric_columns, tensor, false);
          st.area = b.area; st.energy = b.energy; st.H_integral = b.H_integral;
        }
        end_within_step(theta);
      }
      // the fourth-order flow barely shrinks: once the noise is gone its displacement levels off, maybe short
      // of the noise level, and what still moves is shape: stop when the displacement grows more slowly than
      // a wave of 4 pi h decays, |u'/u| = (2 pi / 4 pi h)^4 = 1 / (16 h^4)
      if(noise_stop && s.order == 4 && report.stop_reason != Stop_reason::NOISE_LEVEL && previous_discrepancy > 0 &&
         (discrepancy - previous_discrepancy) / discrepancy < st.time_step / (16 * std::pow(mean_edge_, 4)))
        report.stop_reason = Stop_reason::NOISE_REMOVED;
      // with a maximum deviation short of the noise the displacement levels off where the bound holds it
      if(noise_stop && bound.active() && report.stop_reason != Stop_reason::NOISE_LEVEL && previous_discrepancy > 0 &&
         discrepancy - previous_discrepancy < 0.01 * discrepancy)
        report.stop_reason = Stop_reason::DEVIATION_BOUND;
      if(!fixed) report.noise_displacement = st.noise_displacement;
      if(bound.active())
      {
        std::vector<double> tau(units_.tau);
        const double next = std::min(1.0, 2 * factor);
        for(double& t : tau) t *= next;   // the next step's
        bound.accept(written(Z), Z0, block_.free, tau, factor / next);
      }
      report.steps.push_back(st);
      if(s.verbose) print(st);
      if(report.stop_reason == Stop_reason::NOISE_LEVEL || report.stop_reason == Stop_reason::NOISE_REMOVED ||
         report.stop_reason == Stop_reason::DEVIATION_BOUND)
      {
        callback(report.steps.back());
        break;
      }
      if(cramped >= 4)
      {
        report.stop_reason = Stop_reason::STEP_REJECTED;
        report.message = "steps " + std::to_string(step - 3) + " to " + std::to_string(step) + " went on only with 1/16 of the time "
                         "step or less (" + last_why + " otherwise); the run ends on the last sound surface (step " + std::to_string(step) + ")";
        callback(report.steps.back());
        break;
      }

      // stopping criteria (27)-(29) and the steady state
      bool stop = monitor.should_stop(step, st.time_step / time_unit, fixed ? st.energy : st.H_integral, max_relative_, moved_relative_,
                                      report.stop_reason);
      if(!callback(report.steps.back()) && !stop) { report.stop_reason = Stop_reason::CALLBACK; stop = true; }
      if(stop) break;
      factor = std::min(1.0, 2 * factor);
      ++step;
    }
    // the end: never a surface with more folded edges than the input
    Surface_soundness last;
    if(!fixed) count_folds(layer_, Cache::has_second_derivatives, components_.of_face, component_edge_, Z, last);
    const std::size_t folds = last.folded_edges;
    if(folds > allowed_folds && report.succeeded())
    {
      // every accepted step folded the surface: nothing sound was gained, and an unmoved result is no success
      if(unfolded_steps == 0)
        return fail(report, Fairing_status::FOLDED, "the surface folded at " + std::to_string(folds) + " edges (the input at " +
                    std::to_string(allowed_folds) + ") from the first step on, even with smaller time steps", total);
      Z = Z_unfolded;
      probe_.fall_back();
      report.steps.resize(unfolded_steps);
      report.stop_reason = Stop_reason::STEP_REJECTED;
      report.message = "the surface folded at " + std::to_string(folds) + " edges (the input at " + std::to_string(allowed_folds) +
                       "); the run ends on the last surface without new folds (step " + std::to_string(unfolded_steps) + ")";
      if(noise_stop) { output_positions(Z, Y); report.noise_displacement = s.noise->relative_displacement(Y, Z0, {}); }
    }
    report.bound_fidelity_weight = bound.largest_weight();
    report.bound_held_vertices = bound.held_rows();
    report.bound_uniform_weight = bound.uniform_weight();
    report.total_seconds = total.time();
    return report;
  }

  // the bounds of the settings on Z's columns: the geometry (the first 3, not on a fixed surface) and the
  // attributes (the others, all of them on a fixed surface)
  Deviation_bound make_bound(const Stepper_settings& s, const Control_matrix& Z, bool fixed, bool uniform, Fairing_report& report) const
  {
    Column_bound g, a;
    if(s.maximum_deviation > 0)
      report.maximum_deviation = s.relative_deviation ? s.maximum_deviation * units_.scale : s.maximum_deviation;
    if(s.maximum_deviation > 0 && !fixed) { g.count = 3; g.radius = report.maximum_deviation; }
    a.first = fixed ? 0 : 3;
    if(s.attribute_maximum_deviation > 0 && Z.cols() > a.first) { a.count = Z.cols() - a.first; a.radius = s.attribute_maximum_deviation; }
    return Deviation_bound(g, a, std::size_t(Z.rows()), uniform);
  }

  // The units of every vertex from the input's area per component, the tensor told its length scale,
  // then M and L(D) at X: false (and a failed report) when the input has no surface.
  template <typename Tensor>
  bool set_units(const Control_matrix& X, int metric_columns, const Stepper_settings& s, Tensor& tensor,
                 Fairing_report& report, Assembly_statistics& a, const CGAL::Real_timer& total)
  {
    const bool scaled_tensor = wants_length_scale(tensor);
    Prefilter_solver prefilter;
    prefilter.solver = s.solver;
    prefilter.tolerance = s.solver_tolerance / 100;
    prefilter.maximum_iterations = s.solver_maximum_iterations;
    prefilter.direct = s.direct_solver;
    std::vector<double> eps(std::size_t(X.rows()), scaled_tensor ? 0.0 : prefilter_time(tensor));   // the prefilter time per row
    std::vector<double> m, l;
    if(scaled_tensor) a = operator_.assembler().assemble(X, metric_columns, Isotropic_diffusion_tensor(), m, l, false);
    else
    {
      operator_.set_prefilter(eps, &block_, prefilter);
      a = operator_.assemble(X, metric_columns, tensor, true);
    }
    for(std::size_t c = 0; c < a.component_area.size(); ++c)
      if(!(a.component_area[c] > 0) || !std::isfinite(a.component_area[c]) || !(component_edge_[c] > 0))
      {
        fail(report, Fairing_status::DEGENERATE_METRIC, "the input's limit surface has no area" +
             (components_.count > 1 ? " in connected component " + std::to_string(c) : std::string()) +
             " (sqrt(det G) <= 0 on face " + std::to_string(a.degenerate_face) + "): its control points do not span a surface", total);
        return false;
      }
    const Length_unit tensor_unit = is_automatic_tensor(tensor) ? Length_unit::EDGE : Length_unit::SCALE;
    units_ = make_step_units(a, components_, std::size_t(X.rows()), s.time_step, s.time_unit, s.order, s.fidelity_weight,
                             s.relative_fidelity, s.stopping.relative_units, tensor_unit, component_edge_, mean_edge_);
    report.scale = units_.scale;
    report.flow_order = s.order;
    report.time_step = units_.time_step;
    report.fidelity_weight = units_.fidelity_weight;
    report.components = components_.count;
    // several components: each solved in its own units (unknowns dX / l_c, equations / l_c^2 and l_c^3),
    // so that the solver's tolerance means the same on a small part as on a large one
    unknown_scale_.clear();
    if(components_.count > 1 && units_.length.size() == std::size_t(X.rows()))
      for(std::size_t i = 0; i < std::size_t(X.rows()); ++i)
      {
        const int c = components_.of_vertex[i];
        unknown_scale_.push_back(c >= 0 ? std::sqrt(a.component_area[std::size_t(c)] / (4 * 3.14159265358979323846)) : 1.0);
      }
    if(scaled_tensor)
    {
      // each component's prefilter time as the tensor measures it at that component's scale
      std::vector<double> component_eps(components_.count);
      for(std::size_t c = 0; c < components_.count; ++c)
      {
        Tensor t = tensor;
        give_length_scale(t, units_.tensor_unit * units_.tensor_scale[c]);
        component_eps[c] = prefilter_time(t);
      }
      for(std::size_t i = 0; i < eps.size(); ++i)
        if(components_.of_vertex[i] >= 0) eps[i] = component_eps[std::size_t(components_.of_vertex[i])];
      operator_.assembler().set_component_scales(&units_.tensor_scale);
      give_length_scale(tensor, units_.tensor_unit);
      report.feature_threshold = std::isfinite(threshold_of(tensor)) ? threshold_of(tensor) : 0.0;
      report.prefilter_time = prefilter_time(tensor);
      operator_.set_prefilter(std::move(eps), &block_, prefilter);
      a = operator_.assemble(X, metric_columns, tensor, true);
    }
    report.initial.area = a.area;
    report.initial.energy = a.energy;
    report.initial.H_integral = a.H_integral;
    if(!operator_.error().empty()) { fail(report, Fairing_status::SOLVER_FAILED, operator_.error(), total); return false; }
    return true;
  }

  // the positions written for X: its Loop limit points, or X itself
  void output_positions(const Control_matrix& X, Control_matrix& Y) const
  {
    if(limit_output_) limit_points(layer_, X, Y);
    else Y = X;
  }

  // adds the free rows' displacements to X; records the step's and the total (from X0) largest motion
  // over the first `columns` columns; in units of `row_unit` too, for the stopping criteria
  // (max_relative_, moved_relative_)
  void move_free_rows(Control_matrix& X, const Control_matrix& dX, const Control_matrix& X0, int columns,
                      const std::vector<double>& row_unit, Fairing_step& st)
  {
    double moved = 0;
    moved_relative_ = max_relative_ = 0;
    for(Eigen::Index i = 0; i < dX.rows(); ++i)
    {
      const std::size_t row = std::size_t(block_.free[std::size_t(i)]);
      X.row(Eigen::Index(row)) += dX.row(i);
      const double d = dX.row(i).head(columns).norm();
      moved = std::max(moved, d);
      moved_relative_ = std::max(moved_relative_, d / row_unit[row]);
    }
    st.step_displacement = moved;
    st.max_displacement = 0;
    for(Eigen::Index i = 0; i < X.rows(); ++i)
    {
      const double d = (X.row(i) - X0.row(i)).head(columns).norm();
      st.max_displacement = std::max(st.max_displacement, d);
      max_relative_ = std::max(max_relative_, d / row_unit[std::size_t(i)]);
    }
  }

  Surface_operator<Cache> operator_;
  Free_block block_;
  const Tangential_motion_filter* tangential_filter_ = nullptr;
  Ride_along_probe probe_;
  std::function<Control_matrix(const Control_matrix&)> probe_maker_;
  Control_matrix normal_dZ_;
  const Ghost_layer& layer_;
  const Mesh_components& components_;
  const std::vector<double>& component_edge_;
  double mean_edge_;
  Step_units units_;
  std::vector<double> curvature_bound_; // per component (Assembly_statistics::bounded_H_integral)
  bool limit_output_ = false;
  double moved_relative_ = 0, max_relative_ = 0;
  double limit_weight_ = 1;
  std::vector<double> unknown_scale_;   // per row, with several components (else empty)
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TIME_STEPPER_H
