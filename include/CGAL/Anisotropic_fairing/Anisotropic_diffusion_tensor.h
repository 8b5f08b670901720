// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The curvature-driven diffusion tensor of Bajaj & Xu (section 5), as reconstructed in
// doc/Anisotropic_fairing/design/loop-fem.md section 7: along each principal direction e_a the diffusion is scaled by
// g(k_a), an edge-stopping
// function of the principal curvature that is 1 below the feature threshold lambda and falls off
// above it, so that noise (small curvature) is smoothed while creases (large curvature) are not.

#ifndef CGAL_ANISOTROPIC_FAIRING_ANISOTROPIC_DIFFUSION_TENSOR_H
#define CGAL_ANISOTROPIC_FAIRING_ANISOTROPIC_DIFFUSION_TENSOR_H

#include <CGAL/Anisotropic_fairing/Quadrature_point_geometry.h>
#include <CGAL/Anisotropic_fairing/Surface_curvature.h>

#include <array>
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
\f[ g(s) = 1 \ \text{ if } |s| \leq \lambda,
   \qquad g(s) = \frac{1}{1 + (|s| - \lambda)^2/\lambda^2} \ \text{ otherwise}, \f]
the paper's eq. (32) made even and continuous (as printed it jumps from 1 to 0.2 at \f$s = -\lambda\f$).
In the face's parameters \f$A = \sum_a g(k_a)\,c_a c_a^T\f$ with \f$C^T G C = I\f$; where all
\f$|k_a| \leq \lambda\f$ (flat and gently curved regions) this is \f$G^{-1}\f$, the isotropic tensor, and
where the normal is undefined (\f$|H|\f$ below \f$10^{-10}/\ell\f$ in \f$\mathbb{R}^{3+d}\f$) the tensor is
isotropic too. A cylinder of radius \f$r\f$ then shrinks at the rate \f$g(1/r)/r\f$ instead of \f$1/r\f$.

The threshold is relative to the model's scale \f$\ell = \sqrt{\mathrm{Area}/4\pi}\f$ by default (like
the time step): \f$\lambda = \lambda_{rel}/\ell\f$, so that the same value does the same on a model at any
scale. `anisotropic_fairing()` calls `set_length_scale()` with \f$\ell\f$ before the first step.

<b>Normal motion.</b> \f$\mathrm{div}(D\nabla x)\f$ moves the surface along its normal at the speed
\f$\sum_a g(k_a)\,k_a\f$, which is the anisotropic flow, and also along the surface, by the variation of
\f$g(k_a)\f$ and \f$e_a\f$. The tangential part does not change the shape in the continuum, but on noise,
where \f$g\f$ drops from 1 to almost 0 within one edge, it slides neighbouring control points over each
other in a single step and folds the limit surface (measured on the page \ref af_validation_page, section
\ref sec_AF_tensor_checks). So by default (`normal_motion_only()`) `anisotropic_fairing()` removes from each step's
displacement of a control point its component in the limit tangent plane at that vertex: of
\f$M_\varepsilon\f$ when there is a prefilter (on noise the current surface's normal is mostly noise, and
motion across the noisy surface is what removes it), of the current surface otherwise. Bajaj and Xu keep
the tangential part; pass `false` to do so.
*/
class Anisotropic_diffusion_tensor
{
public:
  /// `lambda`: the feature threshold, a curvature, in units of \f$1/\ell\f$ if `relative` (the default;
  /// Bajaj and Xu use 2 to 2.5 on unit-scale models), in model units (1/length) otherwise. A
  /// threshold of \f$+\infty\f$ gives the isotropic tensor.
  ///
  /// `epsilon`: the prefilter time: the curvature is read on \f$M_\varepsilon\f$, the surface after one
  /// isotropic implicit step of length \f$\varepsilon\f$ from the current one (Bajaj and Xu use
  /// \f$\varepsilon = 0.001\f$), so that noise does not pass for features; in units of \f$\ell^2\f$ if
  /// `relative`, like the time step. The default \f$10^{-3}\f$ did best on the denoising benchmark
  /// (\ref sec_AF_denoising); each step then costs one more isotropic assembly and solve. 0 reads the
  /// curvature on the current surface.
  ///
  /// `normal_motion_only`: move the control points along the surface's normal only (see above).
  explicit Anisotropic_diffusion_tensor(double lambda = 2.0, bool relative = true, double epsilon = 1e-3,
                                        bool normal_motion_only = true)
    : lambda_(lambda), epsilon_(epsilon), relative_(relative), normal_motion_only_(normal_motion_only),
      threshold_(lambda), prefilter_(epsilon) {}

