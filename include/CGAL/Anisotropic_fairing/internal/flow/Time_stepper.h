// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The semi-implicit step ((1 + tau w) M + tau L(D)) X_{n+1} = M (X_n + tau w X_0) of Bajaj & Xu
// (eq. 26 with the fidelity term written consistently, doc/Anisotropic_fairing/design/loop-fem-flow.md section 8), repeated until a
// stopping criterion holds, controlled as an ODE integrator would be: a step that leaves an unsound
// surface (Step_safety.h) is rejected and retried with a quarter of the time step; when even
// 1/1024 of it fails, the run ends on the last sound surface. It knows nothing of the element: any
// cache the Fem_assembler accepts will do (Loop patches or P1 faces).
//
// Constrained vertices are eliminated: the unknowns are the displacements of the free vertices,
//   A_FF dX_F = tau (w M (X_0 - X_n) - L X_n)_F,
// so the system stays symmetric positive definite and its right-hand side does not depend on the
// model's position in space. The pieces: the operator on the current surface (Surface_operator.h), the
// step's system and solver (Step_solver.h), the judgement of a candidate surface (Step_safety.h), the
// step control (Step_control.h) and the stopping criteria (Stopping_monitor.h); one loop (Flow_run.h)
// runs them for the surface and for attributes on a fixed surface.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TIME_STEPPER_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TIME_STEPPER_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Mesh_components.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Deviation_bound.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Flow_run.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Local_time_scale.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Noise_estimate.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Normal_motion.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Ride_along_probe.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_safety.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_solver.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_units.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stopping_monitor.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Surface_operator.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Tensor_hooks.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Free_block.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

template <typename Cache>
class Time_stepper
{
public:
  /// `constrained[i]` holds vertex i fixed. `layer`: the mesh (with its ghosts); `components`: its
  /// connected components, `component_edge[c]` the mean edge length of component c, `mean_edge` of all.
  /// `numbering`: the caller's numbering and border for the assembler (Assembly_context: its first three).
  Time_stepper(const Cache& cache, std::size_t n, const std::vector<bool>& constrained, const Ghost_layer& layer,
               const Mesh_components& components, const std::vector<double>& component_edge, double mean_edge,
               const Assembly_context& numbering = Assembly_context())
    : operator_(cache, n), block_(operator_.pattern(), constrained), layer_(layer), components_(components),
      component_edge_(component_edge), mean_edge_(mean_edge), context_(numbering)
  {
    // the curvature a component's edges can show: |H| up to 2 / h (a sphere of diameter h)
    for(double h : component_edge_) curvature_bound_.push_back(2 / h);
    context_.face_component = &components_.of_face;
    context_.components = components_.count;
    context_.curvature_bound = &curvature_bound_;
    context_.folded_turn = turn_120;
    context_.bent_turn = turn_110;
    operator_.assembler().set_context(context_);
  }

  /// Each step's displacement of the surface's columns then loses its tangential part (null: kept).
  void set_tangential_filter(const Tangential_motion_filter* f) { tangential_filter_ = f; }
  /// The next run carries the probed start P along (Ride_along_probe.h), unless it holds a deviation bound.
  void set_probe(const Control_matrix& P) { probe_.start(P); }
  /// Or makes it, P = make(M_eps), once the run has its start's prefiltered surface (else its start).
  void set_probe_maker(std::function<Control_matrix(const Control_matrix&)> make) { probe_maker_ = std::move(make); }
  /// After a run: where its probe ended (empty: it carried none).
  const Control_matrix& probe_result() const { return probe_.result(); }
  /// 1, or the fraction of the way from the input to the limit points of the result to write (a run
  /// that ended before its first step because the limit surface alone moved by more than the noise)
  double limit_weight() const { return limit_weight_; }

  /// Runs the flow from X (n x kappa; the first `metric_columns` columns define the surface, the
  /// others are carried along with the same operator). On success X holds the faired control points.
  /// On failure X is unspecified and the report says why.
  template <typename Tensor, typename Callback>
  Fairing_report run(Control_matrix& X, int metric_columns, const Tensor& tensor, const Stepper_settings& s, Callback& callback)
  {
    return flow(X, X, metric_columns, tensor, s, callback, false);
  }

