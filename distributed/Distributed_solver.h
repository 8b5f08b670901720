// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The linear systems of a run on PETSc: a time step ((1 + t w) M + t L) dX = t (w M (X0 - X) - L X) and the
// prefilter (M + eps L) dX = -eps L X (w = 0), with t, w per row, held rows eliminated (an identity row
// and column with a zero right-hand side: the free block is the library's A_FF). As the library forms them
// (solve/Step_system.h, solve/Fourth_order_system.h): with a local time scale M_ij stands for M_ij s_i s_j,
// and the fourth-order flow's step has Q = L D^-1 L in place of L (D the lumped mass, 0 on held rows), Q
// used through its product (Fourth_order_shell.h), or formed by MatMatMult for a preconditioner that reads the
// matrix's entries or a deviation bound's fidelity (Distributed_fidelity.h). Each column is one
// KSPSolve, warm-started from the last solution. KSPCG with PCJACOBI by default, as the library iterates
// on one machine; PETSc's options (-ksp_type, -pc_type gamg|hypre, ...; the prefilter's with the prefix
// "prefilter_") choose otherwise.

#ifndef AF_DISTRIBUTED_DISTRIBUTED_SOLVER_H
#define AF_DISTRIBUTED_DISTRIBUTED_SOLVER_H

#include "Distributed_fidelity.h"
#include "Distributed_layout.h"
#include "Fourth_order_shell.h"
#include "Face_partition.h"
#include "Whole_rows.h"

#include <petscksp.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace af_distributed {

struct Distributed_solve
{
  bool ok = true;
  int iterations = 0;     // over the columns
  std::string message;    // why not ok
};

