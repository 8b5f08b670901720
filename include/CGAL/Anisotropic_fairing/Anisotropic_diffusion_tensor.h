// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The curvature-driven diffusion tensor of Bajaj & Xu (section 5), as reconstructed in loop-fem.md
// section 7: along each principal direction e_a the diffusion is scaled by g(k_a), an edge-stopping
// function of the principal curvature that is 1 below the feature threshold lambda and falls off
// above it, so that noise (small curvature) is smoothed while creases (large curvature) are not.

#ifndef CGAL_ANISOTROPIC_FAIRING_ANISOTROPIC_DIFFUSION_TENSOR_H
#define CGAL_ANISOTROPIC_FAIRING_ANISOTROPIC_DIFFUSION_TENSOR_H

#include <CGAL/Anisotropic_fairing/Quadrature_point_geometry.h>
#include <CGAL/Anisotropic_fairing/Surface_curvature.h>

#include <cmath>
#include <limits>

namespace CGAL {
namespace Anisotropic_fairing {

/*!
\ingroup PkgAnisotropicFairingFunctions
\cgalModels `DiffusionTensor`

\f$D z = \sum_a g(k_a)\,(e_a\cdot z)\,e_a\f$ on the tangent plane, with \f$k_a\f$, \f$e_a\f$ the principal
curvatures and directions (`principal_curvatures()`: with respect to the oriented normal for a surface
in \f$\mathbb{R}^3\f$, to \f$h = H/|H|\f$ for a surface with attributes in \f$\mathbb{R}^{3+d}\f$) and the
edge-stopping function
\f[ g(s) = 1 \ \text{ if } |s| \leq \lambda, \qquad g(s) = \frac{1}{1 + (|s| - \lambda)^2/\lambda^2} \ \text{ otherwise}, \f]
the paper's eq. (32) made even and continuous (as printed it jumps from 1 to 0.2 at \f$s = -\lambda\f$).
In the face's parameters \f$A = \sum_a g(k_a)\,c_a c_a^T\f$ with \f$C^T G C = I\f$; where all
\f$|k_a| \leq \lambda\f$ (flat and gently curved regions) this is \f$G^{-1}\f$, the isotropic tensor, and
where the normal is undefined (\f$|H|\f$ below \f$10^{-10}/\ell\f$ in \f$\mathbb{R}^{3+d}\f$) the tensor is
isotropic too. A cylinder of radius \f$r\f$ then shrinks at the rate \f$g(1/r)/r\f$ instead of \f$1/r\f$.

The threshold is relative to the model's scale \f$\ell = \sqrt{\mathrm{Area}/4\pi}\f$ by default (like
the time step): \f$\lambda = \lambda_{rel}/\ell\f$, so that the same value does the same on a model at any
scale. `anisotropic_fairing()` calls `set_length_scale()` with \f$\ell\f$ before the first step.
*/
class Anisotropic_diffusion_tensor
{
public:
  /// `lambda`: the feature threshold, a curvature, in units of \f$1/\ell\f$ if `relative` (the default;
  /// Bajaj and Xu use 2 to 2.5 on unit-scale models), in model units (1/length) otherwise. A
  /// threshold of \f$+\infty\f$ gives the isotropic tensor.
  explicit Anisotropic_diffusion_tensor(double lambda = 2.0, bool relative = true)
    : lambda_(lambda), relative_(relative), threshold_(lambda) {}

  /// sets \f$\ell\f$: the threshold becomes \f$\lambda_{rel}/\ell\f$ (relative mode), and the mean
  /// curvature below which \f$h\f$ is undefined \f$10^{-10}/\ell\f$
  void set_length_scale(double ell)
  {
    if(relative_) threshold_ = lambda_ / ell;
    undefined_ = 1e-10 / ell;
  }

  /// the threshold in model units (1/length), as used
  double threshold() const { return threshold_; }

  /// the edge-stopping function \f$g\f$
  double edge_stopping(double s) const
  {
    const double a = std::abs(s);
    if(!(a > threshold_)) return 1.0;   // also for an infinite threshold
    const double d = (a - threshold_) / threshold_;
    return 1.0 / (1.0 + d * d);
  }

  /// returns \f$A = \sum_a g(k_a) c_a c_a^T\f$
  Parametric_tensor operator()(const Quadrature_point_geometry& q) const
  {
    const Principal_curvatures pc = principal_curvatures(q, undefined_);
    const double inv = 1.0 / q.det;
    if(!pc.defined) return Parametric_tensor{ q.g22 * inv, -q.g12 * inv, q.g11 * inv };
    const double g1 = edge_stopping(pc.k1), g2 = edge_stopping(pc.k2);
    return Parametric_tensor{ g1 * pc.c1[0] * pc.c1[0] + g2 * pc.c2[0] * pc.c2[0],
                              g1 * pc.c1[0] * pc.c1[1] + g2 * pc.c2[0] * pc.c2[1],
                              g1 * pc.c1[1] * pc.c1[1] + g2 * pc.c2[1] * pc.c2[1] };
  }

private:
  double lambda_;
  bool relative_;
  double threshold_;
  double undefined_ = 0;
};

} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_ANISOTROPIC_DIFFUSION_TENSOR_H
