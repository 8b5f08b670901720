// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a diffusion tensor sees at one quadrature point of the current surface, and the 2x2 matrix it
// returns. The stiffness integrand is (D grad phi_i) . grad phi_j = d phi_i^T A d phi_j in the face's
// parameters (xi1, xi2), so a tensor is given by A; D = I gives A = G^-1.

#ifndef CGAL_ANISOTROPIC_FAIRING_QUADRATURE_POINT_GEOMETRY_H
#define CGAL_ANISOTROPIC_FAIRING_QUADRATURE_POINT_GEOMETRY_H

#include <cstddef>

namespace CGAL {
namespace Anisotropic_fairing {

/*!
\ingroup PkgAnisotropicFairingFunctions
The local geometry of the surface \f$x(\xi_1,\xi_2)\f$ in \f$\mathbb{R}^\kappa\f$ at a quadrature point
of a face, as passed to a diffusion tensor. Pointers are valid during the call only.
*/
struct Quadrature_point_geometry
{
  std::size_t face;        ///< face index, in the order of `faces(tm)`
  int point;               ///< index of the quadrature point within the face
  int dimension;           ///< \f$\kappa\f$: number of coordinates of the surface (3 for geometry)
  const double* t1;        ///< \f$\partial x/\partial\xi_1\f$ (`dimension` values)
  const double* t2;        ///< \f$\partial x/\partial\xi_2\f$
  const double* t11;       ///< \f$\partial^2 x/\partial\xi_1^2\f$ (zero for the linear element)
  const double* t12;       ///< \f$\partial^2 x/\partial\xi_1\partial\xi_2\f$
  const double* t22;       ///< \f$\partial^2 x/\partial\xi_2^2\f$
  double g11, g12, g22;    ///< the metric \f$G = [t_i \cdot t_j]\f$
  double det;              ///< \f$\det G > 0\f$
  /// indices (order of `vertices(tm)`) of the control vertices whose basis functions are non-zero on the face
  const int* ring;
  /// the values of those basis functions at the point (sum 1): interpolate per-vertex data with them
  const double* basis;
  int ring_size;           ///< number of entries of `ring` and `basis`
  /// The derivatives at the same point of the prefiltered surface \f$M_\varepsilon\f$ (Bajaj and Xu, section 5),
  /// when the tensor asks for one (a `prefilter_time()` > 0, see `DiffusionTensor`); null pointers otherwise.
  const double* prefiltered_t1 = nullptr;
  const double* prefiltered_t2 = nullptr;   ///< see `prefiltered_t1`
  const double* prefiltered_t11 = nullptr;  ///< see `prefiltered_t1`
  const double* prefiltered_t12 = nullptr;  ///< see `prefiltered_t1`
  const double* prefiltered_t22 = nullptr;  ///< see `prefiltered_t1`
  /// The length scale of the face's connected component relative to the one given to the tensor's
  /// `set_length_scale()` (1 on a mesh of one component): a scale-relative tensor divides its
  /// curvature threshold by it, so that each component is faired as if it were alone.
  double component_scale = 1.0;
};

/// \ingroup PkgAnisotropicFairingFunctions
/// A symmetric 2x2 matrix in the face's parameters: \f$A = [[a_{11}, a_{12}], [a_{12}, a_{22}]]\f$.
struct Parametric_tensor
{
  double a11, a12, a22;
};

/// \ingroup PkgAnisotropicFairingFunctions
/// The inverse metric \f$G^{-1}\f$ at `q` (the tensor of the isotropic flow).
inline Parametric_tensor inverse_metric(const Quadrature_point_geometry& q)
{
  const double inv = 1.0 / q.det;
  return Parametric_tensor{ q.g22 * inv, -q.g12 * inv, q.g11 * inv };
}

} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_QUADRATURE_POINT_GEOMETRY_H
