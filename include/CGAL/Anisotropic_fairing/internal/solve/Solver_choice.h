// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Which linear solver runs each time step when the user leaves the choice to the package.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_SOLVER_CHOICE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_SOLVER_CHOICE_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Spd_solvers.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// Which solver runs each step. AUTOMATIC starts with conjugate gradients; when a step needs many
/// iterations it factorises one step and keeps whichever costs less: CG wins at small steps, the
/// factorisation once CG needs hundreds of iterations (the manual's Validation page, bench_step_speed).
/// The costs are counted operations, not times (the package's factorisation counts its own), so that the
/// choice, and the result, are the same on every machine and at any number of threads; a user's direct
/// solver, which cannot count, is timed.
class Solver_choice
{
public:
  /// `constant_matrix`: every solve has the same matrix (a fixed surface): AUTOMATIC factorises it once
  /// when it may, else iterates, without timing trials.
  /// `direct`: makes the factorising solver (empty: Sparse_cholesky). `factor_budget`: bytes a factorisation
  /// may take; AUTOMATIC iterates where the factor (factor_memory()) would need more.
  Solver_choice(Linear_solver requested, std::size_t free_vertices, bool constant_matrix = false,
                Direct_solver_factory direct = Direct_solver_factory(),
                double factor_budget = std::numeric_limits<double>::infinity())
    : automatic_(requested == Linear_solver::AUTOMATIC && !constant_matrix),
      may_factorise_(requested == Linear_solver::CHOLESKY ||
                     (requested == Linear_solver::AUTOMATIC && free_vertices <= std::size_t(automatic_cholesky_limit) &&
                      factor_memory(free_vertices) <= factor_budget)),
      mode_(requested == Linear_solver::CHOLESKY || (constant_matrix && may_factorise_) ? FACTORISE : ITERATE),
      constant_(constant_matrix), counted_(!direct), make_direct_(std::move(direct))
  {}

  /// The bytes a factorisation of a system of `n` rows takes (its factor, and the matrix formed for it): its
  /// fill under the minimum-degree ordering grows as n^1.2 (Eigen's SimplicialLDLT on the 3-ring patterns of
  /// Loop-refined meshes of 18,000 and 72,000 vertices: 64 and 327 MB above an iterated step; bench/memory_estimate.py)
  static double factor_memory(std::size_t n) { return 475.0 * std::pow(double(n), 1.2); }

  bool factorise_now() const { return mode_ != ITERATE; }
  /// The next solve is of a step of `f` times the time step. One shorter than a step whose iterations
  /// gave way is iterated again: its mass matrix weighs more (a step retried after a rejection), and
  /// iterations that stall give way after a hundred or so (Block_conjugate_gradient's rate test).
  void set_step_factor(double f)
  {
    if(automatic_ && mode_ == FACTORISE && f < gave_way_factor_) { mode_ = ITERATE; failures_in_a_row_ = 0; }
    factor_ = f;
  }
  /// A constant matrix changed (a vertex's fidelity was raised): a kept factorisation is redone.
  void matrix_changed() { if(direct_) direct_->matrix_changed(); }
  bool may_fall_back() const { return automatic_ && may_factorise_; }
  Direct_solver& direct_solver()
  {
    if(!direct_)
    {
      direct_ = make_direct_solver(make_direct_);
      direct_->keep_factorisation(constant_);
    }
    return *direct_;
  }

  /// Solves A X = B the chosen way (X holds the initial guess of conjugate gradients), A given by its
  /// structure and values; a conjugate-gradient solve that fails is retried by the factorisation when
  /// allowed. `direct`: how it was solved.
  Solve_statistics solve(const Sparse_structure& S, const Value_array& values, const Control_matrix& B,
                         Control_matrix& X,
                         Block_conjugate_gradient& cg, bool& direct)
  {
    Eigen::VectorXd diagonal;
    if(!factorise_now()) diagonal = S.diagonal(values.data());
    Eigen::SparseMatrix<double> formed;   // a copy for the factorisation only, gone after the solve
    return solve([&](const Control_matrix& P, Control_matrix& AP) { symmetric_product(S, values, P, AP); }, diagonal,
                 [&]() -> const Eigen::SparseMatrix<double>& { formed = S.matrix(values); return formed; }, B, X, cg,
                 direct, double(S.nonZeros()));
  }

