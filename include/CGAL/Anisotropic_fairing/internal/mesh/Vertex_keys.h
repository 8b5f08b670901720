// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A key per vertex that no numbering changes, for the numbers drawn per vertex (types/Keyed_normal.h): a real
// vertex's is made of its input position, a ghost's (Ghost_layer.h) of the keys and weights of the real vertices
// it combines. Two vertices at the same place share a key, and so their numbers: harmless for what they are
// drawn for (the noise estimate's reference noise, the risk estimate's probe).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_VERTEX_KEYS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_VERTEX_KEYS_H

#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/types/Keyed_normal.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The keys of the vertices of `layer`'s topology (the real ones, then the ghosts); row i of `X`: real vertex i's
/// input position (its first three columns).
template <typename Matrix>
std::vector<std::uint64_t> vertex_keys(const Ghost_layer& layer, const Matrix& X)
{
  const std::size_t n = layer.real_vertices;
  std::vector<std::uint64_t> keys(layer.number_of_extended_vertices());
  for(std::size_t i = 0; i < n; ++i)
  {
    std::uint64_t k = 0;
    for(int a = 0; a < 3; ++a) k = mix_bits(k ^ value_bits(X(Eigen::Index(i), a)));
    keys[i] = k;
  }
  std::vector<std::pair<std::uint64_t, std::uint64_t>> terms;
  for(std::size_t g = 0; g < layer.ghosts.size(); ++g)
  {
    terms.clear();
    for(const auto& w : layer.ghosts[g]) terms.emplace_back(keys[std::size_t(w.first)], value_bits(w.second));
    std::sort(terms.begin(), terms.end());
    std::uint64_t k = 0x6A09E667F3BCC909ull;   // not a real vertex's: a ghost's key starts elsewhere
    for(const auto& t : terms) k = mix_bits(mix_bits(k ^ t.first) ^ t.second);
    keys[n + g] = k;
  }
  return keys;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_VERTEX_KEYS_H
