// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the time stepper is told by the driver: the numbers of the run, in the units they are given in.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STEPPER_SETTINGS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STEPPER_SETTINGS_H

#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Noise_estimate.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_units.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Spd_solvers.h>

#include <cstddef>
#include <limits>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

struct Stepper_settings
{
  int order = 2;                    // of the flow: 2 (diffusion), 4 (Fourth_order_system.h)
  double time_step = 1e-3;          // tau in units of time_unit^order
  Length_unit time_unit = Length_unit::SCALE;
  double fidelity_weight = 0;       // omega, relative (omega = w / scale^2) or absolute
  bool relative_fidelity = true;
  std::size_t maximum_steps = 10;
  Stopping_criteria stopping;
  Linear_solver solver = Linear_solver::AUTOMATIC;
  double solver_tolerance = 1e-8;
  int solver_maximum_iterations = 10000;
  Direct_solver_factory direct_solver;   // the factorisation (empty: Sparse_cholesky)
  // bytes a factorisation may take beyond the run's predicted memory (Memory_estimate.h): AUTOMATIC does not
  // factorise a system whose factor would not fit, and iterates instead
  double factor_budget = std::numeric_limits<double>::infinity();
  bool verbose = false;
  bool measure_limit_surface = false;   // the positions measured are the Loop limit points of the control points
  bool limit_written = false;       // the positions written are (a bound holds them: Deviation_bound.h)
  const Noise_estimate* noise = nullptr;   // of the input, in the stepper's numbering (noise criterion)
  int maximum_rejections = 5;       // retries of a step, each with a quarter of the time step
  bool local_time_scale = false;    // the time step follows the mesh's density (Local_time_scale.h)
  double maximum_deviation = 0;     // the bound on the written geometry's motion (0: none), in units of l if relative
  bool relative_deviation = true;
  double attribute_maximum_deviation = 0;   // on the attribute columns as the stepper holds them (0: none)
  // the named parameter strength: the noise criterion's target is stopping.noise_discrepancy x strength x the
  // noise; above 1 the fourth-order flow is read at the scale strength x h too (Step_control.h)
  double strength = 1;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STEPPER_SETTINGS_H
