// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A k-times 1-to-4 refined triangulation of the control mesh whose vertices are points of the
// limit surface (and limit values of any attribute) at the dyadic parameters i/2^k. Same
// connectivity as k steps of Loop subdivision; vertices are exact limit points, not level-k controls.
// Only the faces of the patch cache are refined: with a ghost layer these are the real faces, so the
// output keeps the user's borders (a border edge has one face, hence its points are written once).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_SURFACE_LIMIT_RESAMPLER_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_SURFACE_LIMIT_RESAMPLER_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Vector3.h>
#include <CGAL/Anisotropic_fairing/internal/element/Patch_cache.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Vertex_limit_masks.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

struct Resampled_surface
{
  Control_matrix positions;            // one row per output vertex (3 columns)
  Control_matrix normals;              // unit normals of the limit surface
  Control_matrix attributes;           // limit values of the attribute columns (may be empty)
  std::vector<std::size_t> prototype;  // a control vertex near each output vertex (for attribute types)
  std::vector<std::array<std::size_t, 3>> faces;
  // Where each output vertex lies: a control face and its (xi1, xi2).
  std::vector<std::size_t> face;
  std::vector<std::array<double, 2>> parameter;
};

/// Numbering of the output vertices of the refined faces: lattice point (i, j), 0 <= i + j <= N, of face f.
struct Resampling_lattice
{
  const Triangle_topology& topo;
  int N;                               // 2^levels: lattice points per edge of a control face, minus one
  std::vector<std::size_t> edge_id;    // per halfedge owning its edge: the number of that edge
  std::size_t per_edge = 0, per_face = 0, edge_base = 0, face_base = 0, n_out = 0;

  // Numbers each edge once (owned by its smaller halfedge) so that neighbouring faces share edge points.
  Resampling_lattice(const Triangle_topology& topo_, std::size_t nv, std::size_t nf, int N_)
    : topo(topo_), N(N_), edge_id(3 * nf, std::size_t(-1))
  {
    // ghost faces come after the refined ones, so a border edge is owned by its only refined face
    std::size_t ne = 0;
    for(int h = 0; h < int(3 * nf); ++h)
      if(h < topo.opposite(h)) edge_id[h] = ne++;
    per_edge = std::size_t(N - 1);
    per_face = std::size_t(N - 1) * std::size_t(N - 2) / 2;
    edge_base = nv;
    face_base = nv + ne * per_edge;
    n_out = face_base + nf * per_face;
  }

  // Whether (i, j) is a corner of the face: those points are the control vertices, written separately.
  bool is_corner(int i, int j) const { return (i == 0 && j == 0) || (i == N && j == 0) || (i == 0 && j == N); }

  // Position of (i, j) in a per-category table of lattice stencils, so that faces can share the table.
  std::size_t stencil_index(int i, int j) const { return std::size_t(j) * (N + 1) + i; }

  // Output vertex of lattice point (i, j) of face f: control vertex, shared edge point or interior point.
  std::size_t output_vertex(std::size_t f, int i, int j) const
  {
    const auto& t = topo.face(f);
    if(i == 0 && j == 0) return std::size_t(t[0]);
    if(i == N && j == 0) return std::size_t(t[1]);
    if(i == 0 && j == N) return std::size_t(t[2]);
    int h = -1, step = 0;
    if(j == 0)          { h = int(3 * f);     step = i; }
    else if(i + j == N) { h = int(3 * f) + 1; step = j; }
    else if(i == 0)     { h = int(3 * f) + 2; step = N - j; }
    if(h >= 0)
    {
      if(h < topo.opposite(h)) return edge_base + edge_id[h] * per_edge + std::size_t(step - 1);
      return edge_base + edge_id[topo.opposite(h)] * per_edge + std::size_t(N - step - 1);
    }
    // interior: rows j = 1..N-2, i = 1..N-1-j
    const std::size_t before = std::size_t(j - 1) * std::size_t(2 * N - 2 - j) / 2;   // sum_{r<j} (N-1-r)
    return face_base + f * per_face + before + std::size_t(i - 1);
  }

