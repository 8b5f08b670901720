// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The noise criterion of the fourth-order flow: that flow barely shrinks, so once the noise is gone its
// displacement levels off, maybe short of the noise level, and what still moves is shape.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_NOISE_REMOVED_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_NOISE_REMOVED_H

#include <CGAL/Anisotropic_fairing/internal/flow/stop/Stop_rule.h>

#include <cmath>
#include <optional>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The fourth-order flow at a strength S > 1 is read at the scale S h: its levelling off on waves S times as
/// long, and with automatic parameters its time step 0.1 (S h)^4, so that it reaches S times the noise in
/// about as many steps as it reaches the noise. Below 1 nothing changes: the target comes sooner.
inline double fourth_order_scale(double strength) { return strength > 1 ? strength : 1.0; }

/// The noise is removed when the displacement grows more slowly than a wave of 4 pi h decays,
/// |u'/u| = (2 pi / 4 pi h)^4 = 1 / (16 h^4); with a strength S > 1 the wave is S times as long.
inline bool noise_removed(double before, double after, double time_step, double h, double strength = 1)
{
  return before > 0 && (after - before) / after < time_step / (16 * std::pow(h * fourth_order_scale(strength), 4));
}

class Noise_removed
{
public:
  explicit Noise_removed(const Stop_rule_setup& s)
    : on_(s.noise_stop && s.settings.order == 4), mean_edge_(s.mean_edge), strength_(s.settings.strength) {}

  std::optional<Stop> after_step(const Step_progress& p) const
  {
    if(on_ && noise_removed(p.discrepancy_before, p.discrepancy, p.step.time_step, mean_edge_, strength_))
      return Stop{ Stop_reason::NOISE_REMOVED };
    return std::nullopt;
  }

private:
  bool on_;
  double mean_edge_, strength_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_NOISE_REMOVED_H
