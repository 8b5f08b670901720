// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The normal-field candidate (Flow_candidates.h; compared by the benchmarks, not yet by the default run): the
// face normals of the input filtered pass after pass (flow/Normal_field_filter.h), the vertices fitted to each
// pass's normals from the input, and the same on the probed input in lockstep, so that every pass has the
// comparison's estimate (Tensor_selection.h, Risk_estimate). The pass kept is the one whose estimate is lowest
// among those that fold no more edges than the input; the passes end once the estimate has not fallen for
// `normal_field_patience` passes. Its positions are the filtered vertices themselves, tied to no limit surface:
// a sharp crease stays as sharp as the filter leaves it.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_NORMAL_FIELD_RUN_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_NORMAL_FIELD_RUN_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Normal_field_filter.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_safety.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/run/Flow_candidates.h>
#include <CGAL/Anisotropic_fairing/internal/run/Tensor_selection.h>

#include <CGAL/Real_timer.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// What the normal-field run reads besides its request.
struct Normal_field_context
{
  const Ghost_layer& layer;
  const std::vector<bool>& moves;             // the rows it may move (not held, not on a border)
  const std::vector<int>& face_component;     // for the fold count
  const std::vector<double>& component_edge;
  std::size_t maximum_passes;                 // the step budget left
  std::function<bool(const Fairing_step&)> callback;   // false: stop (the user's callback)
};

/// The passes after the lowest estimate that end the run, and the most passes it takes.
constexpr std::size_t normal_field_patience = 3;
constexpr std::size_t normal_field_passes = 60;

/// One pass's line of the report.
inline Fairing_step normal_field_step(std::size_t pass, const Control_matrix& Y, const Control_matrix& before,
                                      const Control_matrix& start, double seconds)
{
  Fairing_step s;
  s.step = pass;
  s.solver_iterations = 0;
  s.max_displacement = (Y.leftCols(3) - start.leftCols(3)).rowwise().norm().maxCoeff();
  s.step_displacement = (Y.leftCols(3) - before.leftCols(3)).rowwise().norm().maxCoeff();
  s.assemble_seconds = seconds;
  return s;
}

/// The normal-field candidate's run as `request` asks (its probe start and estimate required).
inline Flow_outcome run_normal_field(const Flow_request& request, const Normal_field_context& c)
{
  Flow_outcome out;
  Fairing_report& r = out.report;
  if(!request.estimate || !request.probe_start)
  {
    r.status = Fairing_status::SOLVER_FAILED;
    r.stop_reason = Stop_reason::FAILURE;
    r.message = "not run: the normal field stops at its lowest estimated error, which needs the comparison's estimate";
    return out;
  }
  const Triangle_topology& topo = *c.layer.topology;
  const std::size_t faces = c.layer.real_faces;
  const Normal_field_filter filter(topo, faces, c.moves, request.start);
  const std::size_t input_folds = count_folded_edges(topo, faces, request.start, c.face_component, c.component_edge);
  const Control_matrix& probe_start = *request.probe_start;
  Normal_field_filter::Face_field field = filter.field_of(request.start), probe_field = filter.field_of(probe_start);
  Control_matrix Y = request.start, P = probe_start;
  out.Y = Y;
  out.probe = P;
  double lowest = std::nan("");
  std::size_t best = 0;
  const std::size_t most = request.fixed_steps > 0 ? request.fixed_steps : normal_field_passes;
  r.stop_reason = Stop_reason::MAXIMUM_STEPS;
  for(std::size_t pass = 1; pass <= (std::min)(most, c.maximum_passes); ++pass)
  {
    CGAL::Real_timer timer;
    timer.start();
    const Control_matrix before = Y;
    // the normals filtered once more, and the vertices fitted to them from the start (Zhang et al.'s scheme:
    // every pass is the result of that many normal iterations)
    filter.filter(field);
    filter.filter(probe_field);
    Y = request.start;
    filter.fit(Y, field);
    P = probe_start;
    filter.fit(P, probe_field);
    const double estimate = request.estimate->relative(Y, P);
    const bool sound = count_folded_edges(topo, faces, Y, c.face_component, c.component_edge) <= input_folds;
    if(sound && std::isfinite(estimate) && !(estimate >= lowest))
    {
      lowest = estimate;
      best = pass;
      out.Y = Y;
      out.probe = P;
    }
    Fairing_step step = normal_field_step(pass, Y, before, request.start, timer.time());
    r.steps.push_back(step);
    if(c.callback && !c.callback(step)) { r.stop_reason = Stop_reason::CALLBACK; break; }
    if(request.fixed_steps == 0 && pass >= best + normal_field_patience)
    {
      r.stop_reason = Stop_reason::LOWEST_ESTIMATE;
      break;
    }
  }
  // the passes after the lowest estimate are not kept: the report ends at the pass kept
  if(r.stop_reason != Stop_reason::CALLBACK && request.fixed_steps == 0) r.steps.resize(best);
  return out;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_NORMAL_FIELD_RUN_H
