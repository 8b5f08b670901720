// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The vertex properties besides x, y, z of a part's vertices (Mesh_part.h), which the file's blocks hold
// (Ply_blocks.h): each process asks the holders of its vertices' blocks for their values, as the part's
// positions were gathered. What a part reads of them: --hold's property, attribute columns.

#ifndef AF_DISTRIBUTED_PART_VALUES_H
#define AF_DISTRIBUTED_PART_VALUES_H

#include "Mesh_part.h"
#include "Part_exchange.h"
#include "Ply_blocks.h"

#include <cstdint>
#include <vector>

namespace af_distributed {

/// blocks.names.size() values per vertex of `part`, in its order, from the blocks of every process (collective).
inline std::vector<double> part_values(MPI_Comm comm, const Ply_blocks& blocks, const Mesh_part& part)
{
  const std::size_t columns = blocks.names.size();
  const std::int64_t n = blocks.mesh.vertices, first = block_first(n, part.rank, part.size);
  std::vector<std::vector<std::int64_t>> asked(static_cast<std::size_t>(part.size));
  for(std::int64_t v : part.global_vertex) asked[std::size_t(block_of(v, n, part.size))].push_back(v);
  std::vector<int> from;
  const std::vector<std::int64_t> questions = af_distributed::exchange(comm, asked, &from);
  // the answers in the order asked: each process's questions came in the order of its vertices
  std::vector<std::vector<double>> answers(static_cast<std::size_t>(part.size));
  for(std::size_t k = 0; k < questions.size(); ++k)
  {
    const double* row = blocks.values.data() + std::size_t(questions[k] - first) * columns;
    answers[std::size_t(from[k])].insert(answers[std::size_t(from[k])].end(), row, row + columns);
  }
  const std::vector<double> received = af_distributed::exchange(comm, answers);
  // received: process 0's answers, then process 1's ...; each in the order this process asked it
  std::vector<double> values(part.global_vertex.size() * columns);
  std::vector<std::size_t> next(static_cast<std::size_t>(part.size), 0), offset(static_cast<std::size_t>(part.size), 0);
  for(std::size_t p = 1; p < offset.size(); ++p) offset[p] = offset[p - 1] + asked[p - 1].size();
  for(std::size_t v = 0; v < part.global_vertex.size(); ++v)
  {
    const std::size_t p = std::size_t(block_of(part.global_vertex[v], n, part.size));
    const double* row = received.data() + (offset[p] + next[p]++) * columns;
    std::copy(row, row + columns, values.begin() + std::ptrdiff_t(v * columns));
  }
  return values;
}

} // namespace af_distributed

#endif // AF_DISTRIBUTED_PART_VALUES_H
