// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether the input's coordinates lie on a lattice (an 8- or 10-bit export, integer scanner units): each
// axis takes values x0 + k q only, far fewer of them than there are vertices. The error of such an input
// is bounded by half a cell, uniform within it, so along a normal its deviation is about
// sqrt((qx^2 + qy^2 + qz^2) / 3) / sqrt(12). When the noise estimated from the mesh is of that size, the
// lattice explains the noise: the input's vertices are within half a cell of the truth, and the
// Loop limit masks would round creases by more than that before the flow began.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_COORDINATE_LATTICE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_COORDINATE_LATTICE_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

struct Coordinate_lattice
{
  bool found = false;
  std::array<double, 3> cell{ { 0, 0, 0 } };   // per axis (0: the axis takes one value)

  /// The deviation of the rounding error along a direction averaged over all directions.
  double normal_deviation() const
  {
    return std::sqrt((cell[0] * cell[0] + cell[1] * cell[1] + cell[2] * cell[2]) / 3.0 / 12.0);
  }
};

/// The lattice of the first 3 columns of the rows where `used[i]`: per axis, the smallest gap q between
/// distinct values, every value an integer number of q from the smallest (to 1e-3 of q), at most half as
/// many distinct values as rows and at most as many lattice positions. Not found on any other input.
inline Coordinate_lattice coordinate_lattice(const Control_matrix& X, const std::vector<bool>& used)
{
  Coordinate_lattice lattice;
  std::vector<double> v;
  for(Eigen::Index a = 0; a < 3 && a < X.cols(); ++a)
  {
    v.clear();
    for(Eigen::Index i = 0; i < X.rows(); ++i)
      if(used[std::size_t(i)]) v.push_back(X(i, a));
    const std::size_t rows = v.size();
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    if(rows < 8 || 2 * v.size() > rows) return Coordinate_lattice();
    if(v.size() == 1) continue;   // a plane across the axis
    double q = 0;
    for(std::size_t k = 1; k < v.size(); ++k)
      if(q == 0 || v[k] - v[k - 1] < q) q = v[k] - v[k - 1];
    // a lattice with more positions than there are vertices is not shown by them (a gap of rounding
    // errors would make any values "multiples" of it)
    if((v.back() - v.front()) / q > double(rows)) return Coordinate_lattice();
    for(double x : v)
    {
      const double steps = (x - v.front()) / q;
      if(std::abs(steps - std::round(steps)) > 1e-3) return Coordinate_lattice();
    }
    lattice.cell[std::size_t(a)] = q;
  }
  lattice.found = lattice.cell[0] > 0 || lattice.cell[1] > 0 || lattice.cell[2] > 0;
  return lattice;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_COORDINATE_LATTICE_H
