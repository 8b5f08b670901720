// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The unknowns of a step are the displacements of the free vertices: held vertices are eliminated, so
// every system (a time step, the prefilter) is the free-free block of the assembler's pattern. Its
// structure is built once (none when no row is held); each system only fills its values from the pattern's.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_FREE_BLOCK_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_FREE_BLOCK_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Sparse_structure.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

class Free_block
{
public:
  std::vector<int> free;           // the free rows, increasing
  std::vector<int> free_index;     // of each row among them (-1: held)

  /// `pattern`: n x n, symmetric, outliving the block; `constrained[i]` holds row i.
  Free_block(const Sparse_structure& pattern, const std::vector<bool>& constrained)
    : free_index(constrained.size(), -1), pattern_(&pattern)
  {
    for(std::size_t i = 0; i < constrained.size(); ++i)
      if(!constrained[i]) { free_index[i] = int(free.size()); free.push_back(int(i)); }
    whole_ = free.size() == constrained.size();
    if(whole_) return;
    std::vector<int> outer(1, 0), inner;
    for(std::size_t k = 0; k < free.size(); ++k)
    {
      for(int p = pattern.outerIndexPtr()[free[k]]; p < pattern.outerIndexPtr()[free[k] + 1]; ++p)
      {
        const int r = free_index[std::size_t(pattern.innerIndexPtr()[p])];
        if(r >= 0) { inner.push_back(r); source_.push_back(p); }   // rows stay sorted: free is increasing
      }
      outer.push_back(int(inner.size()));
    }
    own_ = Sparse_structure(Eigen::Index(free.size()), std::move(outer), std::move(inner));
    source_.shrink_to_fit();
  }
  Free_block(const Free_block&) = delete;
  Free_block& operator=(const Free_block&) = delete;

  std::size_t size() const { return free.size(); }
  /// No row is held: the block is the whole pattern.
  bool whole() const { return whole_; }
  /// free x free: what a system over the unknowns is stored on (the pattern itself when no row is held)
  const Sparse_structure& structure() const { return whole_ ? *pattern_ : own_; }
  /// the pattern's entry of the block's entry e
  std::size_t source(std::size_t e) const { return whole_ ? e : std::size_t(source_[e]); }

  /// B = the free rows of R
  void gather(const Control_matrix& R, Control_matrix& B) const
  {
    B.resize(Eigen::Index(free.size()), R.cols());
    for(Eigen::Index i = 0; i < B.rows(); ++i) B.row(i) = R.row(free[std::size_t(i)]);
  }

private:
  const Sparse_structure* pattern_;
  Sparse_structure own_;
  std::vector<int> source_;   // (none when whole_)
  bool whole_ = false;        // no row is held: the block is the pattern
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_FREE_BLOCK_H
