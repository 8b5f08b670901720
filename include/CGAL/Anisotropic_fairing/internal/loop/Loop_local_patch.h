// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Evaluation of one triangle's Loop limit patch by local subdivision of the triangle's own 1-ring.
//
// The patch of a triangle t = (a, b, c) is controlled by ring(t), the vertices of all triangles
// incident to a, b or c. If a, b and c have valence 6 it is the quartic box spline (Loop_box_spline).
// Otherwise the ring is subdivided locally, the child containing the parameter point is kept, and
// so on until the child is regular. With one extraordinary vertex this is Stam's scheme; with two
// or three it branches at the first level. The user's mesh is never changed: a patch is a set of
// local triangles plus a dense matrix W saying how each local vertex combines the root controls.
// (doc/Anisotropic_fairing/design/loop-fem.md section 4; Bajaj & Xu 2003 section 3.3 with its two errata avoided.)

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_LOOP_LOCAL_PATCH_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_LOOP_LOCAL_PATCH_H

#include <CGAL/Anisotropic_fairing/internal/loop/Loop_box_spline.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Loop_rules.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// Weights of a limit-surface quantity on a ring: rows VALUE..D22 (see Stencil_row), m columns.
struct Stencil
{
  int m = 0;
  std::vector<double> w;      // STENCIL_ROWS x m, row-major
  bool singular = false;      // at (or within 2^-max_depth of) an extraordinary vertex: the
                              // second-derivative rows are zero and D1, D2 are tangent-mask
                              // directions rather than parametric derivatives (which degenerate there)

  void resize(int m_) { m = m_; w.assign(std::size_t(STENCIL_ROWS) * m, 0.0); singular = false; }
  double* row(int r) { return w.data() + std::size_t(r) * m; }
  const double* row(int r) const { return w.data() + std::size_t(r) * m; }
};

/// Which child of a 1-to-4 split: the children at corners a, b, c, and the middle one.
enum Child { CHILD_A = 0, CHILD_B = 1, CHILD_C = 2, CHILD_M = 3 };

class Loop_local_patch
{
public:
  typedef std::array<int, 3> Tri;
  // Stencils are computed once per category, so extended precision is affordable: it keeps the
  // rounding of up to ~5 levels of W products and of the box-spline cancellation (amplified by
  // 4^depth in second derivatives) below double precision in the final stencil.
  typedef long double Real;

  /// The root patch: local vertex j is control j (W = identity); `tris` are oriented triangles in
  /// local ids and must contain every triangle incident to the target's vertices (closed fans).
  Loop_local_patch(int m, std::vector<Tri> tris, const Tri& target)
    : m_(m), nl_(m), W_(std::size_t(m) * m, 0.0), tris_(std::move(tris)), target_(target)
  {
    for(int j = 0; j < m; ++j) W_[std::size_t(j) * m + j] = 1.0;
    build_adjacency();
  }

  int number_of_controls() const { return m_; }
  int number_of_local_vertices() const { return nl_; }
  const Tri& target() const { return target_; }
  const std::vector<Tri>& triangles() const { return tris_; }
  const Real* weights(int local) const { return W_.data() + std::size_t(local) * m_; }

  int valence(int v) const { return valence_[v]; }

  bool is_regular() const
  {
    return valence_[target_[0]] == 6 && valence_[target_[1]] == 6 && valence_[target_[2]] == 6;
  }

  /// Third vertex of the triangle containing the directed edge p -> q, or -1.
  int third(int p, int q) const { return third_[std::size_t(p) * nl_ + q]; }

  /// The vertex opposite to r across the edge {p, q}.
  int opp(int p, int q, int r) const
  {
    const int x = third(p, q);
    const int y = third(q, p);
    const int o = (x == r) ? y : x;
    if(o < 0 || (x != r && y != r))
      throw std::logic_error("Loop_local_patch: open fan or inconsistent local triangles");
    return o;
  }

  /// Neighbours of target vertex v counter-clockwise, starting at `start`.
  std::vector<int> neighbours_ccw(int v, int start) const
  {
    std::vector<int> out;
    int w = start;
    do {
      out.push_back(w);
      w = third(v, w);
      if(w < 0) throw std::logic_error("Loop_local_patch: open fan");
    } while(w != start && int(out.size()) <= valence_[v]);
    return out;
  }

