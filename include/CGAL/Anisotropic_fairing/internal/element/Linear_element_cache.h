// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The linear (P1) element in the shape of Patch_cache: every face is its own "ring" of three
// vertices, all faces share one category, and the stencils are the hat functions at a degree-2
// rule. The same assembly code then yields the consistent mass matrix area/12 (1 + delta_ij) and the
// cotangent stiffness exactly (Clarenz et al.), so the time stepper does not know which element runs.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_ELEMENT_LINEAR_ELEMENT_CACHE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_ELEMENT_LINEAR_ELEMENT_CACHE_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Stencil_row.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>

#include <Eigen/Core>

#include <algorithm>
#include <limits>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

class Linear_element_cache
{
public:
  /// no curvature at points: the curvature integral comes from the discrete Laplacian instead
  static constexpr bool has_second_derivatives = false;

  /// The elements of the first `faces` faces of `topo` (all by default; the real faces of a ghost layer).
  explicit Linear_element_cache(const Triangle_topology& topo,
                                std::size_t faces = (std::numeric_limits<std::size_t>::max)())
  {
    const std::size_t nf = (std::min)(faces, topo.number_of_faces());
    ring_ids_.resize(3 * nf);
    for(std::size_t f = 0; f < nf; ++f)
      for(int k = 0; k < 3; ++k) ring_ids_[3 * f + std::size_t(k)] = topo.face(f)[k];
    // degree-2 rule with interior points (exact for the quadratic products phi_i phi_j)
    const double a = 1.0 / 6.0, b = 2.0 / 3.0;
    const double pts[3][2] = { { a, a }, { b, a }, { a, b } };
    weights_.setConstant(3, 1.0 / 6.0);   // 1/3 of the reference area 1/2
    for(int r = 0; r < STENCIL_ROWS; ++r) rows_[r].setZero(3, 3);
    for(int q = 0; q < 3; ++q)
    {
      const double x1 = pts[q][0], x2 = pts[q][1];
      rows_[VALUE](q, 0) = 1 - x1 - x2; rows_[VALUE](q, 1) = x1; rows_[VALUE](q, 2) = x2;
      rows_[D1](q, 0) = -1; rows_[D1](q, 1) = 1;
      rows_[D2](q, 0) = -1; rows_[D2](q, 2) = 1;
    }
  }

  std::size_t number_of_faces() const { return ring_ids_.size() / 3; }
  int category(std::size_t) const { return 0; }
  int ring_size(std::size_t) const { return 3; }
  const int* ring(std::size_t f) const { return ring_ids_.data() + 3 * f; }
  const Control_matrix& quadrature_rows(int, int r) const { return rows_[r]; }
  const Eigen::VectorXd& quadrature_weights(int) const { return weights_; }

private:
  std::vector<int> ring_ids_;
  Control_matrix rows_[STENCIL_ROWS];
  Eigen::VectorXd weights_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_ELEMENT_LINEAR_ELEMENT_CACHE_H