  /// The same for a matrix that conjugate gradients use through its product (`product(P, AP)`: AP = A P)
  /// and diagonal, and that `matrix()` forms only when it is to be factorised; `product_entries`: the sparse
  /// entries one product with A reads (what an iteration's work is counted by).
  template <typename Product, typename Matrix>
  Solve_statistics solve(const Product& product, const Eigen::VectorXd& diagonal, const Matrix& matrix,
                         const Control_matrix& B, Control_matrix& X, Block_conjugate_gradient& cg, bool& direct,
                         double product_entries)
  {
    direct = factorise_now();
    failed_iterate_work_ = 0;
    iteration_work_ = double(B.cols()) * (2.0 * product_entries + 12.0 * double(B.rows()));
    columns_ = B.cols();
    if(direct) return direct_solver().solve(matrix(), B, X);
    if(may_fall_back()) start_ = X;   // the factorisation's start, should the iterations give way
    CGAL::Real_timer clock;
    clock.start();
    Solve_statistics sol = cg.solve(product, diagonal, B, X, may_fall_back() ? fall_back_iterations() : 0);
    if(!sol.ok && may_fall_back())
    {
      failed_iterate_work_ = counted_ ? sol.iterations * iteration_work_ : clock.time();
      gave_way_factor_ = factor_;
      if(sol.iterations > 0) work_per_iteration_ = failed_iterate_work_ / sol.iterations;
      X = start_;
      direct = true;
      sol = direct_solver().solve(matrix(), B, X);
    }
    return sol;
  }

  /// Iterations after which conjugate gradients give way to the factorisation: as many as cost what one
  /// factorised step costs, once both were timed; before that ten times the trial threshold (a step
  /// that needs more is factorised faster). Where a limit surface is
  /// nearly singular (quantised scans) the iterations stall, and would otherwise run to the user's maximum.
  int fall_back_iterations() const
  {
    if(!(work_per_iteration_ > 0) || !std::isfinite(factorised_work_))
      return 10 * automatic_cholesky_trial_iterations;
    const double worth = factorised_work_ / work_per_iteration_;
    return int(std::min(1e9, std::max(double(automatic_cholesky_trial_iterations), worth)));
  }

  /// After each solve: how it went, and its time (which decides only for a user's direct solver).
  void record(bool direct, const Solve_statistics& sol, double seconds)
  {
    if(!automatic_) return;
    if(direct && !sol.ok) { mode_ = ITERATE; tried_ = true; factorised_work_ = HUGE_VAL; return; }
    if(direct)
    {
      // what every further factorised step costs (without the iterations that gave way to it)
      const double counted = factorisation_weight * direct_solver().operations(columns_);
      factorised_work_ = counted_ && std::isfinite(counted) ? counted
                                                            : seconds - sol.analysis_seconds - failed_iterate_work_;
      tried_ = true;
      if(failed_iterate_work_ > 0)
      {
        // the iterations gave way on this matrix: the next one is iterated again (the roughest surface,
        // the input, is often the only one they fail on), unless they gave way on the last one too
        mode_ = ++failures_in_a_row_ >= 2 ? FACTORISE : ITERATE;
        return;
      }
      mode_ = (mode_ != TRIAL || factorised_work_ < predicted_iterate_work_) ? FACTORISE : ITERATE;
      return;
    }
    failures_in_a_row_ = 0;
    const double work = counted_ ? sol.iterations * iteration_work_ : seconds;
    // CG work often grows from step to step as the surface roughens or pinches: predict the next
    // step's cost from the growth of the iteration count
    const double growth = previous_iterations_ > 0 ? std::max(1.0, double(sol.iterations) / previous_iterations_) : 1.0;
    predicted_iterate_work_ = work * growth;
    previous_iterations_ = sol.iterations;
    if(sol.iterations > 0) work_per_iteration_ = work / sol.iterations;
    if(!may_factorise_) return;
    if(tried_ && predicted_iterate_work_ > factorised_work_) mode_ = FACTORISE;
    else if(!tried_ && sol.iterations > automatic_cholesky_trial_iterations) mode_ = TRIAL;
  }

private:
  enum Mode { ITERATE, TRIAL, FACTORISE };
  /// an operation of the factorisation against one of the iterations: the factorisation's are serial and
  /// scattered, the iterations' stream through memory on every core. Measured on the development machine
  /// (2 cores; 102 factorisations, 86 CG solves of the default runs of Fandisk0.3, a camel head, the 8-bit
  /// face scan and Bunny0.2): 2.45e-10 s per counted operation of the factorisation whatever the mesh, 0.7 to
  /// 1.3e-10 s per operation of the iterations, 2.7 times less in the median, 3.0-3.4 from 26,000 vertices
  static constexpr double factorisation_weight = 3.0;
  bool automatic_, may_factorise_;
  Mode mode_;
  bool constant_;
  bool tried_ = false;
  double factor_ = 1, gave_way_factor_ = 0;   // of the step solved, and of the last whose iterations gave way
  // costs: counted operations (counted_), or seconds for a user's direct solver
  bool counted_;
  double predicted_iterate_work_ = 0, factorised_work_ = HUGE_VAL, work_per_iteration_ = 0, failed_iterate_work_ = 0;
  double iteration_work_ = 0;   // of one iteration of the solve under way, counted
  Eigen::Index columns_ = 1;
  int previous_iterations_ = 0, failures_in_a_row_ = 0;
  Direct_solver_factory make_direct_;
  std::unique_ptr<Direct_solver> direct_;
  Control_matrix start_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_SOLVER_CHOICE_H