  /// The 12 local ids of a regular patch in box-spline order (loop-fem.md section 2).
  std::array<int, 12> layout12() const
  {
    std::array<int, 13> L{};
    L[4] = target_[0]; L[7] = target_[1]; L[8] = target_[2];
    L[3] = opp(L[4], L[7], L[8]);
    L[5] = opp(L[4], L[8], L[7]);
    L[11] = opp(L[7], L[8], L[4]);
    L[1] = opp(L[4], L[3], L[7]);
    L[2] = opp(L[4], L[5], L[8]);
    L[6] = opp(L[7], L[3], L[4]);
    L[10] = opp(L[7], L[11], L[8]);
    L[12] = opp(L[8], L[11], L[7]);
    L[9] = opp(L[8], L[12], L[11]);
    std::array<int, 12> out;
    for(int i = 0; i < 12; ++i) out[i] = L[i + 1];
    return out;
  }

  /// One step of Loop subdivision restricted to what the child's 1-ring needs.
  Loop_local_patch child(Child which) const
  {
    Local_split split(nl_);
    add_vertex_points(split);
    add_edge_points(split);
    const std::vector<Tri> kids = split_triangles(split);
    return patch_around(m_, split.rows, kids, child_target(which, split));
  }

  /// Parameters in the child that contains (u, v), and the derivative factor d(child)/d(parent).
  static Child locate(Real& u, Real& v, Real& factor)
  {
    if(u >= 0.5)            { u = 2 * u - 1; v = 2 * v;     factor = 2;  return CHILD_B; }
    if(v >= 0.5)            { u = 2 * u;     v = 2 * v - 1; factor = 2;  return CHILD_C; }
    if(u + v <= 0.5)        { u = 2 * u;     v = 2 * v;     factor = 2;  return CHILD_A; }
    u = 1 - 2 * u; v = 1 - 2 * v; factor = -2; return CHILD_M;
  }

  /// Stencil of a regular patch at (u, v): box-spline rows times W on the 12-vertex layout,
  /// scaled by the derivative factor f (first rows by f, second by f^2).
  void regular_stencil(Real u, Real v, Stencil& s, Real f = 1) const
  {
    std::array<std::array<Real, 12>, STENCIL_ROWS> B;
    Loop_box_spline::evaluate(u, v, B);
    const std::array<int, 12> L = layout12();
    const Real scale[STENCIL_ROWS] = { 1, f, f, f * f, f * f, f * f };
    s.resize(m_);
    std::vector<Real> acc(static_cast<std::size_t>(m_), Real(0));
    for(int r = 0; r < STENCIL_ROWS; ++r)
    {
      std::fill(acc.begin(), acc.end(), Real(0));
      for(int i = 0; i < 12; ++i)
      {
        const Real bi = B[r][i];
        if(bi == 0) continue;
        const Real* w = weights(L[i]);
        for(int j = 0; j < m_; ++j) acc[std::size_t(j)] += bi * w[j];
      }
      for(int j = 0; j < m_; ++j) s.row(r)[j] = double(scale[r] * acc[std::size_t(j)]);
    }
  }

  /// Limit point and tangent-mask directions at target corner k (0, 1, 2) of an extraordinary
  /// vertex. D1/D2 are the derivatives of a regular reparametrisation (exact for valence 6), mapped
  /// to this patch's (xi1, xi2) orientation; second derivatives are left at zero.
  void corner_stencil(int k, Stencil& s) const
  {
    s.resize(m_);
    s.singular = true;
    const int v = target_[k];
    const int n = valence_[v];
    const int start = target_[(k + 1) % 3];       // next corner: CCW after it comes target[(k+2)%3]
    const std::vector<int> nb = neighbours_ccw(v, start);
    const Real chi = loop_limit_weight<Real>(n);
    std::vector<Real> val(m_, Real(0)), t1(m_, Real(0)), t2(m_, Real(0));
    const Real* wv = weights(v);
    for(int j = 0; j < m_; ++j) val[j] = (1 - n * chi) * wv[j];
    for(int i = 0; i < n; ++i)
    {
      const Real* w = weights(nb[i]);
      const Real c1 = (Real(2) / n) * std::cos(2 * loop_pi() * i / n);
      const Real c2 = (Real(2) / n) * std::cos(2 * loop_pi() * (i - 1) / n);
      for(int j = 0; j < m_; ++j)
      {
        val[j] += chi * w[j];
        t1[j] += c1 * w[j];
        t2[j] += c2 * w[j];
      }
    }
    for(int j = 0; j < m_; ++j) s.row(VALUE)[j] = double(val[j]);
    // (s1, s2) are the parameters of the rotated triangle that starts at corner k.
    double* d1 = s.row(D1);
    double* d2 = s.row(D2);
    for(int j = 0; j < m_; ++j)
    {
      switch(k)
      {
        case 0: d1[j] = double(t1[j]);          d2[j] = double(t2[j]);          break;
        case 1: d1[j] = double(-t2[j]);         d2[j] = double(t1[j] - t2[j]);  break;  // s = (xi2, 1 - xi1 - xi2)
        default: d1[j] = double(-t1[j] + t2[j]); d2[j] = double(-t1[j]);        break;  // s = (1 - xi1 - xi2, xi1)
      }
    }
  }

