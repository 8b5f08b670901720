// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Closed-form limit position and limit tangent plane of a control vertex (no evaluation of patches).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_VERTEX_LIMIT_MASKS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_VERTEX_LIMIT_MASKS_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Vector3.h>
#include <CGAL/Anisotropic_fairing/internal/types/Parallel_blocks.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Loop_rules.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The limit mask of vertex v: f(vertex, weight) for v itself, weight 1 - n chi, then for each neighbour
/// in counter-clockwise order, weight chi (Loop_rules.h). A vertex on no face (accepted by some callers)
/// is on no surface: its "limit" is itself, f(v, 1).
template <typename F>
void for_each_limit_weight(const Triangle_topology& topo, int v, const F& f)
{
  const int h0 = topo.outgoing(v);
  if(h0 < 0) { f(v, 1.0); return; }
  const int n = topo.valence(v);
  const double chi = loop_limit_weight(n);
  f(v, 1.0 - n * chi);
  int h = h0;
  do { f(topo.target(h), chi); h = topo.ccw(h); } while(h != h0);
}

/// out = limit position of vertex v: (1 - n chi) x_v + chi sum of the neighbours (kappa values).
inline void vertex_limit_value(const Triangle_topology& topo, const Control_matrix& X, int v, double* out)
{
  const Eigen::Index kappa = X.cols();
  bool first = true;
  for_each_limit_weight(topo, v, [&](int w, double weight) {
    for(Eigen::Index c = 0; c < kappa; ++c) out[c] = first ? weight * X(w, c) : out[c] + weight * X(w, c);
    first = false;
  });
}

/// Y = the Loop limit points of the control points X (real vertices; the ghosts from the layer); Y must
/// not be X. A vertex on no face keeps its value.
inline void limit_points(const Ghost_layer& layer, const Control_matrix& X, Control_matrix& Y)
{
  const Control_matrix extended = layer.has_boundary() ? layer.extend(X) : Control_matrix();
  const Control_matrix& E = layer.has_boundary() ? extended : X;
  Y.resize(X.rows(), X.cols());
  parallel_blocks(X.rows(), [&](Eigen::Index first, Eigen::Index last) {
    for(Eigen::Index i = first; i < last; ++i) vertex_limit_value(*layer.topology, E, int(i), Y.row(i).data());
  });
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
  const double* table = Loop_tangent_table::coefficients(n);
  int h = h0, j = 0;
  do {
    const int w = topo.target(h);
    const double cu = table ? table[2 * j] : loop_tangent_u(j, n), cv = table ? table[2 * j + 1] : loop_tangent_v(j, n);
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
