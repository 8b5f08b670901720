// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The linear system of one semi-implicit step, ((1 + tau w) M + tau L) dX = tau (w M (X_0 - X_n) - L X_n)
// over the free vertices, from M and L given as value arrays over the assembler's pattern. With a local
// time scale s (Local_time_scale.h) M_ij stands for M_ij w_i w_j in both sides, w_i = 1 / sqrt(s_i)
// (`mass_weight`, empty: none).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_STEP_SYSTEM_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_STEP_SYSTEM_H

#include <CGAL/Anisotropic_fairing/internal/solve/Free_block.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Parallel_blocks.h>
#include <CGAL/Anisotropic_fairing/internal/types/Sparse_structure.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// A (values over block.structure(), free x free) = the step's system: ((1 + f tau_i omega_i) M_ij +
/// f tau_i L_ij) / sys over the free rows and columns. The system is divided by `sys` (so that a huge tau
/// cannot overflow), and with several components the unknowns of row i are in units of unknown_scale[i]
/// (empty: none).
inline void fill_step_matrix(Value_array& A, const Free_block& block, const Value_array& M, const Value_array& L,
                             const std::vector<double>& tau, const std::vector<double>& omega, double factor,
                                 double sys,
                             const std::vector<double>& unknown_scale, const std::vector<double>& mass_weight)
{
  const Sparse_structure& S = block.structure();
  const int* outer = S.outerIndexPtr();
  const int* inner = S.innerIndexPtr();
  const std::vector<int>& free = block.free;
  A.resize(std::size_t(S.nonZeros()));
  parallel_blocks(S.cols(), [&](Eigen::Index first, Eigen::Index last) {
    for(Eigen::Index k = first; k < last; ++k)
    {
      const std::size_t column = std::size_t(free[std::size_t(k)]);
      for(int e = outer[k]; e < outer[k + 1]; ++e)
      {
        const std::size_t p = block.source(std::size_t(e));
        const std::size_t row = std::size_t(free[std::size_t(inner[e])]);
        const double t = factor * tau[row];
        double m = M[p];
        if(!mass_weight.empty()) m *= mass_weight[row] * mass_weight[column];
        double a = ((1 + t * omega[row]) * m + t * L[p]) / sys;
        if(!unknown_scale.empty()) a /= unknown_scale[row] * unknown_scale[row];
        A[std::size_t(e)] = a;
      }
    }
  });
}

/// R = f tau_i (omega_i M (X0 - X) - L X)_i for all rows: the right-hand side of a time step for the
/// displacement.
inline void step_residual(const Sparse_structure& pattern, const Value_array& M, const Value_array& L,
                          const std::vector<double>& tau, const std::vector<double>& omega, const Control_matrix& X,
                          const Control_matrix& X0, double f, Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic,
                              Eigen::RowMajor>& R,
                          const std::vector<double>& mass_weight = std::vector<double>())
{
  const int* outer = pattern.outerIndexPtr();
  const int* rows = pattern.innerIndexPtr();
  const Eigen::Index k = X.cols();
  parallel_blocks(X.rows(), [&](Eigen::Index first, Eigen::Index last) {   // row i: column i of the symmetric pattern
    for(Eigen::Index i = first; i < last; ++i)
    {
      double* r = R.row(i).data();
      std::fill(r, r + k, 0.0);
      const double w = omega[std::size_t(i)];
      for(int p = outer[i]; p < outer[i + 1]; ++p)
      {
        const Eigen::Index j = rows[p];
        double m = w * M[std::size_t(p)];
        if(!mass_weight.empty()) m *= mass_weight[std::size_t(i)] * mass_weight[std::size_t(j)];
        const double l = L[std::size_t(p)];
        for(Eigen::Index col = 0; col < k; ++col) r[col] += m * (X0(j, col) - X(j, col)) - l * X(j, col);
      }
      const double t = f * tau[std::size_t(i)];
      for(Eigen::Index col = 0; col < k; ++col) r[col] *= t;
    }
  });
}

/// The lumped (row-sum) mass D_i = sum_j M_ij, with the local time scale's weights as in the system.
inline Eigen::VectorXd lumped_mass(const Sparse_structure& pattern, const Value_array& M,
                                   const std::vector<double>& mass_weight)
{
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  Eigen::VectorXd d = Eigen::VectorXd::Zero(pattern.rows());
  for(Eigen::Index j = 0; j < pattern.cols(); ++j)
    for(int p = outer[j]; p < outer[j + 1]; ++p)
      d[inner[p]] += M[std::size_t(p)] *
                     (mass_weight.empty() ? 1.0 : mass_weight[std::size_t(inner[p])] * mass_weight[std::size_t(j)]);
  return d;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_STEP_SYSTEM_H
