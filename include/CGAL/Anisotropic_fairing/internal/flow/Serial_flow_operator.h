// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The flow operator of one process (Flow_operator.h says what an operator is): M and L(D) on the current
// surface (Surface_operator.h) over the free block of the unconstrained vertices, the step's system solved by
// Step_solver.h, every measure over the whole mesh it holds. It knows nothing of the element: any cache the
// Fem_assembler accepts will do (Loop patches or P1 faces).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_SERIAL_FLOW_OPERATOR_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_SERIAL_FLOW_OPERATOR_H

#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Flow_operator.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Local_time_scale.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Normal_motion.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Output_fidelity.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_safety.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_solver.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_units.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Surface_operator.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Vertex_limit_masks.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Free_block.h>

#include <algorithm>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

template <typename Cache>
class Serial_flow_operator
{
public:
  /// `constrained[i]` holds vertex i fixed; `numbering`: the caller's numbering and border for the assembler.
  Serial_flow_operator(const Cache& cache, std::size_t n, const std::vector<bool>& constrained, const Flow_mesh& mesh,
                       const Assembly_context& numbering)
    : operator_(cache, n), block_(operator_.pattern(), constrained), mesh_(mesh),
      context_(flow_context(numbering, mesh_, curvature_bound_)), rows_(n)
  {
    operator_.assembler().set_context(context_);
  }

  /// Each step's displacement of the surface's columns then loses its tangential part (null: kept).
  void set_tangential_filter(const Tangential_motion_filter* f) { filter_ = f; }

  const Flow_mesh& mesh() const { return mesh_; }
  std::string unsupported(const Stepper_settings&, bool) const { return std::string(); }
  std::size_t vertex_count() const { return rows_; }
  std::size_t free_count() const { return block_.size(); }
  double largest(double x) const { return x; }
  double total(double x) const { return x; }
  bool everywhere(bool b) const { return b; }
  /// A run starts: its settings, and whether the surface is fixed (attributes only).
  void begin_run(const Stepper_settings& s, bool fixed)
  {
    settings_ = &s;
    fixed_ = fixed;
  }

  // --- the units (Flow_units.h)
  /// The isotropic statistics at X; `kept`: its M and L start the next assembly's prefilter.
  Assembly_statistics assemble_isotropic(const Control_matrix& X, int columns, bool kept)
  {
    if(kept) return operator_.assemble_isotropic(X, columns);
    Value_array m, l;
    return operator_.assembler().assemble(X, columns, Isotropic_diffusion_tensor(), m, l, false);
  }
  void discard_isotropic() { operator_.discard_isotropic(); }
  void set_prefilter(std::vector<double> eps, const Stepper_settings& s)
  {
    Prefilter_solver prefilter;
    prefilter.solver = s.solver;
    prefilter.tolerance = s.solver_tolerance / 100;
    prefilter.maximum_iterations = s.solver_maximum_iterations;
    prefilter.direct = s.direct_solver;
    prefilter.factor_budget = s.factor_budget;
    operator_.set_prefilter(std::move(eps), &block_, prefilter);
  }
  /// The run's units; `component_scale`: the tensor is read at each component's scale. Several components:
  /// each solved in its own units (unknowns dX / l_c, equations / l_c^2 and l_c^3), so that the solver's
  /// tolerance means the same on a small part as on a large one.
  void set_units(const Step_units& u, const Assembly_statistics& a, bool component_scale)
  {
    units_ = u;
    if(component_scale)
    {
      context_.component_scale = &units_.tensor_scale;
      operator_.assembler().set_context(context_);
    }
    unknown_scale_.clear();
    if(mesh_.components.count > 1 && u.length.size() == rows_)
      for(std::size_t i = 0; i < rows_; ++i)
      {
        const int c = mesh_.components.of_vertex[i];
        unknown_scale_.push_back(c >= 0 ? length_scale(a.component_area[std::size_t(c)]) : 1.0);
      }
  }
  const Step_units& units() const { return units_; }
  std::string where_face(const Assembly_statistics&) const { return std::string(); }

  // --- the operator on a surface
  template <typename Tensor>
  Assembly_statistics assemble(const Control_matrix& X, int columns, const Tensor& tensor, bool with_matrices)
  {
    return operator_.assemble(X, columns, tensor, with_matrices);
  }
  const std::string& error() const { return operator_.error(); }
  void save() { operator_.save(); }
  template <typename Tensor>
  void restore(const Control_matrix& X, int columns, const Tensor& tensor) { operator_.restore(X, columns, tensor); }
  const Control_matrix* prefiltered() const { return operator_.prefiltered(); }
  /// M_eps at X alone, after the units (prefiltered(), error())
  void prefilter(const Control_matrix& X, int columns) { operator_.prefilter(X, columns); }
  double dirichlet_energy(const Control_matrix& Z) const
  {
    return internal::dirichlet_energy(operator_.pattern(), operator_.L(), Z);
  }

