// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Loop subdivision weights: the vertex rule a(n), the limit mask chi(n) and the tangent masks.
// (Bajaj & Xu 2003, eq. 14-15; limit and tangent masks as in doc/Anisotropic_fairing/design/loop-fem.md section 1.)

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_LOOP_RULES_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_LOOP_RULES_H

#include <cmath>
#include <cstddef>
#include <vector>

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

/// The tangent-mask coefficients (cos, sin) of every neighbour of a valence-n vertex, the values of
/// loop_tangent_u/v, computed once per valence up to `tabulated` (the long-double sine and cosine cost as
/// much as the rest of a vertex's tangents; every step of a run reads them).
class Loop_tangent_table
{
public:
  static constexpr int tabulated = 64;

  /// Coefficient pairs (u, v) of neighbours 0..n-1, or null when n is not tabulated.
  static const double* coefficients(int n)
  {
    static const Loop_tangent_table table;
    return n >= 1 && n <= tabulated ? table.values_.data() + table.first_[std::size_t(n)] : nullptr;
  }

private:
  Loop_tangent_table() : first_(std::size_t(tabulated) + 1, 0)
  {
    for(int n = 1; n <= tabulated; ++n)
    {
      first_[std::size_t(n)] = values_.size();
      for(int j = 0; j < n; ++j) { values_.push_back(loop_tangent_u(j, n)); values_.push_back(loop_tangent_v(j, n)); }
    }
  }
  std::vector<std::size_t> first_;
  std::vector<double> values_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_LOOP_RULES_H
