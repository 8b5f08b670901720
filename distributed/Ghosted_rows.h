// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rows of a process's copy of a per-vertex matrix (Control_matrix, one row per real vertex of the run)
// that it may read: its own vertices' rows, which it computes, and the overlap's (ghost) rows, refreshed
// from their owners by a PETSc ghosted vector (VecGhostUpdate) of block size = the columns. Every other
// row holds NaN, so that a computation reading beyond the overlap shows at once instead of silently
// using stale values.

#ifndef AF_DISTRIBUTED_GHOSTED_ROWS_H
#define AF_DISTRIBUTED_GHOSTED_ROWS_H

#include "Distributed_layout.h"
#include "Face_partition.h"

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <petscvec.h>

#include <limits>
#include <map>
#include <vector>

namespace af_distributed {

typedef CGAL::Anisotropic_fairing::internal::Control_matrix Control_matrix;

class Ghosted_rows
{
public:
  Ghosted_rows(MPI_Comm comm, const Distributed_layout& d) : comm_(comm), d_(d)
  {
    for(int v : d.ghost_vertices) ghost_blocks_.push_back(d.petsc_row[std::size_t(v)]);
  }
  ~Ghosted_rows()
  {
    for(auto& e : vectors_) VecDestroy(&e.second);
  }
  Ghosted_rows(const Ghosted_rows&) = delete;
  Ghosted_rows& operator=(const Ghosted_rows&) = delete;

  /// The ghost rows of X from their owners (X's own rows are read from X).
  void refresh(Control_matrix& X)
  {
    const int bs = int(X.cols());
    if(bs == 0) return;
    Vec v = vector(bs);
    Vec local;
    petsc_check(VecGhostGetLocalForm(v, &local), "VecGhostGetLocalForm");
    PetscScalar* a = nullptr;
    petsc_check(VecGetArray(local, &a), "VecGetArray");
    std::size_t k = 0;
    for(int r : d_.owned_vertices)
      for(int c = 0; c < bs; ++c) a[k++] = X(r, c);
    petsc_check(VecRestoreArray(local, &a), "VecRestoreArray");
    petsc_check(VecGhostUpdateBegin(v, INSERT_VALUES, SCATTER_FORWARD), "VecGhostUpdateBegin");
    petsc_check(VecGhostUpdateEnd(v, INSERT_VALUES, SCATTER_FORWARD), "VecGhostUpdateEnd");
    petsc_check(VecGetArray(local, &a), "VecGetArray");
    for(int r : d_.ghost_vertices)
      for(int c = 0; c < bs; ++c) X(r, c) = a[k++];
    petsc_check(VecRestoreArray(local, &a), "VecRestoreArray");
    petsc_check(VecGhostRestoreLocalForm(v, &local), "VecGhostRestoreLocalForm");
    doubles_received_ += double(d_.ghost_vertices.size()) * bs;
    ++refreshes_;
  }

  /// Every row neither owned nor in the overlap set to NaN.
  void forget_others(Control_matrix& X) const
  {
    std::vector<char> readable(std::size_t(X.rows()), 0);
    for(int r : d_.owned_vertices) readable[std::size_t(r)] = 1;
    for(int r : d_.ghost_vertices) readable[std::size_t(r)] = 1;
    for(Eigen::Index r = 0; r < X.rows(); ++r)
      if(!readable[std::size_t(r)]) X.row(r).setConstant(std::numeric_limits<double>::quiet_NaN());
  }

  /// On rank 0: every process's own rows of X, in the run's numbering (other ranks: X unchanged).
  void gather_on_first(Control_matrix& X) const
  {
    const int bs = int(X.cols());
    std::vector<double> mine;
    for(int r : d_.owned_vertices)
      for(int c = 0; c < bs; ++c) mine.push_back(X(r, c));
    std::vector<int> rows_of(std::size_t(d_.size), 0), counts(std::size_t(d_.size), 0),
      offsets(std::size_t(d_.size), 0);
    const int n_mine = int(mine.size());
    MPI_Gather(&n_mine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm_);
    for(int p = 1; p < d_.size; ++p) offsets[std::size_t(p)] = offsets[std::size_t(p - 1)] + counts[std::size_t(p - 1)];
    std::vector<double> all(d_.rank == 0 ? std::size_t(offsets.back() + counts.back()) : 0);
    MPI_Gatherv(mine.data(), n_mine, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0, comm_);
    if(d_.rank != 0) return;
    // a process's rows come in its vertices' increasing order, which is also their PETSc order
    for(std::size_t v = 0; v < d_.vertex_owner.size(); ++v)
      for(int c = 0; c < bs; ++c)
        X(Eigen::Index(v), c) = all[std::size_t(d_.petsc_row[v]) * std::size_t(bs) + std::size_t(c)];
  }

  /// doubles received into overlap rows so far, and the refreshes that moved them (communication volume)
  double doubles_received() const { return doubles_received_; }
  std::size_t refreshes() const { return refreshes_; }

private:
  Vec vector(int bs)
  {
    auto it = vectors_.find(bs);
    if(it != vectors_.end()) return it->second;
    Vec v;
    petsc_check(VecCreateGhostBlock(comm_, bs, PetscInt(d_.owned_vertices.size()) * bs, PETSC_DECIDE,
                                    PetscInt(ghost_blocks_.size()), ghost_blocks_.data(), &v),
                "VecCreateGhostBlock");
    vectors_[bs] = v;
    return v;
  }

  MPI_Comm comm_;
  const Distributed_layout& d_;
  std::vector<PetscInt> ghost_blocks_;
  std::map<int, Vec> vectors_;
  double doubles_received_ = 0;
  std::size_t refreshes_ = 0;
};

} // namespace af_distributed

#endif // AF_DISTRIBUTED_GHOSTED_ROWS_H
