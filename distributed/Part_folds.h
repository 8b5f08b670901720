// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The folds of a surface no process holds whole (Distributed_layout::part): each process counts the folded edges
// and reversed faces of its own faces (an edge between two processes' faces by one of them), the counts are
// summed, and each process's lists hold first the folds it judges (its own), then the others' that lie in its
// part, which only mark the places where the surface was folded (flow/Step_safety.h, Fold_sites): a candidate's
// own folds are judged against every fold near them, as the serial run judges them, and the processes' verdicts
// are joined (the flow operator's everywhere()).

#ifndef AF_DISTRIBUTED_PART_FOLDS_H
#define AF_DISTRIBUTED_PART_FOLDS_H

#include "Distributed_layout.h"

#include <CGAL/Anisotropic_fairing/internal/assembly/Fem_assembly.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_safety.h>

#include <mpi.h>

#include <cstdint>
#include <vector>

namespace af_distributed {

/// Every process's `mine`, in the order of the processes, on every process.
inline std::vector<std::int64_t> gathered_numbers(MPI_Comm comm, const std::vector<std::int64_t>& mine)
{
  int size = 1;
  MPI_Comm_size(comm, &size);
  std::vector<int> count(static_cast<std::size_t>(size)), at(static_cast<std::size_t>(size), 0);
  const int n = int(mine.size());
  MPI_Allgather(&n, 1, MPI_INT, count.data(), 1, MPI_INT, comm);
  for(std::size_t p = 1; p < count.size(); ++p) at[p] = at[p - 1] + count[p - 1];
  std::vector<std::int64_t> all(static_cast<std::size_t>(at.back() + count.back()));
  MPI_Allgatherv(mine.data(), n, MPI_INT64_T, all.data(), count.data(), at.data(), MPI_INT64_T, comm);
  return all;
}

/// The folded edges of `s` (this process's own, counted) summed over the processes, with the others' that lie in
/// its part after its own in the list; `bent`: the bent edges are summed too.
inline void share_folded_edges(MPI_Comm comm, const Distributed_layout& d,
                               const CGAL::Anisotropic_fairing::internal::Triangle_topology& topo,
                               CGAL::Anisotropic_fairing::internal::Surface_soundness& s, bool bent)
{
  double counts[2] = { double(s.folded_edges), double(s.bent_edges) };
  MPI_Allreduce(MPI_IN_PLACE, counts, 2, MPI_DOUBLE, MPI_SUM, comm);   // whole numbers: exact in any order
  s.folded_edges = std::size_t(counts[0]);
  if(bent) s.bent_edges = std::size_t(counts[1]);
  s.judged_edges = s.folded_edge_list.size();
  std::vector<std::int64_t> mine;   // each edge by its two faces, the own one first
  for(int h : s.folded_edge_list)
  {
    mine.push_back(d.part->global_face(std::size_t(topo.face_of(h))));
    mine.push_back(d.part->global_face(std::size_t(topo.face_of(topo.opposite(h)))));
  }
  const std::vector<std::int64_t> all = gathered_numbers(comm, mine);
  for(std::size_t k = 0; k + 1 < all.size(); k += 2)
  {
    const auto a = d.face_of_global.find(all[k]), b = d.face_of_global.find(all[k + 1]);
    if(a == d.face_of_global.end() || b == d.face_of_global.end() || d.face_owner[a->second] == d.rank) continue;
    for(int c = 0; c < 3; ++c)
    {
      const int h = int(3 * a->second) + c, o = topo.opposite(h);
      if(o >= 0 && std::size_t(topo.face_of(o)) == b->second) s.folded_edge_list.push_back(h);
    }
  }
}

/// The reversed faces of every process's own faces (`own`, this process's), in `r`'s list: its own first, then
/// the others' that lie in its part.
inline void share_reversed_faces(MPI_Comm comm, const Distributed_layout& d, const std::vector<std::size_t>& own,
                                 CGAL::Anisotropic_fairing::internal::Assembly_statistics& r)
{
  std::vector<std::int64_t> mine;
  for(std::size_t f : own) mine.push_back(d.part->global_face(f));
  r.reversed_face_list = own;
  r.judged_reversed_faces = own.size();
  for(std::int64_t g : gathered_numbers(comm, mine))
  {
    const auto a = d.face_of_global.find(g);
    if(a != d.face_of_global.end() && d.face_owner[a->second] != d.rank) r.reversed_face_list.push_back(a->second);
  }
}

} // namespace af_distributed

#endif // AF_DISTRIBUTED_PART_FOLDS_H
