// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The runs a call makes, in order, each timed from its set-up to its written result: what the report's
// `runs` lists (Fairing_run), so that a user sees what each candidate of the default run cost and gave.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_RUN_LOG_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_RUN_LOG_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/internal/run/Flow_candidates.h>
#include <CGAL/Real_timer.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

class Run_log
{
public:
  /// Makes a run (`run()` gives its outcome), timed; the outcome learns its entry (Flow_outcome::run).
  template <typename Run>
  Flow_outcome record(const std::string& name, Run&& run)
  {
    CGAL::Real_timer clock;
    clock.start();
    Flow_outcome out = run();
    Fairing_run r;
    r.name = name;
    r.steps = out.report.steps.size();
    r.rejected_steps = out.report.rejected_steps;
    r.seconds = clock.time();
    r.status = out.report.status;
    r.stop_reason = out.report.stop_reason;
    out.run = runs_.size();
    runs_.push_back(r);
    return out;
  }

  /// The run whose result is written (the last call wins: the strength's run replaces the comparison's pick).
  void kept(std::size_t run)
  {
    for(Fairing_run& r : runs_) r.kept = false;
    if(run < runs_.size()) runs_[run].kept = true;
  }
  void estimated(std::size_t run, double estimate)
  {
    if(run < runs_.size()) runs_[run].estimate = estimate;
  }
  const std::vector<Fairing_run>& runs() const { return runs_; }

private:
  std::vector<Fairing_run> runs_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_RUN_LOG_H
