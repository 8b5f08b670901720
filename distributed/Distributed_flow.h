// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The flow operator (internal/flow/Flow_operator.h says what one provides) of every run the library makes on
// a Distributed_patch_cache: the library's flow loop, and the whole call around it (the default run's
// candidates, probes and comparison), run on every process as they run on one. M and L(D) come from
// Distributed_operator, each step is solved by PETSc (Distributed_solver: the second- and fourth-order
// steps, the local time scale), and every process holds every row (Whole_rows), so that the measures are the
// library's own on the whole mesh (limit points, folds, the noise level) and every process decides alike.

#ifndef AF_DISTRIBUTED_DISTRIBUTED_FLOW_H
#define AF_DISTRIBUTED_DISTRIBUTED_FLOW_H

#include "Collective_failure.h"
#include "Distributed_cache.h"
#include "Distributed_operator.h"
#include "Distributed_solver.h"
#include "Part_folds.h"

#include <CGAL/Anisotropic_fairing/internal/flow/Flow_operator.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Local_time_scale.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Normal_motion.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Output_fidelity.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_safety.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_units.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Vertex_limit_masks.h>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

namespace af_distributed {

class Distributed_flow_operator
{
public:
  /// As Serial_flow_operator is made: `constrained[i]` holds vertex i fixed.
  Distributed_flow_operator(const Distributed_patch_cache& cache, std::size_t, const std::vector<bool>& constrained,
                            const AFI::Flow_mesh& mesh, const AFI::Assembly_context& numbering)
    : state_(cache.state()), comm_(state_.comm), d_(*state_.layout), rows_(comm_, d_, state_.volume), mesh_(mesh),
      constrained_(constrained), op_(comm_, cache, d_, rows_, constrained),
      context_(AFI::flow_context(numbering, mesh_, curvature_bound_))
  {
    op_.assembler().set_context(context_);
    for(std::size_t k = 0; k < d_.owned_vertices.size(); ++k)
      if(!constrained[std::size_t(d_.owned_vertices[k])]) free_.push_back(k);
    for(std::size_t k : free_) own_free_rows_.push_back(d_.owned_vertices[k]);
    long long mine = (long long)free_.size(), all = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, comm_);
    free_count_ = std::size_t(all);
    state_.off_process_columns = op_.off_process_columns();
  }
  ~Distributed_flow_operator() { state_.prefilter_iterations += op_.prefilter_iterations(); }

  /// Each step's displacement of the surface's columns then loses its tangential part (null: kept).
  void set_tangential_filter(const AFI::Tangential_motion_filter* f) { filter_ = f; }

