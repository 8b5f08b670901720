// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One call of the time stepper (flow/Time_stepper.h) on the run's mesh: what every flow of a call of
// anisotropic_fairing() shares is one context value, what a flow gives back one return value.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_STEPPER_CALL_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_STEPPER_CALL_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/Uniform_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Tensor_hooks.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Probe_flow.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Time_stepper.h>
#include <CGAL/Anisotropic_fairing/internal/element/Ghosted_patch_cache.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Locality_ordering.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Mesh_components.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Process_part.h>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <functional>
#include <type_traits>
#include <variant>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The mean edge length of each connected component (`edge[c]`) and of the whole mesh (returned), over
/// the real faces' edges (an interior edge is seen from both sides, a border edge from one); a process's own
/// faces', summed over the processes (`part`).
inline double component_mean_edges(const Triangle_topology& topo, std::size_t real_faces,
                                   const Mesh_components& components, const Control_matrix& X,
                                   std::vector<double>& edge, const Part_view& part = Part_view())
{
  // per component: the lengths' sum, then the edges'
  std::vector<double> sums(2 * components.count, 0.0);
  for(std::size_t f = 0; f < real_faces; ++f)
    if(part.owns_face(f))
      for(int k = 0; k < 3; ++k)
      {
        const auto& t = topo.face(f);
        sums[std::size_t(components.of_face[f])] += (X.row(t[k]).head(3) - X.row(t[(k + 1) % 3]).head(3)).norm();
        sums[components.count + std::size_t(components.of_face[f])] += 1;
      }
  part.sum(sums);
  edge.assign(components.count, 0.0);
  double sum = 0, count = 0;
  for(std::size_t c = 0; c < components.count; ++c)
  {
    sum += sums[c];
    count += sums[components.count + c];
    edge[c] = sums[c] / sums[components.count + c];
  }
  return count > 0 ? sum / count : 0.0;
}

/// The flow whose time step follows the mesh's density with automatic parameters (Local_time_scale.h):
/// the isotropic or the uniform one; null for any other tensor.
template <typename Tensor>
const char* density_scaled_flow(const Tensor&)
{
  return std::is_same<Tensor, Isotropic_diffusion_tensor>::value ? "isotropic"
         : std::is_same<Tensor, Uniform_diffusion_tensor>::value ? "uniform" : nullptr;
}
template <typename... Tensors>
const char* density_scaled_flow(const std::variant<Tensors...>& t)
{
  return std::visit([](const auto& held) { return density_scaled_flow(held); }, t);
}

/// What every flow of one call shares: the element's cache and the mesh in the solver's numbering, its
/// units per connected component, the attribute mode and the rows the flows hold.
template <typename Cache>
struct Flow_context
{
  const Cache& cache;
  const Locality_ordering& ordering;
  const Mesh_components& components;
  const std::vector<double>& component_edge;
  double mean_edge;
  Attribute_mode mode;
  const std::vector<bool>& constrained;
  const std::vector<bool>& border;
};

/// Where a call's runs step: the Loop element's cache it makes (Fairing_core::run()), whose flow operator
/// (Flow_operator_of) is one process's. The distributed program gives its own (distributed/Distributed_cache.h).
/// `part()`: the part of the mesh this process holds (Process_part.h; null: the whole mesh).
struct Serial_elements
{
  typedef Ghosted_patch_cache Loop_cache;
  Loop_cache loop_cache(const Ghost_layer& layer, const Quadrature_spec& quadrature, const Part_view&) const
  {
    return Loop_cache(layer, quadrature);
  }
  const Process_part* part() const { return nullptr; }
};

/// The risk estimate's probe carried along a flow (Ride_along_probe.h): from `start` (null: no probe).
struct Probe_plan
{
  const Control_matrix* start = nullptr;
  // after each step, on the run's and the probe's control points: false ends the run (Flow_loop.h)
  std::function<bool(const Control_matrix&, const Control_matrix&)> keep_going;
  bool carried() const { return start != nullptr; }
};

/// What one call of the stepper gives back.
struct Stepper_outcome
{
  Fairing_report report;
  Control_matrix Y;            // the control points (and attribute values) the flow ends at
  Control_matrix probe;        // where the probe ended (empty: none rode along)
  Probe_schedule schedule;     // the steps the flow accepted (Probe_flow.h)
  double limit_weight = 1;     // how far toward their limit points the written positions go
  double setup_seconds = 0;    // spent before the stepper's run
};

/// The caller's numbering and border, for the assembler.
template <typename Cache>
Assembly_context flow_numbering(const Flow_context<Cache>& context)
{
  Assembly_context numbering;
  numbering.original_vertex = &context.ordering.old_of_new_vertex;
  numbering.original_face = &context.ordering.old_of_new_face;
  numbering.border = &context.border;
  return numbering;
}

/// The columns that make the surface: the positions, with the attributes in the coupled mode.
template <typename Cache>
int metric_columns_of(const Flow_context<Cache>& context, const Control_matrix& X)
{
  return context.mode == Attribute_mode::COUPLED ? int(X.cols()) : 3;
}

/// The flow's own settings: with automatic parameters, only the isotropic and the uniform flow's time step
/// follows the mesh's density.
template <typename Tensor>
Stepper_settings flow_settings(const Stepper_settings& settings, const Tensor& tensor)
{
  Stepper_settings s = settings;
  s.local_time_scale = settings.local_time_scale && density_scaled_flow(tensor) != nullptr;
  return s;
}

