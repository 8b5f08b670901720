// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// D = I: the Laplace-Beltrami operator of the current surface (mean-curvature flow for geometry,
// heat flow for functions on it).

#ifndef CGAL_ANISOTROPIC_FAIRING_ISOTROPIC_DIFFUSION_TENSOR_H
#define CGAL_ANISOTROPIC_FAIRING_ISOTROPIC_DIFFUSION_TENSOR_H

#include <CGAL/Anisotropic_fairing/Quadrature_point_geometry.h>

namespace CGAL {
namespace Anisotropic_fairing {

/*!
\ingroup PkgAnisotropicFairingFunctions
\cgalModels `DiffusionTensor`

The identity tensor: \f$(D\nabla\phi_i, \nabla\phi_j) = \nabla\phi_i\cdot\nabla\phi_j\f$, i.e.
\f$A = G^{-1}\f$ in the face's parameters. With it, fairing the geometry is mean-curvature flow
\f$\partial_t x = \Delta_M x = 2H\f$ and fairing a function is the heat equation on the surface.
It is the default `diffusion_tensor` of a run given a time step; with automatic parameters the run
starts from `Anisotropic_diffusion_tensor::automatic()` (`Fairing_options::diffusion_tensor_or_default()`).
*/
struct Isotropic_diffusion_tensor
{
  /// marks the tensor as \f$G^{-1}\f$ everywhere (kept for compatibility; the package does not read it)
  static constexpr bool is_isotropic = true;

  /// returns \f$G^{-1}\f$
  Parametric_tensor operator()(const Quadrature_point_geometry& q) const
  {
    return inverse_metric(q);
  }
};

} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_ISOTROPIC_DIFFUSION_TENSOR_H
