// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a run writes into its report besides its steps: a failure, and a verbose run's line per step.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_RUN_REPORT_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_RUN_REPORT_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Real_timer.h>

#include <cstdio>
#include <iostream>
#include <string>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// Ends a report as a failure.
inline Fairing_report& fail(Fairing_report& r, Fairing_status status, const std::string& message,
                            const CGAL::Real_timer& total)
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
  std::snprintf(line, sizeof line,
                "step %zu  t=%.4g  area=%.6g  int|H|^2=%.6g  max disp=%.3g  %d its (res %.1e)  %.3fs + %.3fs\n",
                st.step, st.time, st.area, st.H_integral, st.max_displacement, st.solver_iterations, st.residual,
                st.assemble_seconds, st.solve_seconds);
  std::cerr << line;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_RUN_REPORT_H
