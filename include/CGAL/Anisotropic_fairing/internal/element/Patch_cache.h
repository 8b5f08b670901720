// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every triangle's control ring in a canonical order, its topological category, and per category
// the stencils at the quadrature points. Stencils depend on topology only, so they are computed once
// per category (the paper's "categories"; about 250 for a 7k-triangle scan) and never per step.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_ELEMENT_PATCH_CACHE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_ELEMENT_PATCH_CACHE_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Loop_local_patch.h>
#include <CGAL/Anisotropic_fairing/internal/element/Quadrature_rules.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>
#include <CGAL/Anisotropic_fairing/internal/types/Parallel_blocks.h>

#include <CGAL/assertions.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// How integrals over a control triangle are computed.
struct Quadrature_spec
{
  int degree = 8;        ///< Dunavant rule: 4, 6 or 8
  int tiling_depth = 0;  ///< 0: the rule on the whole triangle ("point" mode); K > 0: irregular
                         ///< patches are split 1-to-4 down to level K and the rule applied per tile
  bool operator==(const Quadrature_spec& o) const { return degree == o.degree && tiling_depth == o.tiling_depth; }
};

/// A quadrature point of a category: weight (including the reference-triangle area 1/2),
/// parameters in the control triangle, and the stencil on the canonical ring.
struct Quadrature_point
{
  double weight, xi1, xi2;
  Stencil stencil;
};

class Patch_cache
{
public:
  typedef Loop_local_patch::Tri Tri;
  /// the Loop element has second-derivative stencils (mean curvature at quadrature points)
  static constexpr bool has_second_derivatives = true;

  /// Categories of the first `faces_to_evaluate` faces of `topo` (all by default; with a ghost layer,
  /// the real faces, which come first and whose vertices all have closed fans).
  explicit Patch_cache(const Triangle_topology& topo,
                       std::size_t faces_to_evaluate = (std::numeric_limits<std::size_t>::max)())
  {
    const std::size_t nf = (std::min)(faces_to_evaluate, topo.number_of_faces());
    category_.resize(nf);
    ring_offset_.assign(nf + 1, 0);
    // a few fixed blocks of faces on every core, each with its own labels and its own table of the
    // categories it meets; the tables are merged in block order, which numbers the categories as one pass
    // over the faces would, whatever the number of threads
    const std::size_t blocks = nf < 20000 ? 1 : 8;
    std::vector<Block> block(blocks);
    parallel_blocks(blocks, [&](std::size_t first, std::size_t last) {
      std::vector<int> label(topo.number_of_vertices(), -1);
      for(std::size_t b = first; b < last; ++b) categorize(topo, b * nf / blocks, (b + 1) * nf / blocks, label,
                                                           block[b]);
    }, std::size_t(1), std::size_t(1));
    std::unordered_map<std::vector<int>, int, Signature_hash> index;
    for(std::size_t b = 0; b < blocks; ++b)
    {
      std::vector<int> global(block[b].categories.size());
      for(std::size_t k = 0; k < global.size(); ++k)
      {
        Block::Met& c = block[b].categories[k];
        auto it = index.find(c.signature);
        if(it == index.end())
        {
          it = index.emplace(std::move(c.signature), int(categories_.size())).first;
          categories_.emplace_back(new Category{ c.m, std::move(c.tris), {} });
        }
        global[k] = it->second;
      }
      for(std::size_t f = b * nf / blocks; f < (b + 1) * nf / blocks; ++f)
        category_[f] = global[std::size_t(category_[f])];
    }
    for(std::size_t f = 0; f < nf; ++f) ring_offset_[f + 1] += ring_offset_[f];
    ring_ids_.resize(ring_offset_[nf]);
    parallel_blocks(blocks, [&](std::size_t first, std::size_t last) {
      for(std::size_t b = first; b < last; ++b)
        std::copy(block[b].rings.begin(), block[b].rings.end(),
                  ring_ids_.begin() + std::ptrdiff_t(ring_offset_[b * nf / blocks]));
    }, std::size_t(1), std::size_t(1));
  }

