// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A body over consecutive blocks of rows (vertices, columns), run on every core: the loop the solvers, the
// noise estimate and the sparsity pattern share.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_PARALLEL_BLOCKS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_PARALLEL_BLOCKS_H

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// `body(first, last)` over blocks covering [0, n), each of at most `grain` indices, on every core (TBB)
/// when n is above `serial_up_to` (enough to pay for the threads), else `body(0, n)` here. Blocks never
/// overlap, so a body that writes only its own rows needs no lock; what it computes must not depend on the
/// block boundaries.
template <typename Index, typename Body>
void parallel_blocks(Index n, const Body& body, Index grain = 4096, Index serial_up_to = 20000)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(n > serial_up_to)
  {
    tbb::parallel_for(tbb::blocked_range<Index>(Index(0), n, grain),
                      [&](const tbb::blocked_range<Index>& r) { body(r.begin(), r.end()); });
    return;
  }
#else
  (void)grain;
  (void)serial_up_to;
#endif
  body(Index(0), n);
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_PARALLEL_BLOCKS_H
