// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// M and L(D) on the current surface, distributed: each process integrates over its own faces with the
// library's Fem_assembler (Loop patches, quadrature, the diffusion tensor) and adds its entries into PETSc
// MPIAIJ matrices (ADD_VALUES: the entries of rows owned elsewhere travel to their owners at
// MatAssemblyEnd), preallocated once from the processes' patterns (MATPREALLOCATOR). The statistics of the
// surface are sums over the faces, one MPI_Allreduce. For a tensor that reads the prefiltered surface
// M_eps, that surface first: the isotropic matrices, one prefilter solve, the other processes' rows received.
// The accepted surface's matrices are kept aside while a candidate is judged (save, restore).

#ifndef AF_DISTRIBUTED_DISTRIBUTED_OPERATOR_H
#define AF_DISTRIBUTED_DISTRIBUTED_OPERATOR_H

#include "Collective_failure.h"
#include "Distributed_layout.h"
#include "Distributed_solver.h"
#include "Face_partition.h"
#include "Part_folds.h"
#include "Whole_rows.h"

#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/internal/assembly/Fem_assembly.h>
#include <CGAL/Anisotropic_fairing/internal/element/Ghosted_patch_cache.h>

#include <petscmat.h>

#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace af_distributed {

namespace AFI = CGAL::Anisotropic_fairing::internal;

/// Every process's entries of `mine` (a few folds: numbers of the whole mesh), in the order of the
/// processes, on every process.
template <typename T>
std::vector<T> gather_everywhere(MPI_Comm comm, const std::vector<T>& mine)
{
  int processes = 1;
  MPI_Comm_size(comm, &processes);
  const int bytes = int(mine.size() * sizeof(T));
  const std::size_t n = std::size_t(processes);
  std::vector<int> counts(n, 0), offsets(n, 0);
  MPI_Allgather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for(std::size_t p = 1; p < counts.size(); ++p) offsets[p] = offsets[p - 1] + counts[p - 1];
  std::vector<T> all(std::size_t(offsets.back() + counts.back()) / sizeof(T));
  MPI_Allgatherv(mine.data(), bytes, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, comm);
  return all;
}

/// The statistics of every process's faces added up, the same on every process.
inline AFI::Assembly_statistics reduce_statistics(MPI_Comm comm, const AFI::Assembly_statistics& a,
                                                   const Distributed_layout& d)
{
  std::vector<double> s = { a.area, a.energy, a.H_integral, a.bounded_H_integral, double(a.degenerate_points),
                            double(a.reversed_faces), double(a.bent_faces) };
  s.insert(s.end(), a.component_area.begin(), a.component_area.end());
  std::vector<double> t(s.size());
  MPI_Allreduce(s.data(), t.data(), int(s.size()), MPI_DOUBLE, MPI_SUM, comm);
  AFI::Assembly_statistics r;
  r.area = t[0]; r.energy = t[1]; r.H_integral = t[2]; r.bounded_H_integral = t[3];
  r.degenerate_points = std::size_t(t[4]); r.reversed_faces = std::size_t(t[5]); r.bent_faces = std::size_t(t[6]);
  r.component_area.assign(t.begin() + 7, t.end());
  if(d.part) share_reversed_faces(comm, d, a.reversed_face_list, r);
  else r.reversed_face_list = gather_everywhere(comm, a.reversed_face_list);
  // the degenerate face named: the lowest-numbered of those found
  // (a part's faces by their numbers in the whole mesh)
  const std::size_t named = a.degenerate && d.part ? std::size_t(d.part->global_face(a.degenerate_face, true))
                                                   : a.degenerate_face;
  unsigned long long face = a.degenerate ? named : std::numeric_limits<unsigned long long>::max(), lowest = face;
  MPI_Allreduce(&face, &lowest, 1, MPI_UNSIGNED_LONG_LONG, MPI_MIN, comm);
  r.degenerate = lowest != std::numeric_limits<unsigned long long>::max();
  r.degenerate_face = r.degenerate ? std::size_t(lowest) : 0;
  return r;
}

