// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sparsity of the Loop finite-element matrices: M_ij can be non-zero iff i and j belong to a
// common triangle ring (i.e. j is in the 3-ring of i). The pattern depends on topology only, so it
// is built once and every later assembly only adds into its values.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_SPARSE_PATTERN_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_SPARSE_PATTERN_H


#include <Eigen/SparseCore>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// Returns an n x n compressed, symmetric matrix whose structural non-zeros are all pairs of
/// vertices sharing a triangle ring, with zero values.
/// A compressed column-major matrix with the given structure and zero values.
inline Eigen::SparseMatrix<double> sparse_matrix_from_pattern(Eigen::Index rows, Eigen::Index cols,
                                                             const std::vector<int>& outer, const std::vector<int>& inner)
{
  std::vector<double> zeros(inner.size(), 0.0);
  const Eigen::Map<const Eigen::SparseMatrix<double>> view(rows, cols, Eigen::Index(inner.size()), outer.data(),
                                                          inner.data(), zeros.data());
  return Eigen::SparseMatrix<double>(view);
}

/// `Cache` is any element cache (Patch_cache, Linear_element_cache) exposing faces and their rings.
template <typename Cache>
Eigen::SparseMatrix<double> ring_sparsity_pattern(const Cache& cache, std::size_t n)
{
  // faces whose ring contains each vertex (CSR)
  std::vector<std::size_t> start(n + 1, 0);
  for(std::size_t f = 0; f < cache.number_of_faces(); ++f)
    for(int k = 0; k < cache.ring_size(f); ++k) ++start[cache.ring(f)[k] + 1];
  for(std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
  std::vector<int> faces_of(start[n]);
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for(std::size_t f = 0; f < cache.number_of_faces(); ++f)
    for(int k = 0; k < cache.ring_size(f); ++k) faces_of[fill[cache.ring(f)[k]]++] = int(f);

  // column j: every vertex of every ring that contains j (sorted), written straight into CSC arrays
  std::vector<int> outer(n + 1, 0), inner, mark(n, -1);
  inner.reserve(n * 40);
  for(std::size_t j = 0; j < n; ++j)
  {
    const std::size_t begin = inner.size();
    for(std::size_t p = start[j]; p < start[j + 1]; ++p)
    {
      const int f = faces_of[p];
      for(int k = 0; k < cache.ring_size(std::size_t(f)); ++k)
      {
        const int i = cache.ring(std::size_t(f))[k];
        if(mark[std::size_t(i)] != int(j)) { mark[std::size_t(i)] = int(j); inner.push_back(i); }
      }
    }
    std::sort(inner.begin() + std::ptrdiff_t(begin), inner.end());
    outer[j + 1] = int(inner.size());
  }
  return sparse_matrix_from_pattern(Eigen::Index(n), Eigen::Index(n), outer, inner);
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_SPARSE_PATTERN_H
