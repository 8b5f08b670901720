// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What anisotropic_fairing() returns: how the run ended and the statistics of every step.

#ifndef CGAL_ANISOTROPIC_FAIRING_FAIRING_REPORT_H
#define CGAL_ANISOTROPIC_FAIRING_FAIRING_REPORT_H

#include <CGAL/Anisotropic_fairing/Fairing_settings.h>

#include <cstddef>
#include <array>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {

/// \ingroup PkgAnisotropicFairingFunctions
/// How a fairing run ended. Anything but `SUCCESS` leaves the mesh and the maps untouched.
enum class Fairing_status {
  SUCCESS,            ///< the result was written back
  SOLVER_FAILED,      ///< the linear solver failed (no convergence, or factorisation failure)
  NON_FINITE_VALUE,   ///< a NaN or infinite value appeared in the solution
  DEGENERATE_METRIC,  ///< the surface pinched: \f$\sqrt{\det G} \le 0\f$ (or not finite) at a quadrature point
  /// a connected component of the surface shrank to (almost) nothing: area below 1% of its initial one
  COLLAPSED,
  /// the first step folded the surface (or made \f$\int|H|^2\f$ explode) even when retried with 1/1024 of the time
  /// step, or every step taken left more folded edges than the input had
  FOLDED,
  /// the run's predicted memory (`Fairing_report::predicted_memory`) exceeds what the process may take
  /// (`Fairing_report::available_memory`): refused before its set-up; the named parameter `memory_limit` overrides
  INSUFFICIENT_MEMORY
};

/// \ingroup PkgAnisotropicFairingFunctions
/// Why the run stopped.
enum class Stop_reason {
  MAXIMUM_STEPS,        ///< `number_of_iterations` steps were taken
  CURVATURE_RATE_RATIO, ///< criterion (27)
  CURVATURE_RATE,       ///< criterion (28)
  DISPLACEMENT,         ///< criterion (29)
  STEADY_STATE,         ///< the flow stopped moving
  CALLBACK,             ///< the callback asked to stop
  NO_FREE_VERTEX,       ///< every vertex is held (constrained or on a border): nothing can move, no step is taken
  FAILURE,              ///< see `Fairing_report::status`
  /// the written surface moved off the input by the estimated noise (`Stopping_criteria::noise_discrepancy`); also
  /// before any step, when the limit surface of the input already does
  NOISE_LEVEL,
  /// a step would have left an unsound surface (folded, pinched, overflowing, \f$\int|H|^2\f$ exploding) even with
  /// 1/1024 of the time step: the run ended on the last sound surface, and `Fairing_report::message` says what failed
  STEP_REJECTED,
  /// the noise criterion, fourth-order flow: its displacement off the input stopped growing short of the estimated
  /// noise. What still moves then is shape: the displacement grows more slowly than a wave of \f$4\pi h\f$ (h: the mean
  /// edge length) decays under the flow, \f$1/16\f$ per unit of time \f$h^4\f$
  NOISE_REMOVED,
  /// the noise criterion with a maximum deviation (`maximum_deviation`): the written surface's displacement off the
  /// input grew by less than 1% in a step, short of the estimated noise: the bound holds it there
  DEVIATION_BOUND,
  /// the normal-field candidate (not yet compared by the default run; measured by `bench/bench_estimate_soundness`):
  /// the pass whose estimated error of the face normals is the lowest (the estimate stopped falling)
  LOWEST_ESTIMATE,
  /// a run of the default run's comparison (never the run kept; in `Fairing_report::runs`): its estimated error
  /// rose, above another run's by more than twice the standard error of their difference, so it was ended
  DROPPED
};

