// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The steps a run accepted, as a probe replaying them needs them (Probe_flow.h): each step's fraction of the
// time step and where the noise level cut it, the step the run was taken back into at its end, and the
// step it fell back to.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_PROBE_SCHEDULE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_PROBE_SCHEDULE_H

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

struct Probe_schedule
{
  struct Step
  {
    double factor;   // of the time step
    double cut;      // in [0, 1): the step ends this far in (the noise level); otherwise whole
  };
  std::vector<Step> steps;   // the accepted ones, in order
  double rewind = -1;        // >= 0: the last step taken back to this fraction of its length
  std::size_t fall_back = std::size_t(-1);   // < steps.size(): the run fell back to the surface after as many
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_PROBE_SCHEDULE_H
