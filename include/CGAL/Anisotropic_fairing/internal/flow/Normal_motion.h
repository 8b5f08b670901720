// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Removes the tangential part of a step's displacement of the control points. div(D grad x) with a
// tensor D that varies along the surface has a tangential component (the gradient of g(k) along the
// principal directions, the divergence of e_a), which moves points within the surface without changing
// its shape in the continuum but, on noise, where g jumps from 1 to almost 0 within one edge, slides
// neighbouring control points over each other in a single step and folds the limit surface. The normal
// part, sum_a g(k_a) k_a, is the anisotropic flow itself. The tangent plane at a control vertex is the
// limit tangent plane (closed-form tangent masks) of the control mesh given, in R^kappa for the columns
// that span the surface: the prefiltered surface M_eps when the tensor has one, the current one otherwise.
// The linear element uses the same masks on its vertices: a smooth estimate of the vertex normal.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NORMAL_MOTION_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NORMAL_MOTION_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Vertex_limit_masks.h>

#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

class Tangential_motion_filter
{
public:
  explicit Tangential_motion_filter(const Ghost_layer& layer) : layer_(layer) {}

  /// Row k of dX is the displacement of vertex free[k]; its first `columns` entries lose their
  /// component in the limit tangent plane of vertex free[k] of X (n x kappa, the real vertices).
  void remove(const Control_matrix& X, int columns, const std::vector<int>& free, Control_matrix& dX) const
  {
    const Control_matrix extended = layer_.has_boundary() ? layer_.extend(X) : Control_matrix();
    // ghosts: the tangent masks of fans next to a border
    const Control_matrix& E = layer_.has_boundary() ? extended : X;
    std::vector<double> tu(std::size_t(X.cols())), tv(std::size_t(X.cols()));
    for(std::size_t k = 0; k < free.size(); ++k)
    {
      vertex_limit_tangents(*layer_.topology, E, free[k], tu.data(), tv.data());
      double g11 = 0, g12 = 0, g22 = 0, p = 0, q = 0;
      double* d = dX.row(Eigen::Index(k)).data();
      for(int c = 0; c < columns; ++c)
      {
        g11 += tu[std::size_t(c)] * tu[std::size_t(c)];
        g12 += tu[std::size_t(c)] * tv[std::size_t(c)];
        g22 += tv[std::size_t(c)] * tv[std::size_t(c)];
        p += tu[std::size_t(c)] * d[c];
        q += tv[std::size_t(c)] * d[c];
      }
      const double det = g11 * g22 - g12 * g12;
      if(!(det > 0)) continue;   // no tangent plane (a degenerate fan): leave the displacement as it is
      const double a = (g22 * p - g12 * q) / det, b = (g11 * q - g12 * p) / det;
      for(int c = 0; c < columns; ++c) d[c] -= a * tu[std::size_t(c)] + b * tv[std::size_t(c)];
    }
  }

private:
  const Ghost_layer& layer_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NORMAL_MOTION_H
