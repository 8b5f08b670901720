// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Closed-form limit position and limit tangent plane of a control vertex (no evaluation of patches).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_VERTEX_LIMIT_MASKS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_VERTEX_LIMIT_MASKS_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Vector3.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Loop_rules.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// out = limit position of vertex v: (1 - n chi) x_v + chi sum of the neighbours (kappa values).
/// A vertex on no face (accepted by some callers) is on no surface: its "limit" is itself.
inline void vertex_limit_value(const Triangle_topology& topo, const Control_matrix& X, int v, double* out)
{
  if(topo.outgoing(v) < 0)
  {
    for(Eigen::Index c = 0; c < X.cols(); ++c) out[c] = X(v, c);
    return;
  }
  const int n = topo.valence(v);
  const double chi = loop_limit_weight(n);
  const Eigen::Index kappa = X.cols();
  for(Eigen::Index c = 0; c < kappa; ++c) out[c] = (1.0 - n * chi) * X(v, c);
  const int h0 = topo.outgoing(v);
  int h = h0;
  do {
    const int w = topo.target(h);
    for(Eigen::Index c = 0; c < kappa; ++c) out[c] += chi * X(w, c);
    h = topo.ccw(h);
  } while(h != h0);
}

/// Tangent masks t_u = sum cos(2 pi j/n) x_j, t_v = sum sin(2 pi j/n) x_j over the neighbours in
/// counter-clockwise order; t_u x t_v is the oriented limit normal.
inline void vertex_limit_tangents(const Triangle_topology& topo, const Control_matrix& X, int v,
                                  double* tu, double* tv)
{
  const int n = topo.valence(v);
  const Eigen::Index kappa = X.cols();
  for(Eigen::Index c = 0; c < kappa; ++c) { tu[c] = 0; tv[c] = 0; }
  const int h0 = topo.outgoing(v);
  if(h0 < 0) return;   // a vertex on no face has no tangent plane (its normal is the zero vector)
  int h = h0, j = 0;
  do {
    const int w = topo.target(h);
    const double cu = loop_tangent_u(j, n), cv = loop_tangent_v(j, n);
    for(Eigen::Index c = 0; c < kappa; ++c) { tu[c] += cu * X(w, c); tv[c] += cv * X(w, c); }
    h = topo.ccw(h);
    ++j;
  } while(h != h0);
}

/// Unit normal of the limit surface at vertex v (geometry: 3 columns).
inline void vertex_limit_normal(const Triangle_topology& topo, const Control_matrix& X, int v, double* n)
{
  double tu[3], tv[3];
  vertex_limit_tangents(topo, X, v, tu, tv);
  unit_cross(tu, tv, n);
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_VERTEX_LIMIT_MASKS_H
