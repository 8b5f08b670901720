// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The diffusion of the uniform (umbrella) Laplacian, on any element: the Dirichlet energy measured
// as if every face were equilateral, so that the operator depends on the connectivity alone: on noisy
// graded scans the noisy metric makes the geometric operator noisy too, and the uniform weights do not
// see it.

#ifndef CGAL_ANISOTROPIC_FAIRING_UNIFORM_DIFFUSION_TENSOR_H
#define CGAL_ANISOTROPIC_FAIRING_UNIFORM_DIFFUSION_TENSOR_H

#include <CGAL/Anisotropic_fairing/Quadrature_point_geometry.h>

#include <cmath>

namespace CGAL {
namespace Anisotropic_fairing {

/*!
\ingroup PkgAnisotropicFairingFunctions
\cgalModels `DiffusionTensor`

The tensor of the uniform Laplacian: \f$(D\nabla\phi_i, \nabla\phi_j)\f$ is the Dirichlet form of
the face's parameter triangle made equilateral, \f$\sqrt{\det G}\,A = \frac{2}{\sqrt 3}
\begin{pmatrix}1 & -1/2\\ -1/2 & 1\end{pmatrix}\f$ in the face's parameters, whatever the surface's
metric \f$G\f$. The stiffness matrix then depends on the mesh's connectivity only (the mass matrix still
on its surface): with the linear element it is the uniform ("umbrella") graph Laplacian divided by
\f$\sqrt 3\f$ (the cotangent weights of equilateral triangles), with the Loop element its smooth
analogue. The flow moves vertices along the surface too, towards an even triangulation.

It suits noisy scans with a graded triangulation (small faces where the surface has detail), where
the surface's own metric is as noisy as its normals. With automatic parameters (no time step given)
its time step follows the mesh's density, as the isotropic tensor's does. It rounds sharp creases
like the isotropic tensor, and on evenly triangulated scans the isotropic tensor does better (page
\ref af_validation_page, section \ref sec_AF_denoising).
*/
struct Uniform_diffusion_tensor
{
  /// returns \f$\frac{2}{\sqrt{3\det G}}\begin{pmatrix}1 & -1/2\\ -1/2 & 1\end{pmatrix}\f$
  Parametric_tensor operator()(const Quadrature_point_geometry& q) const
  {
    const double k = 2 / std::sqrt(3 * q.det);
    return Parametric_tensor{ k, -0.5 * k, k };
  }
};

} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_UNIFORM_DIFFUSION_TENSOR_H
