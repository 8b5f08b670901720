// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The ghost layer that closes the fans of boundary vertices, so that every real triangle of a mesh
// with borders is an ordinary Loop patch (Bajaj & Xu 2003, section 4.3, completed as in
// doc/Anisotropic_fairing/design/loop-fem.md section 6). It lives in a private index space: ghosts are numbered after
// the real
// vertices and are affine combinations of them (x_ghost = sum_j w_j x_j, sum w_j = 1), so they move
// with the surface and X_ext = E X. The user's mesh is never touched.
//
// For a boundary vertex v with real fan (v,r0,r1), ..., (v,r_{m-1},r_m) (boundary edges v->r0, r_m->v):
//  - each boundary edge p->q of a real triangle (p,q,r) gets the edge ghost g = p + q - r and the ghost
//    triangle (q,p,g), shared by both endpoints;
//  - the fan is closed by c = max(1, 4 - m) triangles (v,g_m,h_1), ..., (v,h_{c-1},g_0) with vertex
//    ghosts h_j = 2v - r_{m-2+j} (point reflections through v).
// v then has valence m + 2 + c (6 for m <= 3), and on a regular lattice every ghost is a lattice point.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_GHOST_LAYER_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_GHOST_LAYER_H

#include <CGAL/Anisotropic_fairing/Input_error.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// An affine combination of real vertices.
typedef std::vector<std::pair<int, double>> Affine_row;

struct Ghost_layer
{
  std::size_t real_vertices = 0, real_faces = 0;
  std::vector<Affine_row> ghosts;            // ghost k is extended vertex real_vertices + k
  std::vector<int> boundary_vertices;        // real vertices on a border, increasing
  std::size_t boundary_loops = 0;
  std::vector<int> isolated_vertices;        // real vertices without a face (when allowed), increasing
  std::unique_ptr<Triangle_topology> topology;  // real faces first (same indices), then ghost faces

  std::size_t number_of_extended_vertices() const { return real_vertices + ghosts.size(); }
  /// X_ext = E X: the rows of the real vertices (any number of columns), then those of the ghosts.
  template <typename Matrix>
  Matrix extend(const Matrix& X) const
  {
    Matrix E(Eigen::Index(number_of_extended_vertices()), X.cols());
    E.topRows(X.rows()) = X;
    for(std::size_t k = 0; k < ghosts.size(); ++k)
    {
      auto row = E.row(Eigen::Index(real_vertices + k));
      row.setZero();
      for(const auto& w : ghosts[k]) row += w.second * X.row(w.first);
    }
    return E;
  }
  bool has_boundary() const { return !ghosts.empty(); }

  /// The same mesh and ghost layer with real vertex v renamed new_of_old_vertex[v] and real face
  /// old_of_new_face[f] moved to position f; the ghosts and their faces keep their places after them.
  Ghost_layer renumbered(const std::vector<int>& new_of_old_vertex,
                         const std::vector<std::size_t>& old_of_new_face) const
  {
    Ghost_layer gl;
    gl.real_vertices = real_vertices;
    gl.real_faces = real_faces;
    gl.boundary_loops = boundary_loops;
    std::vector<int> vertex_map(new_of_old_vertex);
    for(std::size_t k = 0; k < ghosts.size(); ++k) vertex_map.push_back(int(real_vertices + k));
    std::vector<std::size_t> face_order(old_of_new_face);
    for(std::size_t f = real_faces; f < topology->number_of_faces(); ++f) face_order.push_back(f);
    gl.topology.reset(new Triangle_topology(topology->renumbered(vertex_map, face_order)));
    gl.ghosts = ghosts;
    for(Affine_row& row : gl.ghosts)
      for(auto& w : row) w.first = new_of_old_vertex[std::size_t(w.first)];
    auto renamed = [&](const std::vector<int>& vertices) {
      std::vector<int> r;
      for(int v : vertices) r.push_back(new_of_old_vertex[std::size_t(v)]);
      std::sort(r.begin(), r.end());
      return r;
    };
    gl.boundary_vertices = renamed(boundary_vertices);
    gl.isolated_vertices = renamed(isolated_vertices);
    return gl;
  }
};

/// Throws Input_error for the first face with a vertex index outside [0, n), before anything
/// indexes by it.
inline void check_vertex_indices(std::size_t n, const std::vector<Triangle_topology::Face>& faces)
{
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(int k = 0; k < 3; ++k)
      if(faces[f][k] < 0 || std::size_t(faces[f][k]) >= n)
        throw Input_error(Input_error::INVALID_PARAMETER, f,
                          "face " + std::to_string(f) + " has a vertex index out of range");
}

/// Appends to gl.isolated_vertices, increasing, the real vertices without a face in gl.topology.
inline void collect_isolated_vertices(Ghost_layer& gl, std::size_t n)
{
  for(std::size_t v = 0; v < n; ++v)
    if(gl.topology->outgoing(int(v)) < 0) gl.isolated_vertices.push_back(int(v));
}

/// Builds the ghosts of a mesh with borders, one boundary fan at a time: the ghost rows (in
/// gl.ghosts), the extended face list (the real faces, then the ghost faces) and each border
/// edge's ghost, which the fans of both its endpoints share and so is made only once.
struct Ghost_fan_closer
{
  Ghost_layer& gl;
  std::size_t n;
  std::vector<Triangle_topology::Face> ext;
  std::unordered_map<std::uint64_t, int> edge_ghost;   // boundary edge p->q -> ghost index

