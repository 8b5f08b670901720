// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The library's Process_part (internal/mesh/Process_part.h) of a Mesh_part: the mesh a process gives the library
// is its part, vertices and faces in the part's order, and the measures of the whole mesh are made over MPI.
// Sums are reduced to process 0 and sent back from it, so that every process holds the same bits and takes the
// library's decisions alike (MPI_Allreduce does not promise that).

#ifndef AF_DISTRIBUTED_PART_PROCESS_H
#define AF_DISTRIBUTED_PART_PROCESS_H

#include "Mesh_part.h"

#include <CGAL/Anisotropic_fairing/internal/mesh/Process_part.h>

#include <mpi.h>

#include <vector>

namespace af_distributed {

class Part_process : public CGAL::Anisotropic_fairing::internal::Process_part
{
public:
  Part_process(MPI_Comm comm, const Mesh_part& part) : comm_(comm), part_(part) {}

  std::int64_t global_vertex(std::size_t v) const override { return part_.global_vertex[v]; }
  std::int64_t global_face(std::size_t f) const override { return part_.global_face[f]; }
  int vertex_owner(std::size_t v) const override { return part_.vertex_owner[v]; }
  int face_owner(std::size_t f) const override { return part_.face_owner[f]; }
  int rank() const override { return part_.rank; }
  void refresh(double* values, std::size_t columns) const override { part_.refresh(comm_, values, int(columns)); }
  void minimum_at_owners(double* values, std::size_t columns) const override
  {
    part_.minimum_at_owners(comm_, values, int(columns));
  }
  void sum(double* values, std::size_t count) const override { reduce(values, count, MPI_SUM); }
  void maximum(double* values, std::size_t count) const override { reduce(values, count, MPI_MAX); }
  std::vector<double> gathered(const std::vector<double>& values) const override
  {
    std::vector<int> count(static_cast<std::size_t>(part_.size)), at(static_cast<std::size_t>(part_.size), 0);
    const int mine = int(values.size());
    MPI_Allgather(&mine, 1, MPI_INT, count.data(), 1, MPI_INT, comm_);
    for(std::size_t p = 1; p < count.size(); ++p) at[p] = at[p - 1] + count[p - 1];
    std::vector<double> all(static_cast<std::size_t>(at.back() + count.back()));
    MPI_Allgatherv(values.data(), mine, MPI_DOUBLE, all.data(), count.data(), at.data(), MPI_DOUBLE, comm_);
    return all;
  }

private:
  void reduce(double* values, std::size_t count, MPI_Op op) const
  {
    std::vector<double> in(values, values + count);
    MPI_Reduce(in.data(), values, int(count), MPI_DOUBLE, op, 0, comm_);
    MPI_Bcast(values, int(count), MPI_DOUBLE, 0, comm_);
  }

  MPI_Comm comm_;
  const Mesh_part& part_;
};

} // namespace af_distributed

#endif // AF_DISTRIBUTED_PART_PROCESS_H
