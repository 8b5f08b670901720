// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Control points whose Loop limit points are given positions: solves P Z = Y for the free vertices, P the
// limit masks (Vertex_limit_masks.h), the other vertices' control points held at Y. The limit surface then
// passes through the input's vertices, so a run that takes no step writes the input back, and creases are
// not rounded before the flow has begun (the limit masks alone turn a clean CAD mesh's normals by degrees).
// P is not symmetric; on the regular lattice its eigenvalues lie in [1/4, 1], so BiCGSTAB with the
// diagonal converges in a few dozen iterations.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_LIMIT_INTERPOLATION_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_LIMIT_INTERPOLATION_H

#include <CGAL/Anisotropic_fairing/internal/loop/Loop_rules.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// Z with P Z = Y on the rows where `solved[i]` (rows < solved.size(), whose 1-rings hold only such rows
/// or held ones below solved.size()); Z = Y elsewhere. Returns false, Z = Y, when the solve fails.
inline bool interpolating_control_points(const Triangle_topology& topo, const Control_matrix& Y, const std::vector<bool>& solved,
                                         Control_matrix& Z)
{
  Z = Y;
  const std::size_t n = solved.size();
  std::vector<Eigen::Index> unknown(n, -1);
  Eigen::Index count = 0;
  for(std::size_t i = 0; i < n; ++i)
    if(solved[i] && topo.outgoing(int(i)) >= 0) unknown[i] = count++;
  if(count == 0) return true;
  std::vector<Eigen::Triplet<double>> t;
  Control_matrix b(count, Y.cols());
  for(std::size_t i = 0; i < n; ++i)
  {
    const Eigen::Index r = unknown[i];
    if(r < 0) continue;
    const int valence = topo.valence(int(i));
    const double chi = loop_limit_weight(valence);
    t.emplace_back(r, r, 1.0 - valence * chi);
    b.row(r) = Y.row(Eigen::Index(i));
    const int h0 = topo.outgoing(int(i));
    int h = h0;
    do {
      const std::size_t j = std::size_t(topo.target(h));
      if(j >= n) { Z = Y; return false; }   // a mask reading a ghost: not a row to solve
      if(unknown[j] >= 0) t.emplace_back(r, unknown[j], chi);
      else b.row(r) -= chi * Y.row(Eigen::Index(j));
      h = topo.ccw(h);
    } while(h != h0);
  }
  Eigen::SparseMatrix<double> P(count, count);
  P.setFromTriplets(t.begin(), t.end());
  Eigen::BiCGSTAB<Eigen::SparseMatrix<double>, Eigen::DiagonalPreconditioner<double>> solver;
  solver.setTolerance(1e-13);
  solver.setMaxIterations(1000);
  solver.compute(P);
  Control_matrix x(count, Y.cols());
  for(Eigen::Index c = 0; c < Y.cols(); ++c)
  {
    const Eigen::VectorXd column = b.col(c);
    x.col(c) = solver.solveWithGuess(column, column);
    if(solver.info() != Eigen::Success || !x.col(c).allFinite()) return false;
  }
  for(std::size_t i = 0; i < n; ++i)
    if(unknown[i] >= 0) Z.row(Eigen::Index(i)) = x.row(unknown[i]);
  return true;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_LOOP_LIMIT_INTERPOLATION_H
