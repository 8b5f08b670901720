// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The choices a caller of anisotropic_fairing() makes besides plain numbers: which element, which
// positions to write back, which linear solver, and when to stop. Passed as named parameters.

#ifndef CGAL_ANISOTROPIC_FAIRING_FAIRING_SETTINGS_H
#define CGAL_ANISOTROPIC_FAIRING_FAIRING_SETTINGS_H

namespace CGAL {
namespace Anisotropic_fairing {

/// \ingroup PkgAnisotropicFairingFunctions
/// The finite element that discretises the diffusion (named parameter `finite_element`).
enum class Finite_element {
  LOOP,   ///< Loop-subdivision limit-surface elements (Bajaj & Xu): smooth, the default
  /// piecewise-linear (P1) hat functions on the mesh itself: consistent mass, cotangent stiffness (Clarenz et al.)
  LINEAR
};

/// \ingroup PkgAnisotropicFairingFunctions
/// What is written into the point map after fairing (named parameter `output_positions`).
enum class Output_positions {
  /// the points of the faired smooth surface at the vertices (the Loop limit points; the vertices
  /// themselves for the linear element). The default: the output mesh interpolates the faired surface.
  LIMIT_SURFACE,
  /// the faired control points: the mesh whose Loop limit surface is the faired surface.
  /// Choose this to subdivide, resample or fair again without shrinking by the limit masks.
  CONTROL_POINTS
};

/// \ingroup PkgAnisotropicFairingFunctions
/// How an attribute map is faired with the geometry (named parameter `attribute_mode`); Bajaj and Xu's
/// cases (a)-(d). Without an attribute map only `GEOMETRY_ONLY` (the default then) makes sense.
enum class Attribute_mode {
  /// (b), the default with an attribute map: geometry and attributes evolve with the operator of the
  /// geometry's surface (one matrix, all columns in one solve); the attributes do not shape the flow
  SEPARATE,
  /// (a): geometry and attributes form one 2-manifold in \f$\mathbb{R}^{3+d}\f$ (the metric, gradients and
  /// mean-curvature vector use all components), the attributes scaled by `attribute_weight` (length per
  /// attribute unit); where the attribute jumps, the manifold is steep and diffusion across it is slow
  COUPLED,
  /// (c): the geometry is fixed and only the attributes diffuse on it, a linear problem: the matrices
  /// are assembled and factorised once, every step is one solve
  ATTRIBUTES_ONLY,
  /// (d): only the geometry is faired; the attribute map is neither read nor written
  GEOMETRY_ONLY
};

/// \ingroup PkgAnisotropicFairingFunctions
/// What a border holds fixed (named parameter `boundary_handling`). Boundary vertices are always held,
/// and never written: their input positions and attribute values are kept in both output modes.
enum class Boundary_handling {
  /// the default: the limit boundary curve does not move. Besides the boundary vertices, this holds
  /// the interior vertices whose basis functions are non-zero on the limit boundary curve (next to
  /// corners with two triangles, to boundary vertices with four or more, to extraordinary vertices
  /// beside the border): without them the border slides, even on a plane. The linear element's
  /// boundary curve is the border polygon, so it holds the boundary vertices only.
  HOLD_BOUNDARY_CURVE,
  /// the paper's choice (Bajaj & Xu, section 4.3): only the boundary vertices are held; the limit
  /// boundary curve may move where interior vertices influence it
  HOLD_BOUNDARY_VERTICES
};

/// \ingroup PkgAnisotropicFairingFunctions
/// The solver of the symmetric positive definite system of each step (named parameter `linear_solver`).
enum class Linear_solver {
  /// conjugate gradients preconditioned by the diagonal, warm-started from the previous step, all
  /// columns in one block; linear cost per step
  CONJUGATE_GRADIENT,
  /// sparse LDL^T (Eigen's `SimplicialLDLT`); the symbolic analysis is done once, only the numeric
  /// factorisation is repeated; exact, but its cost grows faster than linearly with the mesh size
  CHOLESKY,
  /// the default: conjugate gradients, weighed against the factorisation when they become slow. When a
  /// step needs more than `automatic_cholesky_trial_iterations` iterations (large \f$\tau/h^2\f$, poorly shaped
  /// meshes), the next step is factorised; from then on the run factorises whenever that costs less than
  /// the next conjugate-gradient step is predicted to (the last one's cost, scaled by the growth of the
  /// iteration count). A step whose iterations fail to converge is solved
  /// again by `CHOLESKY`; the iterations give way after as many as cost one factorised step (before one
  /// was made: ten times `automatic_cholesky_trial_iterations`), and the next step is iterated again
  /// unless they gave way twice in a row. Factorisation is only tried up to `automatic_cholesky_limit` free vertices
  /// (its fill grows faster than linearly). The costs are counted operations (the iterations' sparse
  /// products, the factor's columns), not times, so that the choice and the result are the same on every
  /// machine and at any number of threads; a `sparse_linear_solver` of the user's is timed instead.
  AUTOMATIC
};

/// \ingroup PkgAnisotropicFairingFunctions
/// The most free vertices for which `Linear_solver::AUTOMATIC` tries the factorisation.
constexpr int automatic_cholesky_limit = 50000;

/// \ingroup PkgAnisotropicFairingFunctions
/// Conjugate-gradient iterations in a step above which `Linear_solver::AUTOMATIC` tries the factorisation.
constexpr int automatic_cholesky_trial_iterations = 100;

/*!
\ingroup PkgAnisotropicFairingFunctions
The stopping criteria (27)-(29) of Bajaj & Xu and a steady-state test (named parameter `stopping_criteria`).

The run ends after `number_of_iterations` steps or as soon as one enabled criterion holds after a step.
With \f$\mathcal{H}(t) = \int_{M(t)} |H|^2 dA / \int_{M(0)} |H|^2 dA\f$ and its backward difference
\f$\mathcal{H}'\f$ (so \f$\mathcal{H}'(0)\f$ is the first difference):
- (27) \f$|\mathcal{H}'(t)/\mathcal{H}'(0)| \le\f$ `curvature_rate_ratio` (from the second step on);
- (28) \f$|\mathcal{H}'(t)| \le\f$ `curvature_rate`;
- (29) \f$\max_i |x_i(t) - x_i(0)| \ge\f$ `displacement` (control points);
- steady state: \f$\max_i |x_i(t_{n+1}) - x_i(t_n)| / \tau \le\f$ `steady_speed` (the flow has stopped, e.g. balanced by
the fidelity term);
- noise level (the discrepancy principle): the written surface has moved off the input, along the input's
  normals and in units of the local edge length (robust deviation over the vertices), by `noise_discrepancy`
  times the noise the package estimates from the input itself (`Fairing_report::noise_level`), times the named
  parameter `strength` (1 unless given). Removing noise
  of deviation \f$\sigma\f$ moves the vertices by about \f$\sigma\f$; diffusing further removes shape.
  The run ends on the surface where the level is reached: the step that passes it is taken again,
  shorter, until it ends within 2% of the level (the rest is interpolated).

A criterion is disabled by a value \f$\le 0\f$. With `relative_units` (the default) the scale-dependent
thresholds are measured with the model's scale \f$\ell = \sqrt{\mathrm{Area}(M(0))/4\pi}\f$ (the radius of
the sphere of equal area): `displacement` in units of \f$\ell\f$, and time in units of \f$\ell^2\f$, so
`curvature_rate` is per unit of \f$t/\ell^2\f$ and `steady_speed` in \f$\ell\f$ per unit of \f$t/\ell^2\f$.
The defaults are the paper's values read on a unit-size model. With `relative_units = false` they are in model units.
*/
struct Stopping_criteria
{
  double curvature_rate_ratio = 0.005; ///< epsilon_1 of (27)
  double curvature_rate = 8.0;         ///< epsilon_2 of (28)
  double displacement = 0.2;           ///< epsilon_3 of (29)
  double steady_speed = 1e-4;          ///< steady-state speed
  double noise_discrepancy = 0;        ///< the noise criterion: displacement in units of the estimated noise (0: off)
  bool relative_units = true;          ///< thresholds relative to the model's scale

  /// the default when no time step is given (automatic parameters): the noise criterion at
  /// `automatic_noise_discrepancy` and the steady state; (27)-(29) off, since they stop denoising runs early
  static Stopping_criteria automatic();

  /// no criterion: exactly `number_of_iterations` steps are taken (unless a failure or the callback stops the run)
  static Stopping_criteria none()
  {
    Stopping_criteria s;
    s.curvature_rate_ratio = s.curvature_rate = s.displacement = s.steady_speed = s.noise_discrepancy = 0;
    return s;
  }
};

/// \ingroup PkgAnisotropicFairingFunctions
/// The most steps of a run with automatic parameters (no time step and no `number_of_iterations` given);
/// the noise criterion normally ends it far earlier.
constexpr unsigned automatic_maximum_steps = 200;

/// \ingroup PkgAnisotropicFairingFunctions
/// The noise criterion's factor in `Stopping_criteria::automatic()`.
constexpr double automatic_noise_discrepancy = 1.0;

inline Stopping_criteria Stopping_criteria::automatic()
{
  Stopping_criteria s = none();
  s.noise_discrepancy = automatic_noise_discrepancy;
  s.steady_speed = 1e-4;
  return s;
}

} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_FAIRING_SETTINGS_H
