// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The noise criterion under a deviation bound short of the noise: the displacement levels off where the
// bound holds it, and the run ends there instead of running out of steps.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_HELD_BY_BOUND_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_HELD_BY_BOUND_H

#include <CGAL/Anisotropic_fairing/internal/flow/stop/Stop_rule.h>

#include <optional>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// the displacement has levelled off when a step adds less than this share of it
constexpr double levelled_off = 0.01;

inline bool held_by_bound(double before, double after) { return before > 0 && after - before < levelled_off * after; }

class Held_by_bound
{
public:
  explicit Held_by_bound(const Stop_rule_setup& s) : on_(s.noise_stop && s.bound_active) {}

  std::optional<Stop> after_step(const Step_progress& p) const
  {
    if(on_ && held_by_bound(p.discrepancy_before, p.discrepancy)) return Stop{ Stop_reason::DEVIATION_BOUND };
    return std::nullopt;
  }

private:
  bool on_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_HELD_BY_BOUND_H
