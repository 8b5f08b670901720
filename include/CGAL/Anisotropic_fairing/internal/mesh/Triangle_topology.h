// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A compact, index-based halfedge view of a closed, manifold triangle mesh. Every later stage
// (patch categories, assembly) works on indices only, so it does not depend on the FaceGraph
// model, and a ghost layer can later extend it without touching the user's mesh.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_TRIANGLE_TOPOLOGY_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_TRIANGLE_TOPOLOGY_H

#include <CGAL/Anisotropic_fairing/Input_error.h>
#include <CGAL/Anisotropic_fairing/internal/types/Parallel_blocks.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// Halfedge h = 3f + c goes from faces[f][c] to faces[f][(c+1)%3].
class Triangle_topology
{
public:
  typedef std::array<int, 3> Face;

  /// Builds and validates the topology. Throws `Input_error` naming the first offending element.
  /// Vertices with index >= `closed_vertices` (ghosts of a boundary layer) may lie on the border and
  /// have any valence; all others must have one closed fan of valence >= 3. With `allow_isolated`, a
  /// vertex without any face is accepted (valence 0, `outgoing()` is -1) instead of refused.
  Triangle_topology(std::size_t number_of_vertices, std::vector<Face> faces,
                    std::size_t closed_vertices = (std::numeric_limits<std::size_t>::max)(),
                    bool allow_isolated = false)
    : faces_(std::move(faces)), n_vertices_(number_of_vertices),
      closed_vertices_((std::min)(closed_vertices, number_of_vertices)), allow_isolated_(allow_isolated)
  {
    if(faces_.empty())
      throw Input_error(Input_error::EMPTY_MESH, Input_error::no_element, "the mesh has no face");
    build();
  }

  std::size_t number_of_vertices() const { return n_vertices_; }
  std::size_t number_of_faces() const { return faces_.size(); }
  const Face& face(std::size_t f) const { return faces_[f]; }
  const std::vector<Face>& faces() const { return faces_; }

  int source(int h) const { return faces_[h / 3][h % 3]; }
  int target(int h) const { return faces_[h / 3][(h % 3 + 1) % 3]; }
  int next(int h) const { return 3 * (h / 3) + (h % 3 + 1) % 3; }
  int prev(int h) const { return 3 * (h / 3) + (h % 3 + 2) % 3; }
  int opposite(int h) const { return opposite_[h]; }
  int face_of(int h) const { return h / 3; }
  /// Next outgoing halfedge counter-clockwise around source(h).
  int ccw(int h) const { return opposite_[prev(h)]; }
  /// One outgoing halfedge of vertex v.
  int outgoing(int v) const { return out_[v]; }
  int valence(int v) const { return valence_[v]; }

  /// Validates the fans of all vertices, as if built with `closed_vertices` = all (the mesh must have
  /// no border edge): saves linking the halfedges twice when a mesh turns out to be closed.
  void require_closed_fans()
  {
    closed_vertices_ = n_vertices_;
    check_fans();
  }

  /// Neighbours of v in counter-clockwise order, starting at target(h0) (h0 outgoing from v).
  template <class Output>
  void neighbours_ccw(int h0, Output out) const
  {
    int h = h0;
    do { *out++ = target(h); h = ccw(h); } while(h != h0);
  }

  /// The same topology with vertex v renamed new_of_old_vertex[v] and face old_of_new_face[f] moved to
  /// position f (each face keeps its vertex cycle): a permutation, no new linking or validation.
  Triangle_topology renumbered(const std::vector<int>& new_of_old_vertex,
                               const std::vector<std::size_t>& old_of_new_face) const
  {
    Triangle_topology t(*this);
    std::vector<int> new_of_old_face(faces_.size());
    for(std::size_t f = 0; f < faces_.size(); ++f) new_of_old_face[old_of_new_face[f]] = int(f);
    auto halfedge = [&](int h) { return h < 0 ? h : 3 * new_of_old_face[std::size_t(h / 3)] + h % 3; };
    for(std::size_t f = 0; f < faces_.size(); ++f)
      for(int c = 0; c < 3; ++c)
      {
        t.faces_[f][c] = new_of_old_vertex[std::size_t(faces_[old_of_new_face[f]][c])];
        t.opposite_[3 * f + std::size_t(c)] = halfedge(opposite_[3 * old_of_new_face[f] + std::size_t(c)]);
      }
    for(std::size_t v = 0; v < n_vertices_; ++v)
    {
      const std::size_t w = std::size_t(new_of_old_vertex[v]);
      t.out_[w] = halfedge(out_[v]);
      t.valence_[w] = valence_[v];
      t.outgoing_count_[w] = outgoing_count_[v];
    }
    return t;
  }

  /// a key of the directed edge (a, b), for hashing
  static std::uint64_t key(int a, int b)
  {
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
  }

private:

