// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The risk estimate's probe (Ride_along_probe.h) on an operator of its own: for a flow whose operator follows
// the data (the anisotropic tensor reads the curvature of its prefiltered surface), the probed input's steps
// are solved with M_eps, L(D) and the tangent planes of the probe's own surface, with the run's time step
// fractions, in lockstep with the run. So the estimate carried along measures the divergence of the whole
// map, the operator's dependence on the data included, which the shared operator leaves out (the anisotropic
// flow's estimate is then 1.1-2.1x too low on the benchmark's cases), without a second run: the probe takes
// exactly the run's accepted steps, never its rejected ones, nor steps of its own.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_PROBE_FLOW_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_PROBE_FLOW_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Flow_units.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Ride_along_probe.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Real_timer.h>

#include <functional>
#include <memory>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

template <typename Operator, typename Tensor>
class Probe_flow
{
public:
  typedef std::function<std::unique_ptr<Operator>()> Operator_maker;

  /// `make`: the probe's operator, of the run's mesh, made when the probe starts; `tensor`: the run's, before
  /// the run gave it its units.
  Probe_flow(Operator_maker make, const Tensor& tensor) : make_(std::move(make)), tensor_(tensor) {}

  /// The probe starts where it is: its units, its operator on its surface and its solver, as a run's. It is
  /// dropped when its surface has none.
  void start(Ride_along_probe& probe, int metric_columns, const Stepper_settings& s)
  {
    if(!probe.active()) return;
    op_ = make_();
    op_->begin_run(s, false);
    P0_ = probe.result();
    columns_ = metric_columns;
    Fairing_report unread;
    Assembly_statistics a;
    const CGAL::Real_timer clock;
    if(!start_units(*op_, P0_, metric_columns, s, tensor_, unread, a, clock)) { probe.drop(); return; }
    op_->start_solver(s, P0_.cols(), false, nullptr, nullptr, P0_);
  }

  /// The step the run accepted, `factor` times the time step, from the probe's surface with its own operator,
  /// less its part in the tangent planes of the probe's prefiltered surface where the run removes its own;
  /// cut at `cut_at` of its length where the run's is (>= 1 or < 0: not cut). Dropped if it fails.
  void step(Ride_along_probe& probe, double factor, double cut_at)
  {
    if(!probe.active()) return;
    bool direct = false;
    const Control_matrix& P = probe.result();
    const Solve_statistics sol = op_->solve(factor, P, P0_, no_weights_, direct);
    if(!sol.ok || !op_->solution_finite(sol)) { probe.drop(); return; }
    Control_matrix d = op_->displacement();
    op_->normal_part(op_->prefiltered() ? *op_->prefiltered() : P, columns_, d);
    probe.make_candidate([&](Control_matrix& candidate) { op_->add(candidate, d); });
    if(cut_at >= 0 && cut_at < 1) probe.shorten(cut_at);
  }

  /// The probe's operator on the surface its accepted step ended on, for the next step. Dropped if it fails.
  void next(Ride_along_probe& probe)
  {
    if(!probe.active()) return;
    op_->assemble(probe.result(), columns_, tensor_, true);
    if(!op_->error().empty()) probe.drop();
  }

private:
  Operator_maker make_;
  Tensor tensor_;
  std::unique_ptr<Operator> op_;
  Control_matrix P0_;
  int columns_ = 3;
  const std::vector<double> no_weights_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_PROBE_FLOW_H
