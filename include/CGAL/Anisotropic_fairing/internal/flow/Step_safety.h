// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether a time step left a sound surface. A folded limit surface keeps sqrt(det G) > 0 almost
// everywhere, so positivity of the metric alone does not see it; what does is the normal reversing
// (between neighbouring faces of the written mesh, or between quadrature points of one face), and
// int |H|^2 exploding. A step is judged against the last accepted state, and rejected if it
//  - adds degenerate quadrature points;
//  - folds (a turn of more than 120 degrees) in more places than that state was nearly folded (110
//    degrees: a place on the brink may tip over by any small motion) or the input was folded (noise
//    leaves folds that fairing takes a few steps to remove), unless all of them lie where that state or
//    the input was folded (Fold_sites: a tangle of noise that no shorter step removes);
//  - raises int min(|H|, 2/h)^2 above 4 times the lowest value reached (bounded, since a cusp on a tiny
//    face is no blow-up) or int |H|^2 above 100 times (cusps that keep growing);
//  - shrinks a connected component to (almost) nothing.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STEP_SAFETY_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STEP_SAFETY_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Vector3.h>
#include <CGAL/Anisotropic_fairing/internal/types/Parallel_blocks.h>
#include <CGAL/Anisotropic_fairing/internal/assembly/Fem_assembly.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Process_part.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Vertex_limit_masks.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// Cosines of the turning angles at which a surface counts as folded, and as nearly folded: between the
/// normals of two faces at an edge, and within a face (Assembly_context::folded_turn, bent_turn).
constexpr double turn_120 = -0.5;
constexpr double turn_110 = -0.34202014332566871;

/// Interior edges between two of the first `real_faces` faces whose normals (of the triangles of Y)
/// turn by more than the angle of cosine `turn` (120 degrees: the mesh folds over there). A triangle
/// smaller than 10^-4 h^2 (h: `edge[c]`, the mean edge length of its component `face_component[f]`) is
/// left out: a zero-area face of a scan has no normal, and any motion gives it an arbitrary one.
/// n = the (unnormalised) normal of face f of Y; returns its length, twice the face's area
inline double face_cross_product(const Triangle_topology& topo, std::size_t f, const Control_matrix& Y, double* n)
{
  const auto& t = topo.face(f);
  double u[3], v[3];
  for(int a = 0; a < 3; ++a) { u[a] = Y(t[1], a) - Y(t[0], a); v[a] = Y(t[2], a) - Y(t[0], a); }
  vec3(n) = vec3(u).cross(vec3(v));
  return vec3(n).norm();
}

/// `faces`: only the edges whose first halfedge lies in these faces (a process's part of a distributed
/// mesh; null: all real faces), so that the parts' counts add up to the whole's.
/// `where`: if given, gets a halfedge of each edge counted.
inline std::size_t count_folded_edges(const Triangle_topology& topo, std::size_t real_faces, const Control_matrix& Y,
                                      const std::vector<int>& face_component, const std::vector<double>& edge,
                                      double turn = turn_120, const std::vector<std::size_t>* faces = nullptr,
                                      std::vector<int>* where = nullptr, const Part_view* part = nullptr)
{
  auto normal = [&](std::size_t f, double* n) {
    const double h = edge[std::size_t(face_component[f])];
    const double twice_area = face_cross_product(topo, f, Y, n);
    return twice_area > 2e-4 * h * h ? twice_area : 0.0;
  };
  // fixed blocks of halfedges, each with its own count and list, joined in order: the list is in
  // halfedge order however the blocks are scheduled
  const std::size_t nh = 3 * (faces ? faces->size() : real_faces), block = 16384;
  const std::size_t blocks = (nh + block - 1) / block;
  std::vector<std::size_t> count(blocks, 0);
  std::vector<std::vector<int>> found(where ? blocks : 0);
  parallel_blocks(blocks, [&](std::size_t first, std::size_t last) {
    for(std::size_t k = first; k < last; ++k)
      for(std::size_t i = k * block; i < std::min(nh, (k + 1) * block); ++i)
      {
        const int h = faces ? int(3 * (*faces)[i / 3] + i % 3) : int(i);
        const int o = topo.opposite(h);
        if(o < 0 || std::size_t(topo.face_of(o)) >= real_faces) continue;
        // each interior edge once: from its lower halfedge; between two processes' faces, by one of them
        const std::size_t f = std::size_t(topo.face_of(h)), g = std::size_t(topo.face_of(o));
        if(part && !part->owns_face(g) ? !part->counts_edge(f, g) : o < h) continue;
        double a[3], b[3];
        const double la = normal(std::size_t(topo.face_of(h)), a), lb = normal(std::size_t(topo.face_of(o)), b);
        if(!(la > 0) || !(lb > 0)) continue;
        if(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] < turn * la * lb)
        {
          ++count[k];
          if(where) found[k].push_back(h);
        }
      }
  }, std::size_t(1), std::size_t(1));
  std::size_t folded = 0;
  for(std::size_t k = 0; k < blocks; ++k)
  {
    folded += count[k];
    if(where) where->insert(where->end(), found[k].begin(), found[k].end());
  }
  return folded;
}

