// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Which vertices a boundary holds fixed. Fixing the boundary vertices alone (the paper) lets the limit
// boundary curve move wherever an interior basis function is non-zero on it (next to corners with
// m = 2, to m >= 4 vertices, to extraordinary apexes): a planar grid then slides by 0.37 edge lengths
// in 10 steps (doc/Anisotropic_fairing/design/loop-fem.md section 6). The default also fixes this influence set: every
// vertex whose
// (ghost-substituted) basis function is non-zero somewhere on the limit boundary curve.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_BOUNDARY_CONSTRAINTS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_BOUNDARY_CONSTRAINTS_H

#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/element/Ghosted_patch_cache.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// Marks the boundary vertices and, with `with_influence_set`, every real vertex whose basis function
/// has a weight above 1e-12 at five points (s = .13, .37, .5, .71, .93) of some border edge.
inline std::vector<bool> boundary_constrained_vertices(const Ghost_layer& gl, const Ghosted_patch_cache& cache,
                                                       bool with_influence_set)
{
  std::vector<bool> fixed(gl.real_vertices, false);
  for(int v : gl.boundary_vertices) fixed[std::size_t(v)] = true;
  if(!with_influence_set || gl.boundary_vertices.empty()) return fixed;
  const Triangle_topology& topo = *gl.topology;
  const double samples[5] = { 0.13, 0.37, 0.5, 0.71, 0.93 };
  for(std::size_t f = 0; f < gl.real_faces; ++f)
    for(int k = 0; k < 3; ++k)
    {
      const int h = int(3 * f) + k;
      if(std::size_t(topo.face_of(topo.opposite(h))) < gl.real_faces) continue;
      // h is a border edge of the real mesh (its twin is a ghost triangle): corners k -> k+1
      for(double s : samples)
      {
        const double xi1 = k == 0 ? s : k == 1 ? 1 - s : 0.0;
        const double xi2 = k == 0 ? 0.0 : k == 1 ? s : 1 - s;
        const std::vector<double> w = cache.value_weights(f, xi1, xi2);
        const int* ring = cache.ring(f);
        for(std::size_t j = 0; j < w.size(); ++j)
          if(std::abs(w[j]) > 1e-12) fixed[std::size_t(ring[j])] = true;
      }
    }
  return fixed;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_BOUNDARY_CONSTRAINTS_H
