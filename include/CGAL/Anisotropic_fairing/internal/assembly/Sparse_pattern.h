// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sparsity of the Loop finite-element matrices: M_ij can be non-zero iff i and j belong to a
// common triangle ring (i.e. j is in the 3-ring of i). The pattern depends on topology only, so it
// is built once and every later assembly only adds into its values.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_SPARSE_PATTERN_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_SPARSE_PATTERN_H

#include <CGAL/Anisotropic_fairing/internal/types/Parallel_blocks.h>
#include <CGAL/Anisotropic_fairing/internal/types/Sparse_structure.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// Returns the n x n symmetric structure whose entries are all pairs of vertices sharing a triangle ring.
/// `Cache` is any element cache (Patch_cache, Linear_element_cache) exposing faces and their rings;
/// `faces`: only the rings of these faces (null: all).
template <typename Cache>
Sparse_structure ring_sparsity_pattern(const Cache& cache, std::size_t n,
                                       const std::vector<std::size_t>* faces = nullptr)
{
  const std::size_t nf = faces ? faces->size() : cache.number_of_faces();
  auto face = [faces](std::size_t i) { return faces ? (*faces)[i] : i; };
  // faces whose ring contains each vertex (CSR)
  std::vector<std::size_t> start(n + 1, 0);
  for(std::size_t i = 0; i < nf; ++i)
    for(int k = 0; k < cache.ring_size(face(i)); ++k) ++start[cache.ring(face(i))[k] + 1];
  for(std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
  std::vector<int> faces_of(start[n]);
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for(std::size_t i = 0; i < nf; ++i)
    for(int k = 0; k < cache.ring_size(face(i)); ++k) faces_of[fill[cache.ring(face(i))[k]]++] = int(face(i));

  // column j: every vertex of every ring that contains j (sorted). Two passes over the columns, in
  // blocks on every core: count each column, then write it at its offset.
  std::vector<int> outer(n + 1, 0), inner;
  auto column = [&](std::size_t j, std::vector<int>& mark, std::vector<int>& rows) {
    rows.clear();
    for(std::size_t p = start[j]; p < start[j + 1]; ++p)
    {
      const int f = faces_of[p];
      for(int k = 0; k < cache.ring_size(std::size_t(f)); ++k)
      {
        const int i = cache.ring(std::size_t(f))[k];
        if(mark[std::size_t(i)] != int(j)) { mark[std::size_t(i)] = int(j); rows.push_back(i); }
      }
    }
  };
  // a few large blocks of columns, each with marks of its own
  auto for_blocks = [n](const auto& body) { parallel_blocks(n, body, n / 8 + 1); };
  for_blocks([&](std::size_t first, std::size_t last) {
    std::vector<int> mark(n, -1), rows;
    for(std::size_t j = first; j < last; ++j) { column(j, mark, rows); outer[j + 1] = int(rows.size()); }
  });
  for(std::size_t j = 0; j < n; ++j) outer[j + 1] += outer[j];
  inner.resize(std::size_t(outer[n]));
  for_blocks([&](std::size_t first, std::size_t last) {
    std::vector<int> mark(n, -1), rows;
    for(std::size_t j = first; j < last; ++j)
    {
      column(j, mark, rows);
      std::sort(rows.begin(), rows.end());
      std::copy(rows.begin(), rows.end(), inner.begin() + outer[j]);
    }
  });
  return Sparse_structure(Eigen::Index(n), std::move(outer), std::move(inner));
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_SPARSE_PATTERN_H
