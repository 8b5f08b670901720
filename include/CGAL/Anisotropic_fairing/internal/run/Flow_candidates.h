// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The flows the default run compares, as a list of named entries: each says which flow it runs and at which
// order, how its risk estimate is made, and holds its result and estimate once run. The selection
// (Smoother_selection.h) reads the list; the run (Fairing_core.h) counts its planned runs from it.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FLOW_CANDIDATES_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FLOW_CANDIDATES_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/Uniform_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Probe_schedule.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The tensor of a candidate's flow: the run's own (the tensor given or chosen), or one of the package's.
enum class Candidate_tensor { RUN_TENSOR, ISOTROPIC, UNIFORM };

/// f called with the tensor of a candidate's flow (`run_tensor`: the run's own)
template <typename Tensor, typename F>
decltype(auto) with_candidate_tensor(Candidate_tensor which, const Tensor& run_tensor, F&& f)
{
  switch(which)
  {
    case Candidate_tensor::ISOTROPIC: return f(Isotropic_diffusion_tensor());
    case Candidate_tensor::UNIFORM: return f(Uniform_diffusion_tensor());
    case Candidate_tensor::RUN_TENSOR: break;
  }
  return f(run_tensor);
}

/// How a candidate smooths: a flow of the surface, or its normal field filtered and the vertices fitted to it.
enum class Candidate_stage { FLOW, NORMAL_FIELD };

/// Which flow a run makes: its tensor and its order (2: diffusion, 4: the fourth-order flow), or the normal field.
struct Flow_settings
{
  Candidate_tensor tensor = Candidate_tensor::RUN_TENSOR;
  int order = 2;
  Candidate_stage stage = Candidate_stage::FLOW;
};

/// What one run gives back, in the run's numbering.
class Risk_estimate;

struct Flow_outcome
{
  Fairing_report report;
  Control_matrix Y;       // the written positions (and attribute values)
  Control_matrix Z;       // its control points, when asked for (empty otherwise)
  Control_matrix probe;   // where the probe carried along ended, written as Y is (empty: none rode along)
  Probe_schedule schedule;   // the steps the run accepted, for its probe to replay (Probe_flow.h)
  std::size_t run = std::size_t(-1);   // its entry in the call's runs (Run_log.h)
};

/// One run the default run asks for: which flow, from where, for how long, and what rides along.
struct Flow_request
{
  Flow_settings flow;
  std::string name;                         // the run's name, which the user's callback sees
  const Control_matrix& start;
  bool may_be_kept = true;                  // its control points are made too (a probe run's are not)
  std::size_t fixed_steps = 0;              // > 0: exactly that many steps, no stopping rule
  const Control_matrix* probe_start = nullptr;   // a probed start carried along (Ride_along_probe.h)
  const Probe_schedule* replay = nullptr;   // a probe's run: the steps to replay on its own operator (Probe_flow.h)
  // after each step, on the written positions of the run and of its probe: false ends it (Candidate_drop.h)
  std::function<bool(const Control_matrix&, const Control_matrix&)> keep_going;
  const Risk_estimate* estimate = nullptr;   // the comparison's estimate, once known
};

/// Whether a run ended where its own stopping rule wanted it: at the noise level (the normal field: at its
/// lowest estimate).
inline bool ended_at_noise_level(const Fairing_report& r)
{
  const Stop_reason s = r.stop_reason;
  return r.succeeded() && (s == Stop_reason::NOISE_LEVEL || s == Stop_reason::NOISE_REMOVED ||
                           s == Stop_reason::DEVIATION_BOUND || s == Stop_reason::LOWEST_ESTIMATE);
}

/// Whether a run is judged: it ran to its end, whatever stopped it, but the user's callback.
inline bool judged_run(const Fairing_report& r) { return r.succeeded() && r.stop_reason != Stop_reason::CALLBACK; }

