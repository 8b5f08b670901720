// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One semi-implicit step: its system over the free vertices, of the second-order flow (Step_system.h) or
// the fourth-order one (Fourth_order_system.h), and its solution by the chosen solver (Solver_choice.h).
// With several components the unknowns are scaled per component so that the solver's tolerance means the
// same on each; the displacement returned is in model units. On a fixed surface the matrix is constant:
// formed once, and factorised once when factorised at all (again when a vertex's own fidelity is raised).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STEP_SOLVER_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STEP_SOLVER_H

#include <CGAL/Anisotropic_fairing/internal/flow/Output_fidelity.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_units.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Fourth_order_system.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Free_block.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Solver_choice.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Spd_solvers.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Step_system.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Real_timer.h>

#include <cmath>
#include <memory>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

class Step_solver
{
public:
  /// `columns`: of the unknowns; `constant_matrix`: every step has the same system (a fixed surface).
  /// `fidelity`: what a vertex's own fidelity holds (null: no bound), at `anchor` (the input's written positions).
  Step_solver(const Sparse_structure& pattern, const Free_block& block, const Stepper_settings& s, Eigen::Index columns,
              bool constant_matrix, const Output_fidelity* fidelity = nullptr, const Control_matrix* anchor = nullptr)
    : pattern_(pattern), block_(block), fidelity_(fidelity), anchor_(anchor),
      cg_(s.solver_tolerance, s.solver_maximum_iterations),
      choice_(s.solver, block.size(), constant_matrix, s.direct_solver, s.factor_budget), constant_(constant_matrix),
      dX_(Control_matrix::Zero(Eigen::Index(block.size()), columns))
  {
    if(s.order == 4) fourth_order_.reset(new Fourth_order_system(pattern, block.free));
  }

  /// Forms the step of `factor` times the time step at (M, L), from X (X0: the input, for the fidelity
  /// term), the system divided by `sys`, and its right-hand side; solve() solves it. X and X0 are not read
  /// after this: the caller may free them first. `mass_weight`: the local time scale; `unknown_scale`: per
  /// row with several components; either empty: none. `mu`: each vertex's own fidelity (Deviation_bound.h;
  /// empty: none). M, L and mass_weight must stay unchanged until solve() returns.
  void prepare(const Value_array& M, const Value_array& L, const Step_units& u, const std::vector<double>& mass_weight,
               const std::vector<double>& unknown_scale, double factor, double sys, const Control_matrix& X,
               const Control_matrix& X0, const std::vector<double>& mu)
  {
    const bool held_changed = mu != formed_mu_;
    const bool form = !(constant_ && formed_) || held_changed;
    if(constant_ && formed_ && held_changed) choice_.matrix_changed();
    formed_mu_ = mu;
    // a vertex's own fidelity on what is written (Output_fidelity.h): its part of the matrix, E
    const bool held = fidelity_ && !mu.empty();
    if(held && form)   // (otherwise M and mu are those of the last solve, and so is held_)
    {
      held_mass(M, mass_weight, mu);
      std::vector<double> coefficient(mu.size());
      for(std::size_t j = 0; j < mu.size(); ++j)
      {
        const double scale = unknown_scale.empty() ? 1.0 : unknown_scale[j];
        coefficient[j] = factor * u.tau[j] / (sys * scale * scale);
      }
      extra_ = fidelity_->matrix(held_, block_.free_index, coefficient, Eigen::Index(block_.size()));
    }
    if(fourth_order_)
    {
      if(form)
      {
        fourth_order_->set_operator(M, L, mass_weight);
        fourth_order_->set_coefficients(u.tau, u.omega, factor, sys, unknown_scale);
        fourth_order_->set_extra(held ? &extra_ : nullptr);
      }
      fourth_order_->residual(u.tau, u.omega, X, X0, factor / sys, R_);
    }
    else
    {
      if(form)
      {
        fill_step_matrix(A_, block_, M, L, u.tau, u.omega, factor, sys, unknown_scale, mass_weight);
        if(held)
          for(Eigen::Index k = 0; k < extra_.outerSize(); ++k)
            for(Eigen::SparseMatrix<double>::InnerIterator it(extra_, k); it; ++it) // a 1-ring's pairs: in the pattern
              A_[std::size_t(block_.structure().find(it.row(), it.col()))] += it.value();
      }
      R_.resize(X.rows(), X.cols());
      step_residual(pattern_, M, L, u.tau, u.omega, X, X0, factor / sys, R_, mass_weight);
    }
    if(held)
    {
      std::vector<double> residual_factor(mu.size());
      for(std::size_t j = 0; j < mu.size(); ++j) residual_factor[j] = factor / sys * u.tau[j];
      fidelity_->add_to_residual(held_, X, *anchor_, residual_factor, R_);
    }
    formed_ = true;
    // the right-hand side: the free rows of R (R itself when no row is held)
    Control_matrix& B = block_.whole() ? R_ : B_;
    if(!block_.whole()) block_.gather(R_, B_);
    if(!unknown_scale.empty())
      for(Eigen::Index i = 0; i < B.rows(); ++i)
        B.row(i) /= std::pow(unknown_scale[std::size_t(block_.free[std::size_t(i)])], 3);
    choice_.set_step_factor(factor);
    unknown_scale_ = &unknown_scale;
  }

