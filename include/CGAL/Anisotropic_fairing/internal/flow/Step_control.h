// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The step control of a run, as an ODE integrator has one: the fraction of the time step the next step
// takes, shrunk when a step is rejected, grown back after one is accepted, and shortened by secants to
// end a run where the noise level is reached; and the stop rules that are not the paper's criteria.
// Every constant of the control is here, with why it has its value.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STEP_CONTROL_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STEP_CONTROL_H

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

namespace step_control {
/// a rejected step is taken again with this fraction of its time step (Stepper_settings::maximum_rejections times)
constexpr double rejection_factor = 0.25;
/// after an accepted step the next may be this many times longer, up to the full time step
constexpr double growth_factor = 2;
/// a flow accepted only with this fraction of its time step or less, `cramped_steps` times in a row, is
/// heading into a fold: the run ends there
constexpr double cramped_factor = 1.0 / 16;
constexpr int cramped_steps = 4;
/// a run that passes the noise level within a step ends within this relative distance of it ...
constexpr double noise_tolerance = 0.02;
/// ... found by at most this many secant retakes of the step, none shorter than `shortest_secant` of it
constexpr int maximum_noise_retakes = 4;
constexpr double shortest_secant = 0.05;
/// a step that carried a written position past the deviation bound is taken again this many times at most,
/// the vertices past it held harder each time
constexpr int maximum_bound_retakes = 4;
/// under a deviation bound short of the noise, the displacement has levelled off when a step adds less
/// than this share of it
constexpr double levelled_off = 0.01;
} // namespace step_control

/// The fraction of the time step the run's next step takes, and the counts that decide it.
class Step_controller
{
public:
  double factor() const { return factor_; }

  /// A rejected step: true if it is to be taken again, shorter; false once the rejections are spent.
  bool reject(int maximum_rejections)
  {
    if(++rejections_ > maximum_rejections) return false;
    factor_ *= step_control::rejection_factor;
    return true;
  }

  /// The candidate moved the surface off the input by `candidate` (`current` before the step), past the
  /// noise level `target` by more than the tolerance: true if the step is to be taken again, ending nearer
  /// it (the displacement grows fastest at first, so the secant undershoots and each retake comes closer).
  bool retake_for_noise_level(double current, double candidate, double target)
  {
    if(!(candidate > target * (1 + step_control::noise_tolerance)) || retakes_ >= step_control::maximum_noise_retakes) return false;
    ++retakes_;
    factor_ *= std::max(step_control::shortest_secant, (target - current) / (candidate - current));
    return true;
  }

  /// A step accepted with the current factor.
  void accept()
  {
    retakes_ = 0;
    cramped_ = factor_ <= step_control::cramped_factor ? cramped_ + 1 : 0;
    rejections_ = 0;
  }

  /// Whether the flow went on only with slivers of its time step for `cramped_steps` steps in a row.
  bool cramped() const { return cramped_ >= step_control::cramped_steps; }

  /// The factor of the step after the one accepted.
  double next_factor() const { return std::min(1.0, step_control::growth_factor * factor_); }
  void grow() { factor_ = next_factor(); }

private:
  double factor_ = 1;
  int rejections_ = 0, cramped_ = 0, retakes_ = 0;
};

/// Where, as a fraction of a step, a displacement that went from `before` to `after` reached `target`.
inline double fraction_reaching(double before, double after, double target)
{
  return std::min(1.0, std::max(0.0, (target - before) / (after - before)));
}

/// The fourth-order flow at a strength S > 1 (the named parameter) is read at the scale S h: its levelling
/// off on waves S times as long, and with automatic parameters its time step 0.1 (S h)^4, so that it reaches
/// S times the noise in about as many steps as it reaches the noise. Its displacement grows ever more slowly:
/// with the waves alone scaled it levelled off at 0.35 h of the 0.40 h asked for after 148 steps of 0.1 h^4
/// (Nicolo0.2 at S = 2), and ran out of the 200 steps on Julius0.2; at 0.1 (2h)^4 it reached the target in
/// 17 and 24 steps, within 0.04 degrees of steps of 0.4 h^4 (64 and 93 of them). Below 1 nothing changes:
/// the target comes sooner.
inline double fourth_order_scale(double strength) { return strength > 1 ? strength : 1.0; }

/// Fourth-order flow: the flow barely shrinks, so once the noise is gone its displacement levels off,
/// maybe short of the noise level, and what still moves is shape. The noise is removed when the
/// displacement grows more slowly than a wave of 4 pi h decays, |u'/u| = (2 pi / 4 pi h)^4 = 1 / (16 h^4).
/// With a `strength` S > 1 (the named parameter) the wave is S times as long, 4 pi S h: a run asked to go
/// S times as far counts S times longer waves as noise (fourth_order_scale).
inline bool noise_removed(double before, double after, double time_step, double h, double strength = 1)
{
  return before > 0 && (after - before) / after < time_step / (16 * std::pow(h * fourth_order_scale(strength), 4));
}

/// Under a deviation bound short of the noise, the displacement levels off where the bound holds it.
inline bool held_by_bound(double before, double after)
{
  return before > 0 && after - before < step_control::levelled_off * after;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STEP_CONTROL_H
