// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The faces of the mesh divided among the processes by PETSc's partitioner (MatPartitioning) on the
// face dual graph: one vertex per real face, one edge per interior mesh edge. Each process gives the
// rows of a contiguous block of faces; the parts come back to every process. The partitioner is PETSc's
// option -mat_partitioning_type (default here: PT-Scotch on more than one process).

#ifndef AF_DISTRIBUTED_FACE_PARTITION_H
#define AF_DISTRIBUTED_FACE_PARTITION_H

#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>

#include <petscmat.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace af_distributed {

/// Throws std::runtime_error naming the PETSc call when `code` is an error.
inline void petsc_check(PetscErrorCode code, const char* call)
{
  if(code != 0)
    throw std::runtime_error(std::string("PETSc ") + call + " failed (error " + std::to_string(int(code)) + ")");
}

/// The part of each of this process's `rows` vertices of a graph of `total` (its rows ia, ja: MatCreateMPIAdj's,
/// which takes them) by PETSc's partitioner.
inline std::vector<int> apply_partitioner(MPI_Comm comm, PetscInt rows, PetscInt total, PetscInt* ia, PetscInt* ja)
{
  Mat adjacency;
  petsc_check(MatCreateMPIAdj(comm, rows, total, ia, ja, nullptr, &adjacency), "MatCreateMPIAdj");
  MatPartitioning partitioning;
  petsc_check(MatPartitioningCreate(comm, &partitioning), "MatPartitioningCreate");
  petsc_check(MatPartitioningSetAdjacency(partitioning, adjacency), "MatPartitioningSetAdjacency");
#if defined(PETSC_HAVE_PTSCOTCH)
  petsc_check(MatPartitioningSetType(partitioning, MATPARTITIONINGPTSCOTCH), "MatPartitioningSetType");
#endif
  petsc_check(MatPartitioningSetFromOptions(partitioning), "MatPartitioningSetFromOptions");
  IS parts;
  petsc_check(MatPartitioningApply(partitioning, &parts), "MatPartitioningApply");
  const PetscInt* p = nullptr;
  petsc_check(ISGetIndices(parts, &p), "ISGetIndices");
  std::vector<int> part(p, p + rows);
  petsc_check(ISRestoreIndices(parts, &p), "ISRestoreIndices");
  ISDestroy(&parts);
  MatPartitioningDestroy(&partitioning);
  MatDestroy(&adjacency);
  return part;
}

/// The part (process) of each of the first `real_faces` faces of `topo`, the same on every process.
inline std::vector<int> partition_faces(MPI_Comm comm,
                                        const CGAL::Anisotropic_fairing::internal::Triangle_topology& topo,
                                        std::size_t real_faces)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  if(size == 1) return std::vector<int>(real_faces, 0);
  const PetscInt nf = PetscInt(real_faces);
  const PetscInt first = nf * rank / size, last = nf * (rank + 1) / size;
  // the rows of this block (MatCreateMPIAdj takes ownership of ia, ja: PETSc's allocator)
  PetscInt *ia = nullptr, *ja = nullptr;
  petsc_check(PetscMalloc1(last - first + 1, &ia), "PetscMalloc1");
  std::vector<PetscInt> neighbours;
  ia[0] = 0;
  for(PetscInt f = first; f < last; ++f)
  {
    for(int k = 0; k < 3; ++k)
    {
      const int o = topo.opposite(int(3 * f + k));
      if(o >= 0 && std::size_t(topo.face_of(o)) < real_faces) neighbours.push_back(PetscInt(topo.face_of(o)));
    }
    std::sort(neighbours.begin() + ia[f - first], neighbours.end());   // MPIAdj wants each row's columns sorted
    ia[f - first + 1] = PetscInt(neighbours.size());
  }
  petsc_check(PetscMalloc1(neighbours.size() + 1, &ja), "PetscMalloc1");
  std::copy(neighbours.begin(), neighbours.end(), ja);
  const std::vector<int> mine = apply_partitioner(comm, last - first, nf, ia, ja);
  // every process's parts, in the order of the blocks
  std::vector<int> count(static_cast<std::size_t>(size)), at(static_cast<std::size_t>(size));
  for(int p = 0; p < size; ++p)
  {
    at[std::size_t(p)] = int(nf * p / size);
    count[std::size_t(p)] = int(nf * (p + 1) / size) - at[std::size_t(p)];
  }
  std::vector<int> part(real_faces);
  MPI_Allgatherv(mine.data(), int(mine.size()), MPI_INT, part.data(), count.data(), at.data(), MPI_INT, comm);
  return part;
}

} // namespace af_distributed

#endif // AF_DISTRIBUTED_FACE_PARTITION_H