  /// Attributes only (Bajaj & Xu's case c): the surface of the first 3 columns of X is fixed, so M
  /// and L are assembled once, the system matrix is constant (factorised once when factorised at all)
  /// and every step is one solve for the other columns. The stopping criteria read the attributes'
  /// Dirichlet energy trace(A^T L A) in place of int |H|^2 (27, 28), and the steady-state speed in units
  /// of the attributes' spread, the root mean square of A_0 - mean(A_0). (29) bounds how far the surface
  /// moves; with the surface fixed it does not apply (noisy values move by about the noise in one step),
  /// nor does the noise criterion, which measures the surface.
  template <typename Tensor, typename Callback>
  Fairing_report run_on_fixed_surface(Control_matrix& X, const Tensor& tensor, const Stepper_settings& s, Callback& callback)
  {
    Control_matrix F = X.rightCols(X.cols() - 3);
    const Fairing_report report = flow(X, F, 3, tensor, s, callback, true);
    X.rightCols(F.cols()) = F;
    return report;
  }

  typedef Cache Cache_type;

private:
  template <typename, typename, typename> friend class Flow_run;

  // The loop of both runs (Flow_run.h). Z: what moves, X itself, or on a fixed surface (the first 3
  // columns of X) the attributes' columns.
  template <typename Tensor, typename Callback>
  Fairing_report flow(const Control_matrix& X, Control_matrix& Z, int metric_columns, const Tensor& tensor,
                      const Stepper_settings& s, Callback& callback, bool fixed)
  {
    return Flow_run<Time_stepper, Tensor, Callback>(*this, X, Z, metric_columns, tensor, s, callback, fixed).run();
  }

  // the bounds of the settings on Z's columns: the geometry (the first 3, not on a fixed surface) and the
  // attributes (the others, all of them on a fixed surface)
  Deviation_bound make_bound(const Stepper_settings& s, const Control_matrix& Z, bool fixed, bool uniform, Fairing_report& report) const
  {
    if(s.maximum_deviation > 0)
    {
      report.absolute_maximum_deviation = s.relative_deviation ? s.maximum_deviation * units_.scale : s.maximum_deviation;
      report.maximum_deviation = report.absolute_maximum_deviation;   // its deprecated name, still filled
    }
    const auto bounds = user_bounds(Z.cols(), !fixed, fixed ? 0 : 3, report.absolute_maximum_deviation, s.attribute_maximum_deviation);
    return Deviation_bound(bounds[0], bounds[1], std::size_t(Z.rows()), uniform);
  }

  // The units of every vertex from the input's area per component, the tensor told its length scale,
  // then M and L(D) at X: false (and a failed report) when the input has no surface.
  template <typename Tensor>
  bool set_units(const Control_matrix& X, int metric_columns, const Stepper_settings& s, Tensor& tensor,
                 Fairing_report& report, Assembly_statistics& a, const CGAL::Real_timer& total)
  {
    const bool scaled_tensor = wants_length_scale(tensor);
    Prefilter_solver prefilter;
    prefilter.solver = s.solver;
    prefilter.tolerance = s.solver_tolerance / 100;
    prefilter.maximum_iterations = s.solver_maximum_iterations;
    prefilter.direct = s.direct_solver;
    std::vector<double> eps(std::size_t(X.rows()), scaled_tensor ? 0.0 : prefilter_time(tensor));   // the prefilter time per row
    Value_array m, l;
    // a prefilter's time follows from the units: then the isotropic M and L of the units are its start
    if(scaled_tensor && prefilter_time(tensor) > 0) a = operator_.assemble_isotropic(X, metric_columns);
    else if(scaled_tensor) a = operator_.assembler().assemble(X, metric_columns, Isotropic_diffusion_tensor(), m, l, false);
    else
    {
      operator_.set_prefilter(eps, &block_, prefilter);
      a = operator_.assemble(X, metric_columns, tensor, true);
    }
    for(std::size_t c = 0; c < a.component_area.size(); ++c)
      if(!(a.component_area[c] > 0) || !std::isfinite(a.component_area[c]) || !(component_edge_[c] > 0))
      {
        operator_.discard_isotropic();
        fail(report, Fairing_status::DEGENERATE_METRIC, "the input's limit surface has no area" +
             (components_.count > 1 ? " in connected component " + std::to_string(c) : std::string()) +
             " (sqrt(det G) <= 0 on face " + std::to_string(a.degenerate_face) + "): its control points do not span a surface", total);
        return false;
      }
    const Length_unit tensor_unit = is_automatic_tensor(tensor) ? Length_unit::EDGE : Length_unit::SCALE;
    units_ = make_step_units(a, components_, std::size_t(X.rows()), s.time_step, s.time_unit, s.order, s.fidelity_weight,
                             s.relative_fidelity, s.stopping.relative_units, tensor_unit, component_edge_, mean_edge_);
    report.scale = units_.scale;
    report.flow_order = s.order;
    report.time_step = units_.time_step;
    report.fidelity_weight = units_.fidelity_weight;
    report.components = components_.count;
    // several components: each solved in its own units (unknowns dX / l_c, equations / l_c^2 and l_c^3),
    // so that the solver's tolerance means the same on a small part as on a large one
    unknown_scale_.clear();
    if(components_.count > 1 && units_.length.size() == std::size_t(X.rows()))
      for(std::size_t i = 0; i < std::size_t(X.rows()); ++i)
      {
        const int c = components_.of_vertex[i];
        unknown_scale_.push_back(c >= 0 ? length_scale(a.component_area[std::size_t(c)]) : 1.0);
      }
    if(scaled_tensor)
    {
      // each component's prefilter time as the tensor measures it at that component's scale
      std::vector<double> component_eps(components_.count);
      for(std::size_t c = 0; c < components_.count; ++c)
      {
        Tensor t = tensor;
        give_length_scale(t, units_.tensor_unit * units_.tensor_scale[c]);
        component_eps[c] = prefilter_time(t);
      }
      for(std::size_t i = 0; i < eps.size(); ++i)
        if(components_.of_vertex[i] >= 0) eps[i] = component_eps[std::size_t(components_.of_vertex[i])];
      context_.component_scale = &units_.tensor_scale;
      operator_.assembler().set_context(context_);
      give_length_scale(tensor, units_.tensor_unit);
      report.feature_threshold = std::isfinite(threshold_of(tensor)) ? threshold_of(tensor) : 0.0;
      report.prefilter_time = prefilter_time(tensor);
      operator_.set_prefilter(std::move(eps), &block_, prefilter);
      a = operator_.assemble(X, metric_columns, tensor, true);
    }
    report.initial.area = a.area;
    report.initial.energy = a.energy;
    report.initial.H_integral = a.H_integral;
    if(!operator_.error().empty()) { fail(report, Fairing_status::SOLVER_FAILED, operator_.error(), total); return false; }
    return true;
  }

