// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The stop rules a run asks after each accepted step, in this order; the first that answers ends it. A new
// rule is a type of its own file (Stop_rule.h says what it provides) added to this list.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_STOP_RULES_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_STOP_RULES_H

#include <CGAL/Anisotropic_fairing/internal/flow/stop/Cramped_flow.h>
#include <CGAL/Anisotropic_fairing/internal/flow/stop/Held_by_bound.h>
#include <CGAL/Anisotropic_fairing/internal/flow/stop/Noise_level.h>
#include <CGAL/Anisotropic_fairing/internal/flow/stop/Noise_removed.h>
#include <CGAL/Anisotropic_fairing/internal/flow/stop/Paper_criteria.h>
#include <CGAL/Anisotropic_fairing/internal/flow/stop/Steady_state.h>
#include <CGAL/Anisotropic_fairing/internal/flow/stop/Stop_rule.h>

#include <optional>
#include <tuple>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

template <typename... Rule>
class Ordered_stop_rules
{
public:
  explicit Ordered_stop_rules(const Stop_rule_setup& s) : rules_(Rule(s)...) {}

  /// the first rule's answer, in the list's order (later rules are not asked)
  std::optional<Stop> after_step(const Step_progress& p)
  {
    std::optional<Stop> stop;
    std::apply([&](auto&... rule) { ((stop = stop ? stop : rule.after_step(p)), ...); }, rules_);
    return stop;
  }

private:
  std::tuple<Rule...> rules_;
};

// the noise level first: a step cut to end there ends the run whatever else holds
typedef Ordered_stop_rules<Noise_level, Noise_removed, Held_by_bound, Cramped_flow, Paper_criteria, Steady_state>
  Stop_rules;

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_STOP_RULES_H