  // Whether face f evaluates (i, j): its interior points and its owned edges' points, so each is written once.
  bool owns(std::size_t f, int i, int j) const
  {
    if(j == 0)          return int(3 * f) < topo.opposite(int(3 * f));
    if(i + j == N)      return int(3 * f) + 1 < topo.opposite(int(3 * f) + 1);
    if(i == 0)          return int(3 * f) + 2 < topo.opposite(int(3 * f) + 2);
    return true;
  }
};

// Lattice stencils of each category's root patch, computed on first use: all faces of a category share them.
class Lattice_stencil_cache
{
public:
  Lattice_stencil_cache(const Patch_cache& cache, const Resampling_lattice& lattice)
    : cache_(cache), lattice_(lattice) {}

  // The stencils of category c by Resampling_lattice::stencil_index; corners stay empty (not evaluated there).
  const std::vector<Stencil>& of_category(int c)
  {
    auto it = by_category_.find(c);
    if(it != by_category_.end()) return it->second;
    std::vector<Stencil>& s = by_category_[c];
    const Loop_local_patch root = cache_.root_patch(c);
    const int N = lattice_.N;
    s.resize(std::size_t(N + 1) * std::size_t(N + 1));
    for(int j = 0; j <= N; ++j)
      for(int i = 0; i + j <= N; ++i)
        if(!lattice_.is_corner(i, j))
          root.stencil(double(i) / N, double(j) / N, s[lattice_.stencil_index(i, j)]);
    return s;
  }

private:
  const Patch_cache& cache_;
  const Resampling_lattice& lattice_;
  std::map<int, std::vector<Stencil>> by_category_;
};

// Control vertices: limit values by closed-form masks (exact, no patch evaluation), each at a corner of a refined face.
inline void resample_control_vertices(const Triangle_topology& topo, std::size_t nv, std::size_t nf,
                                      const Control_matrix& X, const Control_matrix* A, Resampled_surface& out)
{
  for(std::size_t v = 0; v < nv; ++v)
  {
    vertex_limit_value(topo, X, int(v), out.positions.row(Eigen::Index(v)).data());
    double n[3];
    vertex_limit_normal(topo, X, int(v), n);
    for(int c = 0; c < 3; ++c) out.normals(Eigen::Index(v), c) = n[c];
    if(A) vertex_limit_value(topo, *A, int(v), out.attributes.row(Eigen::Index(v)).data());
    out.prototype[v] = v;
    int h = topo.outgoing(int(v));
    if(h < 0)   // a vertex on no face: kept, isolated, in the output too
    {
      out.face[v] = std::size_t(-1);
      out.parameter[v] = { 0.0, 0.0 };
      continue;
    }
    while(std::size_t(topo.face_of(h)) >= nf) h = topo.ccw(h);   // a refined face (not a ghost one) at v
    const int f = topo.face_of(h);
    const auto& t = topo.face(std::size_t(f));
    const int corner = (t[0] == int(v)) ? 0 : (t[1] == int(v)) ? 1 : 2;
    out.face[v] = std::size_t(f);
    out.parameter[v] = { corner == 1 ? 1.0 : 0.0, corner == 2 ? 1.0 : 0.0 };
  }
}

// Writes output vertex o's limit point, unit normal and attributes by applying stencil s to the face's control ring.
inline void evaluate_lattice_point(const Stencil& s, const int* ring, const Control_matrix& X, const Control_matrix* A,
                                   std::size_t o, Resampled_surface& out)
{
  double p[3] = { 0, 0, 0 }, t1[3] = { 0, 0, 0 }, t2[3] = { 0, 0, 0 };
  for(int k = 0; k < s.m; ++k)
    for(int c = 0; c < 3; ++c)
    {
      const double x = X(ring[k], c);
      p[c] += s.row(VALUE)[k] * x;
      t1[c] += s.row(D1)[k] * x;
      t2[c] += s.row(D2)[k] * x;
    }
  double n[3];
  unit_cross(t1, t2, n);
  for(int c = 0; c < 3; ++c) { out.positions(Eigen::Index(o), c) = p[c]; out.normals(Eigen::Index(o), c) = n[c]; }
  if(A)
    for(Eigen::Index c = 0; c < A->cols(); ++c)
    {
      double a = 0;
      for(int k = 0; k < s.m; ++k) a += s.row(VALUE)[k] * (*A)(ring[k], c);
      out.attributes(Eigen::Index(o), c) = a;
    }
}

