// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The risk estimate's probe on an operator of its own. For a flow whose operator follows the data (the
// anisotropic tensor reads the curvature of its prefiltered surface), the probe carried as columns of the
// run's solves (Ride_along_probe.h) leaves out the operator's dependence on the data, and its estimate is a
// lower bound (1.1-2.1x too low on the benchmark's cases). The whole map's is made by the probed input taking
// the run's accepted steps (Probe_schedule.h: their fractions of the time step, cut where the run's were,
// taken back and fallen back as the run was), each solved with M_eps, L(D) and the tangent planes of its own
// surface: a run of its own from the probed start, on the same path as the run, never on another (a run with
// its own stopping rule and step control can reject other steps). Replayed after the run, only when the
// comparison needs it; lockstep with the run would give the same numbers.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_PROBE_FLOW_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_PROBE_FLOW_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Flow_units.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Probe_schedule.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Ride_along_probe.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Real_timer.h>

#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// Where the probe from P ends when it takes the steps of `schedule` on `op` (a fresh operator of the run's
/// mesh, its tangential filter the run's) with `tensor` (the run's, before the run gave it its units) and the
/// run's settings `s`; `metric_columns` as the run's. Empty when a step cannot be made (no surface, a solve
/// that fails or is not finite, an operator that cannot be formed).
template <typename Operator, typename Tensor>
Control_matrix replay_probe(Operator& op, Tensor tensor, const Stepper_settings& s, int metric_columns,
                            const Control_matrix& P, const Probe_schedule& schedule)
{
  op.begin_run(s, false);
  Ride_along_probe probe;
  probe.start(P);
  Fairing_report unread;
  Assembly_statistics a;
  const CGAL::Real_timer clock;
  if(!start_units(op, P, metric_columns, s, tensor, unread, a, clock)) return Control_matrix();
  op.start_solver(s, P.cols(), false, nullptr, nullptr, P);
  const std::vector<double> no_weights;
  for(std::size_t k = 0; k < schedule.steps.size(); ++k)
  {
    const Control_matrix& Z = probe.result();
    bool direct = false;
    const Solve_statistics sol = op.solve(schedule.steps[k].factor, Z, P, no_weights, direct);
    if(!sol.ok || !op.solution_finite(sol)) return Control_matrix();
    Control_matrix d = op.displacement();
    op.normal_part(op.prefiltered() ? *op.prefiltered() : Z, metric_columns, d);
    probe.make_candidate([&](Control_matrix& candidate) { op.add(candidate, d); });
    const double cut = schedule.steps[k].cut;
    if(cut >= 0 && cut < 1) probe.shorten(cut);
    probe.accept();
    if(k + 1 == schedule.fall_back) probe.mark_unfolded();
    if(k + 1 == schedule.steps.size()) break;
    op.assemble(probe.result(), metric_columns, tensor, true);
    if(!op.error().empty()) return Control_matrix();
  }
  if(schedule.rewind >= 0) probe.rewind(schedule.rewind);
  if(schedule.fall_back < schedule.steps.size()) probe.fall_back();
  return probe.result();
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_PROBE_FLOW_H