class Distributed_operator
{
public:
  Distributed_operator(MPI_Comm comm, const AFI::Ghosted_patch_cache& cache, const Distributed_layout& d,
                       Whole_rows& rows, const std::vector<bool>& held)
    : comm_(comm), d_(d), rows_(rows), held_(held), assembler_(cache, d.vertex_owner.size(), true, &d.owned_faces)
  {
    const auto& p = assembler_.pattern();
    for(Eigen::Index k = 0; k < p.nonZeros(); ++k)
      petsc_inner_.push_back(d.petsc_row[std::size_t(p.innerIndexPtr()[k])]);
    preallocate();
  }
  ~Distributed_operator()
  {
    for(Mat* m : { &pattern_, &M_, &L_, &saved_M_, &saved_L_, &Mi_, &Li_ }) MatDestroy(m);
  }
  Distributed_operator(const Distributed_operator&) = delete;
  Distributed_operator& operator=(const Distributed_operator&) = delete;

  AFI::Fem_assembler<AFI::Ghosted_patch_cache>& assembler() { return assembler_; }
  Mat M() const { return M_; }
  Mat L() const { return L_; }
  /// the prefilter time per row (all 0: none), its solver's tolerance and most iterations (PETSc's options
  /// with the prefix -prefilter_ override them)
  void set_prefilter(std::vector<double> eps, double tolerance, int maximum_iterations)
  {
    eps_ = std::move(eps);
    prefilter_ = false;
    for(double e : eps_) prefilter_ = prefilter_ || e > 0;
    if(prefilter_ && !prefilter_solver_)
      prefilter_solver_.reset(new Distributed_solver(comm_, d_, held_, "prefilter_", tolerance, maximum_iterations));
  }
  /// M_eps at X alone (prefiltered()); throws as assemble() does
  void prefilter(const Control_matrix& X, int metric_columns)
  {
    prefiltered_valid_ = false;
    if(prefilter_) make_prefiltered(X, metric_columns);
  }
  /// M_eps of the last assembly (owned and overlap rows), or null
  const Control_matrix* prefiltered() const { return prefiltered_valid_ ? &prefiltered_X_ : nullptr; }
  std::size_t prefilter_iterations() const { return prefilter_iterations_; }
  /// The columns of this process's rows owned elsewhere: the values it receives in one matrix-vector product
  /// (per column of unknowns), the communication of a conjugate-gradient iteration besides its two reductions.
  std::size_t off_process_columns() const
  {
    int size = 1;
    MPI_Comm_size(comm_, &size);
    if(size == 1) return 0;
    Mat diagonal_block, off_block;
    const PetscInt* columns = nullptr;
    PetscInt rows = 0, count = 0;
    petsc_check(MatMPIAIJGetSeqAIJ(pattern_, &diagonal_block, &off_block, &columns), "MatMPIAIJGetSeqAIJ");
    petsc_check(MatGetSize(off_block, &rows, &count), "MatGetSize");
    return std::size_t(count);
  }

  /// M and L(D) at X (owned and overlap rows read), `with_matrices` false: the statistics only. The statistics
  /// are every process's; a failed prefilter throws (the same on every process: the solve is collective).
  template <typename Tensor>
  AFI::Assembly_statistics assemble(const Control_matrix& X, int metric_columns, const Tensor& tensor,
                                    bool with_matrices)
  {
    assembler_.set_prefiltered(nullptr);
    prefiltered_valid_ = false;
    if(prefilter_) make_prefiltered(X, metric_columns);
    AFI::Value_array m, l;
    const AFI::Assembly_statistics a = assembler_.assemble(X, metric_columns, tensor, m, l, with_matrices);
    assembler_.set_prefiltered(nullptr);
    if(with_matrices) { fill(M_, m); fill(L_, l); }
    return reduce_statistics(comm_, a, d_);
  }

  void save()
  {
    std::swap(saved_M_, M_); std::swap(saved_L_, L_);
    saved_prefiltered_X_ = prefiltered_X_;
    saved_prefiltered_valid_ = prefiltered_valid_;
  }
  void restore()
  {
    std::swap(saved_M_, M_); std::swap(saved_L_, L_);
    prefiltered_X_.swap(saved_prefiltered_X_);
    prefiltered_valid_ = saved_prefiltered_valid_;
  }

private:
  // the structure of every process's entries, gathered by PETSc (MATPREALLOCATOR), then one matrix
  // preallocated with it; M and L are copies of its structure
  void preallocate()
  {
    const PetscInt local = PetscInt(d_.owned_vertices.size());
    Mat pre;
    petsc_check(MatCreate(comm_, &pre), "MatCreate");
    petsc_check(MatSetType(pre, MATPREALLOCATOR), "MatSetType");
    petsc_check(MatSetSizes(pre, local, local, d_.rows, d_.rows), "MatSetSizes");
    petsc_check(MatSetUp(pre), "MatSetUp");
    const AFI::Value_array zeros(std::size_t(assembler_.number_of_nonzeros()), 0.0);
    insert(pre, zeros);
    petsc_check(MatCreate(comm_, &pattern_), "MatCreate");
    petsc_check(MatSetType(pattern_, MATAIJ), "MatSetType");
    petsc_check(MatSetSizes(pattern_, local, local, d_.rows, d_.rows), "MatSetSizes");
    petsc_check(MatPreallocatorPreallocate(pre, PETSC_TRUE, pattern_), "MatPreallocatorPreallocate");
    MatDestroy(&pre);
  }