  /// The tensor `anisotropic_fairing()` uses when no tensor and no time step are given: its threshold
  /// and prefilter time are chosen from the mesh (in units of the mean edge length h, from the noise the
  /// package estimates; `Fairing_report::choices` says which) before the first step.
  static Anisotropic_diffusion_tensor automatic()
  {
    Anisotropic_diffusion_tensor t;
    t.automatic_ = true;
    return t;
  }

  /// whether the threshold and prefilter time are still to be chosen from the mesh
  bool is_automatic() const { return automatic_; }

  /// sets the threshold and the prefilter time of an automatic tensor, relative to the length scale
  /// given next to `set_length_scale()` (the mean edge length for automatic tensors); a threshold of
  /// \f$+\infty\f$ and a prefilter time of 0 make it the isotropic tensor, with tangential motion kept
  void choose(double lambda, double epsilon)
  {
    lambda_ = threshold_ = lambda;
    epsilon_ = prefilter_ = epsilon;
    if(std::isinf(lambda) && epsilon == 0) normal_motion_only_ = false;
  }

  /// the threshold \f$\lambda\f$ and the prefilter time \f$\varepsilon\f$ as given (or chosen), before
  /// `set_length_scale()`
  double lambda() const { return lambda_; }
  double epsilon() const { return epsilon_; }

  /// \name Named setters
  /// Each returns the tensor, so that settings chain in place of the constructor's positional arguments:
  /// `Anisotropic_diffusion_tensor().set_lambda(2.5).set_epsilon(5e-4)`. A tensor given a threshold or a
  /// prefilter time is no longer automatic.
  /// @{

  /// the feature threshold \f$\lambda\f$ (units of \f$1/\ell\f$, or 1/length with `set_relative(false)`)
  Anisotropic_diffusion_tensor& set_lambda(double lambda)
  {
    lambda_ = threshold_ = lambda;
    automatic_ = false;
    return *this;
  }
  /// the prefilter time \f$\varepsilon\f$ (units of \f$\ell^2\f$ , or length squared with `set_relative(false)`; 0:
  /// none)
  Anisotropic_diffusion_tensor& set_epsilon(double epsilon)
  {
    epsilon_ = prefilter_ = epsilon;
    automatic_ = false;
    return *this;
  }
  /// whether \f$\lambda\f$ and \f$\varepsilon\f$ are relative to \f$\ell\f$ (the default) or in model units
  Anisotropic_diffusion_tensor& set_relative(bool relative) { relative_ = relative; return *this; }
  /// whether each step's tangential motion is removed (the default; `false`: kept, as Bajaj and Xu do)
  Anisotropic_diffusion_tensor& set_normal_motion_only(bool only) { normal_motion_only_ = only; return *this; }
  /// @}

  /// whether `anisotropic_fairing()` removes the tangential part of each step's displacement
  bool normal_motion_only() const { return normal_motion_only_; }

  /// sets \f$\ell\f$: in relative mode the threshold becomes \f$\lambda/\ell\f$ and the prefilter time
  /// \f$\varepsilon\ell^2\f$; the mean curvature below which \f$h\f$ is undefined is \f$10^{-10}/\ell\f$
  void set_length_scale(double ell)
  {
    // (an infinite lambda stays infinite)
    if(relative_) { threshold_ = lambda_ / ell; prefilter_ = epsilon_ * ell * ell; }
    undefined_ = 1e-10 / ell;
  }

