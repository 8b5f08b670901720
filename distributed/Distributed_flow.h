// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The library's flow loop (internal/flow/Flow_loop.h) on distributed matrices: this file is its operator
// (internal/flow/Flow_operator.h says what one provides). M and L(D) come from Distributed_operator, each step
// is solved by PETSc, and every measure the loop decides on (motion, finiteness, folds, statistics) is reduced
// over the processes, so every process takes the same decision. What needs row-wise measures of the whole
// mesh (the noise level, a deviation bound, a local time scale, the fourth-order flow, a fixed surface) is
// refused: by the program before a run starts (Run_request.h), and by unsupported() here.

#ifndef AF_DISTRIBUTED_DISTRIBUTED_FLOW_H
#define AF_DISTRIBUTED_DISTRIBUTED_FLOW_H

#include "Collective_failure.h"
#include "Distributed_operator.h"
#include "Distributed_solver.h"
#include "Surface_folds.h"

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Flow_loop.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Flow_operator.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Normal_motion.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_units.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <functional>
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

class Distributed_flow_operator
{
public:
  Distributed_flow_operator(MPI_Comm comm, const Distributed_layout& d, Ghosted_rows& rows, Distributed_operator& op,
                            const Flow_input& in, const AFI::Stepper_settings& s)
    : comm_(comm), d_(d), rows_(rows), op_(op), in_(in),
      mesh_{ in.layer, in.components, in.component_edge, in.mean_edge }, filter_(in.layer),
      solver_(comm, d, in.constrained, "", s.solver_tolerance, s.solver_maximum_iterations),
      context_(AFI::flow_context(in.numbering, mesh_, curvature_bound_))
  {
    op_.assembler().set_context(context_);
    for(std::size_t k = 0; k < d.owned_vertices.size(); ++k)
      if(!in.constrained[std::size_t(d.owned_vertices[k])])
      {
        free_.push_back(k);
        free_rows_.push_back(d.owned_vertices[k]);
      }
  }

  const Flow_timing& timing() const { return timing_; }

