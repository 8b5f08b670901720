// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A vertex against the plane of its ring, as the noise estimate and the spike test read it: the ring's
// centroid c, its normal n (the sum of the cross products of consecutive ring vertices about c, which
// does not depend on the vertex itself), the mean distance h from the vertex to its ring and the height
// (x - c) . n of the vertex over that plane.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_RING_PLANE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_RING_PLANE_H

#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Vector3.h>

#include <cmath>
#include <cstddef>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

struct Ring_plane
{
  double centre[3] = { 0, 0, 0 }, normal[3] = { 0, 0, 0 };   // the normal of unit length
  double spacing = 0;                                        // h
  double height = 0;                                         // (x - c) . n, in lengths
};

/// The ring of vertex i, its neighbours in counterclockwise order.
inline void read_ring(const Triangle_topology& topo, std::size_t i, std::vector<int>& ring)
{
  ring.clear();
  topo.neighbours_ccw(topo.outgoing(int(i)), std::back_inserter(ring));
}

/// Vertex i of X (first 3 columns) against its ring (`ring`: read_ring's, vertices of X only); false
/// where the ring spans no plane (a degenerate or non-finite ring), r then unspecified.
inline bool measure_ring_plane(const Control_matrix& X, std::size_t i, const std::vector<int>& ring, Ring_plane& r)
{
  r = Ring_plane();
  double* c = r.centre;
  double nrm[3] = { 0, 0, 0 }, h = 0;
  for(int j : ring)
    for(int a = 0; a < 3; ++a) c[a] += X(j, a) / double(ring.size());
  for(std::size_t k = 0; k < ring.size(); ++k)
  {
    const int p = ring[k], q = ring[(k + 1) % ring.size()];
    const double u[3] = { X(p, 0) - c[0], X(p, 1) - c[1], X(p, 2) - c[2] };
    const double w[3] = { X(q, 0) - c[0], X(q, 1) - c[1], X(q, 2) - c[2] };
    vec3(nrm) += vec3(u).cross(vec3(w));
    h += (X.row(p).head(3) - X.row(Eigen::Index(i)).head(3)).norm();
  }
  const double len = vec3(nrm).norm();
  h /= double(ring.size());
  if(!(len > 0) || !(h > 0) || !std::isfinite(len) || !std::isfinite(h)) return false;
  for(int a = 0; a < 3; ++a) r.normal[a] = nrm[a] / len;
  r.spacing = h;
  for(int a = 0; a < 3; ++a) r.height += (X(Eigen::Index(i), a) - c[a]) * r.normal[a];
  return true;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_RING_PLANE_H
