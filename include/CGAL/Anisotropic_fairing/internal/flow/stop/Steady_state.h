// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The flow stopped moving: the step's largest motion per unit of time is below the steady-state speed.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_STEADY_STATE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_STEADY_STATE_H

#include <CGAL/Anisotropic_fairing/internal/flow/stop/Stop_rule.h>

#include <optional>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

class Steady_state
{
public:
  explicit Steady_state(const Stop_rule_setup& s) : speed_(s.settings.stopping.steady_speed) {}

  std::optional<Stop> after_step(const Step_progress& p) const
  {
    if(speed_ > 0 && p.moved_relative / p.criteria_time_step <= speed_) return Stop{ Stop_reason::STEADY_STATE };
    return std::nullopt;
  }

private:
  double speed_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_STEADY_STATE_H
