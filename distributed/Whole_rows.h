// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every process holds every row of a per-vertex matrix (Control_matrix, one row per real vertex of the run)
// and computes its own vertices' rows; after each change the others' rows come from their owners
// (MPI_Allgatherv), so that every process holds the same bits and the library's measures of the whole mesh
// (limit points, folds, the noise level, the risk estimate) give the same numbers, and decisions, on each.
// The price: every process receives the whole mesh's rows at each refresh. A process that holds a part of the
// mesh (Distributed_layout::part) holds its part's rows, and receives those of its vertices others own (the halo).

#ifndef AF_DISTRIBUTED_WHOLE_ROWS_H
#define AF_DISTRIBUTED_WHOLE_ROWS_H

#include "Distributed_layout.h"

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <mpi.h>

#include <vector>

namespace af_distributed {

typedef CGAL::Anisotropic_fairing::internal::Control_matrix Control_matrix;

/// What the refreshes of a call moved: doubles received into rows other processes own, and how many refreshes.
struct Communication_volume
{
  double doubles_received = 0;
  std::size_t refreshes = 0;
};

class Whole_rows
{
public:
  Whole_rows(MPI_Comm comm, const Distributed_layout& d, Communication_volume& volume)
    : comm_(comm), d_(d), volume_(volume), owned_(std::size_t(d.size), 0)
  {
    const int mine = int(d.owned_vertices.size());
    MPI_Allgather(&mine, 1, MPI_INT, owned_.data(), 1, MPI_INT, comm);
  }

  /// The rows of X other processes own, from them (X's own rows are read from X).
  void refresh(Control_matrix& X)
  {
    const int bs = int(X.cols());
    if(bs == 0 || d_.size == 1) return;
    if(d_.part)   // a part of the mesh: the rows it holds, from their owners (the halo)
    {
      d_.part->refresh(X.data(), std::size_t(bs));
      volume_.doubles_received += double(d_.vertex_owner.size() - d_.owned_vertices.size()) * bs;
      ++volume_.refreshes;
      return;
    }
    std::vector<double> mine;
    mine.reserve(d_.owned_vertices.size() * std::size_t(bs));
    for(int r : d_.owned_vertices)   // in increasing order: the process's PETSc rows
      for(int c = 0; c < bs; ++c) mine.push_back(X(r, c));
    std::vector<int> counts(owned_.size()), offsets(owned_.size(), 0);
    for(std::size_t p = 0; p < owned_.size(); ++p) counts[p] = owned_[p] * bs;
    for(std::size_t p = 1; p < owned_.size(); ++p) offsets[p] = offsets[p - 1] + counts[p - 1];
    std::vector<double> all(std::size_t(offsets.back() + counts.back()));
    MPI_Allgatherv(mine.data(), int(mine.size()), MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                   comm_);
    for(std::size_t v = 0; v < d_.vertex_owner.size(); ++v)
      if(d_.vertex_owner[v] != d_.rank)
        for(int c = 0; c < bs; ++c)
          X(Eigen::Index(v), c) = all[std::size_t(d_.petsc_row[v]) * std::size_t(bs) + std::size_t(c)];
    volume_.doubles_received += double(d_.vertex_owner.size() - d_.owned_vertices.size()) * bs;
    ++volume_.refreshes;
  }

private:
  MPI_Comm comm_;
  const Distributed_layout& d_;
  Communication_volume& volume_;
  std::vector<int> owned_;   // per process: the vertices it owns
};

} // namespace af_distributed

#endif // AF_DISTRIBUTED_WHOLE_ROWS_H