  /// the prefilter time \f$\varepsilon\f$ in model units (length squared), as used
  double prefilter_time() const { return prefilter_; }

  /// the threshold in model units (1/length), as used
  double threshold() const { return threshold_; }

  /// the edge-stopping function \f$g\f$
  double edge_stopping(double s) const { return edge_stopping(s, threshold_); }

  /// returns \f$A = G^{-1} + \sum_a (g(k_a) - 1)\,\hat c_a \hat c_a^T\f$: the \f$k_a\f$ and \f$c_a\f$ of the
  /// prefiltered surface when the point carries it, re-orthonormalised in the current metric
  /// (\f$\hat c_a\f$; without a prefilter \f$\hat c_a = c_a\f$ and this is \f$\sum_a g(k_a) c_a c_a^T\f$)
  Parametric_tensor operator()(const Quadrature_point_geometry& q) const
  {
    Parametric_tensor A = inverse_metric(q);
    Principal_curvatures pc;
    if(q.prefiltered_t1)
    {
      Quadrature_point_geometry p = q;
      p.t1 = q.prefiltered_t1; p.t2 = q.prefiltered_t2;
      p.t11 = q.prefiltered_t11; p.t12 = q.prefiltered_t12; p.t22 = q.prefiltered_t22;
      p.g11 = p.g12 = p.g22 = 0;
      for(int c = 0; c < q.dimension; ++c)
      { p.g11 += p.t1[c] * p.t1[c]; p.g12 += p.t1[c] * p.t2[c]; p.g22 += p.t2[c] * p.t2[c]; }
      p.det = p.g11 * p.g22 - p.g12 * p.g12;
      pc = principal_curvatures(p, relative_ ? undefined_ / q.component_scale : undefined_);
    }
    else pc = principal_curvatures(q, relative_ ? undefined_ / q.component_scale : undefined_);
    if(!pc.defined) return A;
    const double threshold = relative_ ? threshold_ / q.component_scale : threshold_;
    // Gram-Schmidt in the current metric: c^T G c
    auto dot = [&](const std::array<double, 2>& a, const std::array<double, 2>& b) {
      return a[0] * b[0] * q.g11 + (a[0] * b[1] + a[1] * b[0]) * q.g12 + a[1] * b[1] * q.g22;
    };
    std::array<double, 2> c1 = pc.c1, c2 = pc.c2;
    const double n1 = std::sqrt(dot(c1, c1));
    if(!(n1 > 0)) return A;
    c1 = { { c1[0] / n1, c1[1] / n1 } };
    const double d = dot(c2, c1);
    c2 = { { c2[0] - d * c1[0], c2[1] - d * c1[1] } };
    const double n2 = std::sqrt(dot(c2, c2));
    if(!(n2 > 0)) return A;
    c2 = { { c2[0] / n2, c2[1] / n2 } };
    const double w1 = edge_stopping(pc.k1, threshold) - 1, w2 = edge_stopping(pc.k2, threshold) - 1;
    A.a11 += w1 * c1[0] * c1[0] + w2 * c2[0] * c2[0];
    A.a12 += w1 * c1[0] * c1[1] + w2 * c2[0] * c2[1];
    A.a22 += w1 * c1[1] * c1[1] + w2 * c2[1] * c2[1];
    return A;
  }

private:
  static double edge_stopping(double s, double threshold)
  {
    const double a = std::abs(s);
    if(!(a > threshold)) return 1.0;   // also for an infinite threshold
    const double d = (a - threshold) / threshold;
    return 1.0 / (1.0 + d * d);
  }

  double lambda_, epsilon_;
  bool relative_, normal_motion_only_;
  bool automatic_ = false;
  double threshold_, prefilter_;
  double undefined_ = 0;
};

} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_ANISOTROPIC_DIFFUSION_TENSOR_H
