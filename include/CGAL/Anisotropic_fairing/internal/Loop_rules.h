// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Loop subdivision weights: the vertex rule a(n), the limit mask chi(n) and the tangent masks.
// (Bajaj & Xu 2003, eq. 14-15; limit and tangent masks as in loop-fem.md section 1.)

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_RULES_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_RULES_H

#include <cmath>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

inline double loop_pi() { return 3.14159265358979323846; }

/// Weight of each neighbour in Loop's vertex rule: x0' = (1 - n a) x0 + a sum(xi).
inline double loop_vertex_weight(int n)
{
  if(n == 6) return 1.0 / 16.0;                 // exact, so regular patches stay exact
  const double c = 3.0 / 8.0 + 0.25 * std::cos(2.0 * loop_pi() / n);
  return (5.0 / 8.0 - c * c) / n;
}

/// Weight of each neighbour in the limit mask: x_inf = (1 - n chi) x0 + chi sum(xi).
inline double loop_limit_weight(int n)
{
  if(n == 6) return 1.0 / 12.0;
  return 1.0 / (n + 3.0 / (8.0 * loop_vertex_weight(n)));
}

/// Tangent-mask coefficients of neighbour j (0-based, counter-clockwise) of a valence-n vertex.
/// t_u = sum cos(2 pi j / n) x_j, t_v = sum sin(2 pi j / n) x_j span the limit tangent plane and
/// t_u x t_v is the oriented normal.
inline double loop_tangent_u(int j, int n) { return std::cos(2.0 * loop_pi() * j / n); }
inline double loop_tangent_v(int j, int n) { return std::sin(2.0 * loop_pi() * j / n); }

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_RULES_H