  Ghost_fan_closer(Ghost_layer& layer, std::size_t real_vertices, const std::vector<Triangle_topology::Face>& faces)
    : gl(layer), n(real_vertices), ext(faces) {}

  /// Appends a ghost and returns its extended vertex index.
  int add_ghost(Affine_row row)
  {
    gl.ghosts.push_back(std::move(row));
    return int(n + gl.ghosts.size() - 1);
  }

  /// The edge ghost of border edge p->q in real triangle (p,q,r), made with its triangle (q,p,g)
  /// on first use.
  int ghost_of_edge(int p, int q, int r)
  {
    auto it = edge_ghost.find(Triangle_topology::key(p, q));
    if(it != edge_ghost.end()) return it->second;
    const int g = add_ghost({ { p, 1.0 }, { q, 1.0 }, { r, -1.0 } });
    edge_ghost.emplace(Triangle_topology::key(p, q), g);
    ext.push_back({ { q, p, g } });
    return g;
  }

  /// Closes the fan of p for its border edge h = p->q (see the top of this file): the edge ghosts
  /// g_0, g_m of both border edges, the c - 1 vertex ghosts and the c triangles between them.
  void close_fan(const Triangle_topology& real, int h, std::size_t number_of_faces)
  {
    // walk the fan of p counter-clockwise from p->r0 (= p->q) to the border edge r_m->p
    const int p = real.source(h);
    std::vector<int> r(1, real.target(h));
    int g = h;
    for(std::size_t guard = 0; guard <= number_of_faces; ++guard)
    {
      r.push_back(real.target(real.next(g)));          // g's face is (p, r_last, next)
      const int back = real.opposite(real.prev(g));    // next->p, seen from the other side
      if(back < 0) break;                              // r_m -> p is a border edge
      g = back;
    }
    const int m = int(r.size()) - 1;
    const int g0 = ghost_of_edge(p, r[0], r[1]);
    const int gm = ghost_of_edge(r[std::size_t(m)], p, r[std::size_t(m - 1)]);
    const int c = m >= 3 ? 1 : 4 - m;
    std::vector<int> fan(1, gm);
    for(int j = 1; j <= c - 1; ++j) fan.push_back(add_ghost({ { p, 2.0 }, { r[std::size_t(m - 2 + j)], -1.0 } }));
    fan.push_back(g0);
    for(std::size_t j = 0; j + 1 < fan.size(); ++j) ext.push_back({ { p, fan[j], fan[j + 1] } });
  }
};

/// Counts gl.boundary_loops by following, from each boundary vertex not yet seen, the outgoing
/// border edges p -> q (the keys of edge_ghost) until the loop closes; the topology has checked
/// that each boundary vertex has one fan, hence one outgoing border edge.
inline void count_boundary_loops(Ghost_layer& gl, std::size_t n,
                                 const std::unordered_map<std::uint64_t, int>& edge_ghost)
{
  std::vector<int> border_next(n, -1);
  for(const auto& e : edge_ghost) border_next[std::size_t(e.first >> 32)] = int(e.first & 0xffffffffu);
  std::vector<char> seen(n, 0);
  for(int v : gl.boundary_vertices)
  {
    if(seen[std::size_t(v)]) continue;
    ++gl.boundary_loops;
    for(int w = v; w >= 0 && !seen[std::size_t(w)]; w = border_next[std::size_t(w)]) seen[std::size_t(w)] = 1;
  }
}

/// Builds the ghost layer of the triangle mesh (n vertices, faces). Throws Input_error for what the
/// closed topology refuses too (non-manifold edges and vertices, including bow-tie boundary
/// vertices, degenerate faces, interior valence < 3, and isolated vertices unless `allow_isolated`).
inline Ghost_layer make_ghost_layer(std::size_t n, const std::vector<Triangle_topology::Face>& faces,
                                    bool allow_isolated = false)
{
  Ghost_layer gl;
  gl.real_vertices = n;
  gl.real_faces = faces.size();
  check_vertex_indices(n, faces);
  // the real mesh, its halfedges linked (degenerate faces and non-manifold edges refused), borders allowed
  std::unique_ptr<Triangle_topology> real(new Triangle_topology(n, faces, 0, allow_isolated));
  bool closed = true;
  for(int h = 0; h < int(3 * faces.size()) && closed; ++h) closed = real->opposite(h) >= 0;
  if(closed)
  {
    real->require_closed_fans();
    gl.topology = std::move(real);
    collect_isolated_vertices(gl, n);
    return gl;
  }

  Ghost_fan_closer closer(gl, n, faces);
  std::vector<char> on_boundary(n, 0);
  for(int h = 0; h < int(3 * faces.size()); ++h)
  {
    if(real->opposite(h) >= 0) continue;
    on_boundary[std::size_t(real->source(h))] = 1;   // h is a border edge
    closer.close_fan(*real, h, faces.size());
  }
  for(std::size_t v = 0; v < n; ++v)
    if(on_boundary[v]) gl.boundary_vertices.push_back(int(v));
  gl.topology.reset(new Triangle_topology(gl.number_of_extended_vertices(), std::move(closer.ext), n, allow_isolated));
  collect_isolated_vertices(gl, n);
  count_boundary_loops(gl, n, closer.edge_ghost);
  return gl;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_GHOST_LAYER_H
