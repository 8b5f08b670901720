// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The semi-implicit step ((1 + tau w) M + tau L(D)) X_{n+1} = M (X_n + tau w X_0) of Bajaj & Xu
// (eq. 26 with the fidelity term written consistently, loop-fem.md section 8), repeated until a
// stopping criterion (27)-(29) holds, with the monitoring that makes failure loud. It knows nothing
// of the element: any cache the Fem_assembler accepts will do (Loop patches or P1 faces).
//
// Constrained vertices are eliminated: the unknowns are the displacements of the free vertices,
//   A_FF dX_F = tau (w M (X_0 - X_n) - L X_n)_F,
// so the system stays symmetric positive definite and its right-hand side does not depend on the
// model's position in space.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_TIME_STEPPER_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_TIME_STEPPER_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/internal/Fem_assembly.h>
#include <CGAL/Anisotropic_fairing/internal/Normal_motion.h>
#include <CGAL/Anisotropic_fairing/internal/Spd_solvers.h>

#include <chrono>
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

struct Stepper_settings
{
  double time_step = 1e-3;          // tau, relative or absolute
  bool relative_time_step = true;   // tau = time_step * scale^2
  double fidelity_weight = 0;       // omega, relative (omega = w / scale^2) or absolute
  bool relative_fidelity = true;
  std::size_t maximum_steps = 10;
  Stopping_criteria stopping;
  Linear_solver solver = Linear_solver::AUTOMATIC;
  double solver_tolerance = 1e-8;
  int solver_maximum_iterations = 10000;
  bool verbose = false;
};

/// The stopping criteria (27)-(29) and the steady-state test, fed after every step with the
/// monitored functional (int |H|^2 of the surface, or the Dirichlet energy of attributes on a fixed
/// surface) and the displacements, in the units the criteria are read in.
class Stopping_monitor
{
public:
  Stopping_monitor(const Stopping_criteria& c, double time_step_in_units, double initial_value)
    : c_(c), dt_(time_step_in_units), F0_(initial_value) {}

  /// true (and the reason) when the run should end after this step
  bool should_stop(std::size_t step, double value, double max_displacement, double step_displacement, Stop_reason& reason)
  {
    if(F0_ > 0)
    {
      const double F = value / F0_;
      const double rate = (F - F_prev_) / dt_;
      if(step == 1) rate0_ = rate;
      F_prev_ = F;
      if(step >= 2 && c_.curvature_rate_ratio > 0 && rate0_ != 0 && std::abs(rate / rate0_) <= c_.curvature_rate_ratio)
      { reason = Stop_reason::CURVATURE_RATE_RATIO; return true; }
      if(c_.curvature_rate > 0 && std::abs(rate) <= c_.curvature_rate)
      { reason = Stop_reason::CURVATURE_RATE; return true; }
    }
    if(c_.displacement > 0 && max_displacement >= c_.displacement)
    { reason = Stop_reason::DISPLACEMENT; return true; }
    if(c_.steady_speed > 0 && step_displacement / dt_ <= c_.steady_speed)
    { reason = Stop_reason::STEADY_STATE; return true; }
    return false;
  }

private:
  Stopping_criteria c_;
  double dt_, F0_, F_prev_ = 1.0, rate0_ = 0;
};

/// Milliseconds-resolution wall clock.
class Stopwatch
{
public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
private:
  std::chrono::steady_clock::time_point start_;
};

/// Which solver runs each step. AUTOMATIC starts with conjugate gradients; when a step needs many
/// iterations it times one factorised step and keeps whichever was faster (bench_step_speed: CG wins
/// per step on every mesh tried at tau/h^2 <= 1, the factorisation wins by up to 5x once CG needs
/// hundreds of iterations on a few thousand vertices).
class Solver_choice
{
public:
  Solver_choice(Linear_solver requested, std::size_t free_vertices)
    : automatic_(requested == Linear_solver::AUTOMATIC),
      may_factorise_(requested == Linear_solver::CHOLESKY ||
                     (automatic_ && free_vertices <= std::size_t(automatic_cholesky_limit))),
      mode_(requested == Linear_solver::CHOLESKY ? FACTORISE : ITERATE)
  {}

  bool factorise_now() const { return mode_ != ITERATE; }
  bool may_fall_back() const { return automatic_ && may_factorise_; }
  Sparse_cholesky& cholesky()
  {
    if(!cholesky_) cholesky_.reset(new Sparse_cholesky());
    return *cholesky_;
  }

