// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The semi-implicit step ((1 + tau w) M + tau L(D)) X_{n+1} = M (X_n + tau w X_0) of Bajaj & Xu
// (eq. 26 with the fidelity term written consistently, doc/Anisotropic_fairing/design/loop-fem.md section 8), repeated until a
// stopping criterion holds, controlled as an ODE integrator would be: a step that leaves an unsound
// surface (Step_safety.h) is rejected and retried with a quarter of the time step; when even
// 1/1024 of it fails, the run ends on the last sound surface. It knows nothing of the element: any
// cache the Fem_assembler accepts will do (Loop patches or P1 faces).
//
// Constrained vertices are eliminated: the unknowns are the displacements of the free vertices,
//   A_FF dX_F = tau (w M (X_0 - X_n) - L X_n)_F,
// so the system stays symmetric positive definite and its right-hand side does not depend on the
// model's position in space.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TIME_STEPPER_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TIME_STEPPER_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/internal/assembly/Fem_assembly.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Local_time_scale.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Mesh_components.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Noise_estimate.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_safety.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Fourth_order_system.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Step_system.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_units.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Tensor_hooks.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Vertex_limit_masks.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Normal_motion.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Prefilter_step.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Spd_solvers.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Solver_choice.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stopping_monitor.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
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
    : assembler_(cache, n), free_index_(n, -1), layer_(layer), components_(components),
      component_edge_(component_edge), mean_edge_(mean_edge)
  {
    for(std::size_t i = 0; i < n; ++i)
      if(!constrained[i]) { free_index_[i] = int(free_.size()); free_.push_back(int(i)); }
    // the free-free block of the pattern, and where each of its entries comes from
    const Eigen::SparseMatrix<double>& P = assembler_.pattern();
    std::vector<int> outer(1, 0), inner;
    inner.reserve(std::size_t(P.nonZeros()));
    source_.reserve(std::size_t(P.nonZeros()));
    for(std::size_t k = 0; k < free_.size(); ++k)
    {
      for(int p = P.outerIndexPtr()[free_[k]]; p < P.outerIndexPtr()[free_[k] + 1]; ++p)
      {
        const int r = free_index_[std::size_t(P.innerIndexPtr()[p])];
        if(r >= 0) { inner.push_back(r); source_.push_back(p); entry_column_.push_back(int(k)); }   // rows stay sorted: free_ is increasing
      }
      outer.push_back(int(inner.size()));
    }
    A_ = sparse_matrix_from_pattern(Eigen::Index(free_.size()), Eigen::Index(free_.size()), outer, inner);
    assembler_.use_components(&components_.of_face, components_.count);
    // the curvature a component's edges can show: |H| up to 2 / h (a sphere of diameter h)
    for(double h : component_edge_) curvature_bound_.push_back(2 / h);
    assembler_.set_curvature_bounds(&curvature_bound_);
  }

  std::size_t number_of_free_vertices() const { return free_.size(); }
  /// Each step's displacement of the surface's columns then loses its tangential part (null: kept).
  void set_tangential_filter(const Tangential_motion_filter* f) { tangential_filter_ = f; }
  Fem_assembler<Cache>& assembler() { return assembler_; }
  /// 1, or the fraction of the way from the input to the limit points of the result to write (a run
  /// that ended before its first step because the limit surface alone moved by more than the noise)
  double limit_weight() const { return limit_weight_; }

  /// Runs the flow from X (n x kappa; the first `metric_columns` columns define the surface, the
  /// others are carried along with the same operator). On success X holds the faired control points.
  /// On failure X is unspecified and the report says why.
  template <typename Tensor, typename Callback>
  Fairing_report run(Control_matrix& X, int metric_columns, const Tensor& tensor_in,
                     const Stepper_settings& s, Callback& callback)
  {
    CGAL::Real_timer total;
    total.start();
    Fairing_report report;
    report.vertices = std::size_t(X.rows());
    report.constrained_vertices = std::size_t(X.rows()) - free_.size();
    limit_output_ = s.limit_output;
    Block_conjugate_gradient cg(s.solver_tolerance, s.solver_maximum_iterations);
    Solver_choice choice(s.solver, free_.size());
    const Control_matrix X0 = X;
    // automatic isotropic runs: a time step that follows the mesh's density (Local_time_scale.h)
    const std::vector<double> mass_weight = s.local_time_scale ? mass_weights(local_time_scale(*layer_.topology, layer_.real_faces, X0,
                                                                                               components_, component_edge_))
                                                               : std::vector<double>();
    CGAL::Real_timer clock;
    clock.start();
    Tensor tensor = tensor_in;
    Assembly_statistics a;
    if(!set_units(X, metric_columns, s, tensor, report, a, total)) return report;
    double assemble_seconds = clock.time();
    const double time_unit = s.stopping.relative_units ? std::pow(report.scale, s.order) : 1.0;   // (28), steady speed
    Stopping_monitor monitor(s.stopping, a.H_integral);

    // the noise criterion: stop once the written surface moved off the input by the noise
    Control_matrix Y;
    output_positions(X, Y);
    Surface_soundness initial{ a, 0, 0, true };
    count_folds(layer_, Cache::has_second_derivatives, components_.of_face, component_edge_, X, initial);
    Surface_soundness accepted = initial;
    const std::size_t input_folds = count_folded_edges(*layer_.topology, layer_.real_faces, X0, components_.of_face, component_edge_);
    Lowest_curvature lowest_H(a);
    const bool noise_stop = s.noise && s.stopping.noise_discrepancy > 0;
    const double target = noise_stop ? s.stopping.noise_discrepancy * s.noise->relative_sigma() : 0.0;
    double discrepancy = noise_stop ? s.noise->relative_displacement(Y, X0, {}) : 0.0;
    report.noise_displacement = discrepancy;
    // before the first step, the limit surface of the input may round its creases by more than the
    // noise while leaving most vertices in place: a clean mesh, whatever the typical vertex says
    const double first_discrepancy = noise_stop ? std::max(discrepancy, s.noise->relative_displacement(Y, X0, {}, true)) : 0.0;

    const Eigen::Index n = X.rows(), k = X.cols(), nfree = Eigen::Index(free_.size());
    std::unique_ptr<Fourth_order_system> fourth_order;
    if(s.order == 4) fourth_order.reset(new Fourth_order_system(assembler_.pattern(), free_));
    Control_matrix R(n, k), B(nfree, k), dX = Control_matrix::Zero(nfree, k);
    Control_matrix Xc, X_previous;
    // the last surface with no more folded edges than the input mesh (or its limit surface): what the
    // run falls back to if the surface it ends on has more
    const std::size_t allowed_folds = std::max(input_folds, initial.folded_edges);
    Control_matrix X_unfolded = X;
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
      // system and right-hand side at X_n, divided by sys so that a huge tau cannot overflow
      clock.reset();
      const double sys = system_scale(factor, s.order);
      if(fourth_order)
      {
        fourth_order->set_operator(M_, L_, mass_weight);
        fourth_order->fill_matrix(units_.tau, units_.omega, factor, sys, unknown_scale_, A4_);
        fourth_order->residual(units_.tau, units_.omega, X, X0, factor / sys, R);
      }
      else
      {
        fill_step_matrix(A_, source_, entry_column_, free_, M_, L_, units_.tau, units_.omega, factor, sys, unknown_scale_, mass_weight);
        step_residual(assembler_.pattern(), M_, L_, units_.tau, units_.omega, X, X0, factor / sys, R, mass_weight);
      }
      for(Eigen::Index i = 0; i < nfree; ++i) B.row(i) = R.row(free_[std::size_t(i)]);
      if(!unknown_scale_.empty())
        for(Eigen::Index i = 0; i < nfree; ++i) B.row(i) /= std::pow(unknown_scale_[std::size_t(free_[std::size_t(i)])], 3);
      st.assemble_seconds = assemble_seconds + clock.time();

      clock.reset();
      const Solve_statistics sol = choice.solve(fourth_order ? A4_ : A_, B, dX, cg, st.direct_solve);   // CG warm-started from the last dX
      st.solve_seconds = clock.time();
      choice.record(st.direct_solve, sol, st.solve_seconds);
      report.used_cholesky = report.used_cholesky || st.direct_solve;
      st.solver_iterations = sol.iterations;
      st.residual = sol.residual;
      if(!unknown_scale_.empty())
      {
        step_dX_ = dX;
        for(Eigen::Index i = 0; i < nfree; ++i) step_dX_.row(i) *= unknown_scale_[std::size_t(free_[std::size_t(i)])];
      }
      const Control_matrix& dX_model = unknown_scale_.empty() ? dX : step_dX_;
      const bool finite = dX_model.allFinite() && std::isfinite(sol.residual);
      if(!sol.ok && finite) return fail(report, Fairing_status::SOLVER_FAILED, "step " + std::to_string(step) + ": " + sol.message, total);

      // the candidate surface: its matrices (for the next step) and its soundness
      Xc = X;
      if(finite)
      {
        if(tangential_filter_)
        {
          // dX itself stays the solution: the next step's CG starts from it. The tangent plane is that
          // of M_eps when the tensor reads its curvature there: on noise, the current surface's normal
          // is mostly noise, and removing motion in its tangent plane would keep the noise
          normal_dX_ = dX_model;
          tangential_filter_->remove(prefiltered_valid_ ? prefiltered_X_ : X, metric_columns, free_, normal_dX_);
          move_free_rows(Xc, normal_dX_, X0, metric_columns, st);
        }
        else move_free_rows(Xc, dX_model, X0, metric_columns, st);
      }
      clock.reset();
      save_operator();
      Surface_soundness candidate;
      candidate.finite = finite && Xc.allFinite();
      if(candidate.finite)
      {
        candidate.statistics = assemble_at(Xc, metric_columns, tensor, step < s.maximum_steps);  // the last: statistics only
        if(!prefilter_error_.empty())
          return fail(report, Fairing_status::SOLVER_FAILED, "after step " + std::to_string(step) + ": " + prefilter_error_, total);
        output_positions(Xc, Y);
        candidate.finite = Y.allFinite();
        if(candidate.finite) count_folds(layer_, Cache::has_second_derivatives, components_.of_face, component_edge_, Xc, candidate);
      }
      assemble_seconds = clock.time();
      std::string why;
      const Step_verdict verdict = judge_step(initial, accepted, input_folds, lowest_H, candidate, why);
      if(verdict == Step_verdict::COLLAPSED)
        return fail(report, Fairing_status::COLLAPSED, "step " + std::to_string(step) + ": " + why +
                    ": mean-curvature flow shrinks closed surfaces to points; use fewer steps or a larger fidelity weight", total);
      if(verdict == Step_verdict::UNSOUND)
      {
        restore_operator();
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

      // the noise level is passed within this step: take it again, shorter, so that it ends there (the
      // displacement grows fastest at first, so the secant undershoots the time and each retry comes closer)
      const double candidate_discrepancy = noise_stop ? s.noise->relative_displacement(Y, X0, {}) : 0.0;
      if(noise_stop && candidate_discrepancy > target * (1 + noise_tolerance) && locating < maximum_locating)
      {
        restore_operator();
        ++locating;
        factor *= std::max(0.05, (target - discrepancy) / (candidate_discrepancy - discrepancy));
        continue;
      }
      locating = 0;

      // accepted; a flow that only crawls on with a sliver of its time step is heading into a fold
      cramped = factor <= 1.0 / 16 ? cramped + 1 : 0;
      rejections = 0;
      X_previous.swap(X);
      X.swap(Xc);
      accepted = candidate;
      if(candidate.folded_edges <= allowed_folds) { X_unfolded = X; unfolded_steps = report.steps.size() + 1; }
      lowest_H.add(candidate.statistics);
      time += st.time_step;
      st.time = time;
      st.area = accepted.statistics.area; st.energy = accepted.statistics.energy; st.H_integral = accepted.statistics.H_integral;
      if(step == s.maximum_steps) st.assemble_seconds += assemble_seconds;   // the final surface's statistics
      const double previous_discrepancy = discrepancy;
      if(noise_stop) discrepancy = candidate_discrepancy;
      st.noise_displacement = discrepancy;
      if(noise_stop && discrepancy >= target)
      {
        // the noise level is reached within this step: end on the surface where it is reached exactly
        const double theta = std::min(1.0, std::max(0.0, (target - previous_discrepancy) / (discrepancy - previous_discrepancy)));
        if(theta < 1)
        {
          X = X_previous + theta * (X - X_previous);
          const Assembly_statistics b = assemble_at(X, metric_columns, tensor, false);
          st.time = time - (1 - theta) * st.time_step;
          st.area = b.area; st.energy = b.energy; st.H_integral = b.H_integral;
          st.max_displacement = 0;
          for(Eigen::Index i = 0; i < n; ++i)
            st.max_displacement = std::max(st.max_displacement, (X.row(i) - X0.row(i)).head(metric_columns).norm());
          output_positions(X, Y);
          st.noise_displacement = s.noise->relative_displacement(Y, X0, {});
        }
        report.stop_reason = Stop_reason::NOISE_LEVEL;
      }
      // the fourth-order flow barely shrinks: once the noise is gone its displacement levels off, maybe short
      // of the noise level, and what still moves is shape: stop when the displacement grows more slowly than
      // a wave of 4 pi h decays, |u'/u| = (2 pi / 4 pi h)^4 = 1 / (16 h^4)
      if(noise_stop && s.order == 4 && report.stop_reason != Stop_reason::NOISE_LEVEL && previous_discrepancy > 0 &&
         (discrepancy - previous_discrepancy) / discrepancy < st.time_step / (16 * std::pow(mean_edge_, 4)))
        report.stop_reason = Stop_reason::NOISE_REMOVED;
      report.noise_displacement = st.noise_displacement;
      report.steps.push_back(st);
      if(s.verbose) print(st);
      if(report.stop_reason == Stop_reason::NOISE_LEVEL || report.stop_reason == Stop_reason::NOISE_REMOVED)
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
      bool stop = monitor.should_stop(step, st.time_step / time_unit, st.H_integral, max_relative_, moved_relative_, report.stop_reason);
      if(!callback(report.steps.back()) && !stop) { report.stop_reason = Stop_reason::CALLBACK; stop = true; }
      if(stop) break;
      factor = std::min(1.0, 2 * factor);
      ++step;
    }
    // the end: never a surface with more folded edges than the input
    Surface_soundness last;
    count_folds(layer_, Cache::has_second_derivatives, components_.of_face, component_edge_, X, last);
    const std::size_t folds = last.folded_edges;
    if(folds > allowed_folds && report.succeeded())
    {
      X = X_unfolded;
      report.steps.resize(unfolded_steps);
      report.stop_reason = Stop_reason::STEP_REJECTED;
      report.message = "the surface folded at " + std::to_string(folds) + " edges (the input at " + std::to_string(allowed_folds) +
                       "); the run ends on the last surface without new folds (step " + std::to_string(unfolded_steps) + ")";
      if(noise_stop) { output_positions(X, Y); report.noise_displacement = s.noise->relative_displacement(Y, X0, {}); }
    }
    report.total_seconds = total.time();
    return report;
  }

  /// Attributes only (Bajaj & Xu's case c): the surface of the first 3 columns of X is fixed, so M
  /// and L are assembled once, the system matrix is constant (factorised once when factorised at all)
  /// and every step is one solve for the other columns. The stopping criteria read the attributes'
  /// Dirichlet energy trace(A^T L A) in place of int |H|^2 (27, 28), and the steady-state speed in units
  /// of the attributes' spread, the root mean square of A_0 - mean(A_0). (29) bounds how far the surface
  /// moves; with the surface fixed it does not apply (noisy values move by about the noise in one step),
  /// nor does the noise criterion, which measures the surface.
  template <typename Tensor, typename Callback>
  Fairing_report run_on_fixed_surface(Control_matrix& X, const Tensor& tensor_in, const Stepper_settings& s, Callback& callback)
  {
    CGAL::Real_timer total;
    total.start();
    Fairing_report report;
    report.vertices = std::size_t(X.rows());
    report.constrained_vertices = std::size_t(X.rows()) - free_.size();
    CGAL::Real_timer clock;
    clock.start();
    Tensor tensor = tensor_in;
    Assembly_statistics a;
    if(!set_units(X, 3, s, tensor, report, a, total)) return report;
    const double assemble_seconds = clock.time();
    const Eigen::Index n = X.rows(), k = X.cols() - 3, nfree = Eigen::Index(free_.size());
    const Control_matrix F0 = X.rightCols(k);
    Control_matrix F = F0;
    report.initial.energy = dirichlet_energy(assembler_.pattern(), L_, F);

    const Stopping_criteria& c = s.stopping;
    const double time_unit = c.relative_units ? std::pow(report.scale, s.order) : 1.0;
    double spread = 0;
    {
      const Eigen::RowVectorXd mean = F0.colwise().mean();
      for(Eigen::Index i = 0; i < n; ++i) spread += (F0.row(i) - mean).squaredNorm();
      spread = n > 0 ? std::sqrt(spread / double(n)) : 0.0;
    }
    const double value_unit = spread > 0 ? spread : 1.0;
    Stopping_criteria criteria = c;
    criteria.displacement = 0;
    Stopping_monitor monitor(criteria, report.initial.energy);

    // the constant system, and its solver: factorised once (up to automatic_cholesky_limit free
    // vertices for AUTOMATIC), or conjugate gradients warm-started from the last step
    const double sys = system_scale(1.0, s.order);
    std::unique_ptr<Fourth_order_system> fourth_order;
    if(s.order == 4)
    {
      fourth_order.reset(new Fourth_order_system(assembler_.pattern(), free_));
      fourth_order->set_operator(M_, L_, {});
      fourth_order->fill_matrix(units_.tau, units_.omega, 1.0, sys, {}, A4_);
    }
    else fill_step_matrix(A_, source_, entry_column_, free_, M_, L_, units_.tau, units_.omega, 1.0, sys, {}, {});
    const bool factorise = s.solver == Linear_solver::CHOLESKY ||
                           (s.solver == Linear_solver::AUTOMATIC && free_.size() <= std::size_t(automatic_cholesky_limit));
    Sparse_cholesky cholesky;
    cholesky.keep_factorisation(true);
    Block_conjugate_gradient cg(s.solver_tolerance, s.solver_maximum_iterations);
    report.used_cholesky = factorise && nfree > 0;
    if(nfree == 0) report.stop_reason = Stop_reason::NO_FREE_VERTEX;

    Control_matrix R(n, k), B(nfree, k), dF = Control_matrix::Zero(nfree, k);
    for(std::size_t step = 1; step <= s.maximum_steps && nfree > 0; ++step)
    {
      Fairing_step st;
      st.step = step;
      st.time_step = report.time_step;
      st.time = double(step) * report.time_step;
      clock.reset();
      if(fourth_order) fourth_order->residual(units_.tau, units_.omega, F, F0, 1.0 / sys, R);
      else step_residual(assembler_.pattern(), M_, L_, units_.tau, units_.omega, F, F0, 1.0 / sys, R);
      for(Eigen::Index i = 0; i < nfree; ++i) B.row(i) = R.row(free_[std::size_t(i)]);
      st.assemble_seconds = (step == 1 ? assemble_seconds : 0.0) + clock.time();
      clock.reset();
      const Eigen::SparseMatrix<double>& A = fourth_order ? A4_ : A_;
      const Solve_statistics sol = factorise ? cholesky.solve(A, B, dF) : cg.solve(A, B, dF);
      st.solve_seconds = clock.time();
      st.direct_solve = factorise;
      st.solver_iterations = sol.iterations;
      st.residual = sol.residual;
      if(!dF.allFinite() || !std::isfinite(sol.residual))
        return fail(report, Fairing_status::NON_FINITE_VALUE, "step " + std::to_string(step) + ": the solution is not finite", total);
      if(!sol.ok) return fail(report, Fairing_status::SOLVER_FAILED, "step " + std::to_string(step) + ": " + sol.message, total);
      const double moved = move_free_rows(F, dF, F0, int(k), st);
      st.area = a.area;
      st.H_integral = a.H_integral;
      st.energy = dirichlet_energy(assembler_.pattern(), L_, F);
      report.steps.push_back(st);
      if(s.verbose) print(st);
      bool stop = monitor.should_stop(step, report.time_step / time_unit, st.energy, st.max_displacement / value_unit,
                                      moved / value_unit, report.stop_reason);
      if(!callback(report.steps.back()) && !stop) { report.stop_reason = Stop_reason::CALLBACK; stop = true; }
      if(stop) break;
    }
    X.rightCols(k) = F;
    report.total_seconds = total.time();
    return report;
  }

