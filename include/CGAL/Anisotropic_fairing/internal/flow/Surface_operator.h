// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// M and L(D) on the current surface, what a step is built from: the assembler, and for a tensor that reads
// its curvature on the prefiltered surface M_eps (prefilter time eps > 0), that surface first
// (Prefilter_step.h). While a candidate step is judged, the accepted surface's operator is kept aside so
// that a rejected step costs no new assembly.

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
  const Eigen::SparseMatrix<double>& pattern() const { return assembler_.pattern(); }
  /// M and L(D) of the last assembly, as value arrays over pattern()
  const std::vector<double>& M() const { return M_; }
  const std::vector<double>& L() const { return L_; }

  /// The prefilter: its time per row (all 0: none), the free block it is solved on, and the solver.
  void set_prefilter(std::vector<double> eps, const Free_block* block, const Prefilter_solver& solver)
  {
    eps_ = std::move(eps);
    block_ = block;
    prefilter_solver_ = solver;
    prefilter_choice_.reset(block ? new Solver_choice(solver.solver, block->size(), false, solver.direct) : nullptr);
    prefilter_cg_.reset(new Block_conjugate_gradient(solver.tolerance, solver.maximum_iterations));
    prefilter_ = false;
    for(double e : eps_) prefilter_ = prefilter_ || e > 0;
  }

  /// M and L(D) at X (`with_matrices` false: the statistics only). On failure of the prefilter,
  /// error() says why and the matrices are those of the tensor read on the current surface.
  template <typename Tensor>
  Assembly_statistics assemble(const Control_matrix& X, int metric_columns, const Tensor& tensor, bool with_matrices)
  {
    assembler_.set_prefiltered(nullptr);
    error_.clear();
    prefiltered_valid_ = false;
    if(prefilter_ && block_ && block_->size() > 0)
    {
      std::vector<double> Mi, Li;
      assembler_.assemble(X, metric_columns, Isotropic_diffusion_tensor(), Mi, Li);
      if(prefilter_A_.rows() != block_->matrix.rows()) prefilter_A_ = block_->matrix;
      Control_matrix& dX = prefilter_dX_;   // warm start: the last M_eps's displacement
      const Solve_statistics sol = prefilter_step(assembler_.pattern(), Mi, Li, eps_, *block_, prefilter_A_, X, metric_columns,
                                                  prefilter_solver_, *prefilter_choice_, *prefilter_cg_, dX);
      if(!sol.ok) dX.resize(0, 0);
      if(!sol.ok || !dX.allFinite())
        error_ = "the prefiltered surface M_eps could not be computed: " + (sol.ok ? std::string("not finite") : sol.message);
      else
      {
        prefiltered_X_ = X;
        for(Eigen::Index i = 0; i < dX.rows(); ++i) prefiltered_X_.row(block_->free[std::size_t(i)]).head(metric_columns) += dX.row(i);
        assembler_.set_prefiltered(&prefiltered_X_);
        prefiltered_valid_ = true;
      }
    }
    const Assembly_statistics a = assembler_.assemble(X, metric_columns, tensor, M_, L_, with_matrices);
    assembler_.set_prefiltered(nullptr);
    return a;
  }

  const std::string& error() const { return error_; }
  /// M_eps of the last assembly, or null
  const Control_matrix* prefiltered() const { return prefiltered_valid_ ? &prefiltered_X_ : nullptr; }

  /// Keeps the accepted surface's operator aside while a candidate is assembled; restore() brings it back.
  void save()
  {
    saved_M_.swap(M_);
    saved_L_.swap(L_);
    saved_prefiltered_X_ = prefiltered_X_;
    saved_prefiltered_valid_ = prefiltered_valid_;
  }
  void restore()
  {
    saved_M_.swap(M_);
    saved_L_.swap(L_);
    prefiltered_X_.swap(saved_prefiltered_X_);
    prefiltered_valid_ = saved_prefiltered_valid_;
  }

private:
  Fem_assembler<Cache> assembler_;
  std::vector<double> M_, L_, saved_M_, saved_L_;
  std::vector<double> eps_;   // prefilter time per row
  bool prefilter_ = false;
  const Free_block* block_ = nullptr;
  Prefilter_solver prefilter_solver_;
  std::unique_ptr<Solver_choice> prefilter_choice_;
  std::unique_ptr<Block_conjugate_gradient> prefilter_cg_;
  Eigen::SparseMatrix<double> prefilter_A_;
  Control_matrix prefiltered_X_, saved_prefiltered_X_, prefilter_dX_;
  bool prefiltered_valid_ = false, saved_prefiltered_valid_ = false;
  std::string error_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_SURFACE_OPERATOR_H
