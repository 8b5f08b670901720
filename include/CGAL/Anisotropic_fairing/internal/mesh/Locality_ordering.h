// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A private renumbering of vertices (Cuthill-McKee breadth-first order) and faces (by their first
// vertex in that order) so that the control rings of consecutive faces share memory. Assembly
// scatters into, and the solvers multiply with, a matrix whose pattern is the 3-ring; in the user's
// order (e.g. after subdivision, or of a scan) neighbours can be far apart and every face touches
// cold cache lines. The user's mesh and the order results are written in are unchanged.
// Only real vertices and faces are renumbered; the topology and the ghost layer, built and checked once
// in the user's numbering, are permuted (the ghosts, along the borders, keep their order).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_LOCALITY_ORDERING_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_LOCALITY_ORDERING_H

#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>

#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

struct Locality_ordering
{
  std::vector<int> old_of_new_vertex, new_of_old_vertex;
  std::vector<std::size_t> old_of_new_face;
  Ghost_layer layer;   // the same mesh, and its ghost layer, in the new numbering
};

/// Completes `o`, whose vertex numbering is set: faces by their smallest new vertex index (each keeps its
/// vertex cycle, so its orientation), and the layer renumbered.
inline void order_faces_and_renumber(const Ghost_layer& gl, Locality_ordering& o)
{
  const Triangle_topology& topo = *gl.topology;
  const std::size_t nf = gl.real_faces;
  std::vector<std::pair<int, std::size_t>> key(nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    const Triangle_topology::Face& t = topo.face(f);
    key[f] = { std::min({ o.new_of_old_vertex[std::size_t(t[0])], o.new_of_old_vertex[std::size_t(t[1])],
                          o.new_of_old_vertex[std::size_t(t[2])] }), f };
  }
  std::sort(key.begin(), key.end());
  o.old_of_new_face.resize(nf);
  for(std::size_t k = 0; k < nf; ++k) o.old_of_new_face[k] = key[k].second;
  o.layer = gl.renumbered(o.new_of_old_vertex, o.old_of_new_face);
}

/// Renumbers the real vertices and faces of `gl` (whose real fans are closed).
inline Locality_ordering make_locality_ordering(const Ghost_layer& gl)
{
  const Triangle_topology& topo = *gl.topology;
  const int n = int(gl.real_vertices);
  Locality_ordering o;
  o.new_of_old_vertex.assign(std::size_t(n), -1);
  o.old_of_new_vertex.reserve(std::size_t(n));
  std::vector<int> ring;
  std::vector<int> level_mark(std::size_t(n), -1);
  for(int seed = 0; seed < n; ++seed)
  {
    if(o.new_of_old_vertex[std::size_t(seed)] >= 0 || topo.outgoing(seed) < 0) continue;   // isolated: last
    // a pseudo-peripheral start: the last vertex of a breadth-first sweep from the seed
    int start = seed;
    {
      std::vector<int> queue(1, seed);
      level_mark[std::size_t(seed)] = seed;
      for(std::size_t head = 0; head < queue.size(); ++head)
      {
        const int v = queue[head];
        const int h0 = topo.outgoing(v);
        int h = h0;
        do {
          const int w = topo.target(h);
          if(w < n && level_mark[std::size_t(w)] != seed) { level_mark[std::size_t(w)] = seed; queue.push_back(w); }
          h = topo.ccw(h);
        } while(h != h0);
      }
      start = queue.back();
    }
    // Cuthill-McKee from there: neighbours by increasing valence
    std::size_t head = o.old_of_new_vertex.size();
    o.new_of_old_vertex[std::size_t(start)] = int(o.old_of_new_vertex.size());
    o.old_of_new_vertex.push_back(start);
    for(; head < o.old_of_new_vertex.size(); ++head)
    {
      const int v = o.old_of_new_vertex[head];
      ring.clear();
      const int h0 = topo.outgoing(v);
      int h = h0;
      do {
        const int w = topo.target(h);
        if(w < n && o.new_of_old_vertex[std::size_t(w)] < 0) ring.push_back(w);
        h = topo.ccw(h);
      } while(h != h0);
      std::stable_sort(ring.begin(), ring.end(), [&](int a, int b) { return topo.valence(a) < topo.valence(b); });
      for(int w : ring)
      {
        o.new_of_old_vertex[std::size_t(w)] = int(o.old_of_new_vertex.size());
        o.old_of_new_vertex.push_back(w);
      }
    }
  }
  for(int v : gl.isolated_vertices)
  {
    o.new_of_old_vertex[std::size_t(v)] = int(o.old_of_new_vertex.size());
    o.old_of_new_vertex.push_back(v);
  }
  order_faces_and_renumber(gl, o);
  return o;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_LOCALITY_ORDERING_H
