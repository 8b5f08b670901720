// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The stopping criteria (27)-(29) of Bajaj & Xu: the monitored functional (int |H|^2 of the surface, or the
// attributes' Dirichlet energy on a fixed surface) relative to its start changes slowly, relative to its
// first rate (27) or absolutely (28), or a vertex moved off the input by a given distance (29; not on a fixed
// surface, where noisy values move by about the noise in one step).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_PAPER_CRITERIA_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_PAPER_CRITERIA_H

#include <CGAL/Anisotropic_fairing/internal/flow/stop/Stop_rule.h>

#include <cmath>
#include <optional>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

class Paper_criteria
{
public:
  explicit Paper_criteria(const Stop_rule_setup& s)
    : ratio_(s.settings.stopping.curvature_rate_ratio), rate_(s.settings.stopping.curvature_rate),
      displacement_(s.fixed_surface ? 0.0 : s.settings.stopping.displacement), F0_(s.initial_value) {}

  std::optional<Stop> after_step(const Step_progress& p)
  {
    if(F0_ > 0)
    {
      const double F = p.value / F0_;
      const double rate = (F - F_previous_) / p.criteria_time_step;
      if(p.step.step == 1) rate0_ = rate;
      F_previous_ = F;
      if(p.step.step >= 2 && ratio_ > 0 && rate0_ != 0 && std::abs(rate / rate0_) <= ratio_)
        return Stop{ Stop_reason::CURVATURE_RATE_RATIO };
      if(rate_ > 0 && std::abs(rate) <= rate_) return Stop{ Stop_reason::CURVATURE_RATE };
    }
    if(displacement_ > 0 && p.max_relative >= displacement_) return Stop{ Stop_reason::DISPLACEMENT };
    return std::nullopt;
  }

private:
  double ratio_, rate_, displacement_, F0_;
  double F_previous_ = 1, rate0_ = 0;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_PAPER_CRITERIA_H