  // the positions the stopping rules and the soundness measure for X: its Loop limit points, or X itself
  void measured_positions(const Control_matrix& X, Control_matrix& Y) const
  {
    if(measure_limit_surface_) limit_points(layer_, X, Y);
    else Y = X;
  }

  // adds the free rows' displacements to X; records the step's and the total (from X0) largest motion
  // over the first `columns` columns; in units of `row_unit` too, for the stopping criteria
  // (max_relative_, moved_relative_)
  void move_free_rows(Control_matrix& X, const Control_matrix& dX, const Control_matrix& X0, int columns,
                      const std::vector<double>& row_unit, Fairing_step& st)
  {
    double moved = 0;
    moved_relative_ = max_relative_ = 0;
    for(Eigen::Index i = 0; i < dX.rows(); ++i)
    {
      const std::size_t row = std::size_t(block_.free[std::size_t(i)]);
      X.row(Eigen::Index(row)) += dX.row(i);
      const double d = dX.row(i).head(columns).norm();
      moved = std::max(moved, d);
      moved_relative_ = std::max(moved_relative_, d / row_unit[row]);
    }
    st.step_displacement = moved;
    st.max_displacement = 0;
    for(Eigen::Index i = 0; i < X.rows(); ++i)
    {
      const double d = (X.row(i) - X0.row(i)).head(columns).norm();
      st.max_displacement = std::max(st.max_displacement, d);
      max_relative_ = std::max(max_relative_, d / row_unit[std::size_t(i)]);
    }
  }

  Surface_operator<Cache> operator_;
  Free_block block_;
  const Tangential_motion_filter* tangential_filter_ = nullptr;
  Ride_along_probe probe_;
  std::function<Control_matrix(const Control_matrix&)> probe_maker_;
  Control_matrix normal_dZ_;
  const Ghost_layer& layer_;
  const Mesh_components& components_;
  const std::vector<double>& component_edge_;
  double mean_edge_;
  Step_units units_;
  std::vector<double> curvature_bound_; // per component (Assembly_statistics::bounded_H_integral)
  bool measure_limit_surface_ = false;
  double moved_relative_ = 0, max_relative_ = 0;
  double limit_weight_ = 1;
  std::vector<double> unknown_scale_;   // per row, with several components (else empty)
  Assembly_context context_;            // the assembler's (Fem_assembly.h)
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TIME_STEPPER_H