class Distributed_solver
{
public:
  /// `held`: per real vertex of the run; `prefix`: of PETSc's options for this solver.
  Distributed_solver(MPI_Comm comm, const Distributed_layout& d, const std::vector<bool>& held, const char* prefix,
                     double tolerance, int maximum_iterations)
    : d_(d), comm_(comm)
  {
    for(int v : d.owned_vertices)
      if(held[std::size_t(v)]) held_rows_.push_back(d.petsc_row[std::size_t(v)]);
    for(int v : d.owned_vertices) held_.push_back(held[std::size_t(v)]);
    petsc_check(KSPCreate(comm, &ksp_), "KSPCreate");
    petsc_check(KSPSetOptionsPrefix(ksp_, prefix), "KSPSetOptionsPrefix");
    petsc_check(KSPSetType(ksp_, KSPCG), "KSPSetType");
    PC pc;
    petsc_check(KSPGetPC(ksp_, &pc), "KSPGetPC");
    petsc_check(PCSetType(pc, PCJACOBI), "PCSetType");
    // the library's criterion: the residual relative to the right-hand side, unpreconditioned
    petsc_check(KSPSetNormType(ksp_, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
    petsc_check(KSPSetTolerances(ksp_, tolerance, 1e-300, PETSC_DEFAULT, maximum_iterations), "KSPSetTolerances");
    petsc_check(KSPSetInitialGuessNonzero(ksp_, PETSC_TRUE), "KSPSetInitialGuessNonzero");
    petsc_check(KSPSetFromOptions(ksp_), "KSPSetFromOptions");
    PCType type = nullptr;
    petsc_check(PCGetType(pc, &type), "PCGetType");
    by_product_ = type && (std::strcmp(type, PCJACOBI) == 0 || std::strcmp(type, PCNONE) == 0);
  }
  ~Distributed_solver()
  {
    KSPDestroy(&ksp_);
    for(Mat* m : { &A_, &Mw_, &Q_ }) MatDestroy(m);
    for(Vec* v : { &x_, &b_, &u_, &mu_, &lx_, &a_, &t_, &s_, &dinv_, &qx_ }) VecDestroy(v);
  }

  /// The local time scale's weights s per real vertex (empty: none), and whether the steps are the
  /// fourth-order flow's: for the solves from now on.
  void set_step_kind(std::vector<double> mass_weight, bool fourth_order)
  {
    mass_weight_ = std::move(mass_weight);
    fourth_order_ = fourth_order;
  }
  /// A deviation bound's fidelity of each vertex's own, at `anchor` (null: none); `held`: per real vertex.
  void set_fidelity(const CGAL::Anisotropic_fairing::internal::Output_fidelity* fidelity, const Control_matrix* anchor,
                    const std::vector<bool>& held)
  {
    fidelity_.reset(fidelity ? new Distributed_fidelity(*fidelity, *anchor, d_, held) : nullptr);
  }
  Distributed_solver(const Distributed_solver&) = delete;
  Distributed_solver& operator=(const Distributed_solver&) = delete;

  /// Solves for the owned rows' displacement dX (owned rows x `columns`, in the order of the owned vertices;
  /// its value on entry is the first guess) from the first `columns` columns of X and X0. t, w and the
  /// fidelity's mu (empty: none): per real vertex.
  Distributed_solve solve(Mat M, Mat L, const std::vector<double>& t, const std::vector<double>& w,
                          const Control_matrix& X, const Control_matrix& X0, int columns, Control_matrix& dX,
                          const std::vector<double>& mu = std::vector<double>())
  {
    form(M, L, t, w);
    if(shell_) petsc_check(KSPSetOperators(ksp_, shell_->matrix(), shell_->matrix()), "KSPSetOperators");
    else
    {
      if(fidelity_) fidelity_->add_to_matrix(A_, Mw_, u_, mu, t);
      petsc_check(MatZeroRowsColumns(A_, PetscInt(held_rows_.size()), held_rows_.data(), 1.0, nullptr, nullptr),
                  "MatZeroRowsColumns");
      petsc_check(KSPSetOperators(ksp_, A_, A_), "KSPSetOperators");
    }
    if(dX.rows() != Eigen::Index(d_.owned_vertices.size()) || dX.cols() != columns)
      dX = Control_matrix::Zero(Eigen::Index(d_.owned_vertices.size()), columns);
    Distributed_solve result;
    for(int c = 0; c < columns && result.ok; ++c)
    {
      right_hand_side(M, L, t, w, X, X0, c);
      set_owned(x_, [&](std::size_t k) { return held_[k] ? 0.0 : dX(Eigen::Index(k), c); });
      petsc_check(KSPSolve(ksp_, b_, x_), "KSPSolve");
      KSPConvergedReason reason;
      PetscInt its = 0;
      petsc_check(KSPGetConvergedReason(ksp_, &reason), "KSPGetConvergedReason");
      petsc_check(KSPGetIterationNumber(ksp_, &its), "KSPGetIterationNumber");
      result.iterations += int(its);
      if(reason < 0)
      {
        result.ok = false;
        result.message = std::string("the iterations (KSP ") + KSPConvergedReasons[reason] + ") did not converge in " +
                         std::to_string(int(its)) + " iterations on column " + std::to_string(c);
      }
      const PetscScalar* x = nullptr;
      petsc_check(VecGetArrayRead(x_, &x), "VecGetArrayRead");
      for(std::size_t k = 0; k < d_.owned_vertices.size(); ++k) dX(Eigen::Index(k), c) = x[k];
      petsc_check(VecRestoreArrayRead(x_, &x), "VecRestoreArrayRead");
    }
    // the next solve has another matrix: its operator and preconditioner (a multigrid hierarchy) are freed now
    petsc_check(KSPReset(ksp_), "KSPReset");
    shell_.reset();
    for(Mat* m : { &A_, &Mw_, &Q_ }) MatDestroy(m);
    return result;
  }

  /// The sum over the columns c of X_c^T L X_c (X's owned rows), every process's: the Dirichlet energy.
  double quadratic_form(Mat L, const Control_matrix& X)
  {
    make_vectors(L);
    double sum = 0;
    for(Eigen::Index c = 0; c < X.cols(); ++c)
    {
      set_owned(x_, [&](std::size_t k) { return X(d_.owned_vertices[k], c); });
      petsc_check(MatMult(L, x_, lx_), "MatMult");
      PetscScalar value = 0;
      petsc_check(VecDot(x_, lx_, &value), "VecDot");
      sum += double(value);
    }
    return sum;
  }

private:
  void make_vectors(Mat A)
  {
    if(x_) return;
    petsc_check(MatCreateVecs(A, &x_, &b_), "MatCreateVecs");
    for(Vec* v : { &u_, &mu_, &lx_, &a_, &t_, &s_, &dinv_, &qx_ }) petsc_check(VecDuplicate(b_, v), "VecDuplicate");
  }

  template <typename F>
  void set_owned(Vec v, const F& value)
  {
    PetscScalar* a = nullptr;
    petsc_check(VecGetArray(v, &a), "VecGetArray");
    for(std::size_t k = 0; k < d_.owned_vertices.size(); ++k) a[k] = value(k);
    petsc_check(VecRestoreArray(v, &a), "VecRestoreArray");
  }

  // A = diag(1 + t w) M + diag(t) L (or Q), the held rows and columns replaced by the identity's
  void form(Mat M, Mat L, const std::vector<double>& t, const std::vector<double>& w)
  {
    make_vectors(M);
    const std::vector<int>& own = d_.owned_vertices;
    set_owned(a_, [&](std::size_t k) { return 1 + t[std::size_t(own[k])] * w[std::size_t(own[k])]; });
    set_owned(t_, [&](std::size_t k) { return t[std::size_t(own[k])]; });
    for(Mat* m : { &A_, &Mw_, &Q_ }) MatDestroy(m);
    petsc_check(MatDuplicate(M, MAT_COPY_VALUES, &Mw_), "MatDuplicate");
    if(!mass_weight_.empty())
    {
      set_owned(s_, [&](std::size_t k) { return mass_weight_[std::size_t(own[k])]; });
      petsc_check(MatDiagonalScale(Mw_, s_, s_), "MatDiagonalScale");
    }
    if(fourth_order_)
    {
      lumped_inverse();
      // through its product where the preconditioner needs no entries and no fidelity adds to them
      if(!fidelity_ && by_product_)
      {
        shell_.reset(new Fourth_order_shell(comm_, d_, held_, Mw_, L, a_, t_, dinv_));
        return;
      }
      form_q(L);
    }
    Mat T;
    petsc_check(MatDuplicate(fourth_order_ ? Q_ : L, MAT_COPY_VALUES, &T), "MatDuplicate");
    petsc_check(MatDiagonalScale(T, t_, nullptr), "MatDiagonalScale");
    petsc_check(MatDuplicate(Mw_, MAT_COPY_VALUES, &A_), "MatDuplicate");
    petsc_check(MatDiagonalScale(A_, a_, nullptr), "MatDiagonalScale");
    // Q couples the 6-ring, M the 3-ring: A takes Q's pattern
    petsc_check(MatAXPY(T, 1.0, A_, fourth_order_ ? DIFFERENT_NONZERO_PATTERN : SAME_NONZERO_PATTERN), "MatAXPY");
    MatDestroy(&A_);
    A_ = T;
  }

  // D^-1, D the lumped mass (row sums of M with the time scale), 0 on held rows and D at least 1e-12 of the
  // largest (Fourth_order_system::set_operator)
  void lumped_inverse()
  {
    petsc_check(MatGetRowSum(Mw_, dinv_), "MatGetRowSum");
    PetscReal largest = 0;
    petsc_check(VecMax(dinv_, nullptr, &largest), "VecMax");
    PetscScalar* d = nullptr;
    petsc_check(VecGetArray(dinv_, &d), "VecGetArray");
    for(std::size_t k = 0; k < d_.owned_vertices.size(); ++k)
      d[k] = held_[k] ? 0.0 : 1 / std::max(double(d[k]), 1e-12 * double(largest));
    petsc_check(VecRestoreArray(dinv_, &d), "VecRestoreArray");
  }

  // Q = L D^-1 L, formed
  void form_q(Mat L)
  {
    Mat DL;
    petsc_check(MatDuplicate(L, MAT_COPY_VALUES, &DL), "MatDuplicate");
    petsc_check(MatDiagonalScale(DL, dinv_, nullptr), "MatDiagonalScale");
    petsc_check(MatMatMult(L, DL, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &Q_), "MatMatMult");
    MatDestroy(&DL);
  }

  // b = t (w M (X0 - X) - L X) (L X: Q X = L (D^-1 (L X)) for the fourth order) in column c; zero on held rows
  void right_hand_side(Mat, Mat L, const std::vector<double>& t, const std::vector<double>& w,
                       const Control_matrix& X, const Control_matrix& X0, int c)
  {
    const std::vector<int>& own = d_.owned_vertices;
    set_owned(u_, [&](std::size_t k) { return X0(own[k], c) - X(own[k], c); });
    set_owned(x_, [&](std::size_t k) { return X(own[k], c); });
    petsc_check(MatMult(Mw_, u_, mu_), "MatMult");
    petsc_check(MatMult(L, x_, lx_), "MatMult");
    if(fourth_order_)
    {
      petsc_check(VecPointwiseMult(qx_, dinv_, lx_), "VecPointwiseMult");
      petsc_check(MatMult(L, qx_, lx_), "MatMult");
    }
    const PetscScalar *mu = nullptr, *lx = nullptr;
    petsc_check(VecGetArrayRead(mu_, &mu), "VecGetArrayRead");
    petsc_check(VecGetArrayRead(lx_, &lx), "VecGetArrayRead");
    set_owned(b_, [&](std::size_t k) {
      const std::size_t v = std::size_t(own[k]);
      return held_[k] ? 0.0 : t[v] * (w[v] * mu[k] - lx[k]);
    });
    petsc_check(VecRestoreArrayRead(mu_, &mu), "VecRestoreArrayRead");
    petsc_check(VecRestoreArrayRead(lx_, &lx), "VecRestoreArrayRead");
    if(fidelity_) fidelity_->add_to_right_hand_side(b_, X, t, c);
  }

  const Distributed_layout& d_;
  std::vector<PetscInt> held_rows_;
  std::vector<bool> held_;   // per owned vertex
  std::vector<double> mass_weight_;
  bool fourth_order_ = false;
  std::unique_ptr<Distributed_fidelity> fidelity_;
  std::unique_ptr<Fourth_order_shell> shell_;
  bool by_product_ = false;   // the preconditioner reads only the diagonal (Jacobi, none)
  MPI_Comm comm_;
  KSP ksp_ = nullptr;
  Mat A_ = nullptr, Mw_ = nullptr, Q_ = nullptr;   // the system; M with the time scale; Q (fourth order)
  Vec x_ = nullptr, b_ = nullptr, u_ = nullptr, mu_ = nullptr, lx_ = nullptr, a_ = nullptr, t_ = nullptr,
      s_ = nullptr, dinv_ = nullptr, qx_ = nullptr;
};

} // namespace af_distributed

#endif // AF_DISTRIBUTED_DISTRIBUTED_SOLVER_H