// Evaluates the non-corner lattice points face f owns and records where they lie (shared edge points once).
inline void resample_face_points(const Resampling_lattice& lattice, const std::vector<Stencil>& S, const int* ring,
                                 std::size_t f, const Control_matrix& X, const Control_matrix* A,
                                 Resampled_surface& out)
{
  const int N = lattice.N;
  for(int j = 0; j <= N; ++j)
    for(int i = 0; i + j <= N; ++i)
    {
      if(lattice.is_corner(i, j)) continue;
      if(!lattice.owns(f, i, j)) continue;
      const std::size_t o = lattice.output_vertex(f, i, j);
      evaluate_lattice_point(S[lattice.stencil_index(i, j)], ring, X, A, o, out);
      // nearest corner's control vertex as the prototype of attribute values
      const double b[3] = { double(N - i - j), double(i), double(j) };
      const int corner = int(std::max_element(b, b + 3) - b);
      out.prototype[o] = std::size_t(lattice.topo.face(f)[corner]);
      out.face[o] = f;
      out.parameter[o] = { double(i) / N, double(j) / N };
    }
}

// Appends the N^2 triangles that refine face f, oriented like f, giving the connectivity of `levels` Loop steps.
inline void append_face_triangles(const Resampling_lattice& lattice, std::size_t f,
                                  std::vector<std::array<std::size_t, 3>>& faces)
{
  const int N = lattice.N;
  auto vertex = [&](int i, int j) { return lattice.output_vertex(f, i, j); };
  for(int j = 0; j < N; ++j)
    for(int i = 0; i + j < N; ++i)
    {
      faces.push_back({ vertex(i, j), vertex(i + 1, j), vertex(i, j + 1) });
      if(i + j + 2 <= N)
        faces.push_back({ vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1) });
    }
}

/// Output vertices: the control vertices first (in their order), then N-1 points per edge, then
/// the interior points of each face, N = 2^levels. X holds the geometry (3 columns), A optional attributes,
/// both with a row per vertex of `topo`. The faces refined are those of `cache` (the first faces of
/// `topo`); their vertices must be the first `vertices` ones (with a ghost layer: the real vertices).
inline Resampled_surface resample_limit_surface(const Triangle_topology& topo, const Patch_cache& cache,
                                                std::size_t vertices, const Control_matrix& X,
                                                const Control_matrix* A, unsigned levels)
{
  const std::size_t nf = cache.number_of_faces();
  const Resampling_lattice lattice(topo, vertices, nf, 1 << levels);
  const std::size_t n_out = lattice.n_out;

  Resampled_surface out;
  out.positions.resize(Eigen::Index(n_out), 3);
  out.normals.resize(Eigen::Index(n_out), 3);
  if(A) out.attributes.resize(Eigen::Index(n_out), A->cols());
  out.prototype.resize(n_out);
  out.face.resize(n_out);
  out.parameter.resize(n_out);

  resample_control_vertices(topo, vertices, nf, X, A, out);
  Lattice_stencil_cache stencils(cache, lattice);
  for(std::size_t f = 0; f < nf; ++f)
  {
    resample_face_points(lattice, stencils.of_category(cache.category(f)), cache.ring(f), f, X, A, out);
    append_face_triangles(lattice, f, out.faces);
  }
  return out;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_SURFACE_LIMIT_RESAMPLER_H