  /// Evaluates the patch at (u, v) = (xi1, xi2) in the closed unit triangle.
  void stencil(double u_in, double v_in, Stencil& s, int max_depth = 48) const
  {
    Real u = u_in, v = v_in;
    // exactly at an extraordinary corner, the recursion would never reach a regular patch
    const int corner = (u == 0 && v == 0) ? 0 : (u == 1 && v == 0) ? 1 : (u == 0 && v == 1) ? 2 : -1;
    if(corner >= 0 && valence_[target_[corner]] != 6) { corner_stencil(corner, s); return; }
    if(is_regular()) { regular_stencil(u, v, s); return; }

    Real factor = 1;
    const Loop_local_patch* p = this;
    Loop_local_patch current;
    int depth = 0;
    while(!p->is_regular())
    {
      if(depth == max_depth)
      {
        // closer than 2^-max_depth to an extraordinary vertex: evaluate at that vertex
        const Real b[3] = { 1 - u - v, u, v };
        const int k = int(std::max_element(b, b + 3) - b);
        p->corner_stencil(k, s);
        for(int r = D1; r <= D2; ++r) for(int j = 0; j < m_; ++j) s.row(r)[j] *= double(factor);
        return;
      }
      Real f;
      const Child which = locate(u, v, f);
      current = p->child(which);
      p = &current;
      factor *= f;
      ++depth;
    }
    p->regular_stencil(u, v, s, factor);
  }

  Loop_local_patch() = default;

private:
  /// The new vertices of one local 1-to-4 split: their W rows (one row of m_ weights per new
  /// vertex, in creation order) and which new row each old vertex and old edge became (-1: none).
  struct Local_split
  {
    std::vector<int> vertex_point;   // by old local id
    std::vector<int> edge_point;     // symmetric, by old local ids (see edge_slot)
    std::vector<Real> rows;          // new W, grown row by row

    explicit Local_split(int nl)
      : vertex_point(nl, -1), edge_point(std::size_t(nl) * nl, -1) {}
  };

  /// Index of the undirected edge {p, q} in an nl_ x nl_ table, so both directions share a slot.
  std::size_t edge_slot(int p, int q) const { return std::size_t(std::min(p, q)) * nl_ + std::max(p, q); }

  /// Whether local vertex v is a corner of the target.
  bool is_target(int v) const { return v == target_[0] || v == target_[1] || v == target_[2]; }

  /// Appends a zero row to `rows` and returns its index.
  int new_row(std::vector<Real>& rows) const
  {
    rows.resize(rows.size() + m_, 0.0);
    return int(rows.size() / m_) - 1;
  }

  /// rows[dst] += s * W[src]: a new vertex is a weighted sum of old vertices, each a row of W.
  void add_scaled_row(std::vector<Real>& rows, int dst, Real s, int src) const
  {
    Real* d = rows.data() + std::size_t(dst) * m_;
    const Real* x = W_.data() + std::size_t(src) * m_;
    for(int j = 0; j < m_; ++j) d[j] += s * x[j];
  }

  /// The Loop vertex points of the target's corners a, b, c; only they have their whole 1-ring in
  /// the patch, which the vertex rule needs.
  void add_vertex_points(Local_split& split) const
  {
    std::vector<Real>& rows = split.rows;
    for(int k = 0; k < 3; ++k)
    {
      const int v = target_[k];
      const int n = valence_[v];
      const Real beta = loop_vertex_weight<Real>(n);
      const int r = new_row(rows);
      add_scaled_row(rows, r, 1.0 - n * beta, v);
      for(int w : neighbours_ccw(v, first_neighbour(v))) add_scaled_row(rows, r, beta, w);
      split.vertex_point[v] = r;
    }
  }

  /// The Loop edge points of every edge incident to a, b or c, each once; the edge rule needs both
  /// triangles at the edge, which the closed fans of a, b and c guarantee.
  void add_edge_points(Local_split& split) const
  {
    std::vector<Real>& rows = split.rows;
    for(const Tri& t : tris_)
      for(int e = 0; e < 3; ++e)
      {
        const int p = t[e], q = t[(e + 1) % 3];
        if(!is_target(p) && !is_target(q)) continue;
        int& slot = split.edge_point[edge_slot(p, q)];
        if(slot >= 0) continue;
        const int x = third(p, q), y = third(q, p);
        if(x < 0 || y < 0) throw std::logic_error("Loop_local_patch: open fan at an edge");
        slot = new_row(rows);
        add_scaled_row(rows, slot, Real(0.375), p); add_scaled_row(rows, slot, Real(0.375), q);
        add_scaled_row(rows, slot, Real(0.125), x); add_scaled_row(rows, slot, Real(0.125), y);
      }
  }