  // adds the value arrays (over the assembler's pattern) into A, column j of the pattern as row j (symmetric)
  void insert(Mat A, const AFI::Value_array& values)
  {
    const auto& p = assembler_.pattern();
    const int* outer = p.outerIndexPtr();
    for(Eigen::Index j = 0; j < p.outerSize(); ++j)
    {
      const int count = outer[j + 1] - outer[j];
      if(count == 0) continue;
      const PetscInt row = d_.petsc_row[std::size_t(j)];
      petsc_check(MatSetValues(A, 1, &row, count, petsc_inner_.data() + outer[j], values.data() + outer[j], ADD_VALUES),
                  "MatSetValues");
    }
    // every owned row has its diagonal, even a vertex on no face (held: an identity row of the step)
    for(int v : d_.owned_vertices)
    {
      const PetscInt row = d_.petsc_row[std::size_t(v)];
      petsc_check(MatSetValue(A, row, row, 0.0, ADD_VALUES), "MatSetValue");
    }
    petsc_check(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
    petsc_check(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  }

  // A: a zero matrix of the pattern, then the value arrays added
  void fill(Mat& A, const AFI::Value_array& values)
  {
    if(!A) petsc_check(MatDuplicate(pattern_, MAT_DO_NOT_COPY_VALUES, &A), "MatDuplicate");
    else petsc_check(MatZeroEntries(A), "MatZeroEntries");
    insert(A, values);
  }

  // M_eps = X + dX, (M + eps L) dX = -eps L X on the free rows (isotropic M, L at X), every row received
  void make_prefiltered(const Control_matrix& X, int metric_columns)
  {
    AFI::Value_array m, l;
    assembler_.assemble(X, metric_columns, CGAL::Anisotropic_fairing::Isotropic_diffusion_tensor(), m, l);
    fill(Mi_, m);
    fill(Li_, l);
    const std::vector<double> no_fidelity(eps_.size(), 0.0);
    const Distributed_solve s =
      prefilter_solver_->solve(Mi_, Li_, eps_, no_fidelity, X, X, metric_columns, prefilter_dX_);
    prefilter_iterations_ += std::size_t(s.iterations);
    MatDestroy(&Mi_);   // needed again only at the next assembly
    MatDestroy(&Li_);
    if(!s.ok) throw std::runtime_error("the prefiltered surface M_eps could not be computed: " + s.message);
    prefiltered_X_ = X;
    for(std::size_t k = 0; k < d_.owned_vertices.size(); ++k)
      prefiltered_X_.row(d_.owned_vertices[k]).head(metric_columns) += prefilter_dX_.row(Eigen::Index(k));
    rows_.refresh(prefiltered_X_);
    std::string bad =
      prefilter_dX_.allFinite() ? std::string() : "the prefiltered surface M_eps could not be computed: not finite";
    agree(comm_, bad, "solver_failed");
    assembler_.set_prefiltered(&prefiltered_X_);
    prefiltered_valid_ = true;
  }

  MPI_Comm comm_;
  const Distributed_layout& d_;
  Whole_rows& rows_;
  const std::vector<bool>& held_;
  AFI::Fem_assembler<AFI::Ghosted_patch_cache> assembler_;
  std::unique_ptr<Distributed_solver> prefilter_solver_;
  std::vector<PetscInt> petsc_inner_;   // the pattern's row indices in PETSc's numbering
  Mat pattern_ = nullptr, M_ = nullptr, L_ = nullptr, saved_M_ = nullptr, saved_L_ = nullptr, Mi_ = nullptr,
      Li_ = nullptr;
  std::vector<double> eps_;
  bool prefilter_ = false, prefiltered_valid_ = false, saved_prefiltered_valid_ = false;
  Control_matrix prefiltered_X_, saved_prefiltered_X_, prefilter_dX_;
  std::size_t prefilter_iterations_ = 0;
};

} // namespace af_distributed

#endif // AF_DISTRIBUTED_DISTRIBUTED_OPERATOR_H