  // --- the step
  /// A run's solver for `columns` unknowns; `fixed`: one matrix for every step; `fidelity`, `anchor`: a
  /// deviation bound's (or null); the local time scale read at the run's start Z0.
  void start_solver(const Stepper_settings& s, Eigen::Index columns, bool fixed, const Output_fidelity* fidelity,
                    const Control_matrix* anchor, const Control_matrix& Z0)
  {
    mass_weight_.clear();
    // automatic isotropic runs: a time step that follows the mesh's density (Local_time_scale.h)
    if(s.local_time_scale && !fixed)
      mass_weight_ = mass_weights(local_time_scale(*mesh_.layer.topology, mesh_.layer.real_faces, Z0, mesh_.components,
                                                   mesh_.component_edge));
    solver_.emplace(operator_.pattern(), block_, s, columns, fixed, fidelity, anchor);
  }
  /// The step of `factor` times the time step from Z (Z0: the input; `weights`: a bound's, per free row)
  Solve_statistics solve(double factor, const Control_matrix& Z, const Control_matrix& Z0,
                         const std::vector<double>& weights, bool& direct)
  {
    // (on a fixed surface the attributes are solved in their own units)
    const std::vector<double>& scale = fixed_ ? no_scale_ : unknown_scale_;
    solver_->prepare(operator_.M(), operator_.L(), units_, mass_weight_, scale, factor,
                     system_scale(units_, block_.free, factor, settings_->order, mesh_.mean_edge), Z, Z0, weights);
    return solver_->solve(direct);
  }
  const Control_matrix& displacement() const { return solver_->displacement(); }
  bool solution_finite(const Solve_statistics& s) const
  {
    return displacement().allFinite() && std::isfinite(s.residual);
  }
  double solve_seconds() const { return solver_->solve_seconds(); }

  // --- the motion
  /// Adds the free rows' displacements to Zc; the step's and the total (from Z0) largest motion over the first
  /// `columns` columns, also in units of `row_unit`.
  Step_motion move(Control_matrix& Zc, const Control_matrix& dZ, const Control_matrix& Z0, int columns,
                   const std::vector<double>& row_unit) const
  {
    Step_motion m;
    for(Eigen::Index i = 0; i < dZ.rows(); ++i)
    {
      const std::size_t row = std::size_t(block_.free[std::size_t(i)]);
      Zc.row(Eigen::Index(row)) += dZ.row(i);
      const double d = dZ.row(i).head(columns).norm();
      m.step = std::max(m.step, d);
      m.step_relative = std::max(m.step_relative, d / row_unit[row]);
    }
    for(Eigen::Index i = 0; i < Zc.rows(); ++i)
    {
      const double d = (Zc.row(i) - Z0.row(i)).head(columns).norm();
      m.total = std::max(m.total, d);
      m.total_relative = std::max(m.total_relative, d / row_unit[std::size_t(i)]);
    }
    return m;
  }
  /// X += dZ on the free rows (no measure)
  void add(Control_matrix& X, const Control_matrix& dZ) const
  {
    for(Eigen::Index i = 0; i < dZ.rows(); ++i) X.row(Eigen::Index(block_.free[std::size_t(i)])) += dZ.row(i);
  }
  bool moves_normally() const { return filter_ != nullptr; }
  /// dZ (rows: the free vertices) loses its part in the tangent planes of `surface`
  void normal_part(const Control_matrix& surface, int columns, Control_matrix& dZ) const
  {
    if(filter_) filter_->remove(surface, columns, block_.free, dZ);
  }

  // --- the measures
  /// the positions the stopping rules and the soundness measure: X's Loop limit points, or X itself
  void measured_positions(const Control_matrix& X, Control_matrix& Y) const
  {
    if(settings_->measure_limit_surface) internal::limit_points(mesh_.layer, X, Y);
    else Y = X;
  }
  void limit_points(const Control_matrix& X, Control_matrix& Y) const { internal::limit_points(mesh_.layer, X, Y); }
  /// the folds of X's surface (its limit points for the Loop element)
  void count_folds(const Control_matrix& X, Surface_soundness& s) const
  {
    internal::count_folds(mesh_.layer, Cache::has_second_derivatives, mesh_.components.of_face, mesh_.component_edge, X,
                          s);
  }
  /// the folded edges of the mesh of X itself (the input's control mesh)
  void input_folds(const Control_matrix& X, Surface_soundness& s) const
  {
    s.folded_edges = count_folded_edges(*mesh_.layer.topology, mesh_.layer.real_faces, X, mesh_.components.of_face,
                                        mesh_.component_edge, turn_120, nullptr, &s.folded_edge_list);
  }
  bool all_finite(const Control_matrix& X) const { return X.allFinite(); }

  /// the free rows this process judges for a bound (Deviation_bound.h): all of them
  const std::vector<int>& free_rows() const { return block_.free; }

private:
  Surface_operator<Cache> operator_;
  Free_block block_;
  const Flow_mesh mesh_;
  std::vector<double> curvature_bound_; // per component (Assembly_statistics::bounded_H_integral)
  Assembly_context context_;            // the assembler's (Fem_assembly.h)
  std::size_t rows_;
  const Tangential_motion_filter* filter_ = nullptr;
  const Stepper_settings* settings_ = nullptr;
  bool fixed_ = false;
  Step_units units_;
  std::vector<double> mass_weight_, unknown_scale_;
  const std::vector<double> no_scale_;
  std::optional<Step_solver> solver_;
};

/// The flow operator of the runs on `Cache`: this one, unless the cache names its own (`Cache::Flow_operator`,
/// constructed as this one is): the distributed program's cache does, so that the library's runs, the default
/// run's comparison included, step on its processes (distributed/Distributed_cache.h).
template <typename Cache, typename = void>
struct Flow_operator_of
{
  typedef Serial_flow_operator<Cache> type;
};
template <typename Cache>
struct Flow_operator_of<Cache, std::void_t<typename Cache::Flow_operator>>
{
  typedef typename Cache::Flow_operator type;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_SERIAL_FLOW_OPERATOR_H
