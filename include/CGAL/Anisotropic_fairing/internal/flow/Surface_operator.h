// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// M and L(D) on the current surface, what a step is built from: the assembler, and for a tensor that reads
// its curvature on the prefiltered surface M_eps (prefilter time eps > 0), that surface first
// (Prefilter_step.h). While a candidate step is judged, the accepted surface's M_eps is kept aside; its M
// and L are not (two more arrays of the pattern's size, a third of a step's memory): a rejected candidate's
// are assembled again from the accepted surface and its M_eps, the same values.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_SURFACE_OPERATOR_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_SURFACE_OPERATOR_H

#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/internal/assembly/Fem_assembly.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Prefilter_step.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Free_block.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

template <typename Cache>
class Surface_operator
{
public:
  Surface_operator(const Cache& cache, std::size_t n) : assembler_(cache, n) {}

  Fem_assembler<Cache>& assembler() { return assembler_; }
  const Sparse_structure& pattern() const { return assembler_.pattern(); }
  /// M and L(D) of the last assembly, as value arrays over pattern()
  const Value_array& M() const { return M_; }
  const Value_array& L() const { return L_; }

  /// The prefilter: its time per row (all 0: none), the free block it is solved on, and the solver.
  void set_prefilter(std::vector<double> eps, const Free_block* block, const Prefilter_solver& solver)
  {
    eps_ = std::move(eps);
    block_ = block;
    prefilter_solver_ = solver;
    prefilter_choice_.reset(
      block ? new Solver_choice(solver.solver, block->size(), false, solver.direct, solver.factor_budget) : nullptr);
    prefilter_cg_.reset(new Block_conjugate_gradient(solver.tolerance, solver.maximum_iterations));
    prefilter_ = false;
    for(double e : eps_) prefilter_ = prefilter_ || e > 0;
  }

  /// M and L(D) at X (`with_matrices` false: the statistics only, and M and L are no surface's until
  /// restore() or the next assembly with matrices). On failure of the prefilter, error() says why and the
  /// matrices are those of the tensor read on the current surface.
  ///
  /// Statistics only, after an assembly with matrices: the tensor is read on that assembly's M_eps, the one
  /// the step to X was taken from. X's own M_eps would cost a prefilter solve and an isotropic assembly
  /// that no step uses (a run's last surface, a candidate judged for its geometry), and only the energy,
  /// of all the statistics, depends on the tensor.
  template <typename Tensor>
  Assembly_statistics assemble(const Control_matrix& X, int metric_columns, const Tensor& tensor, bool with_matrices)
  {
    error_.clear();
    if(!with_matrices && prefiltered_valid_)
    {
      isotropic_ready_ = false;
      assembler_.set_prefiltered(&prefiltered_X_);
      const Assembly_statistics a = assembler_.assemble(X, metric_columns, tensor, M_, L_, false);
      assembler_.set_prefiltered(nullptr);
      return a;
    }
    prefilter(X, metric_columns);
    // after the prefilter's isotropic assembly at this X, M_ is this X's mass matrix already
    const bool mass_kept = prefilter_ && block_ && block_->size() > 0;
    assembler_.set_prefiltered(prefiltered());
    const Assembly_statistics a = assembler_.assemble(X, metric_columns, tensor, M_, L_, with_matrices, mass_kept);
    assembler_.set_prefiltered(nullptr);
    overwritten_ = overwritten_ || with_matrices;
    return a;
  }

