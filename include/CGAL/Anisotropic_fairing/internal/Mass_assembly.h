// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mass matrix M_ij = (phi_i, phi_j) over the limit surface and the limit-surface area, both by
// the cached quadrature stencils. Control points may live in R^kappa (geometry plus functions): the
// metric uses all kappa components (Bajaj & Xu 2003, eq. 1 and 25).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_MASS_ASSEMBLY_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_MASS_ASSEMBLY_H

#include <CGAL/Anisotropic_fairing/internal/Patch_cache.h>
#include <CGAL/Anisotropic_fairing/internal/Sparse_pattern.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

typedef Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Control_matrix;

/// Tangents t1 = dx/dxi1, t2 = dx/dxi2 of the limit surface at one quadrature point, and the
/// area element sqrt(det G), for control rows `ring` of X.
inline double area_element(const Stencil& s, const int* ring, const Control_matrix& X,
                           double* t1, double* t2)
{
  const Eigen::Index kappa = X.cols();
  for(Eigen::Index c = 0; c < kappa; ++c) { t1[c] = 0; t2[c] = 0; }
  const double* d1 = s.row(D1);
  const double* d2 = s.row(D2);
  for(int j = 0; j < s.m; ++j)
  {
    const double* x = X.data() + std::size_t(ring[j]) * kappa;
    for(Eigen::Index c = 0; c < kappa; ++c) { t1[c] += d1[j] * x[c]; t2[c] += d2[j] * x[c]; }
  }
  double g11 = 0, g12 = 0, g22 = 0;
  for(Eigen::Index c = 0; c < kappa; ++c) { g11 += t1[c] * t1[c]; g12 += t1[c] * t2[c]; g22 += t2[c] * t2[c]; }
  const double det = g11 * g22 - g12 * g12;
  return det > 0 ? std::sqrt(det) : 0.0;
}

/// Limit-surface area by the prepared quadrature.
inline double limit_surface_area(const Patch_cache& cache, const Control_matrix& X)
{
  std::vector<double> t1(X.cols()), t2(X.cols());
  double area = 0;
  for(std::size_t f = 0; f < cache.number_of_faces(); ++f)
    for(const Quadrature_point& q : cache.quadrature_points(cache.category(f)))
      area += q.weight * area_element(q.stencil, cache.ring(f), X, t1.data(), t2.data());
  return area;
}

/// Adds the symmetric local matrix whose lower triangle is `local` (ring x ring) into M, which
/// carries the ring pattern. Reading one triangle only keeps M exactly symmetric.
/// Rows of a column are sorted, so each local column is merged into the global one in one pass.
inline void scatter_local_matrix(const Eigen::MatrixXd& local, const int* ring, int m,
                                 std::vector<int>& order, Eigen::SparseMatrix<double>& M)
{
  order.resize(std::size_t(m));
  for(int k = 0; k < m; ++k) order[std::size_t(k)] = k;
  std::sort(order.begin(), order.end(), [ring](int a, int b) { return ring[a] < ring[b]; });
  const int* outer = M.outerIndexPtr();
  const int* rows = M.innerIndexPtr();
  double* values = M.valuePtr();
  for(int s = 0; s < m; ++s)
  {
    const int j = ring[s];
    int p = outer[j];
    for(int k = 0; k < m; ++k)
    {
      const int r = order[std::size_t(k)];
      while(rows[p] < ring[r]) ++p;
      values[p] += (r >= s) ? local(r, s) : local(s, r);
    }
  }
}

/// Fills the values of M (which must carry ring_sparsity_pattern) with the mass matrix and returns
/// the limit-surface area. Exact identity: sum_ij M_ij = area (partition of unity).
inline double assemble_mass_matrix(const Patch_cache& cache, const Control_matrix& X,
                                   Eigen::SparseMatrix<double>& M)
{
  std::fill(M.valuePtr(), M.valuePtr() + M.nonZeros(), 0.0);
  const Eigen::Index kappa = X.cols();
  Control_matrix Xr, T1, T2;
  Eigen::MatrixXd B, local;
  Eigen::VectorXd c;
  std::vector<int> order;
  double area = 0;
  for(std::size_t f = 0; f < cache.number_of_faces(); ++f)
  {
    const int m = cache.ring_size(f);
    const int* ring = cache.ring(f);
    const int cat = cache.category(f);
    Xr.resize(m, kappa);
    for(int k = 0; k < m; ++k) Xr.row(k) = X.row(ring[k]);
    T1.noalias() = cache.quadrature_rows(cat, D1) * Xr;
    T2.noalias() = cache.quadrature_rows(cat, D2) * Xr;
    const Eigen::VectorXd& w = cache.quadrature_weights(cat);
    c.resize(w.size());
    for(Eigen::Index q = 0; q < w.size(); ++q)
    {
      const double g11 = T1.row(q).squaredNorm(), g22 = T2.row(q).squaredNorm(), g12 = T1.row(q).dot(T2.row(q));
      const double det = g11 * g22 - g12 * g12;
      c[q] = w[q] * (det > 0 ? std::sqrt(det) : 0.0);
    }
    area += c.sum();
    B.noalias() = c.cwiseSqrt().asDiagonal() * cache.quadrature_rows(cat, VALUE);
    local.setZero(m, m);
    local.selfadjointView<Eigen::Lower>().rankUpdate(B.transpose());   // lower triangle of B^T B
    scatter_local_matrix(local, ring, m, order, M);
  }
  return area;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_MASS_ASSEMBLY_H