private:
  // 1, or what the system of a step with f times the time step is divided by so that a huge time
  // step cannot overflow its norms (the solution does not change)
  double system_scale(double f, int order) const
  {
    double largest = 0;
    const double stiffness = std::pow(mean_edge_, -order);
    for(int i : free_) largest = std::max(largest, f * units_.tau[std::size_t(i)] * (units_.omega[std::size_t(i)] + stiffness));
    return largest > 1e6 ? largest : 1.0;
  }

  // The units of every vertex from the input's area per component, the tensor told its length scale,
  // then M and L(D) at X: false (and a failed report) when the input has no surface.
  template <typename Tensor>
  bool set_units(const Control_matrix& X, int metric_columns, const Stepper_settings& s, Tensor& tensor,
                 Fairing_report& report, Assembly_statistics& a, const CGAL::Real_timer& total)
  {
    const bool scaled_tensor = wants_length_scale(tensor, 0);
    std::vector<double> m, l;
    if(scaled_tensor) a = assembler_.assemble(X, metric_columns, Isotropic_diffusion_tensor(), m, l, false);
    else a = assemble_at(X, metric_columns, tensor, true);
    for(std::size_t c = 0; c < a.component_area.size(); ++c)
      if(!(a.component_area[c] > 0) || !std::isfinite(a.component_area[c]) || !(component_edge_[c] > 0))
      {
        fail(report, Fairing_status::DEGENERATE_METRIC, "the input's limit surface has no area" +
             (components_.count > 1 ? " in connected component " + std::to_string(c) : std::string()) +
             " (sqrt(det G) <= 0 on face " + std::to_string(a.degenerate_face) + "): its control points do not span a surface", total);
        return false;
      }
    const Length_unit tensor_unit = is_automatic_tensor(tensor, 0) ? Length_unit::EDGE : Length_unit::SCALE;
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
    eps_.assign(std::size_t(X.rows()), 0.0);
    if(scaled_tensor)
    {
      // each component's prefilter time as the tensor measures it at that component's scale
      std::vector<double> eps(components_.count);
      for(std::size_t c = 0; c < components_.count; ++c)
      {
        Tensor t = tensor;
        give_length_scale(t, units_.tensor_unit * units_.tensor_scale[c], 0);
        eps[c] = prefilter_time(t, 0);
      }
      for(std::size_t i = 0; i < eps_.size(); ++i)
        if(components_.of_vertex[i] >= 0) eps_[i] = eps[std::size_t(components_.of_vertex[i])];
      assembler_.set_component_scales(&units_.tensor_scale);
      give_length_scale(tensor, units_.tensor_unit, 0);
      report.feature_threshold = std::isfinite(threshold_of(tensor, 0)) ? threshold_of(tensor, 0) : 0.0;
      report.prefilter_time = prefilter_time(tensor, 0);
      a = assemble_at(X, metric_columns, tensor, true);
    }
    else eps_.assign(eps_.size(), prefilter_time(tensor, 0));
    report.initial.area = a.area;
    report.initial.energy = a.energy;
    report.initial.H_integral = a.H_integral;
    if(!prefilter_error_.empty()) { fail(report, Fairing_status::SOLVER_FAILED, prefilter_error_, total); return false; }
    return true;
  }

  // the positions written for X: its Loop limit points, or X itself
  void output_positions(const Control_matrix& X, Control_matrix& Y) const
  {
    if(limit_output_) limit_points(layer_, X, Y);
    else Y = X;
  }

  // the operator of the accepted surface, kept while a candidate step is judged
  void save_operator()
  {
    saved_M_.swap(M_);
    saved_L_.swap(L_);
    saved_prefiltered_X_ = prefiltered_X_;
    saved_prefiltered_valid_ = prefiltered_valid_;
  }
  void restore_operator()
  {
    saved_M_.swap(M_);
    saved_L_.swap(L_);
    prefiltered_X_.swap(saved_prefiltered_X_);
    prefiltered_valid_ = saved_prefiltered_valid_;
  }

  // M and L(D) at X. A tensor with a prefilter time eps > 0 reads its curvature on M_eps (Prefilter_step.h).
  template <typename Tensor>
  Assembly_statistics assemble_at(const Control_matrix& X, int metric_columns, const Tensor& tensor, bool with_matrices)
  {
    bool prefilter = false;
    for(double e : eps_) prefilter = prefilter || e > 0;
    assembler_.set_prefiltered(nullptr);
    prefilter_error_.clear();
    prefiltered_valid_ = false;
    if(prefilter && !free_.empty())
    {
      std::vector<double> Mi, Li;
      assembler_.assemble(X, metric_columns, Isotropic_diffusion_tensor(), Mi, Li);
      if(prefilter_A_.rows() != A_.rows()) prefilter_A_ = A_;
      Control_matrix dX;
      const Solve_statistics sol = prefilter_step(assembler_.pattern(), Mi, Li, eps_, free_, source_, entry_column_, prefilter_A_,
                                                  X, metric_columns, dX);
      if(!sol.ok || !dX.allFinite())
        prefilter_error_ = "the prefiltered surface M_eps could not be computed: " + (sol.ok ? std::string("not finite") : sol.message);
      else
      {
        prefiltered_X_ = X;
        for(Eigen::Index i = 0; i < dX.rows(); ++i) prefiltered_X_.row(free_[std::size_t(i)]).head(metric_columns) += dX.row(i);
        assembler_.set_prefiltered(&prefiltered_X_);
        prefiltered_valid_ = true;
      }
    }
    const Assembly_statistics a = assembler_.assemble(X, metric_columns, tensor, M_, L_, with_matrices);
    assembler_.set_prefiltered(nullptr);
    return a;
  }

  // adds the free rows' displacements to X; records the step's and the total (from X0) largest motion
  // over the first `columns` columns; returns the step's
  // (and the same in the units of the relative stopping thresholds: max_relative_, moved_relative_)
  double move_free_rows(Control_matrix& X, const Control_matrix& dX, const Control_matrix& X0, int columns, Fairing_step& st)
  {
    double moved = 0;
    moved_relative_ = max_relative_ = 0;
    for(Eigen::Index i = 0; i < dX.rows(); ++i)
    {
      const std::size_t row = std::size_t(free_[std::size_t(i)]);
      X.row(Eigen::Index(row)) += dX.row(i);
      const double d = dX.row(i).head(columns).norm();
      moved = std::max(moved, d);
      moved_relative_ = std::max(moved_relative_, d / units_.length[row]);
    }
    st.step_displacement = moved;
    st.max_displacement = 0;
    for(Eigen::Index i = 0; i < X.rows(); ++i)
    {
      const double d = (X.row(i) - X0.row(i)).head(columns).norm();
      st.max_displacement = std::max(st.max_displacement, d);
      max_relative_ = std::max(max_relative_, d / units_.length[std::size_t(i)]);
    }
    return moved;
  }

  Fem_assembler<Cache> assembler_;
  std::vector<int> free_index_, free_;
  std::vector<int> source_;
  Eigen::SparseMatrix<double> A_, A4_;   // the system of a second-, a fourth-order step
  std::vector<double> M_, L_;
  Eigen::SparseMatrix<double> prefilter_A_;
  Control_matrix prefiltered_X_;
  bool prefiltered_valid_ = false;
  std::string prefilter_error_;
  const Tangential_motion_filter* tangential_filter_ = nullptr;
  Control_matrix normal_dX_;
  const Ghost_layer& layer_;
  const Mesh_components& components_;
  const std::vector<double>& component_edge_;
  double mean_edge_;
  std::vector<int> entry_column_;       // the free column of each entry of A_
  Step_units units_;
  std::vector<double> curvature_bound_; // per component (Assembly_statistics::bounded_H_integral)
  std::vector<double> eps_;             // prefilter time per row
  bool limit_output_ = false;
  std::vector<double> saved_M_, saved_L_;
  Control_matrix saved_prefiltered_X_;
  bool saved_prefiltered_valid_ = false;
  double moved_relative_ = 0, max_relative_ = 0;
  double limit_weight_ = 1;
  std::vector<double> unknown_scale_;   // per row, with several components (else empty)
  Control_matrix step_dX_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TIME_STEPPER_H
