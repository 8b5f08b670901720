// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The assembled faces in fixed chunks, and the chunks in colours: two chunks of one colour touch no common
// column of the matrices, so that the chunks of a colour write into M and L at once, the colours one after
// the other. Each entry is then summed in one order, chunk by chunk, whatever the number of threads: the
// same bytes on one core as on sixty-four (the chunks follow from the number of faces alone).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_FACE_CHUNKS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_FACE_CHUNKS_H

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

class Face_chunks
{
public:
  /// faces per chunk: enough work per task (a few milliseconds), and enough chunks in each colour to keep
  /// every core busy (Fandisk0.3, 12,946 faces: 51 chunks in 5 colours; 2,048 faces a chunk made its default
  /// run 13% slower, 256 as fast as one chunk per thread)
  static constexpr std::size_t chunk_faces = 256;

  Face_chunks() = default;
  /// Chunks of `faces` faces; `ring(i, visit)` calls visit(j) for every column j that the i-th face writes
  /// (its ring). Without `colour`, one colour holds every chunk (assemblies that write no matrix).
  template <typename Ring>
  Face_chunks(std::size_t faces, std::size_t columns, const Ring& ring, bool colour = true)
    : faces_(faces), count_((faces + chunk_faces - 1) / chunk_faces)
  {
    if(count_ == 0) count_ = 1;
    std::vector<int> colour_of(count_, 0);
    if(colour && count_ > 1) colour_of = colours(columns, ring);
    const int colours = *std::max_element(colour_of.begin(), colour_of.end()) + 1;
    by_colour_.assign(std::size_t(colours), std::vector<int>());
    for(std::size_t k = 0; k < count_; ++k) by_colour_[std::size_t(colour_of[k])].push_back(int(k));
  }

  std::size_t size() const { return count_; }
  std::size_t begin(std::size_t k) const { return std::min(faces_, k * chunk_faces); }
  std::size_t end(std::size_t k) const { return std::min(faces_, (k + 1) * chunk_faces); }
  /// the chunks of each colour, increasing
  const std::vector<std::vector<int>>& by_colour() const { return by_colour_; }

private:
  // greedy colouring in chunk order: each chunk the least colour that no earlier chunk touching one of its
  // columns has (the faces are in the locality order: a chunk meets few others, and few colours follow)
  template <typename Ring>
  std::vector<int> colours(std::size_t columns, const Ring& ring) const
  {
    std::vector<int> first(columns, -1), several(columns, -1);
    std::vector<std::vector<int>> touching;   // for each column of several chunks, those chunks, increasing
    for(std::size_t k = 0; k < count_; ++k)
      for(std::size_t i = begin(k); i < end(k); ++i)
        ring(i, [&](int j) {
          const std::size_t c = std::size_t(j);
          if(first[c] < 0) { first[c] = int(k); return; }
          if(first[c] == int(k)) return;
          if(several[c] < 0) { several[c] = int(touching.size()); touching.push_back({ first[c] }); }
          std::vector<int>& t = touching[std::size_t(several[c])];
          if(t.back() != int(k)) t.push_back(int(k));
        });
    std::vector<std::vector<int>> earlier(count_);   // the earlier chunks each one shares a column with
    for(const std::vector<int>& t : touching)
      for(std::size_t b = 1; b < t.size(); ++b)
        for(std::size_t a = 0; a < b; ++a) earlier[std::size_t(t[b])].push_back(t[a]);
    std::vector<int> colour(count_, 0);
    std::vector<char> used;
    for(std::size_t k = 0; k < count_; ++k)
    {
      used.assign(earlier[k].size() + 1, 0);
      for(int a : earlier[k])
        if(std::size_t(colour[std::size_t(a)]) < used.size()) used[std::size_t(colour[std::size_t(a)])] = 1;
      colour[k] = int(std::find(used.begin(), used.end(), 0) - used.begin());
    }
    return colour;
  }

  std::size_t faces_ = 0, count_ = 1;
  std::vector<std::vector<int>> by_colour_{ { 0 } };
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_FACE_CHUNKS_H
