// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The library's flow (internal/flow/Flow_run.h and Time_stepper.h) for a run with a given time step and
// number of steps, on distributed matrices: the units from the input's area, the semi-implicit steps
// solved by PETSc, each candidate surface judged by the library's Step_safety (statistics and fold counts
// reduced over the processes, so every process takes the same decision), a rejected step retried with the
// library's Step_controller, the library's Stopping_monitor asked after each step, and at the end the
// fall-back to the last surface without new folds. What the library does besides (the noise level, a
// deviation bound, a local time scale, the risk probe, the fourth-order flow, a fixed surface) is refused
// by the program before a run starts (Run_request.h).

#ifndef AF_DISTRIBUTED_DISTRIBUTED_FLOW_H
#define AF_DISTRIBUTED_DISTRIBUTED_FLOW_H

#include "Collective_failure.h"
#include "Distributed_operator.h"
#include "Distributed_solver.h"
#include "Surface_folds.h"

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Normal_motion.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_control.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_units.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stopping_monitor.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Tensor_hooks.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Mesh_components.h>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace af_distributed {

namespace AF = CGAL::Anisotropic_fairing;

/// What a run reads of the mesh, the same on every process.
struct Flow_input
{
  const AFI::Ghost_layer& layer;
  const AFI::Mesh_components& components;
  const std::vector<double>& component_edge;
  double mean_edge;
  const std::vector<bool>& constrained;   // per real vertex
  AFI::Assembly_context numbering;        // the caller's numbering and border (Assembly_context's first three)
  int metric_columns;                     // of the surface: 3, or all (coupled attributes)
  bool normal_motion;                     // each step's displacement loses its tangential part
};

/// Per-phase times and counts of a run (the program's JSON report).
struct Flow_timing
{
  double assemble_seconds = 0, solve_seconds = 0, judge_seconds = 0;
  std::size_t iterations = 0, solves = 0;
};

template <typename Tensor>
class Distributed_flow
{
  enum class Outcome { NEXT, RETRY, ENDED, FAILED };

public:
  Distributed_flow(MPI_Comm comm, const Distributed_layout& d, Ghosted_rows& rows, Distributed_operator& op, const Flow_input& in,
                   const AFI::Stepper_settings& s, const Tensor& tensor)
    : comm_(comm), d_(d), rows_(rows), op_(op), in_(in), s_(s), tensor_(tensor), filter_(in.layer),
      solver_(comm, d, in.constrained, "", s.solver_tolerance, s.solver_maximum_iterations)
  {
    for(double h : in.component_edge) curvature_bound_.push_back(2 / h);
    context_ = in.numbering;
    context_.face_component = &in.components.of_face;
    context_.components = in.components.count;
    context_.curvature_bound = &curvature_bound_;
    context_.folded_turn = AFI::turn_120;
    context_.bent_turn = AFI::turn_110;
    op_.assembler().set_context(context_);
    for(std::size_t k = 0; k < d.owned_vertices.size(); ++k)
      if(!in.constrained[std::size_t(d.owned_vertices[k])]) free_.push_back(k);
  }

  /// Runs the flow from Z (owned and overlap rows); on success Z's owned and overlap rows hold the result.
  /// `progress` is told of every accepted step.
  AF::Fairing_report run(Control_matrix& Z, const std::function<void(const AF::Fairing_step&)>& progress)
  {
    total_.start();
    progress_ = progress;
    if(!start(Z)) return report_;
    for(std::size_t step = 1; step <= s_.maximum_steps && nfree_ > 0;)
    {
      const Outcome o = attempt(Z, step);
      if(o == Outcome::FAILED) return report_;
      if(o == Outcome::ENDED) break;
      if(o == Outcome::RETRY) continue;
      control_.grow();
      ++step;
    }
    finish(Z);
    return report_;
  }

  const Flow_timing& timing() const { return timing_; }

private:
  // the units of every vertex from the input's area, then M and L(D) at Z (Time_stepper::set_units)
  bool set_units(const Control_matrix& Z, AFI::Assembly_statistics& a)
  {
    const bool scaled_tensor = AFI::wants_length_scale(tensor_);
    const std::size_t n = std::size_t(Z.rows());
    std::vector<double> eps(n, scaled_tensor ? 0.0 : AFI::prefilter_time(tensor_));
    if(scaled_tensor) a = op_.assemble(Z, in_.metric_columns, AF::Isotropic_diffusion_tensor(), false);
    else
    {
      op_.set_prefilter(eps);
      a = op_.assemble(Z, in_.metric_columns, tensor_, true);
    }
    for(std::size_t c = 0; c < a.component_area.size(); ++c)
      if(!(a.component_area[c] > 0) || !std::isfinite(a.component_area[c]) || !(in_.component_edge[c] > 0))
      {
        AFI::fail(report_, AF::Fairing_status::DEGENERATE_METRIC, "the input's limit surface has no area" +
                  (in_.components.count > 1 ? " in connected component " + std::to_string(c) : std::string()) +
                  " (sqrt(det G) <= 0 on face " + std::to_string(a.degenerate_face) + "): its control points do not span a surface" +
                  part_of_face(a), total_);
        return false;
      }
    const AFI::Length_unit tensor_unit = AFI::is_automatic_tensor(tensor_) ? AFI::Length_unit::EDGE : AFI::Length_unit::SCALE;
    units_ = AFI::make_step_units(a, in_.components, n, s_.time_step, s_.time_unit, s_.order, s_.fidelity_weight, s_.relative_fidelity,
                                  s_.stopping.relative_units, tensor_unit, in_.component_edge, in_.mean_edge);
    report_.scale = units_.scale;
    report_.flow_order = s_.order;
    report_.time_step = units_.time_step;
    report_.fidelity_weight = units_.fidelity_weight;
    report_.components = in_.components.count;
    if(scaled_tensor)
    {
      // each component's prefilter time as the tensor measures it at that component's scale
      std::vector<double> component_eps(in_.components.count);
      for(std::size_t c = 0; c < in_.components.count; ++c)
      {
        Tensor t = tensor_;
        AFI::give_length_scale(t, units_.tensor_unit * units_.tensor_scale[c]);
        component_eps[c] = AFI::prefilter_time(t);
      }
      for(std::size_t i = 0; i < n; ++i)
        if(in_.components.of_vertex[i] >= 0) eps[i] = component_eps[std::size_t(in_.components.of_vertex[i])];
      context_.component_scale = &units_.tensor_scale;
      op_.assembler().set_context(context_);
      AFI::give_length_scale(tensor_, units_.tensor_unit);
      report_.feature_threshold = std::isfinite(AFI::threshold_of(tensor_)) ? AFI::threshold_of(tensor_) : 0.0;
      report_.prefilter_time = AFI::prefilter_time(tensor_);
      op_.set_prefilter(std::move(eps));
      a = op_.assemble(Z, in_.metric_columns, tensor_, true);
    }
    report_.initial.area = a.area;
    report_.initial.energy = a.energy;
    report_.initial.H_integral = a.H_integral;
    return true;
  }

  // which process's part holds the degenerate face named by `a` (the caller's numbering), when there are several
  std::string part_of_face(const AFI::Assembly_statistics& a) const
  {
    if(d_.size == 1 || !a.degenerate || !in_.numbering.original_face) return std::string();
    const std::vector<std::size_t>& original = *in_.numbering.original_face;
    for(std::size_t f = 0; f < original.size(); ++f)
      if(original[f] == a.degenerate_face) return " (in the part of process " + std::to_string(d_.face_owner[f]) + ")";
    return std::string();
  }

  // the units, the input's operator, the criteria's measures and the soundness of the start (Flow_run::start)
  bool start(Control_matrix& Z)
  {
    report_.vertices = std::size_t(Z.rows());
    unsigned long long free_count = free_.size(), all_free = 0;
    MPI_Allreduce(&free_count, &all_free, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm_);
    nfree_ = std::size_t(all_free);
    report_.constrained_vertices = std::size_t(Z.rows()) - nfree_;
    CGAL::Real_timer clock;
    clock.start();
    AFI::Assembly_statistics a;
    if(!set_units(Z, a)) return false;
    timing_.assemble_seconds += clock.time();
    Z0_ = Z;
    time_unit_ = s_.stopping.relative_units ? std::pow(report_.scale, s_.order) : 1.0;
    monitor_.emplace(s_.stopping, a.H_integral);
    initial_ = AFI::Surface_soundness();
    initial_.statistics = a;
    count_folds(Z, initial_);
    const AFI::Surface_soundness input = folds_of(Z0_);
    input_folds_ = input.folded_edges;
    input_fold_edges_ = input.folded_edge_list;
    accepted_ = initial_;
    lowest_H_.emplace(a);
    allowed_folds_ = std::max(input_folds_, initial_.folded_edges);
    Z_unfolded_ = Z;
    if(nfree_ == 0) report_.stop_reason = AF::Stop_reason::NO_FREE_VERTEX;
    return true;
  }

  // the folds of the mesh of X's written positions (the limit points for the Loop element, as count_folds)
  void count_folds(const Control_matrix& X, AFI::Surface_soundness& s)
  {
    distributed_limit_points(in_.layer, d_, rows_, X, Y_);
    count_distributed_folds(comm_, in_.layer, d_, in_.components.of_face, in_.component_edge, Y_, s);
  }
  // the folds of the mesh of X itself (the input's control mesh)
  AFI::Surface_soundness folds_of(const Control_matrix& X)
  {
    AFI::Surface_soundness s;
    count_distributed_folds(comm_, in_.layer, d_, in_.components.of_face, in_.component_edge, X, s);
    return s;
  }

  // one try at step `step`: solved, made a candidate, judged, then accepted or taken again
  Outcome attempt(Control_matrix& Z, std::size_t step)
  {
    AF::Fairing_step st;
    st.step = step;
    st.time_step = control_.factor() * report_.time_step;
    bool finite = false;
    if(!solve(Z, st, finite)) return Outcome::FAILED;
    make_candidate(Z, st, finite);
    const Outcome judged = judge(step, finite, step == s_.maximum_steps);
    if(judged != Outcome::NEXT) return judged;
    return accept(Z, st);
  }

  // the step's system at Z_n solved (Step_solver.h): its displacement dZ_ over the owned rows
  bool solve(const Control_matrix& Z, AF::Fairing_step& st, bool& finite)
  {
    CGAL::Real_timer clock;
    clock.start();
    std::vector<double> t(units_.tau);
    for(double& x : t) x *= control_.factor();
    const Distributed_solve sol = solver_.solve(op_.M(), op_.L(), t, units_.omega, Z, Z0_, int(Z.cols()), dZ_);
    st.solve_seconds = clock.time();
    st.assemble_seconds = pending_assemble_seconds_;
    pending_assemble_seconds_ = 0;
    st.solver_iterations = sol.iterations;
    timing_.solve_seconds += st.solve_seconds;
    timing_.iterations += std::size_t(sol.iterations);
    ++timing_.solves;
    int mine = dZ_.allFinite() ? 1 : 0, all = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MIN, comm_);
    finite = all == 1;
    if(!sol.ok && finite)
    {
      AFI::fail(report_, AF::Fairing_status::SOLVER_FAILED, "step " + std::to_string(st.step) + ": " + sol.message, total_);
      return false;
    }
    return true;
  }

  // Zc = Z + the solution (its normal part for the anisotropic flow), the overlap refreshed, and the step's
  // and the total motion (Time_stepper::move_free_rows)
  void make_candidate(const Control_matrix& Z, AF::Fairing_step& st, bool finite)
  {
    Zc_ = Z;
    if(finite)
    {
      Control_matrix dZ = dZ_;
      if(in_.normal_motion)
      {
        const Control_matrix& tangent_surface = op_.prefiltered() ? *op_.prefiltered() : Z;
        filter_.remove(tangent_surface, in_.metric_columns, d_.owned_vertices, dZ);
      }
      double motion[3] = { 0, 0, 0 };   // the step's largest, its largest relative, the total's largest relative
      double largest_total = 0;
      const int columns = in_.metric_columns;
      for(std::size_t k : free_)
      {
        const int row = d_.owned_vertices[k];
        Zc_.row(row) += dZ.row(Eigen::Index(k));
        const double m = dZ.row(Eigen::Index(k)).head(columns).norm();
        motion[0] = std::max(motion[0], m);
        motion[1] = std::max(motion[1], m / units_.length[std::size_t(row)]);
      }
      for(int row : d_.owned_vertices)
      {
        const double m = (Zc_.row(row) - Z0_.row(row)).head(columns).norm();
        largest_total = std::max(largest_total, m);
        motion[2] = std::max(motion[2], m / units_.length[std::size_t(row)]);
      }
      double local[4] = { motion[0], motion[1], motion[2], largest_total }, all[4];
      MPI_Allreduce(local, all, 4, MPI_DOUBLE, MPI_MAX, comm_);
      st.step_displacement = all[0];
      moved_relative_ = all[1];
      max_relative_ = all[2];
      st.max_displacement = all[3];
    }
    rows_.refresh(Zc_);
  }

  // the candidate judged by the library's Step_safety: NEXT when sound, else failed, retried shorter or ended
  Outcome judge(std::size_t step, bool finite, bool last_step)
  {
    CGAL::Real_timer clock;
    clock.start();
    candidate_ = AFI::Surface_soundness();
    candidate_.finite = finite && finite_everywhere(comm_, d_, Zc_);
    std::string why;
    AFI::Step_verdict verdict = AFI::Step_verdict::SOUND;
    bool saved = false;
    if(candidate_.finite) count_folds(Zc_, candidate_);
    // folds where the accepted surface or the input was folded, as the serial flow judges them (every
    // process has the whole mesh and the gathered fold lists)
    const AFI::Known_fold_places known = [this](const AFI::Surface_soundness& c) {
      return AFI::folds_at_known_places(*in_.layer.topology, in_.layer.real_faces, accepted_, input_fold_edges_, allowed_folds_, c);
    };
    if(candidate_.finite && AFI::edges_folded(accepted_, input_folds_, candidate_, why, known)) verdict = AFI::Step_verdict::UNSOUND;
    else
    {
      op_.save();
      saved = true;
      if(candidate_.finite)
      {
        try { candidate_.statistics = op_.assemble(Zc_, in_.metric_columns, tensor_, !last_step); }
        catch(const std::exception& e)
        {
          AFI::fail(report_, AF::Fairing_status::SOLVER_FAILED, "after step " + std::to_string(step) + ": " + e.what(), total_);
          return Outcome::FAILED;
        }
        candidate_.finite = finite_everywhere(comm_, d_, s_.measure_limit_surface ? Y_ : Zc_);
      }
      verdict = AFI::judge_step(initial_, accepted_, input_folds_, *lowest_H_, candidate_, why, known);
    }
    pending_assemble_seconds_ = clock.time();
    timing_.judge_seconds += clock.time();
    if(verdict == AFI::Step_verdict::COLLAPSED)
    {
      AFI::fail(report_, AF::Fairing_status::COLLAPSED, "step " + std::to_string(step) + ": " + why +
                ": mean-curvature flow shrinks closed surfaces to points; use fewer steps or a larger fidelity weight", total_);
      return Outcome::FAILED;
    }
    if(verdict != AFI::Step_verdict::UNSOUND) return Outcome::NEXT;
    if(saved) op_.restore();
    return rejected(step, why);
  }

  // a rejected candidate: retried shorter, or the run ends on the last sound surface (or fails before any)
  Outcome rejected(std::size_t step, const std::string& why)
  {
    ++report_.rejected_steps;
    last_why_ = why;
    if(control_.reject(s_.maximum_rejections)) return Outcome::RETRY;
    const std::string what = "step " + std::to_string(step) + ": " + why + " even with 1/" +
                             std::to_string(1 << (2 * s_.maximum_rejections)) + " of the time step";
    if(report_.steps.empty())
    {
      AFI::fail(report_, !candidate_.finite ? AF::Fairing_status::NON_FINITE_VALUE : AF::Fairing_status::FOLDED, what, total_);
      return Outcome::FAILED;
    }
    report_.stop_reason = AF::Stop_reason::STEP_REJECTED;
    report_.message = what + "; the run ends on the last sound surface (step " + std::to_string(step - 1) + ")";
    return Outcome::ENDED;
  }

  // the candidate becomes the surface; its step recorded, then the stop rules asked (Flow_run::accept)
  Outcome accept(Control_matrix& Z, AF::Fairing_step& st)
  {
    control_.accept();
    Z.swap(Zc_);
    accepted_ = candidate_;
    if(candidate_.folded_edges <= allowed_folds_)
    {
      Z_unfolded_ = Z;
      unfolded_steps_ = report_.steps.size() + 1;
    }
    lowest_H_->add(candidate_.statistics);
    time_ += st.time_step;
    st.time = time_;
    st.area = accepted_.statistics.area;
    st.energy = accepted_.statistics.energy;
    st.H_integral = accepted_.statistics.H_integral;
    if(st.step == s_.maximum_steps) st.assemble_seconds += pending_assemble_seconds_;
    report_.steps.push_back(st);
    if(progress_) progress_(st);
    if(control_.cramped())
    {
      report_.stop_reason = AF::Stop_reason::STEP_REJECTED;
      report_.message = "steps " + std::to_string(st.step - 3) + " to " + std::to_string(st.step) + " went on only with 1/16 of the time "
                        "step or less (" + last_why_ + " otherwise); the run ends on the last sound surface (step " +
                        std::to_string(st.step) + ")";
      return Outcome::ENDED;
    }
    const bool stop = monitor_->should_stop(st.step, st.time_step / time_unit_, st.H_integral, max_relative_, moved_relative_,
                                            report_.stop_reason);
    return stop ? Outcome::ENDED : Outcome::NEXT;
  }

  // the end: never a surface with more folded edges than the input (Flow_run::finish)
  void finish(Control_matrix& Z)
  {
    AFI::Surface_soundness last;
    count_folds(Z, last);
    const std::size_t folds = last.folded_edges;
    if(folds > allowed_folds_ && report_.succeeded())
    {
      if(unfolded_steps_ == 0)
      {
        AFI::fail(report_, AF::Fairing_status::FOLDED, "the surface folded at " + std::to_string(folds) + " edges (the input at " +
                  std::to_string(allowed_folds_) + ") from the first step on, even with smaller time steps", total_);
        return;
      }
      Z = Z_unfolded_;
      report_.steps.resize(unfolded_steps_);
      report_.stop_reason = AF::Stop_reason::STEP_REJECTED;
      report_.message = "the surface folded at " + std::to_string(folds) + " edges (the input at " + std::to_string(allowed_folds_) +
                        "); the run ends on the last surface without new folds (step " + std::to_string(unfolded_steps_) + ")";
    }
    report_.total_seconds = total_.time();
  }

  MPI_Comm comm_;
  const Distributed_layout& d_;
  Ghosted_rows& rows_;
  Distributed_operator& op_;
  const Flow_input& in_;
  const AFI::Stepper_settings& s_;
  Tensor tensor_;
  const AFI::Tangential_motion_filter filter_;
  Distributed_solver solver_;
  AFI::Assembly_context context_;
  std::vector<double> curvature_bound_;
  std::vector<std::size_t> free_;   // positions in d_.owned_vertices of the free ones
  std::size_t nfree_ = 0;
  AFI::Step_units units_;
  AF::Fairing_report report_;
  CGAL::Real_timer total_;
  std::function<void(const AF::Fairing_step&)> progress_;
  Control_matrix Z0_, Zc_, Y_, Z_unfolded_, dZ_;
  double time_unit_ = 1, time_ = 0, moved_relative_ = 0, max_relative_ = 0, pending_assemble_seconds_ = 0;
  std::optional<AFI::Stopping_monitor> monitor_;
  std::optional<AFI::Lowest_curvature> lowest_H_;
  AFI::Surface_soundness initial_, accepted_, candidate_;
  std::size_t input_folds_ = 0, allowed_folds_ = 0, unfolded_steps_ = 0;
  std::vector<int> input_fold_edges_;   // the input mesh's folded edges (a halfedge of each)
  AFI::Step_controller control_;
  std::string last_why_;
  Flow_timing timing_;
};

} // namespace af_distributed

#endif // AF_DISTRIBUTED_DISTRIBUTED_FLOW_H