  void record(bool direct, const Solve_statistics& sol, double seconds)
  {
    if(!automatic_) return;
    if(direct && !sol.ok) { mode_ = ITERATE; tried_ = true; factorised_seconds_ = HUGE_VAL; return; }
    if(direct)
    {
      factorised_seconds_ = seconds - sol.analysis_seconds;   // what every further factorised step costs
      mode_ = (mode_ != TRIAL || factorised_seconds_ < predicted_iterate_seconds_) ? FACTORISE : ITERATE;
      tried_ = true;
      return;
    }
    // CG work often grows from step to step as the surface roughens or pinches: predict the next
    // step's cost from the growth of the iteration count
    const double growth = previous_iterations_ > 0 ? std::max(1.0, double(sol.iterations) / previous_iterations_) : 1.0;
    predicted_iterate_seconds_ = seconds * growth;
    previous_iterations_ = sol.iterations;
    if(!may_factorise_) return;
    if(tried_ && predicted_iterate_seconds_ > factorised_seconds_) mode_ = FACTORISE;
    else if(!tried_ && sol.iterations > automatic_cholesky_trial_iterations) mode_ = TRIAL;
  }

private:
  enum Mode { ITERATE, TRIAL, FACTORISE };
  bool automatic_, may_factorise_;
  Mode mode_;
  bool tried_ = false;
  double predicted_iterate_seconds_ = 0, factorised_seconds_ = HUGE_VAL;
  int previous_iterations_ = 0;
  std::unique_ptr<Sparse_cholesky> cholesky_;
};