/// What is judged of a surface after a step.
struct Surface_soundness
{
  Assembly_statistics statistics;
  std::size_t folded_edges = 0, bent_edges = 0;   // turning by more than 120 and 110 degrees
  std::vector<int> folded_edge_list;   // a halfedge of each folded edge
  bool finite = true;
  // a process of a distributed run holds the folds of its part, and judges the first of the list (its own
  // edges'), the others' only marking places (Fold_sites::hold; the reversed faces: Assembly_statistics)
  std::size_t judged_edges = std::size_t(-1);

  /// edges of the written mesh and faces of the limit surface where the normal turns by more than 120 degrees
  std::size_t folds() const { return folded_edges + statistics.reversed_faces; }
  /// the same beyond 110 degrees: places that may tip over into a fold without the step being at fault
  std::size_t near_folds() const { return bent_edges + statistics.bent_faces; }
};

/// The folded (and nearly folded) edges of the surface of X: of its limit points for the Loop element
/// (`loop`), whatever is written: a control mesh oscillates about its surface, and its edges fold
/// where the surface does not.
/// A process of a distributed run counts the edges of its own `faces` it judges (`part`).
inline void count_folds(const Ghost_layer& layer, bool loop, const std::vector<int>& face_component,
                        const std::vector<double>& edge, const Control_matrix& X, Surface_soundness& s,
                        const std::vector<std::size_t>* faces = nullptr, const Part_view* part = nullptr)
{
  Control_matrix Y;
  if(loop) limit_points(layer, X, Y);
  const Control_matrix& P = loop ? Y : X;
  s.folded_edge_list.clear();
  s.folded_edges = count_folded_edges(*layer.topology, layer.real_faces, P, face_component, edge, turn_120, faces,
                                      &s.folded_edge_list, part);
  s.bent_edges = count_folded_edges(*layer.topology, layer.real_faces, P, face_component, edge, turn_110, faces,
                                    nullptr, part);
}

/// The places where a surface was folded: the vertices of its folded edges' and reversed faces' triangles
/// and the two rings around them, as far as one control vertex reaches on the limit surface (the support of
/// a Loop basis function). A step whose folds all lie where the last accepted surface or the input mesh
/// was folded did not fold the surface: it left the input's folds (a tangle of noise on small triangles)
/// where they were, and no shorter step removes them.
class Fold_sites
{
public:
  Fold_sites(const Triangle_topology& topo, std::size_t real_faces) : topo_(topo), real_faces_(real_faces) {}

  /// marks the faces of `halfedges` (edges) and `faces`
  void add(const std::vector<int>& halfedges, const std::vector<std::size_t>& faces)
  {
    if(marked_.empty()) marked_.assign(topo_.number_of_vertices(), 0);
    for(int h : halfedges)
    {
      mark_face(std::size_t(topo_.face_of(h)));
      mark_face(std::size_t(topo_.face_of(topo_.opposite(h))));
    }
    for(std::size_t f : faces) mark_face(f);
  }

  /// widens the places by the two rings of the Loop basis
  void widen()
  {
    for(int ring = 0; ring < 2 && !marked_.empty(); ++ring)
    {
      std::vector<std::size_t> touching;
      for(std::size_t f = 0; f < real_faces_; ++f)
        if(touches(f)) touching.push_back(f);
      for(std::size_t f : touching) mark_face(f);
    }
  }

  /// whether every fold of `s` (its folded edges and reversed faces, those it judges) lies at these places
  bool hold(const Surface_soundness& s) const
  {
    const std::vector<int>& edges = s.folded_edge_list;
    const std::vector<std::size_t>& faces = s.statistics.reversed_face_list;
    for(std::size_t k = 0; k < edges.size() && k < s.judged_edges; ++k)
    {
      const int h = edges[k];
      if(!touches(std::size_t(topo_.face_of(h))) && !touches(std::size_t(topo_.face_of(topo_.opposite(h)))))
        return false;
    }
    for(std::size_t k = 0; k < faces.size() && k < s.statistics.judged_reversed_faces; ++k)
      if(!touches(faces[k])) return false;
    return true;
  }

private:
  void mark_face(std::size_t f) { for(int v : topo_.face(f)) marked_[std::size_t(v)] = 1; }
  bool touches(std::size_t f) const
  {
    if(marked_.empty()) return false;   // nothing marked
    for(int v : topo_.face(f)) if(marked_[std::size_t(v)]) return true;
    return false;
  }

  const Triangle_topology& topo_;
  std::size_t real_faces_;
  std::vector<char> marked_;   // per vertex
};