/// One flow of the comparison: its names, its settings, how its estimate is made, and once run its result
/// and its estimate.
struct Flow_candidate
{
  const char* name;    // in the report's selected_tensor and in "kept the ... result"
  const char* label;   // in the list of estimates
  const char* flow;    // its runs' name, which the callback sees
  Flow_settings settings;
  // its operator depends on the connectivity alone, so the probe carried along its run is linear in the
  // data and gives its estimate; the others' estimates need a run of their own on the probed input
  bool carried_is_estimate = false;
  // that run replays its steps on an operator of its own (Probe_flow.h) rather than running the flow again
  bool probe_replays = false;
  // without the first run's normals, the estimate measures along this candidate's result
  bool gives_normals = false;
  bool made = false;   // its run is made (the run's own flow is, before the selection)
  Flow_outcome result;
  double risk = std::nan(""), carried = std::nan("");   // the estimate, and the one its probe carried along gave
  std::vector<double> terms;   // the estimate's terms per vertex, once estimated after its run (Candidate_drop.h)
  double dropped_at = std::nan("");   // its last estimate along its run, where it was dropped
  Control_matrix probe_end;   // where its run on the probed input ended, when it was run again

  /// Compared: judged, and at the noise level unless none of the candidates reached it.
  bool compared(bool any_at_noise) const
  {
    return judged_run(result.report) && (ended_at_noise_level(result.report) || !any_at_noise);
  }
};

typedef std::vector<Flow_candidate> Candidate_list;

/// The default run's candidates, in the order they run: the uniform fourth-order flow, the isotropic flow and
/// the run's own (anisotropic) flow at `order`, the costliest, last, where it can be dropped against the others
/// (Candidate_drop.h); with `normal_field` (benchmarks), the normal field after them (it needs the estimate to
/// stop).
inline Candidate_list default_candidates(int order, bool normal_field = false)
{
  Candidate_list list(normal_field ? 4 : 3);
  list[0] = Flow_candidate{ "uniform", "uniform fourth-order", "uniform fourth-order flow",
                            { Candidate_tensor::UNIFORM, 4 } };
  list[0].carried_is_estimate = true;
  list[1] = Flow_candidate{ "isotropic", "isotropic", "isotropic flow", { Candidate_tensor::ISOTROPIC, 2 } };
  list[1].gives_normals = true;
  list[2] = Flow_candidate{ "anisotropic", "anisotropic", "anisotropic flow", { Candidate_tensor::RUN_TENSOR, order } };
  // its operator follows the data (the curvature of its prefiltered surface)
  list[2].probe_replays = true;
  if(!normal_field) return list;
  list[3] = Flow_candidate{ "normal field", "normal field", "normal-field filter",
                            { Candidate_tensor::RUN_TENSOR, 2, Candidate_stage::NORMAL_FIELD } };
  list[3].carried_is_estimate = true;   // its probe takes the same passes, through the same nonlinear map
  return list;
}

/// The most runs a comparison of `list` makes: each candidate's own, and its run on the probed input unless
/// its carried probe is its estimate; under a deviation bound (`bounded`) no probe rides along a flow (the
/// normal field's probe is part of its run).
inline std::size_t planned_runs(const Candidate_list& list, bool bounded)
{
  std::size_t runs = 0;
  for(const Flow_candidate& c : list)
    runs += c.carried_is_estimate && (!bounded || c.settings.stage == Candidate_stage::NORMAL_FIELD) ? 1 : 2;
  return runs;
}

/// The run's own flow: the candidate with the run's tensor (the one kept when nothing else is; its run is
/// made before the selection when the input is at the noise level already).
inline std::size_t own_candidate(const Candidate_list& list)
{
  for(std::size_t k = 0; k < list.size(); ++k)
    if(list[k].settings.tensor == Candidate_tensor::RUN_TENSOR && list[k].settings.stage == Candidate_stage::FLOW)
      return k;
  return 0;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FLOW_CANDIDATES_H