/// Whether the flow moves the surface along its normals only (its tangential motion removed).
template <typename Cache, typename Tensor>
bool normal_motion_of(const Flow_context<Cache>& context, const Tensor& tensor)
{
  return wants_normal_motion(tensor) && context.mode != Attribute_mode::ATTRIBUTES_ONLY;
}

/// The surface a flow with `tensor` from `start` reads its curvature on before its first step (M_eps), made as
/// its run makes it (Flow_units.h); empty when the tensor reads none or it cannot be made.
template <typename Cache, typename Tensor>
Control_matrix prefiltered_start(const Flow_context<Cache>& context, const Tensor& tensor,
                                 const Stepper_settings& settings, const Control_matrix& start)
{
  const Flow_mesh mesh{ context.ordering.layer, context.components, context.component_edge, context.mean_edge };
  typename Flow_operator_of<Cache>::type op(context.cache, std::size_t(start.rows()), context.constrained, mesh,
                                            flow_numbering(context));
  const Stepper_settings s = flow_settings(settings, tensor);
  op.begin_run(s, false);
  Tensor t = tensor;
  Fairing_report unread;
  Assembly_statistics a;
  const CGAL::Real_timer clock;
  const int columns = metric_columns_of(context, start);
  if(!start_units(op, start, columns, s, t, unread, a, clock, false, true)) return Control_matrix();
  op.prefilter(start, columns);
  return op.prefiltered() ? *op.prefiltered() : Control_matrix();
}

/// The probe from P replaying, on an operator of its own, the steps `schedule` of a flow with `tensor` and
/// `settings` (Probe_flow.h): where it ends (P when it could not, and the report failed), as many steps as the
/// flow's report gives.
template <typename Cache, typename Tensor>
Stepper_outcome replayed_probe(const Flow_context<Cache>& context, const Tensor& tensor,
                               const Stepper_settings& settings, const Control_matrix& P,
                               const Probe_schedule& schedule)
{
  const Flow_mesh mesh{ context.ordering.layer, context.components, context.component_edge, context.mean_edge };
  typename Flow_operator_of<Cache>::type op(context.cache, std::size_t(P.rows()), context.constrained, mesh,
                                            flow_numbering(context));
  const Tangential_motion_filter filter(context.ordering.layer);
  if(normal_motion_of(context, tensor)) op.set_tangential_filter(&filter);
  Stepper_outcome o;
  o.Y = replay_probe(op, tensor, flow_settings(settings, tensor), metric_columns_of(context, P), P, schedule);
  const bool made = o.Y.size() > 0;
  o.report.status = made ? Fairing_status::SUCCESS : Fairing_status::SOLVER_FAILED;
  o.report.stop_reason = made ? Stop_reason::MAXIMUM_STEPS : Stop_reason::FAILURE;
  o.report.steps.resize((std::min)(schedule.steps.size(), schedule.fall_back));
  if(!made) o.Y = P;
  return o;
}

/// A test on the written positions of a run and its probe made a test on their control points, whose Loop
/// limit points they are.
inline std::function<bool(const Control_matrix&, const Control_matrix&)>
on_limit_points(std::function<bool(const Control_matrix&, const Control_matrix&)> test, const Ghost_layer& layer)
{
  return [test, &layer](const Control_matrix& Z, const Control_matrix& P) {
    Control_matrix Y, YP;
    limit_points(layer, Z, Y);
    limit_points(layer, P, YP);
    return test(Y, YP);
  };
}

/// One flow from `start` with `tensor` and `settings`; the user's `callback` sees every step.
template <typename Cache, typename Tensor, typename Callback>
Stepper_outcome run_stepper(const Flow_context<Cache>& context, const Tensor& tensor, const Stepper_settings& settings,
                            const Control_matrix& start, const Probe_plan& probe, Callback& callback)
{
  CGAL::Real_timer clock;
  clock.start();
  const Stepper_settings s = flow_settings(settings, tensor);
  Time_stepper<Cache> stepper(context.cache, std::size_t(start.rows()), context.constrained, context.ordering.layer,
                              context.components, context.component_edge, context.mean_edge, flow_numbering(context));
  const Tangential_motion_filter filter(context.ordering.layer);
  const bool normal_motion = normal_motion_of(context, tensor);
  if(normal_motion) stepper.set_tangential_filter(&filter);
  const int metric_columns = metric_columns_of(context, start);
  Stepper_outcome out;
  out.Y = start;
  out.setup_seconds = clock.time();
  if(context.mode == Attribute_mode::ATTRIBUTES_ONLY)
  {
    out.report = stepper.run_on_fixed_surface(out.Y, tensor, s, callback);
    return out;
  }
  if(probe.start) stepper.set_probe(*probe.start);
  stepper.set_probe_test(probe.keep_going);
  out.report = stepper.run(out.Y, metric_columns, tensor, s, callback);
  out.report.normal_motion_only = normal_motion;
  out.limit_weight = stepper.limit_weight();
  if(probe.carried()) out.probe = stepper.probe_result();
  out.schedule = stepper.schedule();
  return out;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_STEPPER_CALL_H