template <typename Cache>
class Time_stepper
{
public:
  /// `constrained[i]` holds vertex i fixed.
  Time_stepper(const Cache& cache, std::size_t n, const std::vector<bool>& constrained)
    : assembler_(cache, n), free_index_(n, -1)
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
        if(r >= 0) { inner.push_back(r); source_.push_back(p); }   // rows stay sorted: free_ is increasing
      }
      outer.push_back(int(inner.size()));
    }
    A_ = sparse_matrix_from_pattern(Eigen::Index(free_.size()), Eigen::Index(free_.size()), outer, inner);
  }

  std::size_t number_of_free_vertices() const { return free_.size(); }
  /// Each step's displacement of the surface's columns then loses its tangential part (null: kept).
  void set_tangential_filter(const Tangential_motion_filter* f) { tangential_filter_ = f; }
  Fem_assembler<Cache>& assembler() { return assembler_; }

  /// Runs the flow from X (n x kappa; the first `metric_columns` columns define the surface, the
  /// others are carried along with the same operator). On success X holds the faired control points.
  /// On failure X is unspecified and the report says why.
  template <typename Tensor, typename Callback>
  Fairing_report run(Control_matrix& X, int metric_columns, const Tensor& tensor,
                     const Stepper_settings& s, Callback& callback)
  {
    Stopwatch total;
    Fairing_report report;
    report.vertices = std::size_t(X.rows());
    report.constrained_vertices = std::size_t(X.rows()) - free_.size();
    Block_conjugate_gradient cg(s.solver_tolerance, s.solver_maximum_iterations);
    Solver_choice choice(s.solver, free_.size());

    const Control_matrix X0 = X;
    Stopwatch clock;
    Assembly_statistics a = assemble_at(X, metric_columns, tensor, true);
    if(!prefilter_error_.empty()) return fail(report, Fairing_status::SOLVER_FAILED, prefilter_error_, total);
    double assemble_seconds = clock.seconds();
    report.initial.area = a.area;
    report.initial.energy = a.energy;
    report.initial.H_integral = a.H_integral;
    if(a.degenerate) return fail(report, Fairing_status::DEGENERATE_METRIC, degenerate_message(a, 0), total);

    const double scale = set_units(a.area, s, report), tau = report.time_step, omega = report.fidelity_weight;
    const Stopping_criteria& c = s.stopping;
    const double time_unit = c.relative_units ? scale * scale : 1.0;   // (28) and steady speed per this much time
    const double length_unit = c.relative_units ? scale : 1.0;
    Stopping_monitor monitor(c, tau / time_unit, a.H_integral);

    const Eigen::Index n = X.rows(), k = X.cols(), nfree = Eigen::Index(free_.size());
    Dense_block R(n, k), B(nfree, k), dX = Dense_block::Zero(nfree, k);
    if(nfree == 0) report.stop_reason = Stop_reason::NO_FREE_VERTEX;
    for(std::size_t step = 1; step <= s.maximum_steps && nfree > 0; ++step)
    {
      Fairing_step st;
      st.step = step;
      st.time = double(step) * tau;
      // system and right-hand side at X_n
      clock = Stopwatch();
      double* av = A_.valuePtr();
      for(std::size_t e = 0; e < source_.size(); ++e)
        av[e] = (1 + tau * omega) * M_[std::size_t(source_[e])] + tau * L_[std::size_t(source_[e])];
      residual_rhs(X, X0, tau, omega, R);
      for(Eigen::Index i = 0; i < nfree; ++i) B.row(i) = R.row(free_[std::size_t(i)]);
      st.assemble_seconds = assemble_seconds + clock.seconds();

      clock = Stopwatch();
      Solve_statistics sol;
      st.direct_solve = choice.factorise_now();
      if(st.direct_solve) sol = choice.cholesky().solve(A_, B, dX);
      else
      {
        previous_dX_ = dX;
        sol = cg.solve(A_, B, dX);   // warm start: the previous displacement
        if(!sol.ok && choice.may_fall_back())
        {
          dX = previous_dX_;
          st.direct_solve = true;
          sol = choice.cholesky().solve(A_, B, dX);
        }
      }
      st.solve_seconds = clock.seconds();
      choice.record(st.direct_solve, sol, st.solve_seconds);
      report.used_cholesky = report.used_cholesky || st.direct_solve;
      st.solver_iterations = sol.iterations;
      st.residual = sol.residual;
      if(!sol.ok) return fail(report, Fairing_status::SOLVER_FAILED, "step " + std::to_string(step) + ": " + sol.message, total);
      if(!dX.allFinite())
        return fail(report, Fairing_status::NON_FINITE_VALUE, "step " + std::to_string(step) + ": the solution is not finite", total);

      double moved = 0;
      if(tangential_filter_)
      {
        // dX itself stays the solution: the next step's CG starts from it
        normal_dX_ = dX;
        // the normal of M_eps when the tensor reads its curvature there: on noise, the current
        // surface's normal is mostly noise, and removing motion in its tangent plane would keep the noise
        tangential_filter_->remove(prefiltered_valid_ ? prefiltered_X_ : X, metric_columns, free_, normal_dX_);
        moved = move_free_rows(X, normal_dX_, X0, metric_columns, st);
      }
      else moved = move_free_rows(X, dX, X0, metric_columns, st);

      // the new surface: diagnostics now, and the matrices of the next step
      clock = Stopwatch();
      a = assemble_at(X, metric_columns, tensor, step < s.maximum_steps);  // the last: statistics only
      if(!prefilter_error_.empty())
        return fail(report, Fairing_status::SOLVER_FAILED, "after step " + std::to_string(step) + ": " + prefilter_error_, total);
      assemble_seconds = clock.seconds();
      st.area = a.area; st.energy = a.energy; st.H_integral = a.H_integral;
      if(step == s.maximum_steps) st.assemble_seconds += assemble_seconds;   // the final surface's statistics
      report.steps.push_back(st);
      if(s.verbose) print(st);
      if(a.degenerate) return fail(report, Fairing_status::DEGENERATE_METRIC, degenerate_message(a, step), total);
      if(!std::isfinite(a.area) || !std::isfinite(a.H_integral) || !std::isfinite(a.energy))
        return fail(report, Fairing_status::NON_FINITE_VALUE, "step " + std::to_string(step) + ": the surface's area or curvature is not finite", total);
      if(a.area < 1e-8 * report.initial.area)
        return fail(report, Fairing_status::COLLAPSED, "step " + std::to_string(step) + ": the surface collapsed to a point (area " +
                    ratio_text(a.area / report.initial.area) + " of the initial one): mean-curvature flow shrinks closed surfaces to points; use fewer steps or a larger fidelity weight", total);

      // stopping criteria (27)-(29) and the steady state
      bool stop = monitor.should_stop(step, a.H_integral, st.max_displacement / length_unit, moved / length_unit, report.stop_reason);
      if(!callback(report.steps.back()) && !stop) { report.stop_reason = Stop_reason::CALLBACK; stop = true; }
      if(stop) break;
    }
    report.total_seconds = total.seconds();
    return report;
  }

  /// Attributes only (Bajaj & Xu's case c): the surface of the first 3 columns of X is fixed, so M
  /// and L are assembled once, the system matrix is constant (factorised once when factorised at all)
  /// and every step is one solve for the other columns. The stopping criteria read the attributes'
  /// Dirichlet energy trace(A^T L A) in place of int |H|^2 (27, 28), and the steady-state speed in units
  /// of the attributes' spread, the root mean square of A_0 - mean(A_0). (29) bounds how far the surface
  /// moves; with the surface fixed it does not apply (noisy values move by about the noise in one step).
  template <typename Tensor, typename Callback>
  Fairing_report run_on_fixed_surface(Control_matrix& X, const Tensor& tensor, const Stepper_settings& s, Callback& callback)
  {
    Stopwatch total;
    Fairing_report report;
    report.vertices = std::size_t(X.rows());
    report.constrained_vertices = std::size_t(X.rows()) - free_.size();
    Stopwatch clock;
    const Assembly_statistics a = assemble_at(X, 3, tensor, true);
    if(!prefilter_error_.empty()) return fail(report, Fairing_status::SOLVER_FAILED, prefilter_error_, total);
    const double assemble_seconds = clock.seconds();
    if(a.degenerate) return fail(report, Fairing_status::DEGENERATE_METRIC, degenerate_message(a, 0), total);
    const Eigen::Index n = X.rows(), k = X.cols() - 3, nfree = Eigen::Index(free_.size());
    const Control_matrix F0 = X.rightCols(k);
    Control_matrix F = F0;
    report.initial.area = a.area;
    report.initial.H_integral = a.H_integral;
    report.initial.energy = dirichlet_energy(F);

    const double scale = set_units(a.area, s, report), tau = report.time_step, omega = report.fidelity_weight;
    const Stopping_criteria& c = s.stopping;
    const double time_unit = c.relative_units ? scale * scale : 1.0;
    double spread = 0;
    {
      const Eigen::RowVectorXd mean = F0.colwise().mean();
      for(Eigen::Index i = 0; i < n; ++i) spread += (F0.row(i) - mean).squaredNorm();
      spread = n > 0 ? std::sqrt(spread / double(n)) : 0.0;
    }
    const double value_unit = spread > 0 ? spread : 1.0;
    Stopping_criteria criteria = c;
    criteria.displacement = 0;
    Stopping_monitor monitor(criteria, tau / time_unit, report.initial.energy);

    // the constant system, and its solver: factorised once (up to automatic_cholesky_limit free
    // vertices for AUTOMATIC), or conjugate gradients warm-started from the last step
    double* av = A_.valuePtr();
    for(std::size_t e = 0; e < source_.size(); ++e)
      av[e] = (1 + tau * omega) * M_[std::size_t(source_[e])] + tau * L_[std::size_t(source_[e])];
    const bool factorise = s.solver == Linear_solver::CHOLESKY ||
                           (s.solver == Linear_solver::AUTOMATIC && free_.size() <= std::size_t(automatic_cholesky_limit));
    Sparse_cholesky cholesky;
    cholesky.keep_factorisation(true);
    Block_conjugate_gradient cg(s.solver_tolerance, s.solver_maximum_iterations);
    report.used_cholesky = factorise && nfree > 0;
    if(nfree == 0) report.stop_reason = Stop_reason::NO_FREE_VERTEX;

    Dense_block R(n, k), B(nfree, k), dF = Dense_block::Zero(nfree, k);
    for(std::size_t step = 1; step <= s.maximum_steps && nfree > 0; ++step)
    {
      Fairing_step st;
      st.step = step;
      st.time = double(step) * tau;
      clock = Stopwatch();
      residual_rhs(F, F0, tau, omega, R);
      for(Eigen::Index i = 0; i < nfree; ++i) B.row(i) = R.row(free_[std::size_t(i)]);
      st.assemble_seconds = (step == 1 ? assemble_seconds : 0.0) + clock.seconds();
      clock = Stopwatch();
      const Solve_statistics sol = factorise ? cholesky.solve(A_, B, dF) : cg.solve(A_, B, dF);
      st.solve_seconds = clock.seconds();
      st.direct_solve = factorise;
      st.solver_iterations = sol.iterations;
      st.residual = sol.residual;
      if(!sol.ok) return fail(report, Fairing_status::SOLVER_FAILED, "step " + std::to_string(step) + ": " + sol.message, total);
      if(!dF.allFinite())
        return fail(report, Fairing_status::NON_FINITE_VALUE, "step " + std::to_string(step) + ": the solution is not finite", total);
      const double moved = move_free_rows(F, dF, F0, int(k), st);
      st.area = a.area;
      st.H_integral = a.H_integral;
      st.energy = dirichlet_energy(F);
      report.steps.push_back(st);
      if(s.verbose) print(st);
      bool stop = monitor.should_stop(step, st.energy, st.max_displacement / value_unit, moved / value_unit, report.stop_reason);
      if(!callback(report.steps.back()) && !stop) { report.stop_reason = Stop_reason::CALLBACK; stop = true; }
      if(stop) break;
    }
    X.rightCols(k) = F;
    report.total_seconds = total.seconds();
    return report;
  }

