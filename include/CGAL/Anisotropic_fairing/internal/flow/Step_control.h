// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The step control of a run, as an ODE integrator has one: the fraction of the time step the next step
// takes, shrunk when a step is rejected, grown back after one is accepted, and shortened by secants to
// end a run where the noise level is reached. Every constant of the control is here, with why it has its value.

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
    if(!(candidate > target * (1 + step_control::noise_tolerance)) || retakes_ >= step_control::maximum_noise_retakes)
      return false;
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

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STEP_CONTROL_H
