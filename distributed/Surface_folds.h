// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the library's Step_safety judges of a surface besides its statistics, distributed: the written
// positions (the Loop limit points of the control points, or the control points themselves), computed by
// each vertex's owner and refreshed into the overlap, and the folded edges of the mesh they span, each
// interior edge counted by the process of the face holding its first halfedge, added up over the processes.

#ifndef AF_DISTRIBUTED_SURFACE_FOLDS_H
#define AF_DISTRIBUTED_SURFACE_FOLDS_H

#include "Distributed_layout.h"
#include "Ghosted_rows.h"

#include <CGAL/Anisotropic_fairing/internal/flow/Step_safety.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Vertex_limit_masks.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>

#include <limits>
#include <vector>

namespace af_distributed {

namespace AFI = CGAL::Anisotropic_fairing::internal;

/// Y = the Loop limit points of X on the owned and overlap rows (NaN elsewhere).
inline void distributed_limit_points(const AFI::Ghost_layer& layer, const Distributed_layout& d, Ghosted_rows& rows,
                                     const Control_matrix& X, Control_matrix& Y)
{
  const Control_matrix extended = layer.has_boundary() ? layer.extend(X) : Control_matrix();
  const Control_matrix& E = layer.has_boundary() ? extended : X;
  Y.setConstant(X.rows(), X.cols(), std::numeric_limits<double>::quiet_NaN());
  for(int v : d.owned_vertices) AFI::vertex_limit_value(*layer.topology, E, v, Y.row(v).data());
  rows.refresh(Y);
}

/// Whether the owned rows of X are finite on every process.
inline bool finite_everywhere(MPI_Comm comm, const Distributed_layout& d, const Control_matrix& X)
{
  int finite = 1;
  for(int v : d.owned_vertices) finite = finite && X.row(v).allFinite();
  int all = 0;
  MPI_Allreduce(&finite, &all, 1, MPI_INT, MPI_MIN, comm);
  return all == 1;
}

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

/// The folded (120 degrees) and nearly folded (110 degrees) edges of the mesh of P (owned and overlap rows),
/// every process's, and where the folded ones are; as the library's count_folds does on one machine.
inline void count_distributed_folds(MPI_Comm comm, const AFI::Ghost_layer& layer, const Distributed_layout& d,
                                    const std::vector<int>& face_component, const std::vector<double>& edge,
                                    const Control_matrix& P, AFI::Surface_soundness& s)
{
  std::vector<int> where;
  unsigned long long mine[2] = { AFI::count_folded_edges(*layer.topology, layer.real_faces, P, face_component, edge,
                                                         AFI::turn_120, &d.owned_faces, &where),
                                 AFI::count_folded_edges(*layer.topology, layer.real_faces, P, face_component, edge,
                                                         AFI::turn_110, &d.owned_faces) };
  unsigned long long all[2] = { 0, 0 };
  MPI_Allreduce(mine, all, 2, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
  s.folded_edges = std::size_t(all[0]);
  s.bent_edges = std::size_t(all[1]);
  s.folded_edge_list = gather_everywhere(comm, where);
}

} // namespace af_distributed

#endif // AF_DISTRIBUTED_SURFACE_FOLDS_H