  const AFI::Flow_mesh& mesh() const { return mesh_; }
  std::string unsupported(const AFI::Stepper_settings&, bool) const { return std::string(); }
  std::size_t vertex_count() const { return std::size_t(d_.rows); }
  std::size_t free_count() const { return free_count_; }
  double largest(double x) const
  {
    double all = x;
    MPI_Allreduce(&x, &all, 1, MPI_DOUBLE, MPI_MAX, comm_);
    return all;
  }
  double total(double x) const
  {
    double all = x;
    MPI_Allreduce(&x, &all, 1, MPI_DOUBLE, MPI_SUM, comm_);
    return all;
  }
  bool everywhere(bool b) const
  {
    int mine = b ? 1 : 0, all = 0;
    MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MIN, comm_);
    return all == 1;
  }
  void begin_run(const AFI::Stepper_settings& s, bool)
  {
    settings_ = &s;
    if(!solver_)
      solver_.reset(
        new Distributed_solver(comm_, d_, constrained_, "", s.solver_tolerance, s.solver_maximum_iterations));
  }

  // --- the units
  AFI::Assembly_statistics assemble_isotropic(const Control_matrix& X, int columns, bool)
  {
    return assemble(X, columns, CGAL::Anisotropic_fairing::Isotropic_diffusion_tensor(), false);
  }
  void discard_isotropic() {}
  void set_prefilter(std::vector<double> eps, const AFI::Stepper_settings& s)
  {
    op_.set_prefilter(std::move(eps), s.solver_tolerance / 100, s.solver_maximum_iterations);
  }
  void set_units(const AFI::Step_units& u, const AFI::Assembly_statistics&, bool component_scale)
  {
    units_ = u;
    if(!component_scale) return;
    context_.component_scale = &units_.tensor_scale;
    op_.assembler().set_context(context_);
  }
  const AFI::Step_units& units() const { return units_; }
  /// which process's part holds the degenerate face named by `a` (the caller's numbering; in parts, the whole
  /// mesh's: its owner found over the processes, all of which ask), when there are several
  std::string where_face(const AFI::Assembly_statistics& a) const
  {
    if(d_.size == 1 || !a.degenerate || (!context_.original_face && !d_.part)) return std::string();
    int owner = -1;
    if(d_.part)
    {
      const auto at = d_.face_of_global.find(std::int64_t(a.degenerate_face));
      const int mine = at == d_.face_of_global.end() ? -1 : d_.face_owner[at->second];
      MPI_Allreduce(&mine, &owner, 1, MPI_INT, MPI_MAX, comm_);
    }
    else
    {
      const std::vector<std::size_t>& original = *context_.original_face;
      for(std::size_t f = 0; f < original.size() && owner < 0; ++f)
        if(original[f] == a.degenerate_face) owner = d_.face_owner[f];
    }
    return owner < 0 ? std::string() : " (in the part of process " + std::to_string(owner) + ")";
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
    catch(const std::runtime_error& e) { error_ = e.what(); }
    (stepping_ ? state_.timing.judge_seconds : state_.timing.assemble_seconds) += clock.time();
    return a;
  }
  const std::string& error() const { return error_; }
  void save() { op_.save(); }
  template <typename Tensor>
  void restore(const Control_matrix&, int, const Tensor&) { op_.restore(); }
  const Control_matrix* prefiltered() const { return op_.prefiltered(); }
  void prefilter(const Control_matrix& X, int columns)
  {
    error_.clear();
    try { op_.prefilter(X, columns); }
    catch(const std::runtime_error& e) { error_ = e.what(); }
  }
  double dirichlet_energy(const Control_matrix& Z) { return solver_->quadratic_form(op_.L(), Z); }

  // --- the step: the local time scale read at the run's start Z0, as the library reads it
  void start_solver(const AFI::Stepper_settings& s, Eigen::Index, bool fixed, const AFI::Output_fidelity* fidelity,
                    const Control_matrix* anchor, const Control_matrix& Z0)
  {
    solver_->set_fidelity(fidelity, anchor, constrained_);
    std::vector<double> weight;
    if(s.local_time_scale && !fixed)
      weight = AFI::mass_weights(AFI::local_time_scale(*mesh_.layer.topology, mesh_.layer.real_faces, Z0,
                                                       mesh_.components, mesh_.component_edge,
                                                       d_.part ? *d_.part : AFI::whole_mesh_view()));
    solver_->set_step_kind(std::move(weight), s.order == 4);
  }
  AFI::Solve_statistics solve(double factor, const Control_matrix& Z, const Control_matrix& Z0,
                              const std::vector<double>& weights, bool& direct)
  {
    stepping_ = true;
    CGAL::Real_timer clock;
    clock.start();
    std::vector<double> t(units_.tau);
    for(double& x : t) x *= factor;
    const Distributed_solve sol =
      solver_->solve(op_.M(), op_.L(), t, units_.omega, Z, Z0, int(Z.cols()), dZ_, weights);
    solve_seconds_ = clock.time();
    state_.timing.solve_seconds += solve_seconds_;
    state_.timing.iterations += std::size_t(sol.iterations);
    ++state_.timing.solves;
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

  // --- the motion: dZ's rows are the owned vertices; every process's rows received after every move
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
  bool moves_normally() const { return filter_ != nullptr; }
  void normal_part(const Control_matrix& surface, int columns, Control_matrix& dZ) const
  {
    if(filter_) filter_->remove(surface, columns, d_.owned_vertices, dZ);
  }

  // --- the measures: the library's own, on the whole rows every process holds alike
  void measured_positions(const Control_matrix& X, Control_matrix& Y) const
  {
    if(settings_->measure_limit_surface) AFI::limit_points(mesh_.layer, X, Y);
    else Y = X;
  }
  void limit_points(const Control_matrix& X, Control_matrix& Y) const { AFI::limit_points(mesh_.layer, X, Y); }
  void count_folds(const Control_matrix& X, AFI::Surface_soundness& s)
  {
    CGAL::Real_timer clock;
    clock.start();
    AFI::count_folds(mesh_.layer, AFI::Ghosted_patch_cache::has_second_derivatives, mesh_.components.of_face,
                     mesh_.component_edge, X, s, d_.part ? &d_.owned_faces : nullptr, d_.part);
    if(d_.part) share_folded_edges(comm_, d_, *mesh_.layer.topology, s, true);
    if(stepping_) state_.timing.judge_seconds += clock.time();
  }
  void input_folds(const Control_matrix& X, AFI::Surface_soundness& s) const
  {
    s.folded_edges = AFI::count_folded_edges(*mesh_.layer.topology, mesh_.layer.real_faces, X, mesh_.components.of_face,
                                             mesh_.component_edge, AFI::turn_120, d_.part ? &d_.owned_faces : nullptr,
                                             &s.folded_edge_list, d_.part);
    if(d_.part) share_folded_edges(comm_, d_, *mesh_.layer.topology, s, false);
  }
  bool all_finite(const Control_matrix& X) const { return everywhere(X.allFinite()); }
  /// the free rows of the whole mesh: a bound's weights are decided on every row, alike on every process
  const std::vector<int>& free_rows() const { return own_free_rows_; }

private:
  Distributed_state& state_;
  MPI_Comm comm_;
  const Distributed_layout& d_;
  Whole_rows rows_;
  const AFI::Flow_mesh mesh_;
  const std::vector<bool>& constrained_;
  Distributed_operator op_;
  std::vector<double> curvature_bound_;
  AFI::Assembly_context context_;
  std::unique_ptr<Distributed_solver> solver_;
  const AFI::Tangential_motion_filter* filter_ = nullptr;
  std::vector<std::size_t> free_;   // positions in d_.owned_vertices of the free ones
  std::vector<int> own_free_rows_;  // the same, as rows of the mesh the library was given
  std::size_t free_count_ = 0;      // of the whole mesh
  const AFI::Stepper_settings* settings_ = nullptr;
  AFI::Step_units units_;
  Control_matrix dZ_;
  std::string error_;
  bool stepping_ = false;   // the first step was solved: assemblies from now on judge candidates
  double solve_seconds_ = 0;
};

} // namespace af_distributed

#endif // AF_DISTRIBUTED_DISTRIBUTED_FLOW_H
