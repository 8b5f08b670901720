// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bajaj & Xu's prefiltered surface M_eps, where an anisotropic tensor reads its curvature: the surface
// after one isotropic implicit step of length eps (per row) from X, (M + eps L) X_eps = M X, held
// vertices fixed (doc/Anisotropic_fairing/design/loop-fem.md section 7). Solved for the free rows' displacement, like a time step.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_PREFILTER_STEP_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_PREFILTER_STEP_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Spd_solvers.h>

#include <Eigen/Sparse>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// M, L: value arrays over `pattern` (isotropic); `free`: the free rows; A: the free-free system, whose
/// entry e comes from pattern entry source[e] in free row free[entry_row[e]] (its values are overwritten).
/// dX: the displacement of the free rows' first `columns` columns.
inline Solve_statistics prefilter_step(const Eigen::SparseMatrix<double>& pattern, const std::vector<double>& M,
                                       const std::vector<double>& L, const std::vector<double>& eps,
                                       const std::vector<int>& free, const std::vector<int>& source,
                                       const std::vector<int>& entry_row, Eigen::SparseMatrix<double>& A,
                                       const Control_matrix& X, int columns, Control_matrix& dX)
{
  double* av = A.valuePtr();
  for(std::size_t e = 0; e < source.size(); ++e)
    av[e] = M[std::size_t(source[e])] + eps[std::size_t(free[std::size_t(entry_row[e])])] * L[std::size_t(source[e])];
  const Eigen::Index nfree = Eigen::Index(free.size());
  Control_matrix B(nfree, columns);
  dX = Control_matrix::Zero(nfree, columns);
  for(Eigen::Index i = 0; i < nfree; ++i)
  {
    const int row = free[std::size_t(i)];
    B.row(i).setZero();
    for(int p = pattern.outerIndexPtr()[row]; p < pattern.outerIndexPtr()[row + 1]; ++p)
      B.row(i) -= eps[std::size_t(row)] * L[std::size_t(p)] * X.row(pattern.innerIndexPtr()[p]).head(columns);
  }
  Block_conjugate_gradient cg(1e-10, 10000);
  Solve_statistics sol = cg.solve(A, B, dX);
  if(!sol.ok)   // near-degenerate faces (quantised scans) can make it too ill-conditioned for CG
  {
    Sparse_cholesky cholesky;
    dX.setZero();
    sol = cholesky.solve(A, B, dX);
  }
  return sol;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_PREFILTER_STEP_H
