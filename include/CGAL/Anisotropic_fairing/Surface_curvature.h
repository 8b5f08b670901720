// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Curvature of a parametrised surface x(xi1, xi2) in R^kappa at one point, from its first and second
// derivatives (doc/Anisotropic_fairing/design/loop-fem.md section 7, the paper's garbled section 5 reconstructed): the
// mean-curvature
// vector H = Q (g22 t11 + g11 t22 - 2 g12 t12) / (2 det G), and the principal curvatures and directions
// with respect to a unit normal nu, from the generalised eigenproblem B_nu c = k G c with
// B_nu = [t_ij . nu].

#ifndef CGAL_ANISOTROPIC_FAIRING_SURFACE_CURVATURE_H
#define CGAL_ANISOTROPIC_FAIRING_SURFACE_CURVATURE_H

#include <CGAL/Anisotropic_fairing/Quadrature_point_geometry.h>
#include <CGAL/Anisotropic_fairing/internal/types/Symmetric_2x2_eigen.h>
#include <CGAL/Anisotropic_fairing/internal/types/Vector3.h>

#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {

/*!
\ingroup PkgAnisotropicFairingFunctions
Principal curvatures and directions at a point of a surface in \f$\mathbb{R}^\kappa\f$, with respect to
a unit normal \f$\nu\f$: the oriented normal \f$t_1\times t_2/|t_1\times t_2|\f$ for \f$\kappa = 3\f$, the
normalised mean-curvature vector \f$h = H/|H|\f$ for \f$\kappa > 3\f$ (Bajaj and Xu, section 5).
*/
struct Principal_curvatures
{
  double k1 = 0, k2 = 0;                 ///< \f$k_1 \leq k_2\f$; \f$k_1 + k_2 = 2H\cdot\nu\f$
  /// parametric direction of \f$k_1\f$ : \f$e_1 = c_{1,1} t_1 + c_{1,2} t_2\f$ , with \f$c_a^T G c_b = \delta_{ab}\f$
  std::array<double, 2> c1{ { 0, 0 } };
  std::array<double, 2> c2{ { 0, 0 } };  ///< parametric direction of \f$k_2\f$
  /// false where the normal is undefined: for \f$\kappa > 3\f$ where \f$|H|\f$ is below the threshold
  /// given (planar or minimal points), for any \f$\kappa\f$ where the metric is degenerate. Then
  /// \f$k_1 = k_2 = 0\f$ and \f$c_1, c_2\f$ are still a \f$G\f$-orthonormal pair.
  bool defined = false;
};

/// \ingroup PkgAnisotropicFairingFunctions
/// Writes the mean-curvature vector \f$H = \frac12\Delta_M x\f$ (`q.dimension` values) into `H`; for the
/// unit sphere \f$H = -x\f$.
inline void mean_curvature_vector(const Quadrature_point_geometry& q, double* H)
{
  const int k = q.dimension;
  double d1 = 0, d2 = 0;
  for(int c = 0; c < k; ++c)
  {
    H[c] = (q.g22 * q.t11[c] + q.g11 * q.t22[c] - 2 * q.g12 * q.t12[c]) / (2 * q.det);
    d1 += q.t1[c] * H[c];
    d2 += q.t2[c] * H[c];
  }
  // remove the tangential part: H - T G^-1 T^T H
  const double a1 = (q.g22 * d1 - q.g12 * d2) / q.det, a2 = (q.g11 * d2 - q.g12 * d1) / q.det;
  for(int c = 0; c < k; ++c) H[c] -= a1 * q.t1[c] + a2 * q.t2[c];
}

/// \ingroup PkgAnisotropicFairingFunctions
/// The principal curvatures and directions at the point described by `q` (its second derivatives are
/// used). For \f$\kappa > 3\f$ the normal is \f$h = H/|H|\f$, undefined where \f$|H| \leq\f$
/// `undefined_mean_curvature` (in 1/length; choose it relative to the model's scale).
inline Principal_curvatures principal_curvatures(const Quadrature_point_geometry& q,
                                                 double undefined_mean_curvature = 0)
{
  Principal_curvatures pc;
  const int k = q.dimension;
  // G = R R^T with R lower triangular; the G-orthonormal frame is C = R^-T Y
  if(!(q.det > 0) || !(q.g11 > 0)) return pc;
  const double r11 = std::sqrt(q.g11), r21 = q.g12 / r11, r22 = std::sqrt(q.det) / r11;
  // the unit normal (on the stack for up to 8 components: the tensor asks at every quadrature point)
  double small[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
  std::vector<double> large(k > 8 ? std::size_t(k) : 0, 0.0);
  double* nu = k > 8 ? large.data() : small;
  if(k == 3)
  {
    internal::vec3(nu) = internal::vec3(q.t1).cross(internal::vec3(q.t2));
  }
  else mean_curvature_vector(q, nu);
  double norm = 0;
  for(int c = 0; c < k; ++c) norm += nu[c] * nu[c];
  norm = std::sqrt(norm);
  const bool normal_defined = k == 3 ? norm > 0 : norm > undefined_mean_curvature && norm > 0;
  // second fundamental form B = [t_ij . nu]
  double b11 = 0, b12 = 0, b22 = 0;
  if(normal_defined)
    for(int c = 0; c < k; ++c)
    {
      b11 += q.t11[c] * nu[c] / norm;
      b12 += q.t12[c] * nu[c] / norm;
      b22 += q.t22[c] * nu[c] / norm;
    }
  // S = R^-1 B R^-T (symmetric 2x2)
  const double i11 = 1 / r11, i21 = -r21 / (r11 * r22), i22 = 1 / r22;   // R^-1 = [[i11, 0], [i21, i22]]
  const double m11 = i11 * b11, m12 = i11 * b12;                          // R^-1 B
  const double m21 = i21 * b11 + i22 * b12, m22 = i21 * b12 + i22 * b22;
  const double s11 = m11 * i11, s12 = m11 * i21 + m12 * i22, s22 = m21 * i21 + m22 * i22;
  const internal::Symmetric_2x2_eigen e = internal::symmetric_2x2_eigen(s11, s12, s22);
  pc.k1 = e.k1;
  pc.k2 = e.k2;
  const double y1x = e.x, y1y = e.y, y2x = -e.y, y2y = e.x;   // unit eigenvectors of k1 and k2
  // c = R^-T y with R^-T = [[i11, i21], [0, i22]]
  pc.c1 = { { i11 * y1x + i21 * y1y, i22 * y1y } };
  pc.c2 = { { i11 * y2x + i21 * y2y, i22 * y2y } };
  pc.defined = normal_defined;
  return pc;
}

} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_SURFACE_CURVATURE_H
