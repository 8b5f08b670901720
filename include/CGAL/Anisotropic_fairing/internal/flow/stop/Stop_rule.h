// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What every stop rule is made from and reads, and what it answers. A rule is a small type with a
// constructor from Stop_rule_setup and `std::optional<Stop> after_step(const Step_progress&)`; the loop asks
// the rules of Stop_rules.h in their order after each accepted step, and the first that answers ends the run.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_STOP_RULE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_STOP_RULE_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_control.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>

#include <cstddef>
#include <optional>
#include <string>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// What a rule is made from, once per run.
struct Stop_rule_setup
{
  const Stepper_settings& settings;
  bool fixed_surface;        // attributes on a fixed surface: the surface's own measures do not apply
  bool noise_stop;           // the run ends where its written surface is off the input by the noise
  bool bound_active;         // a deviation bound holds the written positions
  double initial_value;      // of the monitored functional: int |H|^2, or the attributes' Dirichlet energy
  double mean_edge;          // h of the whole mesh
};

/// What a rule reads after an accepted step.
struct Step_progress
{
  const Fairing_step& step;
  double criteria_time_step;   // the step's length in the criteria's units
  double value;                // of the monitored functional after the step
  double max_relative;         // the largest total motion off the input, in each vertex's length unit
  double moved_relative;       // the largest motion of the step, likewise
  double discrepancy_before;   // the written surface's distance off the input before the step (noise units)
  double discrepancy;          // ... and after it
  double target;               // the noise level's distance (0: no noise criterion)
  double cut_at;               // >= 0: the step was cut this far into it, to end at the noise level
  const Step_controller& control;
  const std::string& last_rejection;   // why the last rejected step was
};

/// A rule's answer: the run ends, for `reason`; `message` says more (empty: nothing); `at` >= 0: where in
/// the step it ends, with `rewind` when the accepted surface must first be taken back there.
struct Stop
{
  Stop_reason reason;
  std::string message;
  double at = -1;
  bool rewind = false;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_STOP_RULE_H