/// \ingroup PkgAnisotropicFairingFunctions
/// Short snake_case name of a stop reason (as written in the command-line tool's JSON report).
inline const char* to_string(Stop_reason r)
{
  switch(r)
  {
    case Stop_reason::MAXIMUM_STEPS: return "max_steps";
    case Stop_reason::CURVATURE_RATE_RATIO: return "curvature_rate_ratio";
    case Stop_reason::CURVATURE_RATE: return "curvature_rate";
    case Stop_reason::DISPLACEMENT: return "displacement";
    case Stop_reason::STEADY_STATE: return "steady_state";
    case Stop_reason::CALLBACK: return "callback";
    case Stop_reason::NO_FREE_VERTEX: return "no_free_vertex";
    case Stop_reason::NOISE_LEVEL: return "noise_level";
    case Stop_reason::NOISE_REMOVED: return "noise_removed";
    case Stop_reason::DEVIATION_BOUND: return "deviation_bound";
    case Stop_reason::LOWEST_ESTIMATE: return "lowest_estimate";
    case Stop_reason::DROPPED: return "dropped";
    case Stop_reason::STEP_REJECTED: return "step_rejected";
    case Stop_reason::FAILURE: return "failure";
  }
  return "failure";   // not an enumerator: a value cast from an integer
}

/// \ingroup PkgAnisotropicFairingFunctions
/// Short snake_case name of a status.
inline const char* to_string(Fairing_status s)
{
  switch(s)
  {
    case Fairing_status::SUCCESS: return "success";
    case Fairing_status::SOLVER_FAILED: return "solver_failed";
    case Fairing_status::NON_FINITE_VALUE: return "non_finite_value";
    case Fairing_status::DEGENERATE_METRIC: return "degenerate_metric";
    case Fairing_status::FOLDED: return "folded";
    case Fairing_status::COLLAPSED: return "collapsed";
    case Fairing_status::INSUFFICIENT_MEMORY: return "insufficient_memory";
  }
  return "collapsed";   // not an enumerator: a value cast from an integer
}

/*!
\ingroup PkgAnisotropicFairingFunctions
Statistics of one time step \f$t_{n-1} \to t_n\f$; the geometric quantities are those of the surface
\f$M(t_n)\f$ reached by the step (area, energy and \f$\int|H|^2\f$ of step 0 are in `Fairing_report::initial`).
*/
struct Fairing_step
{
  std::size_t step = 0;         ///< n (1 for the first step)
  /// \f$t_n\f$ , the sum of the time steps taken (of the largest connected component), model units
  double time = 0;
  double time_step = 0;         ///< the time step of this step: \f$\tau\f$, or a fraction of it after a rejected step
  int solver_iterations = 0;    ///< CG iterations (the largest over the columns), 1 for a direct solve
  double residual = 0;          ///< largest relative residual \f$\|b - AX\|/\|b\|\f$ over the columns
  double area = 0;              ///< area of the surface
  /// \f$\mathrm{trace}(X^T L(D) X)\f$ : the Dirichlet energy (2 area when D = I); for the last step of a run whose
  /// tensor reads a prefiltered surface, D is read on the \f$M_\varepsilon\f$ the step was taken from (the surface's
  /// own would cost a prefilter solve that no step uses)
  double energy = 0;
  double H_integral = 0;        ///< \f$\int |H|^2 dA\f$ (mean-curvature vector H, \f$\Delta x = 2H\f$)
  double max_displacement = 0;  ///< \f$\max_i |x_i(t_n) - x_i(0)|\f$ over the control points, model units
  double step_displacement = 0; ///< \f$\max_i |x_i(t_n) - x_i(t_{n-1})|\f$, model units
  /// wall time to assemble the system of this step (for the last step, plus the final surface's statistics)
  double assemble_seconds = 0;
  double solve_seconds = 0;     ///< wall time to solve it
  bool direct_solve = false;    ///< solved by the sparse factorisation (else by conjugate gradients)
  /// how far the written surface moved off the input along the input's normals, in units of the local edge length
  /// (robust deviation; see `Fairing_report::noise_level`); 0 without the noise criterion
  double noise_displacement = 0;
  /// which run of the call the step belongs to: the default run compares several flows, each also on a probed copy of
  /// the input (`runs` at most), and `number_of_iterations` bounds their steps in all
  std::size_t run = 1;
  std::size_t runs = 1;         ///< the most runs the call makes
  std::string run_name;         ///< what the run is, e.g. "anisotropic flow", "isotropic flow on the probed input"
};

