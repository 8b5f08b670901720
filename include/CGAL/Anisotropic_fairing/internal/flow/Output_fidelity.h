// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A fidelity of each vertex's own (Deviation_bound.h) that holds what is written, not the control point:
// the energy sum_i mu_i D_i |y_i - y0_i|^2 / 2, y = P z the written positions (P: the Loop limit masks, or
// the identity when control points are written), y0 the input's, D_i the lumped mass. Its semi-implicit
// step adds tau P^T H P to the step's matrix, H = diag(mu_i D_i), and tau P^T H (y0 - P z) to its
// right-hand side.
// P^T H P couples a held vertex's 1-ring, inside the 3-ring pattern of M; it stays symmetric positive
// semi-definite, so the step's matrix stays positive definite. Held hard, a vertex's limit point stays
// where it started, which pulling the control point to its input could not do.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_OUTPUT_FIDELITY_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_OUTPUT_FIDELITY_H

#include <CGAL/Anisotropic_fairing/internal/loop/Vertex_limit_masks.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <Eigen/SparseCore>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

class Output_fidelity
{
public:
  /// `topo`: the mesh's (with its ghost layer); `limit`: y = the limit points (else the control points).
  Output_fidelity(const Triangle_topology& topo, bool limit) : topo_(topo), limit_(limit) {}

  /// The mask of row i: (vertex, weight) with y_i = sum weight z_vertex.
  const std::vector<std::pair<int, double>>& mask(int i) const
  {
    mask_.clear();
    if(!limit_) mask_.emplace_back(i, 1.0);
    else for_each_limit_weight(topo_, i, [this](int v, double weight) { mask_.emplace_back(v, weight); });
    return mask_;
  }

  /// Whether a mask reads only the real vertices (of `rows`): a border vertex's reads ghosts, and a border
  /// vertex is never written.
  static bool real_mask(const std::vector<std::pair<int, double>>& m, std::size_t rows)
  {
    for(const auto& a : m)
      if(std::size_t(a.first) >= rows) return false;
    return true;
  }

  /// E (free x free) = c_j (P^T H P)_jk over the free rows, c_j the matrix's coefficient of row j (constant
  /// within a component, where P^T H P has all its entries). `held[i]`: mu_i D_i; `index_of_row[j]`: j's
  /// free index, or -1.
  Eigen::SparseMatrix<double> matrix(const std::vector<double>& held, const std::vector<int>& index_of_row,
                                     const std::vector<double>& coefficient, Eigen::Index free_rows) const
  {
    std::vector<Eigen::Triplet<double>> t;
    for(std::size_t i = 0; i < held.size(); ++i)
    {
      if(held[i] == 0) continue;
      const std::vector<std::pair<int, double>>& m = mask(int(i));
      if(!real_mask(m, held.size())) continue;
      for(const auto& a : m)
        for(const auto& b : m)
        {
          const int r = index_of_row[std::size_t(a.first)], c = index_of_row[std::size_t(b.first)];
          if(r >= 0 && c >= 0) t.emplace_back(r, c, coefficient[std::size_t(a.first)] * held[i] * a.second * b.second);
        }
    }
    Eigen::SparseMatrix<double> E(free_rows, free_rows);
    E.setFromTriplets(t.begin(), t.end());
    return E;
  }

  /// R_j += f_j (P^T H (Y0 - P X))_j: the right-hand side's part, f_j the residual's factor of row j.
  void add_to_residual(const std::vector<double>& held, const Control_matrix& X, const Control_matrix& Y0,
                       const std::vector<double>& factor, Control_matrix& R) const
  {
    Eigen::RowVectorXd e(X.cols());
    for(std::size_t i = 0; i < held.size(); ++i)
    {
      if(held[i] == 0) continue;
      const std::vector<std::pair<int, double>>& m = mask(int(i));
      if(!real_mask(m, held.size())) continue;
      e = Y0.row(Eigen::Index(i));
      for(const auto& a : m) e -= a.second * X.row(a.first);
      e *= held[i];
      for(const auto& a : m) R.row(a.first) += factor[std::size_t(a.first)] * a.second * e;
    }
  }

private:
  const Triangle_topology& topo_;
  bool limit_;
  mutable std::vector<std::pair<int, double>> mask_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_OUTPUT_FIDELITY_H