  /// Solves the step prepare() formed; `direct`: whether it was factorised.
  Solve_statistics solve(bool& direct)
  {
    Control_matrix& B = block_.whole() ? R_ : B_;
    CGAL::Real_timer clock;
    clock.start();
    // CG warm-started from the last dX
    Fourth_order_system* q = fourth_order_.get();
    const Solve_statistics sol = !q ? choice_.solve(block_.structure(), A_, B, dX_, cg_, direct)
      : choice_.solve([q](const Control_matrix& P, Control_matrix& AP) { q->product(P, AP); }, q->diagonal(),
                      [q]() -> const Eigen::SparseMatrix<double>& { return q->matrix(); }, B, dX_, cg_, direct,
                      3.0 * double(pattern_.nonZeros()));   // M, L and L again
    solve_seconds_ = clock.time();
    choice_.record(direct, sol, solve_seconds_);
    // on a surface that moves the system is formed anew at every solve: not kept while the next is assembled
    if(!constant_)
    {
      Value_array().swap(A_);
      if(q) q->release();
    }
    // nor its right-hand side, nor the solver's work (made anew for the next)
    R_.resize(0, 0);
    B_.resize(0, 0);
    cg_.release();
    const std::vector<double>& unknown_scale = *unknown_scale_;
    scaled_ = !unknown_scale.empty();
    if(scaled_)
    {
      model_dX_ = dX_;
      for(Eigen::Index i = 0; i < dX_.rows(); ++i)
        model_dX_.row(i) *= unknown_scale[std::size_t(block_.free[std::size_t(i)])];
    }
    return sol;
  }

  /// The free rows' displacement of the last solve, in model units
  const Control_matrix& displacement() const { return scaled_ ? model_dX_ : dX_; }
  /// of the last solve alone (without forming the system)
  double solve_seconds() const { return solve_seconds_; }

private:
  // held_i = mu_i D_i, D_i = sum_j M_ij (with the local time scale's weights): a vertex's fidelity on its
  // lumped mass
  void held_mass(const Value_array& M, const std::vector<double>& mass_weight, const std::vector<double>& mu)
  {
    const Eigen::VectorXd D = lumped_mass(pattern_, M, mass_weight);
    held_.resize(mu.size());
    for(std::size_t i = 0; i < mu.size(); ++i) held_[i] = mu[i] * D[Eigen::Index(i)];
  }

  const Sparse_structure& pattern_;
  const Free_block& block_;
  const Output_fidelity* fidelity_;
  const Control_matrix* anchor_;
  Value_array A_;   // the system of a second-order step: values over block_.structure()
  Eigen::SparseMatrix<double> extra_;
  std::unique_ptr<Fourth_order_system> fourth_order_;
  Block_conjugate_gradient cg_;
  Solver_choice choice_;
  bool constant_, formed_ = false, scaled_ = false;
  double solve_seconds_ = 0;
  Control_matrix R_, B_, dX_, model_dX_;
  const std::vector<double>* unknown_scale_ = nullptr;   // prepare()'s, read by solve()
  std::vector<double> formed_mu_, held_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STEP_SOLVER_H
