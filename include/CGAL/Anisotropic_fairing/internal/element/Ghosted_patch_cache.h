// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Loop element on a mesh with borders, in the shape of Patch_cache but over the real vertices
// only. A face whose ring holds ghosts (doc/Anisotropic_fairing/design/loop-fem.md section 6) has the ghosts
// substituted by their
// affine rows: with P the (ring x real ring) matrix of that substitution, its stencils become S P, so
// the basis is phi~_i = phi_i + sum_g E_gi phi_g and every assembled matrix is E^T M_ext E without
// ever forming the extended one. Faces away from the border keep their shared per-category stencils;
// each face next to the border gets its own (they are few: one or two rows of faces).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_ELEMENT_GHOSTED_PATCH_CACHE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_ELEMENT_GHOSTED_PATCH_CACHE_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/element/Patch_cache.h>

#include <Eigen/Core>

#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

class Ghosted_patch_cache
{
public:
  static constexpr bool has_second_derivatives = true;

  Ghosted_patch_cache(const Ghost_layer& gl, const Quadrature_spec& spec)
    : base_(*gl.topology, gl.real_faces)
  {
    base_.prepare_quadrature(spec);
    const int n = int(gl.real_vertices);
    const int base_categories = int(base_.number_of_categories());
    const std::size_t nf = base_.number_of_faces();
    category_.resize(nf);
    std::vector<int> slot(gl.number_of_extended_vertices(), -1);
    for(std::size_t f = 0; f < nf; ++f)
    {
      const int m = base_.ring_size(f);
      const int* ext = base_.ring(f);
      bool ghosted = false;
      for(int k = 0; k < m; ++k) ghosted = ghosted || ext[k] >= n;
      const std::size_t begin = ring_.size();
      if(!ghosted) category_[f] = base_.category(f);   // its ring is the base cache's
      else
      {
        // the real ring: every real vertex of the ring or of a ghost's row, in first-seen order
        auto add = [&](int v) {
          if(slot[std::size_t(v)] < 0)
          {
            slot[std::size_t(v)] = int(ring_.size() - begin);
            ring_.push_back(v);
          }
        };
        for(int k = 0; k < m; ++k)
          if(ext[k] < n) add(ext[k]);
          else for(const auto& w : gl.ghosts[std::size_t(ext[k] - n)]) add(w.first);
        const int mr = int(ring_.size() - begin);
        Eigen::MatrixXd P = Eigen::MatrixXd::Zero(m, mr);
        for(int k = 0; k < m; ++k)
          if(ext[k] < n) P(k, slot[std::size_t(ext[k])]) = 1.0;
          else for(const auto& w : gl.ghosts[std::size_t(ext[k] - n)]) P(k, slot[std::size_t(w.first)]) += w.second;
        for(std::size_t j = begin; j < ring_.size(); ++j) slot[std::size_t(ring_[j])] = -1;
        Ghosted_face g;
        g.face = f;
        g.ring_begin = begin;
        g.ring_size = mr;
        g.substitution = P;
        g.base_category = base_.category(f);
        for(int r = 0; r < STENCIL_ROWS; ++r) g.rows[r] = base_.quadrature_rows(g.base_category, r) * P;
        category_[f] = base_categories + int(ghosted_.size());
        ghosted_.push_back(std::move(g));
      }
    }
    base_categories_ = base_categories;
  }

  std::size_t number_of_faces() const { return category_.size(); }
  int category(std::size_t f) const { return category_[f]; }
  int ring_size(std::size_t f) const
  {
    const int c = category_[f];
    return c < base_categories_ ? base_.ring_size(f) : ghosted_[std::size_t(c - base_categories_)].ring_size;
  }
  const int* ring(std::size_t f) const
  {
    const int c = category_[f];
    return c < base_categories_ ? base_.ring(f) : ring_.data() + ghosted_[std::size_t(c - base_categories_)].ring_begin;
  }
  const Control_matrix& quadrature_rows(int c, int r) const
  {
    return c < base_categories_ ? base_.quadrature_rows(c, r) : ghosted_[std::size_t(c - base_categories_)].rows[r];
  }
  const Eigen::VectorXd& quadrature_weights(int c) const
  {
    return base_.quadrature_weights(c < base_categories_ ? c
                                                         : ghosted_[std::size_t(c - base_categories_)].base_category);
  }
  /// faces whose ring holds ghosts
  std::size_t number_of_ghosted_faces() const { return ghosted_.size(); }

  /// The value weights on ring(f) of the limit surface at (xi1, xi2) of face f.
  std::vector<double> value_weights(std::size_t f, double xi1, double xi2) const
  {
    Stencil st;
    base_.root_patch(base_.category(f)).stencil(xi1, xi2, st);
    const Eigen::Map<const Eigen::RowVectorXd> ext(st.row(VALUE), st.m);
    const int c = category_[f];
    if(c < base_categories_) return std::vector<double>(ext.data(), ext.data() + st.m);
    const Eigen::RowVectorXd real = ext * ghosted_[std::size_t(c - base_categories_)].substitution;
    return std::vector<double>(real.data(), real.data() + real.size());
  }
  /// the cache over the extended vertices
  const Patch_cache& extended() const { return base_; }

private:
  struct Ghosted_face
  {
    std::size_t face;
    std::size_t ring_begin;   // in ring_
    int ring_size;
    Eigen::MatrixXd substitution;   // P: extended ring slot -> real ring slot
    int base_category;
    Control_matrix rows[STENCIL_ROWS];
  };

  Patch_cache base_;
  int base_categories_ = 0;
  std::vector<int> category_;
  std::vector<int> ring_;   // the real rings of the ghosted faces (the others' are the base cache's)
  std::vector<Ghosted_face> ghosted_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_ELEMENT_GHOSTED_PATCH_CACHE_H
