// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The linear systems of a run on PETSc: a time step ((1 + t w) M + t L) dX = t (w M (X0 - X) - L X) and the
// prefilter (M + eps L) dX = -eps L X (w = 0), with t, w per row, held rows eliminated (an identity row
// and column with a zero right-hand side: the free block is the library's A_FF). Each column is one
// KSPSolve, warm-started from the last solution. KSPCG with PCJACOBI by default, as the library iterates
// on one machine; PETSc's options (-ksp_type, -pc_type gamg|hypre, ...; the prefilter's with the prefix
// "prefilter_") choose otherwise.

#ifndef AF_DISTRIBUTED_DISTRIBUTED_SOLVER_H
#define AF_DISTRIBUTED_DISTRIBUTED_SOLVER_H

#include "Distributed_layout.h"
#include "Face_partition.h"
#include "Ghosted_rows.h"

#include <petscksp.h>

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
    : d_(d)
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
  }
  ~Distributed_solver()
  {
    KSPDestroy(&ksp_);
    MatDestroy(&A_);
    for(Vec* v : { &x_, &b_, &u_, &mu_, &lx_, &a_, &t_ }) VecDestroy(v);
  }
  Distributed_solver(const Distributed_solver&) = delete;
  Distributed_solver& operator=(const Distributed_solver&) = delete;

  /// Solves for the owned rows' displacement dX (owned rows x `columns`, in the order of the owned vertices;
  /// its value on entry is the first guess) from the first `columns` columns of X and X0. t, w: per real vertex.
  Distributed_solve solve(Mat M, Mat L, const std::vector<double>& t, const std::vector<double>& w,
                          const Control_matrix& X, const Control_matrix& X0, int columns, Control_matrix& dX)
  {
    form(M, L, t, w);
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
    MatDestroy(&A_);
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
    for(Vec* v : { &u_, &mu_, &lx_, &a_, &t_ }) petsc_check(VecDuplicate(b_, v), "VecDuplicate");
  }

  template <typename F>
  void set_owned(Vec v, const F& value)
  {
    PetscScalar* a = nullptr;
    petsc_check(VecGetArray(v, &a), "VecGetArray");
    for(std::size_t k = 0; k < d_.owned_vertices.size(); ++k) a[k] = value(k);
    petsc_check(VecRestoreArray(v, &a), "VecRestoreArray");
  }

  // A = diag(1 + t w) M + diag(t) L, the held rows and columns replaced by the identity's
  void form(Mat M, Mat L, const std::vector<double>& t, const std::vector<double>& w)
  {
    make_vectors(M);
    const std::vector<int>& own = d_.owned_vertices;
    set_owned(a_, [&](std::size_t k) { return 1 + t[std::size_t(own[k])] * w[std::size_t(own[k])]; });
    set_owned(t_, [&](std::size_t k) { return t[std::size_t(own[k])]; });
    MatDestroy(&A_);
    Mat T;
    petsc_check(MatDuplicate(M, MAT_COPY_VALUES, &A_), "MatDuplicate");
    petsc_check(MatDiagonalScale(A_, a_, nullptr), "MatDiagonalScale");
    petsc_check(MatDuplicate(L, MAT_COPY_VALUES, &T), "MatDuplicate");
    petsc_check(MatDiagonalScale(T, t_, nullptr), "MatDiagonalScale");
    petsc_check(MatAXPY(A_, 1.0, T, SAME_NONZERO_PATTERN), "MatAXPY");
    MatDestroy(&T);
    petsc_check(MatZeroRowsColumns(A_, PetscInt(held_rows_.size()), held_rows_.data(), 1.0, nullptr, nullptr),
                "MatZeroRowsColumns");
    petsc_check(KSPSetOperators(ksp_, A_, A_), "KSPSetOperators");
  }

  // b = t (w M (X0 - X) - L X) in column c; zero on held rows
  void right_hand_side(Mat M, Mat L, const std::vector<double>& t, const std::vector<double>& w,
                       const Control_matrix& X, const Control_matrix& X0, int c)
  {
    const std::vector<int>& own = d_.owned_vertices;
    set_owned(u_, [&](std::size_t k) { return X0(own[k], c) - X(own[k], c); });
    set_owned(x_, [&](std::size_t k) { return X(own[k], c); });
    petsc_check(MatMult(M, u_, mu_), "MatMult");
    petsc_check(MatMult(L, x_, lx_), "MatMult");
    const PetscScalar *mu = nullptr, *lx = nullptr;
    petsc_check(VecGetArrayRead(mu_, &mu), "VecGetArrayRead");
    petsc_check(VecGetArrayRead(lx_, &lx), "VecGetArrayRead");
    set_owned(b_, [&](std::size_t k) {
      const std::size_t v = std::size_t(own[k]);
      return held_[k] ? 0.0 : t[v] * (w[v] * mu[k] - lx[k]);
    });
    petsc_check(VecRestoreArrayRead(mu_, &mu), "VecRestoreArrayRead");
    petsc_check(VecRestoreArrayRead(lx_, &lx), "VecRestoreArrayRead");
  }

  const Distributed_layout& d_;
  std::vector<PetscInt> held_rows_;
  std::vector<bool> held_;   // per owned vertex
  KSP ksp_ = nullptr;
  Mat A_ = nullptr;
  Vec x_ = nullptr, b_ = nullptr, u_ = nullptr, mu_ = nullptr, lx_ = nullptr, a_ = nullptr, t_ = nullptr;
};

} // namespace af_distributed

#endif // AF_DISTRIBUTED_DISTRIBUTED_SOLVER_H
