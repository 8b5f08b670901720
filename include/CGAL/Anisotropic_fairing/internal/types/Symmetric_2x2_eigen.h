// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The closed-form eigen-decomposition of a symmetric 2x2 matrix (a shape operator in a tangent
// frame), shared by the curvature at quadrature points and at vertices. Eigen's computeDirect does the
// same with a shift and a scaling, which rounds differently: amplified over the steps, that moves the
// anisotropic runs of scripts/fixed_runs.sh by up to 4e-12 relative, so the package has its own dozen lines.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_SYMMETRIC_2X2_EIGEN_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_SYMMETRIC_2X2_EIGEN_H

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The eigenvalues k1 <= k2 of [[s11, s12], [s12, s22]], their mean, and a unit eigenvector (x, y) of k1.
struct Symmetric_2x2_eigen
{
  double k1, k2, mean, x, y;
};

/// sqrt(a^2 + b^2): the plain formula where its squares can neither overflow nor lose their digits to
/// underflow, std::hypot (several times slower; the tensor calls this twice per quadrature point) elsewhere
inline double length_2d(double a, double b)
{
  const double m = std::max(std::abs(a), std::abs(b));
  if(m < 1e150 && m > 1e-150) return std::sqrt(a * a + b * b);
  return std::hypot(a, b);
}

inline Symmetric_2x2_eigen symmetric_2x2_eigen(double s11, double s12, double s22)
{
  Symmetric_2x2_eigen e;
  e.mean = 0.5 * (s11 + s22);
  const double dev = length_2d(0.5 * (s11 - s22), s12);
  e.k1 = e.mean - dev;
  e.k2 = e.mean + dev;
  // the eigenvector from the better conditioned of the two rows of S - k1 I
  if(dev == 0) { e.x = 1; e.y = 0; }
  else if(s11 - e.k1 >= s22 - e.k1) { e.x = -s12; e.y = s11 - e.k1; }
  else { e.x = s22 - e.k1; e.y = -s12; }
  const double l = length_2d(e.x, e.y);
  if(l > 0) { e.x /= l; e.y /= l; } else { e.x = 1; e.y = 0; }
  return e;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_SYMMETRIC_2X2_EIGEN_H
