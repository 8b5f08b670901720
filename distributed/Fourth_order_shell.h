// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fourth-order step's matrix A = diag(1 + t w) M + diag(t) L D^-1 L through its product, as the library
// iterates on it (solve/Fourth_order_system.h): M x and L (D^-1 (L x)) on the 3-ring pattern, never the
// 6-ring Q, whose forming (MatMatMult) cost more time and memory than the whole step's conjugate gradients.
// A PETSc shell matrix: held rows and columns are the identity's; its diagonal (a_i M_ii + t_i sum_j L_ij^2 /
// D_j) is the Jacobi preconditioner's. A preconditioner that needs the matrix's entries (GAMG, hypre) gets
// the formed matrix instead (Distributed_solver.h).

#ifndef AF_DISTRIBUTED_FOURTH_ORDER_SHELL_H
#define AF_DISTRIBUTED_FOURTH_ORDER_SHELL_H

#include "Distributed_layout.h"
#include "Face_partition.h"

#include <petscmat.h>

#include <vector>

namespace af_distributed {

class Fourth_order_shell
{
public:
  /// `Mw`: M with the time scale, `a` = 1 + t w, `t`, `dinv` = D^-1 (0 on held rows), `held`: per owned vertex.
  /// The vectors and matrices are read at each product: they must outlive matrix().
  Fourth_order_shell(MPI_Comm comm, const Distributed_layout& d, const std::vector<bool>& held, Mat Mw, Mat L, Vec a,
                     Vec t, Vec dinv)
    : Mw_(Mw), L_(L), a_(a), t_(t), dinv_(dinv)
  {
    for(Vec* v : { &free_, &x_, &y_, &lx_, &q_, &diagonal_ }) petsc_check(VecDuplicate(a, v), "VecDuplicate");
    PetscScalar* f = nullptr;
    petsc_check(VecGetArray(free_, &f), "VecGetArray");
    for(std::size_t k = 0; k < held.size(); ++k) f[k] = held[k] ? 0.0 : 1.0;
    petsc_check(VecRestoreArray(free_, &f), "VecRestoreArray");
    make_diagonal(d, held);
    const PetscInt local = PetscInt(d.owned_vertices.size());
    petsc_check(MatCreateShell(comm, local, local, d.rows, d.rows, this, &A_), "MatCreateShell");
    petsc_check(MatShellSetOperation(A_, MATOP_MULT, (void (*)(void))product), "MatShellSetOperation");
    petsc_check(MatShellSetOperation(A_, MATOP_GET_DIAGONAL, (void (*)(void))get_diagonal), "MatShellSetOperation");
    petsc_check(MatSetOption(A_, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  }
  ~Fourth_order_shell()
  {
    MatDestroy(&A_);
    for(Vec* v : { &free_, &x_, &y_, &lx_, &q_, &diagonal_ }) VecDestroy(v);
  }
  Fourth_order_shell(const Fourth_order_shell&) = delete;
  Fourth_order_shell& operator=(const Fourth_order_shell&) = delete;

  Mat matrix() const { return A_; }

private:
  // y = A x: on the free rows and columns a (Mw x) + t (L (dinv (L x))), on the held ones x
  static PetscErrorCode product(Mat A, Vec x, Vec y)
  {
    Fourth_order_shell* s = nullptr;
    PetscCall(MatShellGetContext(A, &s));
    PetscCall(VecPointwiseMult(s->x_, s->free_, x));
    PetscCall(MatMult(s->Mw_, s->x_, s->y_));
    PetscCall(MatMult(s->L_, s->x_, s->lx_));
    PetscCall(VecPointwiseMult(s->lx_, s->dinv_, s->lx_));
    PetscCall(MatMult(s->L_, s->lx_, s->q_));
    PetscCall(VecPointwiseMult(s->y_, s->a_, s->y_));
    PetscCall(VecPointwiseMult(s->q_, s->t_, s->q_));
    PetscCall(VecAXPY(s->y_, 1.0, s->q_));
    PetscCall(VecPointwiseMult(y, s->free_, s->y_));   // held rows: x itself
    PetscCall(VecAXPY(s->x_, -1.0, x));                // -x on the held rows, 0 elsewhere
    PetscCall(VecAXPY(y, -1.0, s->x_));
    return 0;
  }
  static PetscErrorCode get_diagonal(Mat A, Vec d)
  {
    Fourth_order_shell* s = nullptr;
    PetscCall(MatShellGetContext(A, &s));
    PetscCall(VecCopy(s->diagonal_, d));
    return 0;
  }

  // a_i Mw_ii + t_i Q_ii, Q_ii = sum_j L_ji^2 dinv_j (L symmetric: each owned row j adds to its columns i); 1 held
  void make_diagonal(const Distributed_layout& d, const std::vector<bool>& held)
  {
    petsc_check(VecSet(q_, 0.0), "VecSet");
    const PetscScalar* dinv = nullptr;
    petsc_check(VecGetArrayRead(dinv_, &dinv), "VecGetArrayRead");
    std::vector<PetscInt> columns;
    std::vector<PetscScalar> values;
    for(std::size_t k = 0; k < d.owned_vertices.size(); ++k)
    {
      const PetscInt row = d.first_row + PetscInt(k);
      PetscInt count = 0;
      const PetscInt* c = nullptr;
      const PetscScalar* v = nullptr;
      petsc_check(MatGetRow(L_, row, &count, &c, &v), "MatGetRow");
      columns.assign(c, c + count);
      values.resize(std::size_t(count));
      for(PetscInt e = 0; e < count; ++e) values[std::size_t(e)] = v[e] * v[e] * dinv[k];
      petsc_check(MatRestoreRow(L_, row, &count, &c, &v), "MatRestoreRow");   // (which sets count to 0)
      petsc_check(VecSetValues(q_, PetscInt(columns.size()), columns.data(), values.data(), ADD_VALUES),
                  "VecSetValues");
    }
    petsc_check(VecRestoreArrayRead(dinv_, &dinv), "VecRestoreArrayRead");
    petsc_check(VecAssemblyBegin(q_), "VecAssemblyBegin");
    petsc_check(VecAssemblyEnd(q_), "VecAssemblyEnd");
    petsc_check(MatGetDiagonal(Mw_, diagonal_), "MatGetDiagonal");
    petsc_check(VecPointwiseMult(diagonal_, a_, diagonal_), "VecPointwiseMult");
    petsc_check(VecPointwiseMult(q_, t_, q_), "VecPointwiseMult");
    petsc_check(VecAXPY(diagonal_, 1.0, q_), "VecAXPY");
    PetscScalar* g = nullptr;
    petsc_check(VecGetArray(diagonal_, &g), "VecGetArray");
    for(std::size_t k = 0; k < held.size(); ++k)
      if(held[k]) g[k] = 1.0;
    petsc_check(VecRestoreArray(diagonal_, &g), "VecRestoreArray");
  }

  Mat Mw_, L_, A_ = nullptr;
  Vec a_, t_, dinv_;
  Vec free_ = nullptr, x_ = nullptr, y_ = nullptr, lx_ = nullptr, q_ = nullptr, diagonal_ = nullptr;
};

} // namespace af_distributed

#endif // AF_DISTRIBUTED_FOURTH_ORDER_SHELL_H
