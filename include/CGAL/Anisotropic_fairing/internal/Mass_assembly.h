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

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

typedef Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Control_matrix;

/// Work space of one face: its ring's control rows and the tangents at its quadrature points.
struct Face_metric_workspace
{
  Control_matrix Xr, T1, T2;
  Eigen::VectorXd c;   // quadrature weight times sqrt(det G) at each point
};

/// Fills ws.c with w_q sqrt(det G(xi_q)) for face f (metric from all kappa columns of X).
inline void face_area_elements(const Patch_cache& cache, std::size_t f, const Control_matrix& X,
                               Face_metric_workspace& ws)
{
  const int m = cache.ring_size(f);
  const int* ring = cache.ring(f);
  const int cat = cache.category(f);
  ws.Xr.resize(m, X.cols());
  for(int k = 0; k < m; ++k) ws.Xr.row(k) = X.row(ring[k]);
  ws.T1.noalias() = cache.quadrature_rows(cat, D1) * ws.Xr;
  ws.T2.noalias() = cache.quadrature_rows(cat, D2) * ws.Xr;
  const Eigen::VectorXd& w = cache.quadrature_weights(cat);
  ws.c.resize(w.size());
  for(Eigen::Index q = 0; q < w.size(); ++q)
  {
    const double g11 = ws.T1.row(q).squaredNorm(), g22 = ws.T2.row(q).squaredNorm();
    const double g12 = ws.T1.row(q).dot(ws.T2.row(q));
    const double det = g11 * g22 - g12 * g12;
    ws.c[q] = w[q] * (det > 0 ? std::sqrt(det) : 0.0);
  }
}

/// Limit-surface area by the prepared quadrature.
inline double limit_surface_area(const Patch_cache& cache, const Control_matrix& X)
{
  Face_metric_workspace ws;
  double area = 0;
  for(std::size_t f = 0; f < cache.number_of_faces(); ++f)
  {
    face_area_elements(cache, f, X, ws);
    area += ws.c.sum();
  }
  return area;
}

/// Adds N symmetric local matrices, given by their lower triangles (ring x ring), into N value arrays
/// sharing one compressed column pattern (outer, rows) that contains the ring's pairs. Reading one
/// triangle only keeps the results exactly symmetric. Rows of a column are sorted, so each local
/// column is merged into the global one in one pass.
template <int N, typename Local>
void scatter_local_matrices(const Local* const (&local)[N], const int* ring, int m, std::vector<int>& order,
                            const int* outer, const int* rows, double* const (&values)[N])
{
  order.resize(std::size_t(m));
  for(int k = 0; k < m; ++k) order[std::size_t(k)] = k;
  std::sort(order.begin(), order.end(), [ring](int a, int b) { return ring[a] < ring[b]; });
  for(int s = 0; s < m; ++s)
  {
    int p = outer[ring[s]];
    for(int k = 0; k < m; ++k)
    {
      const int r = order[std::size_t(k)];
      while(rows[p] < ring[r]) ++p;
      for(int i = 0; i < N; ++i) values[i][p] += (r >= s) ? (*local[i])(r, s) : (*local[i])(s, r);
    }
  }
}

/// One local matrix into a sparse matrix carrying the ring pattern.
inline void scatter_local_matrix(const Eigen::MatrixXd& local, const int* ring, int m,
                                 std::vector<int>& order, Eigen::SparseMatrix<double>& M)
{
  const Eigen::MatrixXd* const locals[1] = { &local };
  double* const values[1] = { M.valuePtr() };
  scatter_local_matrices<1, Eigen::MatrixXd>(locals, ring, m, order, M.outerIndexPtr(), M.innerIndexPtr(), values);
}

/// Fills the values of M (which must carry ring_sparsity_pattern) with the mass matrix and returns
/// the limit-surface area. Exact identity: sum_ij M_ij = area (partition of unity).
inline double assemble_mass_matrix(const Patch_cache& cache, const Control_matrix& X,
                                   Eigen::SparseMatrix<double>& M)
{
  std::fill(M.valuePtr(), M.valuePtr() + M.nonZeros(), 0.0);
  Face_metric_workspace ws;
  Eigen::MatrixXd B, local;
  std::vector<int> order;
  double area = 0;
  for(std::size_t f = 0; f < cache.number_of_faces(); ++f)
  {
    const int m = cache.ring_size(f);
    face_area_elements(cache, f, X, ws);
    area += ws.c.sum();
    B.noalias() = ws.c.cwiseSqrt().asDiagonal() * cache.quadrature_rows(cache.category(f), VALUE);
    local.setZero(m, m);
    local.selfadjointView<Eigen::Lower>().rankUpdate(B.transpose());   // lower triangle of B^T B
    scatter_local_matrix(local, cache.ring(f), m, order, M);
  }
  return area;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_MASS_ASSEMBLY_H
