// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Loop subdivision weights: the vertex rule a(n), the limit mask chi(n) and the tangent masks.
// (Bajaj & Xu 2003, eq. 14-15; limit and tangent masks as in doc/Anisotropic_fairing/design/loop-fem.md section 1.)

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_LOOP_RULES_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_LOOP_RULES_H

#include <cmath>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

inline long double loop_pi() { return 3.141592653589793238462643383279502884L; }

/// Weight of each neighbour in Loop's vertex rule: x0' = (1 - n a) x0 + a sum(xi).
template <typename Real = double>
inline Real loop_vertex_weight(int n)
{
  if(n == 6) return Real(1) / 16;               // exact, so regular patches stay exact
  const long double c = 0.375L + 0.25L * std::cos(2 * loop_pi() / n);
  return Real((0.625L - c * c) / n);
}

/// Weight of each neighbour in the limit mask: x_inf = (1 - n chi) x0 + chi sum(xi).
template <typename Real = double>
inline Real loop_limit_weight(int n)
{
  if(n == 6) return Real(1) / 12;
  return Real(1.0L / (n + 3.0L / (8 * loop_vertex_weight<long double>(n))));
}

/// Tangent-mask coefficients of neighbour j (0-based, counter-clockwise) of a valence-n vertex.
/// t_u = sum cos(2 pi j / n) x_j, t_v = sum sin(2 pi j / n) x_j span the limit tangent plane and
/// t_u x t_v is the oriented normal.
inline double loop_tangent_u(int j, int n) { return double(std::cos(2 * loop_pi() * j / n)); }
inline double loop_tangent_v(int j, int n) { return double(std::sin(2 * loop_pi() * j / n)); }

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_LOOP_RULES_H
