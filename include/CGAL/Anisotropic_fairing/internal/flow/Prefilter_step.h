// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bajaj & Xu's prefiltered surface M_eps, where an anisotropic tensor reads its curvature: the surface
// after one isotropic implicit step of length eps (per row) from X, (M + eps L) X_eps = M X, held
// vertices fixed (doc/Anisotropic_fairing/design/loop-fem.md section 7). Solved for the free rows' displacement, like
// a time step, with the user's solver.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_PREFILTER_STEP_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_PREFILTER_STEP_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Parallel_blocks.h>
#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Free_block.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Solver_choice.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Spd_solvers.h>
#include <CGAL/Real_timer.h>

#include <Eigen/Sparse>

#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The prefilter's share of the user's solver settings. Its tolerance is a hundredth of a step's: the
/// tensor reads the second derivatives of M_eps, which amplify its error.
struct Prefilter_solver
{
  Linear_solver solver = Linear_solver::AUTOMATIC;
  double tolerance = 1e-10;
  int maximum_iterations = 10000;
  Direct_solver_factory direct;   // empty: Sparse_cholesky
  double factor_budget = std::numeric_limits<double>::infinity();   // Stepper_settings::factor_budget
};

/// M, L: value arrays over `pattern` (isotropic); A: the system's values over `block.structure()`,
/// overwritten. dX: the displacement of the free rows' first `columns` columns; when it has
/// their size on entry, conjugate gradients start from it (the last step's M_eps is a close guess).
/// `choice` and `cg` persist over a run's prefilters, as a time step's do: iterations that stall
/// (near-degenerate faces of quantised scans) give way to the factorisation, analysed once per run.
inline Solve_statistics prefilter_step(const Sparse_structure& pattern, const Value_array& M,
                                       const Value_array& L, const std::vector<double>& eps,
                                       const Free_block& block, Value_array& A,
                                       const Control_matrix& X, int columns, const Prefilter_solver& settings,
                                       Solver_choice& choice, Block_conjugate_gradient& cg, Control_matrix& dX)
{
  const std::vector<int>& free = block.free;
  const Sparse_structure& S = block.structure();
  A.resize(std::size_t(S.nonZeros()));
  parallel_blocks(S.cols(), [&](Eigen::Index first, Eigen::Index last) {
    for(Eigen::Index k = first; k < last; ++k)
    {
      const double e_k = eps[std::size_t(free[std::size_t(k)])];
      for(int e = S.outerIndexPtr()[k]; e < S.outerIndexPtr()[k + 1]; ++e)
      {
        const std::size_t p = block.source(std::size_t(e));
        A[std::size_t(e)] = M[p] + e_k * L[p];
      }
    }
  });
  const Eigen::Index nfree = Eigen::Index(free.size());
  Control_matrix B(nfree, columns);
  if(dX.rows() != nfree || dX.cols() != columns) dX = Control_matrix::Zero(nfree, columns);
  for(Eigen::Index i = 0; i < nfree; ++i)
  {
    const int row = free[std::size_t(i)];
    B.row(i).setZero();
    for(int p = pattern.outerIndexPtr()[row]; p < pattern.outerIndexPtr()[row + 1]; ++p)
      B.row(i) -= eps[std::size_t(row)] * L[std::size_t(p)] * X.row(pattern.innerIndexPtr()[p]).head(columns);
  }
  CGAL::Real_timer clock;
  clock.start();
  bool direct = false;
  Solve_statistics sol = choice.solve(S, A, B, dX, cg, direct);
  choice.record(direct, sol, clock.time());
  if(!sol.ok && !direct && settings.solver == Linear_solver::AUTOMATIC)
  {
    // above automatic_cholesky_limit the choice does not factorise; M_eps is needed all the same
    dX.setZero();
    sol = choice.direct_solver().solve(S.matrix(A), B, dX);
  }
  return sol;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_PREFILTER_STEP_H