  /// M_eps at X alone (prefiltered(); error() says why not; none without a prefilter), from the isotropic M and
  /// L of assemble_isotropic() at X, or assembled here.
  void prefilter(const Control_matrix& X, int metric_columns)
  {
    const bool isotropic_ready = isotropic_ready_;
    isotropic_ready_ = false;
    prefiltered_valid_ = false;
    if(!prefilter_ || !block_ || block_->size() == 0) return;
    // the isotropic M and L in M_ and L_ (no two more arrays of the pattern's size), which the tensor's
    // own assembly then overwrites, or leaves as scratch when it computes statistics only
    overwritten_ = true;
    if(!isotropic_ready)   // (its statistics are the tensor's assembly's: no curvature read here)
      assembler_.assemble(X, metric_columns, Isotropic_diffusion_tensor(), M_, L_, true, false, false);
    Control_matrix& dX = prefilter_dX_;   // warm start: the last M_eps's displacement
    const Solve_statistics sol =
      prefilter_step(assembler_.pattern(), M_, L_, eps_, *block_, prefilter_A_, X, metric_columns, prefilter_solver_,
                     *prefilter_choice_, *prefilter_cg_, dX);
    Value_array().swap(prefilter_A_);   // not kept while the step's system is formed
    if(!sol.ok) dX.resize(0, 0);
    if(!sol.ok || !dX.allFinite())
    {
      error_ =
        "the prefiltered surface M_eps could not be computed: " + (sol.ok ? std::string("not finite") : sol.message);
      return;
    }
    prefiltered_X_ = X;
    for(Eigen::Index i = 0; i < dX.rows(); ++i)
      prefiltered_X_.row(block_->free[std::size_t(i)]).head(metric_columns) += dX.row(i);
    prefiltered_valid_ = true;
  }

  /// The isotropic M and L at X and their statistics, before the prefilter's times are known (they follow
  /// from the surface's units): the next assemble(), which must be at the same X, starts its prefilter from them.
  Assembly_statistics assemble_isotropic(const Control_matrix& X, int metric_columns)
  {
    const Assembly_statistics a = assembler_.assemble(X, metric_columns, Isotropic_diffusion_tensor(), M_, L_);
    isotropic_ready_ = true;
    return a;
  }
  /// ... unless the run ends before it
  void discard_isotropic() { isotropic_ready_ = false; }

  const std::string& error() const { return error_; }
  /// M_eps of the last assembly with matrices, or null
  const Control_matrix* prefiltered() const { return prefiltered_valid_ ? &prefiltered_X_ : nullptr; }

  /// Before a candidate is assembled: keeps the accepted surface's M_eps aside.
  void save()
  {
    saved_prefiltered_X_ = prefiltered_X_;
    saved_prefiltered_valid_ = prefiltered_valid_;
    overwritten_ = false;
  }
  /// The operator of the accepted surface X again, after a candidate was assembled (no prefilter: its M_eps
  /// was kept).
  template <typename Tensor>
  void restore(const Control_matrix& X, int metric_columns, const Tensor& tensor)
  {
    prefiltered_X_.swap(saved_prefiltered_X_);
    prefiltered_valid_ = saved_prefiltered_valid_;
    if(!overwritten_) return;
    assembler_.set_prefiltered(prefiltered_valid_ ? &prefiltered_X_ : nullptr);
    assembler_.assemble(X, metric_columns, tensor, M_, L_, true);
    assembler_.set_prefiltered(nullptr);
    overwritten_ = false;
  }

private:
  Fem_assembler<Cache> assembler_;
  Value_array M_, L_;
  bool overwritten_ = false;   // M_ and L_ were assembled since save()
  bool isotropic_ready_ = false;   // M_ and L_ are the isotropic ones at the next assemble()'s X
  std::vector<double> eps_;   // prefilter time per row
  bool prefilter_ = false;
  const Free_block* block_ = nullptr;
  Prefilter_solver prefilter_solver_;
  std::unique_ptr<Solver_choice> prefilter_choice_;
  std::unique_ptr<Block_conjugate_gradient> prefilter_cg_;
  Value_array prefilter_A_;   // the prefilter system's values over the free block
  Control_matrix prefiltered_X_, saved_prefiltered_X_, prefilter_dX_;
  bool prefiltered_valid_ = false, saved_prefiltered_valid_ = false;
  std::string error_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_SURFACE_OPERATOR_H