  void build()
  {
    const std::size_t nh = 3 * faces_.size();
    opposite_.assign(nh, -1);
    out_.assign(n_vertices_, -1);
    std::vector<int> outgoing_count(n_vertices_, 0);

    for(std::size_t f = 0; f < faces_.size(); ++f)
    {
      const Face& t = faces_[f];
      if(t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
        throw Input_error(Input_error::DEGENERATE_FACE, f,
                          "face " + std::to_string(f) + " uses vertex " +
                          std::to_string(t[0] == t[1] || t[0] == t[2] ? t[0] : t[1]) + " twice");
    }

    // each vertex's outgoing halfedges, in increasing order (CSR): a directed edge (s, t) is looked up
    // among the few of s
    for(std::size_t h = 0; h < nh; ++h) ++outgoing_count[std::size_t(source(int(h)))];
    std::vector<std::size_t> first(n_vertices_ + 1, 0);
    for(std::size_t v = 0; v < n_vertices_; ++v) first[v + 1] = first[v] + std::size_t(outgoing_count[v]);
    std::vector<int> outgoing(nh);
    {
      std::vector<std::size_t> fill(first.begin(), first.end() - 1);
      for(int h = 0; h < int(nh); ++h) outgoing[fill[std::size_t(source(h))]++] = h;
    }
    const auto find = [&](int s, int t, int before) {   // the first halfedge s -> t below `before`, or -1
      for(std::size_t k = first[std::size_t(s)]; k < first[std::size_t(s) + 1] && outgoing[k] < before; ++k)
        if(target(outgoing[k]) == t) return outgoing[k];
      return -1;
    };
    for(int h = 0; h < int(nh); ++h)
    {
      const int s = source(h), t = target(h);
      if(find(s, t, h) >= 0)
        throw Input_error(Input_error::NON_MANIFOLD_EDGE, std::size_t(s),
                          "the edge between vertices " + std::to_string(s) + " and " + std::to_string(t) +
                          " is used by more than two faces, twice in the same direction, or twice");
      out_[s] = h;
    }
    // each halfedge's opposite on every core; the error names the first border edge, as a serial loop would
    const std::size_t bucket = 4096, buckets = nh / bucket + 1;   // fixed buckets: one writer per entry of first_border
    std::vector<int> first_border(buckets, int(nh));
    parallel_blocks(buckets, [&](std::size_t first, std::size_t last) {
      for(std::size_t k = first; k < last; ++k)
        for(int h = int(k * bucket); h < int(std::min(nh, (k + 1) * bucket)); ++h)
        {
          const int o = find(target(h), source(h), int(nh));
          if(o < 0 && !is_closed(source(h)) && !is_closed(target(h))) continue;   // ghost border
          if(o < 0) first_border[k] = std::min(first_border[k], h);
          else opposite_[h] = o;
        }
    }, std::size_t(1), std::size_t(1));
    const int border = *std::min_element(first_border.begin(), first_border.end());
    if(border < int(nh))
      throw Input_error(Input_error::BORDER_EDGE, std::size_t(source(border)),
                        "the edge between vertices " + std::to_string(source(border)) + " and " +
                        std::to_string(target(border)) + " is a border edge; this operation needs a closed mesh");

    outgoing_count_ = std::move(outgoing_count);
    check_fans();
  }

  // one fan of valence >= 3 per closed vertex; the others keep their number of outgoing halfedges
  void check_fans()
  {
    const std::vector<int>& outgoing_count = outgoing_count_;
    valence_.assign(n_vertices_, 0);
    for(std::size_t v = 0; v < n_vertices_; ++v)
    {
      if(out_[v] < 0 && allow_isolated_) continue;
      if(out_[v] < 0)
        throw Input_error(Input_error::ISOLATED_VERTEX, v,
                          "vertex " + std::to_string(v) + " has no incident face");
      if(!is_closed(int(v))) { valence_[v] = outgoing_count[v]; continue; }
      int n = 0, h = out_[v];
      do { ++n; h = ccw(h); } while(h != out_[v] && n <= outgoing_count[v]);
      if(n != outgoing_count[v])
        throw Input_error(Input_error::NON_MANIFOLD_VERTEX, v,
                          "vertex " + std::to_string(v) + " is non-manifold (its faces form more than one fan)");
      if(n < 3)
        throw Input_error(Input_error::LOW_VALENCE_VERTEX, v,
                          "vertex " + std::to_string(v) + " has valence " + std::to_string(n) +
                          "; Loop subdivision needs valence 3 or more");
      valence_[v] = n;
    }
  }

  bool is_closed(int v) const { return std::size_t(v) < closed_vertices_; }

  std::vector<Face> faces_;
  std::size_t n_vertices_;
  std::size_t closed_vertices_;
  bool allow_isolated_;
  std::vector<int> opposite_;
  std::vector<int> out_;
  std::vector<int> valence_;
  std::vector<int> outgoing_count_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_TRIANGLE_TOPOLOGY_H