/// Whether the candidate's folds all lie where the accepted surface or the input mesh (`input_fold_edges`)
/// was folded: there a shorter step would leave them too. Not beyond `allowed_folds` folded edges, the
/// most a run may end with. Both flows (Flow_run, the distributed one) judge their steps with it.
inline bool folds_at_known_places(const Triangle_topology& topo, std::size_t real_faces,
                                  const Surface_soundness& accepted, const std::vector<int>& input_fold_edges,
                                  std::size_t allowed_folds, const Surface_soundness& candidate)
{
  if(candidate.folded_edges > allowed_folds) return false;
  Fold_sites sites(topo, real_faces);
  sites.add(accepted.folded_edge_list, accepted.statistics.reversed_face_list);
  sites.add(input_fold_edges, {});
  sites.widen();
  return sites.hold(candidate);
}

enum class Step_verdict { SOUND, UNSOUND, COLLAPSED };

/// The lowest int |H|^2 and int min(|H|, 2/h)^2 of the accepted surfaces
struct Lowest_curvature
{
  double full, bounded;
  explicit Lowest_curvature(const Assembly_statistics& a) : full(a.H_integral), bounded(a.bounded_H_integral) {}
  void add(const Assembly_statistics& a)
  {
    full = std::min(full, a.H_integral);
    bounded = std::min(bounded, a.bounded_H_integral);
  }
};

/// Whether every fold of a candidate lies where the accepted surface or the input was folded (Fold_sites);
/// empty: folds are judged by their number only.
typedef std::function<bool(const Surface_soundness&)> Known_fold_places;

/// Whether the candidate's written mesh alone already folds more edges than the accepted state allows
/// (what judge_step finds first when the limit surface's faces add none): `why` says so.
inline bool edges_folded(const Surface_soundness& accepted, std::size_t input_folds, const Surface_soundness& candidate,
                         std::string& why, const Known_fold_places& known = {})
{
  if(candidate.folded_edges <= std::max(accepted.near_folds(), input_folds)) return false;
  if(known && known(candidate)) return false;
  char text[160];
  std::snprintf(text, sizeof text,
                "the surface folded (%zu edges where the normal turns by more than 120 degrees, %zu before)",
                candidate.folded_edges, accepted.folds());
  why = text;
  return true;
}

/// Compares `candidate` with the last accepted state (and the initial one for collapse); `input_folds`
/// are the folds of the input mesh itself, `lowest` the lowest int |H|^2 reached so far. `why` names what failed.
inline Step_verdict judge_step(const Surface_soundness& initial, const Surface_soundness& accepted,
                               std::size_t input_folds, const Lowest_curvature& lowest,
                               const Surface_soundness& candidate, std::string& why,
                               const Known_fold_places& known = {})
{
  const Assembly_statistics& c = candidate.statistics;
  const Assembly_statistics& a = accepted.statistics;
  char text[200];
  if(!candidate.finite || !std::isfinite(c.area) || !std::isfinite(c.H_integral) || !std::isfinite(c.energy))
  { why = "the surface's coordinates, area or curvature overflowed"; return Step_verdict::UNSOUND; }
  for(std::size_t k = 0; k < c.component_area.size() && k < initial.statistics.component_area.size(); ++k)
    if(c.component_area[k] < 1e-2 * initial.statistics.component_area[k])
    {
      std::snprintf(text, sizeof text, "connected component %zu shrank to %.3g of its initial area", k,
                    c.component_area[k] / initial.statistics.component_area[k]);
      why = text;
      return Step_verdict::COLLAPSED;
    }
  if(c.degenerate_points > a.degenerate_points)
  {
    std::snprintf(text, sizeof text, "the surface pinched (sqrt(det G) <= 0 on face %zu)", c.degenerate_face);
    why = text;
    return Step_verdict::UNSOUND;
  }
  if(candidate.folds() > std::max(accepted.near_folds(), input_folds) && !(known && known(candidate)))
  {
    std::snprintf(text, sizeof text,
                  "the surface folded (%zu edges and %zu faces where the normal turns by more than 120 degrees, "
                  "%zu before)",
                  candidate.folded_edges, c.reversed_faces, accepted.folds());
    why = text;
    return Step_verdict::UNSOUND;
  }
  if((c.bounded_H_integral > 4 * lowest.bounded && lowest.bounded > 0) ||
     (c.H_integral > 100 * lowest.full && lowest.full > 0))
  {
    std::snprintf(text, sizeof text,
                  "int |H|^2 exploded (%.4g, the lowest value reached %.4g; bounded by 2/h: %.4g, lowest %.4g)",
                  c.H_integral, lowest.full, c.bounded_H_integral, lowest.bounded);
    why = text;
    return Step_verdict::UNSOUND;
  }
  return Step_verdict::SOUND;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_STEP_SAFETY_H