  std::size_t number_of_faces() const { return category_.size(); }
  std::size_t number_of_categories() const { return categories_.size(); }
  int category(std::size_t f) const { return category_[f]; }
  int ring_size(std::size_t f) const { return int(ring_offset_[f + 1] - ring_offset_[f]); }
  const int* ring(std::size_t f) const { return ring_ids_.data() + ring_offset_[f]; }
  int category_ring_size(int c) const { return categories_[c]->m; }

  /// The root patch of a category: canonical local ids, target (0, 1, 2).
  Loop_local_patch root_patch(int c) const
  {
    return Loop_local_patch(categories_[c]->m, categories_[c]->tris, Tri{ { 0, 1, 2 } });
  }

  /// Whether the category's triangle has three valence-6 vertices (a single box-spline patch).
  bool is_regular(int c) const { return root_patch(c).is_regular(); }

  /// Computes (once per spec) the quadrature points and stencils of every category.
  void prepare_quadrature(const Quadrature_spec& spec)
  {
    if(quadrature_ready_ && spec == spec_) return;
    // the user's spec is checked where it is read (Quadrature_parameters.h)
    CGAL_precondition(spec.tiling_depth >= 0 && spec.tiling_depth <= 12);
    const std::vector<Triangle_rule_point> rule = triangle_rule(spec.degree);
    for(auto& c : categories_)
    {
      c->points.clear();
      const Loop_local_patch root(c->m, c->tris, Tri{ { 0, 1, 2 } });
      tile(root, rule, spec.tiling_depth, 0.0, 0.0, 1.0, c->points);
      const Eigen::Index nq = Eigen::Index(c->points.size());
      c->weights.resize(nq);
      for(int r = 0; r < STENCIL_ROWS; ++r) c->rows[r].resize(nq, c->m);
      for(Eigen::Index q = 0; q < nq; ++q)
      {
        c->weights[q] = c->points[std::size_t(q)].weight;
        for(int r = 0; r < STENCIL_ROWS; ++r)
          for(int j = 0; j < c->m; ++j) c->rows[r](q, j) = c->points[std::size_t(q)].stencil.row(r)[j];
      }
    }
    spec_ = spec;
    quadrature_ready_ = true;
  }

  const std::vector<Quadrature_point>& quadrature_points(int c) const { return categories_[c]->points; }

  /// The stencils of a category stacked by row kind: quadrature_rows(c, r) is (points x ring size),
  /// row q holding row r of point q's stencil. Dense, so assembly works with small matrix products.
  const Control_matrix& quadrature_rows(int c, int r) const { return categories_[c]->rows[r]; }
  /// Weights of a category's quadrature points (including the reference area 1/2).
  const Eigen::VectorXd& quadrature_weights(int c) const { return categories_[c]->weights; }
  const Quadrature_spec& quadrature_spec() const { return spec_; }

private:
  // Tile with corner o and scale s (negative for a 180-degree turn): triangle parameter =
  // o + s * local parameter, so d/dxi = (1/s) d/dlocal and the weight scales by s^2.
  static void tile(const Loop_local_patch& p, const std::vector<Triangle_rule_point>& rule,
                   int depth_left, double o1, double o2, double s,
                   std::vector<Quadrature_point>& out)
  {
    if(p.is_regular() || depth_left == 0)
    {
      const double f = 1.0 / s;
      for(const Triangle_rule_point& q : rule)
      {
        Quadrature_point qp;
        qp.weight = 0.5 * q.weight * s * s;
        qp.xi1 = o1 + s * q.xi1;
        qp.xi2 = o2 + s * q.xi2;
        p.stencil(q.xi1, q.xi2, qp.stencil);
        for(int j = 0; j < qp.stencil.m; ++j)
        {
          qp.stencil.row(D1)[j] *= f;      qp.stencil.row(D2)[j] *= f;
          qp.stencil.row(D11)[j] *= f * f; qp.stencil.row(D12)[j] *= f * f; qp.stencil.row(D22)[j] *= f * f;
        }
        out.push_back(std::move(qp));
      }
      return;
    }
    const double h = 0.5 * s;
    tile(p.child(CHILD_A), rule, depth_left - 1, o1, o2, h, out);
    tile(p.child(CHILD_B), rule, depth_left - 1, o1 + h, o2, h, out);
    tile(p.child(CHILD_C), rule, depth_left - 1, o1, o2 + h, h, out);
    tile(p.child(CHILD_M), rule, depth_left - 1, o1 + h, o2 + h, -h, out);
  }

