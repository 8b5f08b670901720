// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A run's start on any flow operator (Flow_operator.h): the units of every vertex from the input's area per
// component (Step_units.h), the tensor told its length scale and each component's prefilter time, then M and
// L(D) at the input.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_FLOW_UNITS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_FLOW_UNITS_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Flow_operator.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Run_report.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_units.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Tensor_hooks.h>
#include <CGAL/Real_timer.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The units of a run from X (then op.units()), the tensor given its length scale; M and L(D) at X assembled,
/// their statistics in `a` and the report's initial values. False (and the report failed) when the input has
/// no surface. A run that takes no step (`takes_steps` false) leaves out the operator of a tensor that needs
/// its units first (M_eps and L(D)): its statistics are the isotropic assembly's, but for the energy (NaN);
/// with `keep_isotropic`, the isotropic M and L at X are kept for the caller's op.prefilter(X) (M_eps alone).
template <typename Operator, typename Tensor>
bool start_units(Operator& op, const Control_matrix& X, int metric_columns, const Stepper_settings& s, Tensor& tensor,
                 Fairing_report& report, Assembly_statistics& a, const CGAL::Real_timer& total, bool takes_steps = true,
                 bool keep_isotropic = false)
{
  const Flow_mesh& mesh = op.mesh();
  const bool scaled_tensor = wants_length_scale(tensor);
  std::vector<double> eps(std::size_t(X.rows()),
                          scaled_tensor ? 0.0 : prefilter_time(tensor)); // the prefilter time per row
  // a prefilter's time follows from the units: then the isotropic M and L of the units are its start
  if(scaled_tensor) a = op.assemble_isotropic(X, metric_columns, prefilter_time(tensor) > 0);
  else
  {
    op.set_prefilter(eps, s);
    a = op.assemble(X, metric_columns, tensor, true);
  }
  for(std::size_t c = 0; c < a.component_area.size(); ++c)
    if(!(a.component_area[c] > 0) || !std::isfinite(a.component_area[c]) || !(mesh.component_edge[c] > 0))
    {
      op.discard_isotropic();
      fail(report, Fairing_status::DEGENERATE_METRIC,
           "the input's limit surface has no area" +
             (mesh.components.count > 1 ? " in connected component " + std::to_string(c) : std::string()) +
             " (sqrt(det G) <= 0 on face " + std::to_string(a.degenerate_face) +
             "): its control points do not span a surface" + op.where_face(a),
           total);
      return false;
    }
  const Length_unit tensor_unit = is_automatic_tensor(tensor) ? Length_unit::EDGE : Length_unit::SCALE;
  Step_units units = make_step_units(a, mesh.components, std::size_t(X.rows()), s.time_step, s.time_unit, s.order,
                                     s.fidelity_weight, s.relative_fidelity, s.stopping.relative_units, tensor_unit,
                                     mesh.component_edge, mesh.mean_edge);
  report.scale = units.scale;
  report.flow_order = s.order;
  report.time_step = units.time_step;
  report.fidelity_weight = units.fidelity_weight;
  report.components = mesh.components.count;
  op.set_units(units, a, scaled_tensor);
  if(scaled_tensor)
  {
    // each component's prefilter time as the tensor measures it at that component's scale
    std::vector<double> component_eps(mesh.components.count);
    for(std::size_t c = 0; c < mesh.components.count; ++c)
    {
      Tensor t = tensor;
      give_length_scale(t, units.tensor_unit * units.tensor_scale[c]);
      component_eps[c] = prefilter_time(t);
    }
    for(std::size_t i = 0; i < eps.size(); ++i)
      if(mesh.components.of_vertex[i] >= 0) eps[i] = component_eps[std::size_t(mesh.components.of_vertex[i])];
    give_length_scale(tensor, units.tensor_unit);
    report.feature_threshold = std::isfinite(threshold_of(tensor)) ? threshold_of(tensor) : 0.0;
    report.prefilter_time = prefilter_time(tensor);
    op.set_prefilter(std::move(eps), s);
    if(takes_steps) a = op.assemble(X, metric_columns, tensor, true);
    else if(!keep_isotropic)
    {
      op.discard_isotropic();
      a.energy = std::numeric_limits<double>::quiet_NaN();   // the tensor's, unknown without its operator
    }
  }
  report.initial.area = a.area;
  report.initial.energy = a.energy;
  report.initial.H_integral = a.H_integral;
  if(!op.error().empty()) { fail(report, Fairing_status::SOLVER_FAILED, op.error(), total); return false; }
  return true;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_FLOW_UNITS_H