  /// The children of every local triangle whose three new vertices were computed (the others
  /// cannot be formed), in the ids of the split's rows.
  std::vector<Tri> split_triangles(const Local_split& split) const
  {
    std::vector<Tri> kids;
    for(const Tri& t : tris_)
    {
      const int i = t[0], j = t[1], k = t[2];
      const int vi = split.vertex_point[i], vj = split.vertex_point[j], vk = split.vertex_point[k];
      const int eij = split.edge_point[edge_slot(i, j)], ejk = split.edge_point[edge_slot(j, k)],
                eki = split.edge_point[edge_slot(k, i)];
      const Tri cand[4] = { {vi, eij, eki}, {vj, ejk, eij}, {vk, eki, ejk}, {eij, ejk, eki} };
      for(const Tri& ct : cand)
        if(ct[0] >= 0 && ct[1] >= 0 && ct[2] >= 0) kids.push_back(ct);
    }
    return kids;
  }

  /// The child `which` of the target, in the ids of the split's rows, oriented so that its
  /// (xi1, xi2) are those that locate() gives.
  Tri child_target(Child which, const Local_split& split) const
  {
    auto ep = [&](int p, int q) { return split.edge_point[edge_slot(p, q)]; };
    const int a = target_[0], b = target_[1], cc = target_[2];
    Tri nt;
    switch(which)
    {
      case CHILD_A: nt = { split.vertex_point[a], ep(a, b), ep(cc, a) }; break;
      case CHILD_B: nt = { ep(a, b), split.vertex_point[b], ep(b, cc) }; break;
      case CHILD_C: nt = { ep(cc, a), ep(b, cc), split.vertex_point[cc] }; break;
      default:      nt = { ep(b, cc), ep(cc, a), ep(a, b) }; break;
    }
    return nt;
  }

  /// The patch of m controls made of the triangles of `kids` incident to the new target `nt`, with
  /// their vertices renumbered compactly (the target first: ids 0, 1, 2) and their W rows taken
  /// from `rows`; dropping the rest keeps the next level of subdivision small.
  static Loop_local_patch patch_around(int m, const std::vector<Real>& rows, const std::vector<Tri>& kids,
                                       const Tri& nt)
  {
    Loop_local_patch c;
    c.m_ = m;
    const int total = int(rows.size() / m);
    std::vector<int> remap(total, -1);
    int used = 0;
    for(int k = 0; k < 3; ++k) remap[nt[k]] = used++;   // target first: ids 0, 1, 2
    for(const Tri& t : kids)
    {
      const bool incident = (t[0] == nt[0] || t[0] == nt[1] || t[0] == nt[2] ||
                             t[1] == nt[0] || t[1] == nt[1] || t[1] == nt[2] ||
                             t[2] == nt[0] || t[2] == nt[1] || t[2] == nt[2]);
      if(!incident) continue;
      Tri r;
      for(int k = 0; k < 3; ++k)
      {
        if(remap[t[k]] < 0) remap[t[k]] = used++;
        r[k] = remap[t[k]];
      }
      c.tris_.push_back(r);
    }
    c.nl_ = used;
    c.W_.assign(std::size_t(used) * m, Real(0));
    for(int old = 0; old < total; ++old)
      if(remap[old] >= 0)
        std::copy(rows.begin() + std::size_t(old) * m, rows.begin() + std::size_t(old + 1) * m,
                  c.W_.begin() + std::size_t(remap[old]) * m);
    c.target_ = { 0, 1, 2 };
    c.build_adjacency();
    return c;
  }

  int first_neighbour(int v) const
  {
    for(const Tri& t : tris_)
      for(int k = 0; k < 3; ++k)
        if(t[k] == v) return t[(k + 1) % 3];
    throw std::logic_error("Loop_local_patch: vertex without triangle");
  }

  void build_adjacency()
  {
    third_.assign(std::size_t(nl_) * nl_, -1);
    valence_.assign(nl_, 0);
    for(const Tri& t : tris_)
      for(int k = 0; k < 3; ++k)
      {
        third_[std::size_t(t[k]) * nl_ + t[(k + 1) % 3]] = t[(k + 2) % 3];
        ++valence_[t[k]];
      }
  }

  int m_ = 0, nl_ = 0;
  std::vector<Real> W_;
  std::vector<Tri> tris_;
  Tri target_{ { 0, 1, 2 } };
  std::vector<int> third_;
  std::vector<int> valence_;   // number of local triangles at each local vertex (the valence for closed fans)
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_LOOP_LOCAL_PATCH_H
