// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The semi-implicit step ((1 + tau w) M + tau L(D)) X_{n+1} = M (X_n + tau w X_0) of Bajaj & Xu
// (eq. 26 with the fidelity term written consistently, doc/Anisotropic_fairing/design/loop-fem-flow.md
// section 8), repeated until a stop rule holds: the flow loop (Flow_loop.h) on one process's operator
// (Serial_flow_operator.h). Constrained vertices are eliminated: the unknowns are the displacements of the
// free vertices, A_FF dX_F = tau (w M (X_0 - X_n) - L X_n)_F, so the system stays symmetric positive
// definite and its right-hand side does not depend on the model's position in space.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TIME_STEPPER_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TIME_STEPPER_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Flow_loop.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Serial_flow_operator.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <functional>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

template <typename Cache>
class Time_stepper
{
  typedef typename Flow_operator_of<Cache>::type Operator;

public:
  /// `constrained[i]` holds vertex i fixed. `layer`: the mesh (with its ghosts); `components`: its
  /// connected components, `component_edge[c]` the mean edge length of component c, `mean_edge` of all.
  /// `numbering`: the caller's numbering and border for the assembler (Assembly_context: its first three).
  Time_stepper(const Cache& cache, std::size_t n, const std::vector<bool>& constrained, const Ghost_layer& layer,
               const Mesh_components& components, const std::vector<double>& component_edge, double mean_edge,
               const Assembly_context& numbering = Assembly_context())
    : operator_(cache, n, constrained, Flow_mesh{ layer, components, component_edge, mean_edge }, numbering) {}

  /// Each step's displacement of the surface's columns then loses its tangential part (null: kept).
  void set_tangential_filter(const Tangential_motion_filter* f) { operator_.set_tangential_filter(f); }
  /// The next run carries the probed start P along (Ride_along_probe.h), unless it holds a deviation bound.
  void set_probe(const Control_matrix& P) { probe_.start = P; }
  /// After each step that no rule ends, `keep_going(Z, probe)` may end the run (Stop_reason::DROPPED).
  void set_probe_test(std::function<bool(const Control_matrix&, const Control_matrix&)> keep_going)
  {
    probe_.keep_going = std::move(keep_going);
  }
  /// After a run: where its probe ended (empty: it carried none).
  const Control_matrix& probe_result() const { return probe_result_; }
  /// After a run: the steps it accepted (Probe_schedule.h).
  const Probe_schedule& schedule() const { return schedule_; }
  /// 1, or the fraction of the way from the input to the limit points of the result to write (a run
  /// that ended before its first step because the limit surface alone moved by more than the noise)
  double limit_weight() const { return limit_weight_; }

  /// Runs the flow from X (n x kappa; the first `metric_columns` columns define the surface, the
  /// others are carried along with the same operator). On success X holds the faired control points.
  /// On failure X is unspecified and the report says why.
  template <typename Tensor, typename Callback>
  Fairing_report run(Control_matrix& X, int metric_columns, const Tensor& tensor, const Stepper_settings& s,
                     Callback& callback)
  {
    Flow_loop<Operator, Tensor, Callback> loop(operator_, X, X, metric_columns, tensor, s, callback, false,
                                               std::move(probe_));
    return kept(loop.run());
  }

  /// Attributes only (Bajaj & Xu's case c): the surface of the first 3 columns of X is fixed, so M
  /// and L are assembled once, the system matrix is constant (factorised once when factorised at all)
  /// and every step is one solve for the other columns. The stop rules read the attributes' Dirichlet
  /// energy trace(A^T L A) in place of int |H|^2 (27, 28), and the steady-state speed in units of the
  /// attributes' spread; (29) and the noise criterion, which measure the surface, do not apply.
  template <typename Tensor, typename Callback>
  Fairing_report run_on_fixed_surface(Control_matrix& X, const Tensor& tensor, const Stepper_settings& s,
                                      Callback& callback)
  {
    Control_matrix F = X.rightCols(X.cols() - 3);
    const Fairing_report report = kept(
      Flow_loop<Operator, Tensor, Callback>(operator_, X, F, 3, tensor, s, callback, true).run());
    X.rightCols(F.cols()) = F;
    return report;
  }

  typedef Cache Cache_type;

private:
  Fairing_report kept(Flow_result r)
  {
    probe_ = Probe_request();
    probe_result_ = std::move(r.probe);
    schedule_ = std::move(r.schedule);
    limit_weight_ = r.limit_weight;
    return std::move(r.report);
  }

  Operator operator_;
  Probe_request probe_;
  Control_matrix probe_result_;
  Probe_schedule schedule_;
  double limit_weight_ = 1;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_TIME_STEPPER_H
