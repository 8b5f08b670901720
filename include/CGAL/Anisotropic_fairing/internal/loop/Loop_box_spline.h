// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The 12 quartic box-spline basis functions of a regular Loop patch and their first and second
// derivatives (Bajaj & Xu 2003, eq. 17-18; Stam 1998).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_LOOP_BOX_SPLINE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_LOOP_BOX_SPLINE_H

#include <CGAL/Anisotropic_fairing/internal/types/Stencil_row.h>

#include <array>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// Values and derivatives of the 12 basis functions at a parameter point; `b[row][i]` belongs to
/// local control vertex i+1 of the patch numbering (doc/Anisotropic_fairing/design/loop-fem.md section 2):
///
///           1   2
///         3   4   5
///       6   7   8   9
///        10  11  12
///
/// The patch is the triangle (4, 7, 8) with xi0 <-> 4, xi1 <-> 7, xi2 <-> 8.
typedef std::array<std::array<double, 12>, STENCIL_ROWS> Box_spline_values;

class Loop_box_spline
{
  // Each basis function as a polynomial in (u, v) = (xi1, xi2): coef[i][p][q] multiplies u^p v^q.
  typedef std::array<std::array<std::array<long double, 5>, 5>, 12> Coefficients;

  // N1..N4 in barycentric monomials xi0^e0 xi1^e1 xi2^e2, times 12 (the paper's eq. 18).
  struct Term { int e0, e1, e2; long double c; };

  static void add_barycentric_monomial(std::array<std::array<long double, 5>, 5>& poly,
                                       int e0, int e1, int e2, long double c)
  {
    // xi0^e0 = (1 - u - v)^e0 = sum over i+j+k = e0 of multinomial * (-u)^j (-v)^k
    static const long double fact[5] = { 1, 1, 2, 6, 24 };
    for(int j = 0; j <= e0; ++j)
      for(int k = 0; j + k <= e0; ++k)
      {
        const int i = e0 - j - k;
        const long double multinomial = fact[e0] / (fact[i] * fact[j] * fact[k]);
        const long double sign = ((j + k) % 2 == 0) ? 1.0L : -1.0L;
        poly[e1 + j][e2 + k] += c * sign * multinomial;
      }
  }

  static Coefficients make_coefficients()
  {
    static const Term n1[] = { {4,0,0,1}, {3,1,0,2} };
    static const Term n2[] = { {4,0,0,1}, {3,0,1,2} };
    static const Term n3[] = { {4,0,0,1}, {3,1,0,6}, {3,0,1,2}, {2,2,0,12}, {2,1,1,6}, {1,3,0,6},
                               {1,2,1,6}, {0,4,0,1}, {0,3,1,2} };
    static const Term n4[] = { {4,0,0,6}, {3,1,0,24}, {3,0,1,24}, {2,2,0,24}, {2,1,1,60}, {2,0,2,24},
                               {1,3,0,8}, {1,2,1,36}, {1,1,2,36}, {1,0,3,8}, {0,4,0,1}, {0,3,1,6},
                               {0,2,2,12}, {0,1,3,6}, {0,0,4,1} };
    struct Base { const Term* terms; int size; };
    const Base bases[4] = { {n1, 2}, {n2, 2}, {n3, 9}, {n4, 15} };
    // Rotations (paper, after eq. 18): (xi0,xi1,xi2) -> (xi1,xi2,xi0) maps N1..N4 to N10,N6,N11,N7,
    // (xi0,xi1,xi2) -> (xi2,xi0,xi1) maps them to N9,N12,N5,N8 (1-based labels).
    const int identity[4] = { 1, 2, 3, 4 };
    const int rot1[4] = { 10, 6, 11, 7 };
    const int rot2[4] = { 9, 12, 5, 8 };

    Coefficients coef{};
    for(int b = 0; b < 4; ++b)
      for(int t = 0; t < bases[b].size; ++t)
      {
        const Term& m = bases[b].terms[t];
        const long double c = m.c / 12.0L;
        add_barycentric_monomial(coef[identity[b] - 1], m.e0, m.e1, m.e2, c);
        // N(xi1,xi2,xi0): xi1^e0 xi2^e1 xi0^e2 -> exponents (e2, e0, e1) in (xi0, xi1, xi2)
        add_barycentric_monomial(coef[rot1[b] - 1], m.e2, m.e0, m.e1, c);
        // N(xi2,xi0,xi1): xi2^e0 xi0^e1 xi1^e2 -> exponents (e1, e2, e0)
        add_barycentric_monomial(coef[rot2[b] - 1], m.e1, m.e2, m.e0, c);
      }
    return coef;
  }

  static const Coefficients& coefficients()
  {
    static const Coefficients coef = make_coefficients();
    return coef;
  }

public:
  /// Evaluates the 12 basis functions and their derivatives at (xi1, xi2), in precision Real.
  template <typename Real>
  static void evaluate(Real u, Real v, std::array<std::array<Real, 12>, STENCIL_ROWS>& out)
  {
    const Coefficients& coef = coefficients();
    Real up[5] = { 1, u, u * u, u * u * u, u * u * u * u };
    Real vp[5] = { 1, v, v * v, v * v * v, v * v * v * v };
    for(int i = 0; i < 12; ++i)
    {
      Real f = 0, fu = 0, fv = 0, fuu = 0, fuv = 0, fvv = 0;
      for(int p = 0; p <= 4; ++p)
        for(int q = 0; p + q <= 4; ++q)
        {
          const Real c = Real(coef[i][p][q]);
          if(c == 0) continue;
          f += c * up[p] * vp[q];
          if(p >= 1) fu += c * p * up[p - 1] * vp[q];
          if(q >= 1) fv += c * q * up[p] * vp[q - 1];
          if(p >= 2) fuu += c * p * (p - 1) * up[p - 2] * vp[q];
          if(p >= 1 && q >= 1) fuv += c * p * q * up[p - 1] * vp[q - 1];
          if(q >= 2) fvv += c * q * (q - 1) * up[p] * vp[q - 2];
        }
      out[VALUE][i] = f;
      out[D1][i] = fu;
      out[D2][i] = fv;
      out[D11][i] = fuu;
      out[D12][i] = fuv;
      out[D22][i] = fvv;
    }
  }
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_LOOP_BOX_SPLINE_H
