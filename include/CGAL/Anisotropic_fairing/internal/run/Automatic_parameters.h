// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The parameters of a run for which the user gave no time step, in the units of noise on a mesh:
// the mean edge length h of each connected component. How long to diffuse is not chosen here: the
// noise criterion (Stopping_criteria::automatic()) stops the run when the surface has moved off the
// input by the noise estimated from the mesh itself (Noise_estimate.h), so the time step only sets
// the resolution of that search (the last step is interpolated), and the tensor's constants say what
// a feature is, per edge:
//  - time step 0.3 h^2: a noise of 0.2-0.5 h is reached in 3-11 steps; 0.1 h^2 costs three times as
//    many steps for the same result within 0.1-0.6 degrees on the denoising pairs (bench_defaults);
//  - the fourth-order flow's time step 0.1 h^4: the noise is reached in 3-15 steps on our noisy scans at
//    0.2-0.5 h; 0.03 h^4 takes three times as many for results within 0.1 degrees, while at 1 h^4 one step
//    overshoots and the last-step interpolation loses (camel head at 0.2 h: 4.58 degrees against 3.99);
//  - prefilter 0.4 h^2: one isotropic step that removes most of the curvature of noise (at 0.3 h,
//    the best single isotropic step of the Fandisk0.3 pair is 0.41 h^2);
//  - feature threshold 0.1 / h: a surface that turns by more than about 6 degrees per edge on M_eps.
//    With the strongly falling edge-stopping function most of a noisy surface diffuses slowly, and the
//    noise criterion runs it long enough; twice the threshold lost 1.7-3.6 degrees on CAD pairs.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_AUTOMATIC_PARAMETERS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_AUTOMATIC_PARAMETERS_H

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

struct Automatic_parameters
{
  double time_step = 0.3;   // tau / h^2 per step
  double time_step4 = 0.1;  // tau / h^4 per step of the fourth-order flow
  double lambda = 0.1;      // feature threshold, units of 1/h
  double epsilon = 0.4;     // prefilter time, units of h^2
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_AUTOMATIC_PARAMETERS_H
