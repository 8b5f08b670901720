// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The unknowns of a step are the displacements of the free vertices: held vertices are eliminated, so
// every system (a time step, the prefilter) is the free-free block of the assembler's pattern. Its
// structure is built once; each system only fills its values from the pattern's.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_FREE_BLOCK_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_FREE_BLOCK_H

#include <CGAL/Anisotropic_fairing/internal/assembly/Sparse_pattern.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <Eigen/SparseCore>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

struct Free_block
{
  std::vector<int> free;           // the free rows, increasing
  std::vector<int> free_index;     // of each row among them (-1: held)
  std::vector<int> source;         // the pattern entry of each entry of `matrix`
  std::vector<int> entry_column;   // the free column of each entry of `matrix`
  Eigen::SparseMatrix<double> matrix;   // free x free, the structure of the block (values: zero)

  /// `pattern`: n x n, symmetric; `constrained[i]` holds row i.
  Free_block(const Eigen::SparseMatrix<double>& pattern, const std::vector<bool>& constrained)
    : free_index(constrained.size(), -1)
  {
    for(std::size_t i = 0; i < constrained.size(); ++i)
      if(!constrained[i]) { free_index[i] = int(free.size()); free.push_back(int(i)); }
    std::vector<int> outer(1, 0), inner;
    inner.reserve(std::size_t(pattern.nonZeros()));
    source.reserve(std::size_t(pattern.nonZeros()));
    entry_column.reserve(std::size_t(pattern.nonZeros()));
    for(std::size_t k = 0; k < free.size(); ++k)
    {
      for(int p = pattern.outerIndexPtr()[free[k]]; p < pattern.outerIndexPtr()[free[k] + 1]; ++p)
      {
        const int r = free_index[std::size_t(pattern.innerIndexPtr()[p])];
        if(r >= 0) { inner.push_back(r); source.push_back(p); entry_column.push_back(int(k)); }   // rows stay sorted: free is increasing
      }
      outer.push_back(int(inner.size()));
    }
    matrix = sparse_matrix_from_pattern(Eigen::Index(free.size()), Eigen::Index(free.size()), outer, inner);
  }

  std::size_t size() const { return free.size(); }

  /// B = the free rows of R
  void gather(const Control_matrix& R, Control_matrix& B) const
  {
    for(Eigen::Index i = 0; i < B.rows(); ++i) B.row(i) = R.row(free[std::size_t(i)]);
  }
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_FREE_BLOCK_H
