// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Symmetric Gauss rules on the reference triangle (Dunavant 1985), degrees 4, 6 and 8.
// Integral over T = {xi1, xi2 >= 0, xi1 + xi2 <= 1} of g  ~=  1/2 sum_q w_q g(xi_q), sum w_q = 1.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_ELEMENT_QUADRATURE_RULES_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_ELEMENT_QUADRATURE_RULES_H

#include <CGAL/assertions.h>

#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

struct Triangle_rule_point { double xi1, xi2, weight; };

inline void add_orbit3(std::vector<Triangle_rule_point>& r, double a, double b, double w)
{
  // barycentric orbit (a, b, b): the odd coordinate at each corner in turn
  r.push_back({ b, b, w });
  r.push_back({ a, b, w });
  r.push_back({ b, a, w });
}

inline void add_orbit6(std::vector<Triangle_rule_point>& r, double a, double b, double c, double w)
{
  const double p[6][3] = { {a, b, c}, {a, c, b}, {b, a, c}, {b, c, a}, {c, a, b}, {c, b, a} };
  for(const auto& q : p) r.push_back({ q[1], q[2], w });
}

/// The degree-`degree` rule (4, 6 or 8).
inline std::vector<Triangle_rule_point> triangle_rule(int degree)
{
  std::vector<Triangle_rule_point> r;
  switch(degree)
  {
    case 4:
      add_orbit3(r, 0.108103018168070, 0.445948490915965, 0.223381589678011);
      add_orbit3(r, 0.816847572980459, 0.091576213509771, 0.109951743655322);
      break;
    case 6:
      add_orbit3(r, 0.501426509658179, 0.249286745170910, 0.116786275726379);
      add_orbit3(r, 0.873821971016996, 0.063089014491502, 0.050844906370207);
      add_orbit6(r, 0.053145049844817, 0.310352451033784, 0.636502499121399, 0.082851075618374);
      break;
    case 8:
      r.push_back({ 1.0 / 3.0, 1.0 / 3.0, 0.144315607677787 });
      add_orbit3(r, 0.081414823414554, 0.459292588292723, 0.095091634267285);
      add_orbit3(r, 0.658861384496480, 0.170569307751760, 0.103217370534718);
      add_orbit3(r, 0.898905543365938, 0.050547228317031, 0.032458497623198);
      add_orbit6(r, 0.008394777409958, 0.263112829634638, 0.728492392955404, 0.027230314174435);
      break;
    default:   // the user's degree is checked where it is read (Quadrature_parameters.h)
      CGAL_error_msg("the quadrature degree must be 4, 6 or 8");
  }
  // The tabulated weights carry 15 digits; normalise so that sum w = 1 exactly and the discrete
  // identities (sum of M = area, partition of unity) hold to rounding.
  double s = 0;
  for(const auto& q : r) s += q.weight;
  for(auto& q : r) q.weight /= s;
  return r;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_ELEMENT_QUADRATURE_RULES_H
