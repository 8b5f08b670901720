// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The noise criterion: the run ends where its written surface is off the input by the estimated noise. A
// step that passes that distance is taken again shorter (secants, Step_controller) or cut where the distance
// is reached, so the run ends there rather than a step beyond.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_NOISE_LEVEL_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_NOISE_LEVEL_H

#include <CGAL/Anisotropic_fairing/internal/flow/stop/Stop_rule.h>

#include <algorithm>
#include <optional>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

class Noise_level
{
public:
  explicit Noise_level(const Stop_rule_setup& s) : on_(s.noise_stop) {}

  /// How far the surface Y measured at the start Z0 is off it, for before_first_step(): by the typical vertex
  /// or, where the limit surface rounds the creases of a clean mesh while leaving most vertices in place, by
  /// the root mean square.
  template <typename Noise, typename Matrix>
  static double at_start(const Noise& noise, const Matrix& Y, const Matrix& Z0)
  {
    return std::max(noise.relative_displacement(Y, Z0, {}), noise.relative_displacement(Y, Z0, {}, true));
  }

  /// Before the first step: the input's own limit surface is off it by `first` already. The result then
  /// lies between the two, this far from the input to its limit surface (empty: the run goes on).
  static std::optional<double> before_first_step(double first, double target)
  {
    if(!(first >= target)) return std::nullopt;
    return first > 0 ? target / first : 0.0;
  }

  /// What the step to a candidate at `candidate` (from `current`) does: RETAKE it shorter (the controller's
  /// factor is shortened), CUT it at `fraction` of its length, or GO on.
  enum class Candidate { GO, RETAKE, CUT };
  static Candidate judge_candidate(Step_controller& control, double current, double candidate, double target,
                                   double& fraction)
  {
    if(control.retake_for_noise_level(current, candidate, target)) return Candidate::RETAKE;
    if(!(candidate >= target)) return Candidate::GO;
    fraction = fraction_reaching(current, candidate, target);
    return Candidate::CUT;
  }

  /// Reached within the step: at the cut made before, or (under a deviation bound, which judges a step
  /// before its distance) where the secant reaches it, the accepted surface taken back there.
  std::optional<Stop> after_step(const Step_progress& p) const
  {
    if(!on_) return std::nullopt;
    if(p.cut_at >= 0) return Stop{ Stop_reason::NOISE_LEVEL, std::string(), p.cut_at, false };
    if(!(p.discrepancy >= p.target)) return std::nullopt;
    const double theta = fraction_reaching(p.discrepancy_before, p.discrepancy, p.target);
    return Stop{ Stop_reason::NOISE_LEVEL, std::string(), theta, theta < 1 };
  }

private:
  bool on_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOP_NOISE_LEVEL_H
