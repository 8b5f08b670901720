// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// When a run of time steps ends: the stopping criteria (27)-(29) of Bajaj & Xu, the steady state,
// and the wall clock the steps are timed with.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOPPING_MONITOR_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOPPING_MONITOR_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/Real_timer.h>

#include <cstdio>
#include <iostream>
#include <string>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The stopping criteria (27)-(29) and the steady-state test, fed after every step with the
/// monitored functional (int |H|^2 of the surface, or the Dirichlet energy of attributes on a fixed
/// surface) and the displacements, in the units the criteria are read in.
class Stopping_monitor
{
public:
  Stopping_monitor(const Stopping_criteria& c, double initial_value) : c_(c), F0_(initial_value) {}

  /// true (and the reason) when the run should end after this step, of length `dt` in the criteria's units
  bool should_stop(std::size_t step, double dt, double value, double max_displacement, double step_displacement, Stop_reason& reason)
  {
    dt_ = dt;
    if(F0_ > 0)
    {
      const double F = value / F0_;
      const double rate = (F - F_prev_) / dt_;
      if(step == 1) rate0_ = rate;
      F_prev_ = F;
      if(step >= 2 && c_.curvature_rate_ratio > 0 && rate0_ != 0 && std::abs(rate / rate0_) <= c_.curvature_rate_ratio)
      { reason = Stop_reason::CURVATURE_RATE_RATIO; return true; }
      if(c_.curvature_rate > 0 && std::abs(rate) <= c_.curvature_rate)
      { reason = Stop_reason::CURVATURE_RATE; return true; }
    }
    if(c_.displacement > 0 && max_displacement >= c_.displacement)
    { reason = Stop_reason::DISPLACEMENT; return true; }
    if(c_.steady_speed > 0 && step_displacement / dt_ <= c_.steady_speed)
    { reason = Stop_reason::STEADY_STATE; return true; }
    return false;
  }

private:
  Stopping_criteria c_;
  double F0_, dt_ = 1.0, F_prev_ = 1.0, rate0_ = 0;
};


/// Ends a report as a failure.
inline Fairing_report& fail(Fairing_report& r, Fairing_status status, const std::string& message, const CGAL::Real_timer& total)
{
  r.status = status;
  r.stop_reason = Stop_reason::FAILURE;
  r.message = message;
  r.total_seconds = total.time();
  return r;
}

/// The progress line of a step (verbose runs).
inline void print(const Fairing_step& st)
{
  char line[256];
  std::snprintf(line, sizeof line, "step %zu  t=%.4g  area=%.6g  int|H|^2=%.6g  max disp=%.3g  %d its (res %.1e)  %.3fs + %.3fs\n",
                st.step, st.time, st.area, st.H_integral, st.max_displacement, st.solver_iterations,
                st.residual, st.assemble_seconds, st.solve_seconds);
  std::cerr << line;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STOPPING_MONITOR_H