  // what one block of faces found: the rings in face order, and the categories in the order met
  struct Block
  {
    struct Met { std::vector<int> signature; int m; std::vector<Tri> tris; };
    std::vector<int> rings;
    std::vector<Met> categories;
  };

  // faces [first, last): each face's ring (its vertices, labelled in the order met), its category in the
  // block's own table (in category_), its ring's size (in ring_offset_[f + 1])
  void categorize(const Triangle_topology& topo, std::size_t first, std::size_t last, std::vector<int>& label,
                  Block& block)
  {
    std::vector<int> ring, fan_faces, signature;
    std::vector<Tri> local;
    std::unordered_map<std::vector<int>, int, Signature_hash> index;
    for(std::size_t f = first; f < last; ++f)
    {
      ring.clear(); fan_faces.clear(); local.clear(); signature.clear();
      auto label_of = [&](int v) {
        if(label[v] < 0) { label[v] = int(ring.size()); ring.push_back(v); }
        return label[v];
      };
      const Triangle_topology::Face& t = topo.face(f);
      for(int k = 0; k < 3; ++k) label_of(t[k]);
      // fans of a from b, of b from c, of c from a, each counter-clockwise
      for(int k = 0; k < 3; ++k)
      {
        const int h0 = int(3 * f) + k;
        int h = h0;
        do {
          label_of(topo.target(h));
          const int g = topo.face_of(h);
          if(std::find(fan_faces.begin(), fan_faces.end(), g) == fan_faces.end()) fan_faces.push_back(g);
          h = topo.ccw(h);
        } while(h != h0);
      }
      for(int g : fan_faces)
      {
        const Triangle_topology::Face& q = topo.face(g);
        Tri r = { label[q[0]], label[q[1]], label[q[2]] };
        std::rotate(r.begin(), std::min_element(r.begin(), r.end()), r.end());
        local.push_back(r);
      }
      std::sort(local.begin(), local.end());
      signature.push_back(int(ring.size()));
      for(const Tri& r : local) signature.insert(signature.end(), r.begin(), r.end());
      auto it = index.find(signature);
      if(it == index.end())
      {
        it = index.emplace(signature, int(block.categories.size())).first;
        block.categories.push_back({ signature, int(ring.size()), local });
      }
      category_[f] = it->second;
      block.rings.insert(block.rings.end(), ring.begin(), ring.end());
      ring_offset_[f + 1] = ring.size();
      for(int v : ring) label[v] = -1;
    }
  }

  struct Signature_hash
  {
    std::size_t operator()(const std::vector<int>& s) const
    {
      std::uint64_t h = 1469598103934665603ull;
      for(int x : s) { h ^= std::uint64_t(x) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2); }
      return std::size_t(h);
    }
  };

  struct Category
  {
    int m;
    std::vector<Tri> tris;
    std::vector<Quadrature_point> points;
    Control_matrix rows[STENCIL_ROWS];
    Eigen::VectorXd weights;
  };

  std::vector<int> category_;
  std::vector<std::size_t> ring_offset_;
  std::vector<int> ring_ids_;
  std::vector<std::unique_ptr<Category>> categories_;
  Quadrature_spec spec_;
  bool quadrature_ready_ = false;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_ELEMENT_PATCH_CACHE_H
