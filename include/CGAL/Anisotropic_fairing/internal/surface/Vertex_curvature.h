// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Curvature of the limit surface attributed to a control vertex where it has none. The Loop limit
// surface has no finite curvature at an extraordinary vertex in general (unbounded for valence > 6, a flat point with
// direction-dependent limits for valence 3-5), so a vertex gets the average of the shape operator over
// the limit patches of its incident faces, weighted by its hat function (its barycentric coordinate):
//   S_v = int xi_v S dA / int xi_v dA,   S = k1 e1 e1^T + k2 e2 e2^T (3x3, ambient),
// then restricted to the limit tangent plane at the vertex (closed-form tangent masks) and
// diagonalised there. The singularities are integrable, the quadrature points lie inside the faces,
// and on a smooth surface the average is second-order accurate (the star is symmetric to first order).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_SURFACE_VERTEX_CURVATURE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_SURFACE_VERTEX_CURVATURE_H

#include <CGAL/Anisotropic_fairing/Quadrature_point_geometry.h>
#include <CGAL/Anisotropic_fairing/Surface_curvature.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Symmetric_2x2_eigen.h>
#include <CGAL/Anisotropic_fairing/internal/types/Vector3.h>
#include <CGAL/Anisotropic_fairing/internal/element/Patch_cache.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Vertex_limit_masks.h>

#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The geometry at a point of a face of a surface in R^3 from its derivatives, the rows t[0..4] =
/// (x_1, x_2, x_11, x_12, x_22).
inline Quadrature_point_geometry point_geometry_3(const double (*t)[3], std::size_t face, int point)
{
  Quadrature_point_geometry g;
  g.face = face; g.point = point; g.dimension = 3;
  g.t1 = t[0]; g.t2 = t[1]; g.t11 = t[2]; g.t12 = t[3]; g.t22 = t[4];
  g.g11 = t[0][0] * t[0][0] + t[0][1] * t[0][1] + t[0][2] * t[0][2];
  g.g12 = t[0][0] * t[1][0] + t[0][1] * t[1][1] + t[0][2] * t[1][2];
  g.g22 = t[1][0] * t[1][0] + t[1][1] * t[1][1] + t[1][2] * t[1][2];
  g.det = g.g11 * g.g22 - g.g12 * g.g12;
  g.ring = nullptr; g.basis = nullptr; g.ring_size = 0;
  return g;
}

struct Vertex_curvature_value
{
  std::array<double, 3> H{ { 0, 0, 0 } };     // (k1 + k2)/2 times the limit normal
  double k1 = 0, k2 = 0;                       // k1 <= k2, w.r.t. the oriented limit normal
  std::array<double, 3> d1{ { 0, 0, 0 } }, d2{ { 0, 0, 0 } };   // unit, tangent to the limit surface
};

/// Curvatures of the first `vertices` vertices of `topo` (the real ones; X holds the extended
/// geometry, 3 columns) from the quadrature points of the faces of `cache`. Vertices on no face get zeros.
inline std::vector<Vertex_curvature_value>
averaged_vertex_curvatures(const Triangle_topology& topo, const Patch_cache& cache, std::size_t vertices,
                           const Control_matrix& X)
{
  std::vector<Eigen::Matrix3d> S(vertices, Eigen::Matrix3d::Zero());   // int xi_v S dA
  std::vector<double> W(vertices, 0.0);                              // int xi_v dA
  for(std::size_t f = 0; f < cache.number_of_faces(); ++f)
  {
    const int cat = cache.category(f), m = cache.ring_size(f);
    const int* ring = cache.ring(f);
    const std::vector<Quadrature_point>& points = cache.quadrature_points(cat);
    for(std::size_t q = 0; q < points.size(); ++q)
    {
      const Quadrature_point& qp = points[q];
      double t[5][3] = {};
      for(int r = 0; r < 5; ++r)
        for(int k = 0; k < m; ++k)
        {
          const double s = qp.stencil.row(D1 + r)[k];
          for(int c = 0; c < 3; ++c) t[r][c] += s * X(ring[k], c);
        }
      const Quadrature_point_geometry g = point_geometry_3(t, f, int(q));
      if(!(g.det > 0) || !std::isfinite(g.det)) continue;
      const Principal_curvatures pc = principal_curvatures(g);
      const Eigen::Vector3d e1 = pc.c1[0] * vec3(t[0]) + pc.c1[1] * vec3(t[1]);
      const Eigen::Vector3d e2 = pc.c2[0] * vec3(t[0]) + pc.c2[1] * vec3(t[1]);
      Eigen::Matrix3d s = pc.k1 * e1 * e1.transpose() + pc.k2 * e2 * e2.transpose();
      s.triangularView<Eigen::StrictlyLower>() = s.transpose();   // exactly symmetric
      const double area = qp.weight * std::sqrt(g.det);
      const double hat[3] = { 1 - qp.xi1 - qp.xi2, qp.xi1, qp.xi2 };   // ring starts with the face's corners
      for(int corner = 0; corner < 3; ++corner)
      {
        const std::size_t v = std::size_t(ring[corner]);
        if(v >= vertices) continue;
        const double w = area * hat[corner];
        W[v] += w;
        S[v] += w * s;
      }
    }
  }

  std::vector<Vertex_curvature_value> out(vertices);
  for(std::size_t v = 0; v < vertices; ++v)
  {
    if(!(W[v] > 0)) continue;
    Eigen::Vector3d n;
    vertex_limit_normal(topo, X, int(v), n.data());
    // a tangent basis u1, u2 of the limit tangent plane
    const Eigen::Vector3d a = std::abs(n[0]) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d u1 = n.cross(a).normalized(), u2 = n.cross(u1);
    const Eigen::Vector3d y1 = S[v] * u1 / W[v], y2 = S[v] * u2 / W[v];
    const Symmetric_2x2_eigen e = symmetric_2x2_eigen(u1.dot(y1), 0.5 * (u2.dot(y1) + u1.dot(y2)), u2.dot(y2));
    Vertex_curvature_value& r = out[v];
    r.k1 = e.k1;
    r.k2 = e.k2;
    // the eigenvector of k1 is (x, y) in (u1, u2)
    vec3(r.H.data()) = e.mean * n;
    vec3(r.d1.data()) = e.x * u1 + e.y * u2;
    vec3(r.d2.data()) = -e.y * u1 + e.x * u2;
  }
  return out;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_SURFACE_VERTEX_CURVATURE_H
