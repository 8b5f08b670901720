// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Adding a face's local matrices into the global ones: each local column merged into its global column,
// whose rows are sorted, in one pass over the ring in increasing vertex order.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_LOCAL_MATRIX_SCATTER_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_LOCAL_MATRIX_SCATTER_H

#include <algorithm>
#include <cstddef>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The ring's positions 0..m-1 in increasing vertex order, the order scatter_local_matrices merges in.
template <typename Index>
void sorted_ring_order(const int* ring, int m, Index* order)
{
  for(int k = 0; k < m; ++k) order[k] = Index(k);
  std::sort(order, order + m, [ring](Index a, Index b) { return ring[a] < ring[b]; });
}

/// Adds N symmetric local matrices, given by their lower triangles (ring x ring), into N value arrays
/// sharing one compressed column pattern (outer, rows) that contains the ring's pairs. Reading one
/// triangle only keeps the results exactly symmetric. Rows of a column are sorted, so each local
/// column is merged into the global one in one pass, in the ring's `order` (sorted_ring_order).
template <int N, typename Local, typename Index>
void scatter_local_matrices(const Local* const (&local)[N], const int* ring, int m, const Index* order,
                            const int* outer, const int* rows, double* const (&values)[N])
{
  for(int s = 0; s < m; ++s)
  {
    const int j = ring[s];
    int p = outer[j];
    for(int k = 0; k < m; ++k)
    {
      const int r = int(order[k]);
      while(rows[p] < ring[r]) ++p;
      for(int i = 0; i < N; ++i) values[i][p] += (r >= s) ? (*local[i])(r, s) : (*local[i])(s, r);
    }
  }
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_LOCAL_MATRIX_SCATTER_H