/*!
\ingroup PkgAnisotropicFairingFunctions
One run a call made, in `Fairing_report::runs`: the default run makes several (its candidate flows, a flow's run on
the probed input when its risk estimate needs one, the anisotropic flow's replaying its steps, the kept flow's run
to `strength`), any other call one. What it cost, how it ended (`Stop_reason::DROPPED`: the
comparison ended it), and what the comparison made of it.
*/
struct Fairing_run
{
  std::string name;             ///< the callback's `Fairing_step::run_name` ("" for a call's only run)
  std::size_t steps = 0;        ///< accepted steps
  std::size_t rejected_steps = 0; ///< steps rejected by the step control
  double seconds = 0;           ///< wall time, from its set-up to its written result
  Fairing_status status = Fairing_status::SUCCESS; ///< how it ended
  Stop_reason stop_reason = Stop_reason::MAXIMUM_STEPS; ///< why it ended
  /// the risk estimate the comparison gave its result, in the unit `choices` names; NaN when it has none (not
  /// compared, only a lower bound carried along, a run on the probed input, or no comparison)
  double estimate = std::numeric_limits<double>::quiet_NaN();
  bool kept = false;            ///< its result is the one written
};

/*!
\ingroup PkgAnisotropicFairingFunctions
The result of `anisotropic_fairing()`.
*/
struct Fairing_report
{
  Fairing_status status = Fairing_status::SUCCESS; ///< how the run ended
  Stop_reason stop_reason = Stop_reason::MAXIMUM_STEPS; ///< why it ended
  /// a one-line explanation of a failure, or of a run that ended early on the last sound surface
  /// (`Stop_reason::STEP_REJECTED`); empty otherwise
  std::string message;
  std::vector<Fairing_step> steps;///< one entry per completed step
  /// area, energy and \f$\int|H|^2\f$ of the input surface (step 0); the energy is NaN when a run with the
  /// anisotropic tensor's relative parameters takes no step (a clean mesh at the noise stop, or no step allowed):
  /// its operator, which needs the prefiltered surface \f$M_\varepsilon\f$, is then not assembled
  Fairing_step initial;
  /// \f$\ell = \sqrt{\mathrm{Area}(M(0))/4\pi}\f$ , the length unit of relative parameters
  double scale = 0;
  double time_step = 0;           ///< \f$\tau\f$ in model units (length^2, or length^4 for the fourth-order flow)
  /// 2: diffusion (the paper's flow); 4: the fourth-order flow \f$\partial_t x = -(M^{-1}L)^2 x\f$ (named parameter
  /// `flow_order`)
  int flow_order = 2;
  double fidelity_weight = 0;     ///< \f$\omega\f$ in model units (1/time)
  double mean_edge_length = 0;    ///< h of the input mesh; \f$\tau/h^2\f$ governs the linear solver's work
  bool used_cholesky = false;     ///< whether any step was solved by the sparse factorisation
  std::size_t vertices = 0;       ///< number of vertices
  std::size_t faces = 0;          ///< number of faces
  /// vertices held fixed: by the user's constraints, by a border (`boundary_held_vertices`), or because they are on no
  /// face (`isolated_vertices`)
  std::size_t constrained_vertices = 0;
  std::size_t boundary_vertices = 0;    ///< vertices on a border of the mesh
  /// vertices held because of a border: the boundary vertices and, with `Boundary_handling::HOLD_BOUNDARY_CURVE`, the
  /// interior vertices that shape the limit boundary curve
  std::size_t boundary_held_vertices = 0;
  std::size_t boundary_loops = 0;       ///< number of boundary loops (holes and outer borders)
  Attribute_mode attribute_mode = Attribute_mode::GEOMETRY_ONLY; ///< how the attributes were faired
  /// number of attribute components faired (0 without attributes or in `GEOMETRY_ONLY`)
  std::size_t attribute_dimension = 0;
  std::size_t isolated_vertices = 0;    ///< vertices on no face (scanner leftovers): held and left as they are
  /// each step's displacement lost its tangential part (the tensor's `normal_motion_only()`, e.g.
  /// `Anisotropic_diffusion_tensor`'s default)
  bool normal_motion_only = false;
  /// connected components of the surface; relative parameters are measured per component
  std::size_t components = 0;
  /// steps rejected because they left an unsound surface, each retried with a quarter of the time step
  std::size_t rejected_steps = 0;
  /// the time step, the stopping rule and (unless given) the tensor were chosen from the mesh (no time step was given)
  bool automatic_parameters = false;
  /// the input's noise estimated from the mesh itself: deviation along the normal in units of the local mean edge
  /// length (robust; times `noise_correlation_factor` where the noise is correlated over the surface)
  double noise_level = 0;
  /// the same in model units, \f$\sigma \approx\f$ `noise_level` \f$\times\f$ `mean_edge_length`
  double noise_deviation = 0;
  /// how far the noise is correlated over the surface: the point of the curve of unit noise averaged k times with
  /// its ring's mean nearest to what the noise's second differences read at lags 1 and 2 (0: independent from
  /// vertex to vertex)
  double noise_correlation = 0;
  /// the factor `noise_level` includes for that correlation: 1 unless the noise lies on that curve nearer averaged
  /// noise than independent noise (then 1 / the reading of unit noise there; about 1.5 for noise averaged once)
  double noise_correlation_factor = 1;
  /// with automatic parameters: vertices that stood out of their ring alone, moved to its centroid before the noise was
  /// estimated, when they were at least 2% of the vertices (impulsive noise; a clean mesh's tips and corners are far
  /// fewer); 0 otherwise
  std::size_t removed_spikes = 0;
  /// with automatic parameters, the noise model read from the mesh beyond `noise_level` (after the spikes were
  /// moved): the deviation across the normals, in each direction, in units of the local mean edge length (the noise
  /// there and the mesh's own irregular sampling alike: motion within the surface changes no normal); 0 otherwise
  double tangential_noise_level = 0;
  /// how much the deviation along the normals varies over the surface: the 90th over the 10th percentile of its
  /// local values, each read from the three rings around a vertex and shrunk by what unit noise reads there (1:
  /// the same everywhere); the same across the normals
  double noise_level_spread = 1;
  double tangential_noise_level_spread = 1;   ///< (see `noise_level_spread`)
  /// impulses left after the spikes were moved: the share of the vertices more likely hit than not, a two-component
  /// mixture (a Gaussian core, a wider component) fitted to the noise samples, a hit standing out of its ring alone
  /// (not along a feature line); 0 without
  double impulse_share = 0;
  double impulse_deviation = 0;   ///< the hits' deviation along the normals in units of `noise_level` (0 without)
  /// the coordinates' lattice, per axis, model units: every value a whole number of steps from the smallest, the
  /// step below the mean edge length and at least 32 levels (a quantised file: rounding uniform within the cell);
  /// 0 where the axis is not on one
  std::array<double, 3> lattice_step{ { 0, 0, 0 } };
  /// how far the written surface moved off the input (as `Fairing_step::noise_displacement`), at the end
  double noise_displacement = 0;
  /// the named parameter `strength`: the noise criterion's target was `Stopping_criteria::noise_discrepancy` times it
  /// times `noise_level` (1: the estimated noise itself)
  double strength = 1;
  /// the anisotropic tensor's threshold \f$\lambda\f$ used, model units (1/length); 0 for the isotropic tensor
  double feature_threshold = 0;
  /// the anisotropic tensor's prefilter time \f$\varepsilon\f$ used, model units; 0 without prefilter
  double prefilter_time = 0;
  /// the share of the way from the input to its Loop limit points that the written positions go,
  /// \f$x = x_0 + w\,(\mathrm{limit}(x_0) - x_0)\f$: below 1 only when the noise stop ends the run before its
  /// first step, the input's own limit surface being off it by more than the noise (Loop element; with
  /// `Output_positions::CONTROL_POINTS` the input is written and this says what the limit output would be)
  double limit_weight = 1;
  /// the bound on how far a written vertex moves off the input (named parameter `relative_maximum_deviation` or
  /// `absolute_maximum_deviation`), model units; 0 without a bound
  double absolute_maximum_deviation = 0;
  /// \deprecated `absolute_maximum_deviation` under its former name, which the named parameters give the relative
  /// bound; filled as it, to be removed (no compiler warning: on a data member the compilers warn wherever a
  /// report is made or copied)
  double maximum_deviation = 0;
  /// the largest distance from a written vertex to its input position, model units (with or without a bound)
  double largest_deviation = 0;
  /// the bound on each vertex's attribute values (`attribute_maximum_deviation`), the attributes' units; 0 without
  double attribute_maximum_deviation = 0;
  /// the largest Euclidean distance between a vertex's written and input attribute values
  double largest_attribute_deviation = 0;
  /// the largest fidelity weight a vertex was given to hold it within a bound, model units (1/time; the global one,
  /// `fidelity_weight`, comes on top)
  double bound_fidelity_weight = 0;
  std::size_t bound_held_vertices = 0;   ///< vertices given a fidelity weight of their own by a bound
  /// in a run not stopped at the noise level, the fidelity weight every vertex got from a bound (model units, 1/time),
  /// at its last value: the steady state within 0.8 of the bound
  double bound_uniform_weight = 0;
  /// steps taken again, with more vertices held, because they carried a vertex past a bound
  std::size_t bound_retaken_steps = 0;
  /// written vertices put on a bound along the line to their input position: their fidelity could not hold them (e.g.
  /// the input's own limit point lies farther off than the bound)
  std::size_t clamped_vertices = 0;
  std::string choices;            ///< with automatic parameters: what was chosen and why, in one sentence
  std::vector<Fairing_run> runs;  ///< every run the call made, in order, with its cost (`Fairing_run`)
  /// with automatic parameters and no tensor given: "anisotropic", "isotropic" or "uniform", the result kept (empty
  /// otherwise; "uniform" is the uniform tensor's fourth-order flow, `flow_order` 4)
  std::string selected_tensor;
  double input_seconds = 0;       ///< the mesh and maps read and checked: numbering, topology, ghost layer
  /// set-up: private numbering, element (patch categories, stencils), sparsity patterns
  double setup_seconds = 0;
  double write_back_seconds = 0;  ///< the result written into the caller's maps
  double total_seconds = 0;       ///< the whole call
  /// bytes the process held when the run was checked against the memory available (its resident set, once the
  /// input was read and its noise estimated; 0 where it cannot be read)
  double memory_in_use = 0;
  /// bytes the run was predicted to take above `memory_in_use` at its peak, from the mesh's size and the parameters;
  /// with an automatic factorisation's factor where it fits beside the run (the check asks for the run without it)
  double predicted_memory = 0;
  /// bytes the process could still take at the check: the named parameter `memory_limit`, or the tightest of the
  /// cgroup's memory limit, the address-space and data limits (`ulimit -v`, `ulimit -d`) and the memory the system
  /// has available; infinity when nothing is known or the check is off
  double available_memory = std::numeric_limits<double>::infinity();
  std::string memory_limited_by;  ///< what sets `available_memory`, e.g. "the address-space limit (ulimit -v)"

  /// true when the result was written back
  bool succeeded() const { return status == Fairing_status::SUCCESS; }
};

} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_FAIRING_REPORT_H
