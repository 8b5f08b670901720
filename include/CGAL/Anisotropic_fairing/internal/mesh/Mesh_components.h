// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The connected components of the real faces of a mesh. Relative parameters (time step, fidelity,
// feature threshold, prefilter) are measured per component, so that a small part next to a large
// one is faired like the same part alone instead of shrinking to a dot in the first step.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_MESH_COMPONENTS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_MESH_COMPONENTS_H

#include <CGAL/Anisotropic_fairing/internal/mesh/Process_part.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

struct Mesh_components
{
  std::size_t count = 0;
  std::vector<int> of_vertex;   // -1 for a vertex on no face
  std::vector<int> of_face;     // real faces
};

/// Components of the first `real_faces` faces of `topo` over its first `real_vertices` vertices
/// (faces sharing a vertex are connected).
inline Mesh_components make_mesh_components(const Triangle_topology& topo, std::size_t real_vertices,
                                            std::size_t real_faces)
{
  std::vector<int> parent(real_vertices);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while(parent[std::size_t(v)] != v)
    {
      parent[std::size_t(v)] = parent[std::size_t(parent[std::size_t(v)])];
      v = parent[std::size_t(v)];
    }
    return v;
  };
  for(std::size_t f = 0; f < real_faces; ++f)
    for(int k = 1; k < 3; ++k)
    {
      const int a = find(topo.face(f)[0]), b = find(topo.face(f)[k]);
      if(a != b) parent[std::size_t(a)] = b;
    }
  Mesh_components c;
  c.of_vertex.assign(real_vertices, -1);
  c.of_face.resize(real_faces);
  std::vector<int> label(real_vertices, -1);
  for(std::size_t f = 0; f < real_faces; ++f)
  {
    const int root = find(topo.face(f)[0]);
    if(label[std::size_t(root)] < 0) label[std::size_t(root)] = int(c.count++);
    c.of_face[f] = label[std::size_t(root)];
    for(int k = 0; k < 3; ++k) c.of_vertex[std::size_t(topo.face(f)[k])] = c.of_face[f];
  }
  return c;
}

/// The components of the whole mesh a process holds a part of: the part's own (above) named by the lowest global
/// number of a vertex they reach over the processes -- each passes its names to the owners of its vertices and
/// takes theirs, until no name changes -- and numbered by those names, alike on every process.
inline Mesh_components make_mesh_components(const Triangle_topology& topo, std::size_t real_vertices,
                                            std::size_t real_faces, const Part_view& part)
{
  Mesh_components c = make_mesh_components(topo, real_vertices, real_faces);
  if(part.whole()) return c;
  const double none = std::numeric_limits<double>::infinity();
  std::vector<double> name(c.count, none), at(real_vertices, none);
  for(std::size_t v = 0; v < real_vertices; ++v)
    if(c.of_vertex[v] >= 0)
      name[std::size_t(c.of_vertex[v])] = std::min(name[std::size_t(c.of_vertex[v])], double(part.global_vertex(v)));
  for(double changed = 1; changed > 0;)
  {
    for(std::size_t v = 0; v < real_vertices; ++v)
      at[v] = c.of_vertex[v] >= 0 ? name[std::size_t(c.of_vertex[v])] : none;
    part.minimum_at_owners(at);
    part.refresh(at);
    changed = 0;
    for(std::size_t v = 0; v < real_vertices; ++v)
      if(c.of_vertex[v] >= 0 && at[v] < name[std::size_t(c.of_vertex[v])])
      {
        name[std::size_t(c.of_vertex[v])] = at[v];
        changed = 1;
      }
    changed = part.maximum(changed);
  }
  // the names of the components of the processes' own faces: every component has one
  std::vector<double> own;
  for(std::size_t f = 0; f < real_faces; ++f)
    if(part.owns_face(f)) own.push_back(name[std::size_t(c.of_face[f])]);
  std::sort(own.begin(), own.end());
  own.erase(std::unique(own.begin(), own.end()), own.end());
  std::vector<double> names = part.gathered(own);
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  const auto number = [&](int local) {
    return int(std::lower_bound(names.begin(), names.end(), name[std::size_t(local)]) - names.begin());
  };
  for(int& x : c.of_face) x = number(x);
  for(int& x : c.of_vertex)
    if(x >= 0) x = number(x);
  c.count = names.size();
  return c;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_MESH_COMPONENTS_H
