// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Who owns what once the faces are divided (Face_partition.h). A process assembles its own faces; a
// vertex belongs to the process of the first face around it (so each owned vertex lies on an owned face,
// and its limit masks read only vertices of that face's Loop patch); the overlap (ghost rows) is every
// other vertex of the patches (rings) of the owned faces: the control points a Loop element of an owned
// face reads, the same role as the ghost layer on a border. Rows are numbered for PETSc by process, each
// process's vertices in the run's (locality) order.

#ifndef AF_DISTRIBUTED_DISTRIBUTED_LAYOUT_H
#define AF_DISTRIBUTED_DISTRIBUTED_LAYOUT_H

#include <CGAL/Anisotropic_fairing/internal/element/Ghosted_patch_cache.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Process_part.h>

#include <mpi.h>

#include <petscsys.h>

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace af_distributed {

struct Distributed_layout
{
  int rank = 0, size = 1;
  std::vector<int> face_owner, vertex_owner;   // per real face, per real vertex
  std::vector<std::size_t> owned_faces;        // increasing
  std::vector<int> owned_vertices, ghost_vertices;   // increasing
  std::vector<PetscInt> petsc_row;             // per real vertex: its row in PETSc's numbering
  PetscInt first_row = 0, rows = 0;            // this process's first row; all rows
  // the part of the mesh this process holds, when the library's mesh is one (null: every process holds it whole)
  const CGAL::Anisotropic_fairing::internal::Part_view* part = nullptr;
  std::unordered_map<std::int64_t, std::size_t> face_of_global;   // with a part: its faces by whole-mesh number

  bool owns_vertex(int v) const { return vertex_owner[std::size_t(v)] == rank; }
};

namespace layout_detail {

// the owned faces and vertices, and the overlap: the other vertices of the owned faces' Loop patches
inline void list_owned(Distributed_layout& d, std::size_t n, std::size_t real_faces,
                       const CGAL::Anisotropic_fairing::internal::Ghosted_patch_cache& cache)
{
  for(std::size_t f = 0; f < real_faces; ++f)
    if(d.face_owner[f] == d.rank) d.owned_faces.push_back(f);
  std::vector<char> seen(n, 0);
  for(std::size_t v = 0; v < n; ++v)
    if(d.vertex_owner[v] == d.rank) { d.owned_vertices.push_back(int(v)); seen[v] = 1; }
  for(std::size_t f : d.owned_faces)
    for(int k = 0; k < cache.ring_size(f); ++k)
    {
      const int v = cache.ring(f)[k];
      if(!seen[std::size_t(v)]) { seen[std::size_t(v)] = 1; d.ghost_vertices.push_back(v); }
    }
  std::sort(d.ghost_vertices.begin(), d.ghost_vertices.end());
}

} // namespace layout_detail

/// The layout of `face_owner` (per real face of `layer`) on process `rank` of `size`.
inline Distributed_layout make_distributed_layout(const CGAL::Anisotropic_fairing::internal::Ghost_layer& layer,
                                                  const CGAL::Anisotropic_fairing::internal::Ghosted_patch_cache& cache,
                                                  std::vector<int> face_owner, int rank, int size)
{
  Distributed_layout d;
  d.rank = rank;
  d.size = size;
  d.face_owner = std::move(face_owner);
  const std::size_t n = layer.real_vertices;
  const auto& topo = *layer.topology;
  d.vertex_owner.assign(n, -1);
  for(std::size_t f = 0; f < layer.real_faces; ++f)
    for(int k = 0; k < 3; ++k)
    {
      int& o = d.vertex_owner[std::size_t(topo.face(f)[k])];
      if(o < 0) o = d.face_owner[f];
    }
  for(int& o : d.vertex_owner) if(o < 0) o = 0;   // a vertex on no face (held, never moved): the first process's
  std::vector<PetscInt> count(std::size_t(size) + 1, 0);
  d.petsc_row.assign(n, 0);
  for(std::size_t v = 0; v < n; ++v) d.petsc_row[v] = count[std::size_t(d.vertex_owner[v]) + 1]++;
  for(int p = 0; p < size; ++p) count[std::size_t(p) + 1] += count[std::size_t(p)];
  for(std::size_t v = 0; v < n; ++v) d.petsc_row[v] += count[std::size_t(d.vertex_owner[v])];
  d.first_row = count[std::size_t(rank)];
  d.rows = count[std::size_t(size)];
  layout_detail::list_owned(d, n, layer.real_faces, cache);
  return d;
}

/// The layout of a process's part of a mesh no process holds whole (`view`: the library's mesh is the part,
/// internal/mesh/Process_part.h): the owners the part says; PETSc's rows numbered by process over the whole
/// mesh, each process's own vertices in their order, a vertex's row learnt from its owner.
inline Distributed_layout make_part_layout(const CGAL::Anisotropic_fairing::internal::Ghost_layer& layer,
                                           const CGAL::Anisotropic_fairing::internal::Ghosted_patch_cache& cache,
                                           const CGAL::Anisotropic_fairing::internal::Part_view& view, MPI_Comm comm)
{
  Distributed_layout d;
  MPI_Comm_rank(comm, &d.rank);
  MPI_Comm_size(comm, &d.size);
  d.part = &view;
  const std::size_t n = layer.real_vertices;
  d.face_owner.resize(layer.real_faces);
  for(std::size_t f = 0; f < layer.real_faces; ++f)
  {
    d.face_owner[f] = view.face_owner(f);
    d.face_of_global.emplace(view.global_face(f), f);
  }
  d.vertex_owner.resize(n);
  long long mine = 0, first = 0, all = 0;
  for(std::size_t v = 0; v < n; ++v)
  {
    d.vertex_owner[v] = view.vertex_owner(v);
    mine += d.vertex_owner[v] == d.rank ? 1 : 0;
  }
  MPI_Exscan(&mine, &first, 1, MPI_LONG_LONG, MPI_SUM, comm);
  if(d.rank == 0) first = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, comm);
  d.first_row = PetscInt(first);
  d.rows = PetscInt(all);
  std::vector<double> row(n, 0.0);
  long long next = first;
  for(std::size_t v = 0; v < n; ++v)
    if(d.vertex_owner[v] == d.rank) row[v] = double(next++);
  view.refresh(row);
  d.petsc_row.resize(n);
  for(std::size_t v = 0; v < n; ++v) d.petsc_row[v] = PetscInt(row[v]);
  layout_detail::list_owned(d, n, layer.real_faces, cache);
  return d;
}

} // namespace af_distributed

#endif // AF_DISTRIBUTED_DISTRIBUTED_LAYOUT_H