  const AFI::Flow_mesh& mesh() const { return mesh_; }
  std::string unsupported(const AFI::Stepper_settings& s, bool fixed) const
  {
    std::string what = fixed ? "a fixed surface (the attributes-only mode)" : s.noise ? "the noise criterion"
                     : s.maximum_deviation > 0 || s.attribute_maximum_deviation > 0 ? "a deviation bound"
                     : s.local_time_scale ? "a local time scale" : s.order != 2 ? "the fourth-order flow" : "";
    return what.empty() ? what : what + " is not supported by the distributed program";
  }
  std::size_t free_count() const
  {
    unsigned long long mine = free_.size(), all = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm_);
    return std::size_t(all);
  }
  void begin_run(const AFI::Stepper_settings& s, bool) { settings_ = &s; }

  // --- the units
  AFI::Assembly_statistics assemble_isotropic(const Control_matrix& X, int columns, bool)
  {
    return assemble(X, columns, AF::Isotropic_diffusion_tensor(), false);
  }
  void discard_isotropic() {}
  void set_prefilter(std::vector<double> eps, const AFI::Stepper_settings&) { op_.set_prefilter(std::move(eps)); }
  void set_units(const AFI::Step_units& u, const AFI::Assembly_statistics&, bool component_scale)
  {
    units_ = u;
    if(!component_scale) return;
    context_.component_scale = &units_.tensor_scale;
    op_.assembler().set_context(context_);
  }
  const AFI::Step_units& units() const { return units_; }
  /// which process's part holds the degenerate face named by `a` (the caller's numbering), when there are several
  std::string where_face(const AFI::Assembly_statistics& a) const
  {
    if(d_.size == 1 || !a.degenerate || !in_.numbering.original_face) return std::string();
    const std::vector<std::size_t>& original = *in_.numbering.original_face;
    for(std::size_t f = 0; f < original.size(); ++f)
      if(original[f] == a.degenerate_face) return " (in the part of process " + std::to_string(d_.face_owner[f]) + ")";
    return std::string();
  }

  // --- the operator on a surface: a failed prefilter (the same on every process) is an error()
  template <typename Tensor>
  AFI::Assembly_statistics assemble(const Control_matrix& X, int columns, const Tensor& tensor, bool with_matrices)
  {
    CGAL::Real_timer clock;
    clock.start();
    error_.clear();
    AFI::Assembly_statistics a;
    try { a = op_.assemble(X, columns, tensor, with_matrices); }
    catch(const std::exception& e) { error_ = e.what(); }
    (stepping_ ? timing_.judge_seconds : timing_.assemble_seconds) += clock.time();
    return a;
  }
  const std::string& error() const { return error_; }
  void save() { op_.save(); }
  template <typename Tensor>
  void restore(const Control_matrix&, int, const Tensor&) { op_.restore(); }
  const Control_matrix* prefiltered() const { return op_.prefiltered(); }
  double dirichlet_energy(const Control_matrix& Z) { return solver_.quadratic_form(op_.L(), Z); }

  // --- the step (the solver was made with the run's settings)
  void start_solver(const AFI::Stepper_settings&, Eigen::Index, bool, const AFI::Output_fidelity*,
                    const Control_matrix*, const Control_matrix&)
  {}
  AFI::Solve_statistics solve(double factor, const Control_matrix& Z, const Control_matrix& Z0,
                              const std::vector<double>&, bool& direct)
  {
    stepping_ = true;
    CGAL::Real_timer clock;
    clock.start();
    std::vector<double> t(units_.tau);
    for(double& x : t) x *= factor;
    const Distributed_solve sol = solver_.solve(op_.M(), op_.L(), t, units_.omega, Z, Z0, int(Z.cols()), dZ_);
    solve_seconds_ = clock.time();
    timing_.solve_seconds += solve_seconds_;
    timing_.iterations += std::size_t(sol.iterations);
    ++timing_.solves;
    direct = false;
    AFI::Solve_statistics s;
    s.ok = sol.ok;
    s.iterations = sol.iterations;
    s.message = sol.message;
    return s;
  }
  const Control_matrix& displacement() const { return dZ_; }
  bool solution_finite(const AFI::Solve_statistics&) const
  {
    int mine = dZ_.allFinite() ? 1 : 0, all = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MIN, comm_);
    return all == 1;
  }
  double solve_seconds() const { return solve_seconds_; }

  // --- the motion: dZ's rows are the owned vertices; the overlap refreshed after every move
  AFI::Step_motion move(Control_matrix& Zc, const Control_matrix& dZ, const Control_matrix& Z0, int columns,
                        const std::vector<double>& row_unit)
  {
    double local[4] = { 0, 0, 0, 0 },
           all[4]; // the step's largest, its largest relative, the total's relative, the total's
    for(std::size_t k : free_)
    {
      const int row = d_.owned_vertices[k];
      Zc.row(row) += dZ.row(Eigen::Index(k));
      const double m = dZ.row(Eigen::Index(k)).head(columns).norm();
      local[0] = std::max(local[0], m);
      local[1] = std::max(local[1], m / row_unit[std::size_t(row)]);
    }
    for(int row : d_.owned_vertices)
    {
      const double m = (Zc.row(row) - Z0.row(row)).head(columns).norm();
      local[3] = std::max(local[3], m);
      local[2] = std::max(local[2], m / row_unit[std::size_t(row)]);
    }
    MPI_Allreduce(local, all, 4, MPI_DOUBLE, MPI_MAX, comm_);
    rows_.refresh(Zc);
    AFI::Step_motion motion;
    motion.step = all[0];
    motion.step_relative = all[1];
    motion.total_relative = all[2];
    motion.total = all[3];
    return motion;
  }
  void add(Control_matrix& X, const Control_matrix& dZ)
  {
    for(std::size_t k : free_) X.row(d_.owned_vertices[k]) += dZ.row(Eigen::Index(k));
    rows_.refresh(X);
  }
  bool moves_normally() const { return in_.normal_motion; }
  void normal_part(const Control_matrix& surface, int columns, Control_matrix& dZ) const
  {
    if(in_.normal_motion) filter_.remove(surface, columns, d_.owned_vertices, dZ);
  }

  // --- the measures, of every process's rows
  void measured_positions(const Control_matrix& X, Control_matrix& Y)
  {
    if(settings_->measure_limit_surface) limit_points(X, Y);
    else Y = X;
  }
  void limit_points(const Control_matrix& X, Control_matrix& Y)
  {
    distributed_limit_points(in_.layer, d_, rows_, X, Y);
  }
  /// the folds of the mesh of X's limit points
  void count_folds(const Control_matrix& X, AFI::Surface_soundness& s)
  {
    CGAL::Real_timer clock;
    clock.start();
    limit_points(X, Y_);
    count_distributed_folds(comm_, in_.layer, d_, in_.components.of_face, in_.component_edge, Y_, s);
    if(stepping_) timing_.judge_seconds += clock.time();
  }
  /// the folds of the mesh of X itself (the input's control mesh)
  void input_folds(const Control_matrix& X, AFI::Surface_soundness& s)
  {
    count_distributed_folds(comm_, in_.layer, d_, in_.components.of_face, in_.component_edge, X, s);
  }
  bool all_finite(const Control_matrix& X) const { return finite_everywhere(comm_, d_, X); }
  /// this process's free rows
  const std::vector<int>& free_rows() const { return free_rows_; }

private:
  MPI_Comm comm_;
  const Distributed_layout& d_;
  Ghosted_rows& rows_;
  Distributed_operator& op_;
  const Flow_input& in_;
  const AFI::Flow_mesh mesh_;
  const AFI::Tangential_motion_filter filter_;
  Distributed_solver solver_;
  std::vector<double> curvature_bound_;
  AFI::Assembly_context context_;
  std::vector<std::size_t> free_;   // positions in d_.owned_vertices of the free ones
  std::vector<int> free_rows_;      // ... and their rows
  const AFI::Stepper_settings* settings_ = nullptr;
  AFI::Step_units units_;
  Control_matrix dZ_, Y_;
  std::string error_;
  bool stepping_ = false;   // the first step was solved: assemblies from now on judge candidates
  double solve_seconds_ = 0;
  Flow_timing timing_;
};

/// The run from Z (owned and overlap rows) on this process's part; on success Z's owned and overlap rows hold
/// the result. `progress` is told of every accepted step; `timing` gets the run's.
template <typename Tensor>
AF::Fairing_report run_distributed_flow(MPI_Comm comm, const Distributed_layout& d, Ghosted_rows& rows,
                                        Distributed_operator& op, const Flow_input& in, const AFI::Stepper_settings& s,
                                        const Tensor& tensor, Control_matrix& Z,
                                        const std::function<void(const AF::Fairing_step&)>& progress,
                                        Flow_timing& timing)
{
  Distributed_flow_operator flow(comm, d, rows, op, in, s);
  const auto told = [&](const AF::Fairing_step& st) { if(progress) progress(st); return true; };
  AF::Fairing_report report = AFI::Flow_loop<Distributed_flow_operator, Tensor, decltype(told)>(
                                flow, Z, Z, in.metric_columns, tensor, s, told, false)
                                .run()
                                .report;
  timing = flow.timing();
  return report;
}

} // namespace af_distributed

#endif // AF_DISTRIBUTED_DISTRIBUTED_FLOW_H