private:
  // R = tau (omega M (X0 - X) - L X), all rows
  void residual_rhs(const Control_matrix& X, const Control_matrix& X0, double tau, double omega, Dense_block& R) const
  {
    const Eigen::SparseMatrix<double>& P = assembler_.pattern();
    const int* outer = P.outerIndexPtr();
    const int* rows = P.innerIndexPtr();
    const Eigen::Index k = X.cols();
    for(Eigen::Index i = 0; i < X.rows(); ++i)
    {
      double* r = R.row(i).data();
      std::fill(r, r + k, 0.0);
      for(int p = outer[i]; p < outer[i + 1]; ++p)
      {
        const Eigen::Index j = rows[p];
        const double l = L_[std::size_t(p)], m = omega * M_[std::size_t(p)];
        for(Eigen::Index col = 0; col < k; ++col) r[col] += m * (X0(j, col) - X(j, col)) - l * X(j, col);
      }
      for(Eigen::Index col = 0; col < k; ++col) r[col] *= tau;
    }
  }

  // M and L(D) at X. A tensor with a prefilter time eps > 0 (Bajaj & Xu's M_eps) first gets the surface
  // after one isotropic implicit step of length eps from X, (M + eps L) X_eps = M X, held vertices
  // fixed, and reads its curvature there (loop-fem.md section 7).
  template <typename Tensor>
  Assembly_statistics assemble_at(const Control_matrix& X, int metric_columns, const Tensor& tensor, bool with_matrices)
  {
    const double eps = prefilter_time(tensor, 0);
    assembler_.set_prefiltered(nullptr);
    prefilter_error_.clear();
    prefiltered_valid_ = false;
    if(eps > 0 && !free_.empty())
    {
      std::vector<double> Mi, Li;
      assembler_.assemble(X, metric_columns, Isotropic_diffusion_tensor(), Mi, Li);
      if(prefilter_A_.rows() != A_.rows()) prefilter_A_ = A_;
      double* av = prefilter_A_.valuePtr();
      for(std::size_t e = 0; e < source_.size(); ++e) av[e] = Mi[std::size_t(source_[e])] + eps * Li[std::size_t(source_[e])];
      const Eigen::SparseMatrix<double>& P = assembler_.pattern();
      const Eigen::Index nfree = Eigen::Index(free_.size());
      Dense_block B(nfree, metric_columns), dX = Dense_block::Zero(nfree, metric_columns);
      for(Eigen::Index i = 0; i < nfree; ++i)
      {
        const int row = free_[std::size_t(i)];
        B.row(i).setZero();
        for(int p = P.outerIndexPtr()[row]; p < P.outerIndexPtr()[row + 1]; ++p)
          B.row(i) -= eps * Li[std::size_t(p)] * X.row(P.innerIndexPtr()[p]).head(metric_columns);
      }
      Block_conjugate_gradient cg(1e-10, 10000);
      const Solve_statistics sol = cg.solve(prefilter_A_, B, dX);
      if(!sol.ok || !dX.allFinite())
        prefilter_error_ = "the prefiltered surface M_eps could not be computed: " + (sol.ok ? std::string("not finite") : sol.message);
      else
      {
        prefiltered_X_ = X;
        for(Eigen::Index i = 0; i < nfree; ++i) prefiltered_X_.row(free_[std::size_t(i)]).head(metric_columns) += dX.row(i);
        assembler_.set_prefiltered(&prefiltered_X_);
        prefiltered_valid_ = true;
      }
    }
    const Assembly_statistics a = assembler_.assemble(X, metric_columns, tensor, M_, L_, with_matrices);
    assembler_.set_prefiltered(nullptr);
    return a;
  }

  template <typename Tensor>
  static auto prefilter_time(const Tensor& t, int) -> decltype(double(t.prefilter_time())) { return double(t.prefilter_time()); }
  template <typename Tensor>
  static double prefilter_time(const Tensor&, long) { return 0.0; }

  // l = sqrt(Area / 4 pi), and tau and omega in model units, into the report; returns l
  static double set_units(double area, const Stepper_settings& s, Fairing_report& report)
  {
    const double scale = std::sqrt(area / (4 * 3.14159265358979323846));
    report.scale = scale;
    report.time_step = s.relative_time_step ? s.time_step * scale * scale : s.time_step;
    report.fidelity_weight = s.relative_fidelity ? s.fidelity_weight / (scale * scale) : s.fidelity_weight;
    return scale;
  }

  // adds the free rows' displacements to X; records the step's and the total (from X0) largest motion
  // over the first `columns` columns; returns the step's
  double move_free_rows(Control_matrix& X, const Dense_block& dX, const Control_matrix& X0, int columns, Fairing_step& st) const
  {
    double moved = 0;
    for(Eigen::Index i = 0; i < dX.rows(); ++i)
    {
      X.row(free_[std::size_t(i)]) += dX.row(i);
      moved = std::max(moved, dX.row(i).head(columns).norm());
    }
    st.step_displacement = moved;
    for(Eigen::Index i = 0; i < X.rows(); ++i)
      st.max_displacement = std::max(st.max_displacement, (X.row(i) - X0.row(i)).head(columns).norm());
    return moved;
  }

  // trace(F^T L F) over all columns of F
  double dirichlet_energy(const Control_matrix& F) const
  {
    const Eigen::SparseMatrix<double>& P = assembler_.pattern();
    double e = 0;
    for(Eigen::Index i = 0; i < P.cols(); ++i)
      for(int p = P.outerIndexPtr()[i]; p < P.outerIndexPtr()[i + 1]; ++p)
        e += L_[std::size_t(p)] * F.row(i).dot(F.row(P.innerIndexPtr()[p]));
    return e;
  }

  static std::string degenerate_message(const Assembly_statistics& a, std::size_t step)
  {
    if(step == 0)
      return "the input's limit surface is degenerate (sqrt(det G) <= 0) on face " + std::to_string(a.degenerate_face) +
             ": its control points do not span a surface there";
    return "after step " + std::to_string(step) + " the surface is degenerate (sqrt(det G) <= 0) on face " +
           std::to_string(a.degenerate_face) + ": it pinched; use a smaller time step or fewer steps";
  }

  static std::string ratio_text(double x)
  {
    char b[32];
    std::snprintf(b, sizeof b, "%.3g", x);
    return b;
  }

  static Fairing_report& fail(Fairing_report& r, Fairing_status status, const std::string& message, const Stopwatch& total)
  {
    r.status = status;
    r.stop_reason = Stop_reason::FAILURE;
    r.message = message;
    r.total_seconds = total.seconds();
    return r;
  }

  static void print(const Fairing_step& st)
  {
    char line[256];
    std::snprintf(line, sizeof line, "step %zu  t=%.4g  area=%.6g  int|H|^2=%.6g  max disp=%.3g  %d its (res %.1e)  %.3fs + %.3fs\n",
                  st.step, st.time, st.area, st.H_integral, st.max_displacement, st.solver_iterations,
                  st.residual, st.assemble_seconds, st.solve_seconds);
    std::cerr << line;
  }

  Fem_assembler<Cache> assembler_;
  std::vector<int> free_index_, free_;
  std::vector<int> source_;
  Eigen::SparseMatrix<double> A_;
  std::vector<double> M_, L_;
  Eigen::SparseMatrix<double> prefilter_A_;
  Control_matrix prefiltered_X_;
  bool prefiltered_valid_ = false;
  std::string prefilter_error_;
  Dense_block previous_dX_;
  const Tangential_motion_filter* tangential_filter_ = nullptr;
  Dense_block normal_dX_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_TIME_STEPPER_H
