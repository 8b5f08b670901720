// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A flow that goes on only with slivers of its time step, several steps in a row, is heading into a fold:
// the run ends on the last sound surface instead of crawling on (Step_controller::cramped()).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_CRAMPED_FLOW_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_CRAMPED_FLOW_H

#include <CGAL/Anisotropic_fairing/internal/flow/stop/Stop_rule.h>

#include <optional>
#include <string>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

class Cramped_flow
{
public:
  explicit Cramped_flow(const Stop_rule_setup&) {}

  std::optional<Stop> after_step(const Step_progress& p) const
  {
    if(!p.control.cramped()) return std::nullopt;
    const std::size_t last = p.step.step, first = last + 1 - std::size_t(step_control::cramped_steps);
    const int sliver = int(1 / step_control::cramped_factor + 0.5);
    return Stop{ Stop_reason::STEP_REJECTED, "steps " + std::to_string(first) + " to " + std::to_string(last) +
                 " went on only with 1/" + std::to_string(sliver) + " of the time step or less (" + p.last_rejection +
                 " otherwise); the run ends on the last sound surface (step " + std::to_string(last) + ")" };
  }
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_CRAMPED_FLOW_H
