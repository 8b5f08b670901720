// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Impulsive noise: a share of the vertices thrown off the surface, the rest left clean. The noise
// estimate is robust, so it sees the clean majority and calls the mesh nearly noise-free; every flow
// then stops before its first step and the spikes stay. A spike is told from a feature by its
// neighbourhood, not by its height: a crease or a corner stands out of its ring together with the
// vertices along it, a spike alone (or with one other spike beside it). On clean meshes, features that
// stand out alone (tips, cone points) are rare; impulsive noise makes them a population. So the spikes
// are put back at the centroid of their ring only when they are at least one vertex in fifty, and only
// those (the shares measured on clean meshes: the manual's Parameters page, "Impulsive noise").

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_ISOLATED_SPIKES_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_ISOLATED_SPIKES_H

#include <CGAL/Anisotropic_fairing/internal/flow/Ring_plane.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Process_part.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Parallel_blocks.h>
#include <CGAL/Anisotropic_fairing/internal/types/Vector3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The constants of the spike test.
struct Spike_test
{
  double outlier = 4;          // a spike stands out of its ring by this many robust deviations of all heights,
  double least_height = 0.1;   // and by at least this share of its ring's edge length
  double population = 0.02;    // the spikes found are removed only if at least this share of the vertices
  int rounds = 4;              // a spike removed can uncover one it hid
};

/// The isolated spikes among the vertices with `usable[i]` (interior, free, a closed fan) of the real
/// vertices X (first 3 columns) moved to the centroid of their ring (not along the ring's normal: next
/// to other spikes that normal is tilted, and the move would fold thin triangles of a scan). Returns how
/// many vertices were moved (0: too few to be noise, X unchanged). `part`: the part of the mesh a process holds
/// (it moves its own vertices, its other rows read from their owners).
inline std::size_t remove_isolated_spikes(const Triangle_topology& topo, const std::vector<bool>& usable,
                                          Control_matrix& X, const Part_view& part = whole_mesh_view(),
                                          const Spike_test& test = Spike_test())
{
  const std::size_t n = std::size_t(X.rows());
  std::vector<double> height(n), centre(3 * n), measured(n);
  // e_i = (x_i - c_i) . n_i / h_i: the height of vertex i over its ring's plane (Ring_plane.h) in units
  // of its mean distance to the ring
  const auto measure = [&] {
    parallel_blocks(n, [&](std::size_t first, std::size_t last) {
      std::vector<int> ring;
      Ring_plane r;
      for(std::size_t i = first; i < last; ++i)
      {
        measured[i] = 0;
        if(!usable[i] || topo.outgoing(int(i)) < 0) continue;
        read_ring(topo, i, ring);
        if(std::any_of(ring.begin(), ring.end(), [n](int j) { return std::size_t(j) >= n; }) ||
           !measure_ring_plane(X, i, ring, r))
          continue;
        for(int a = 0; a < 3; ++a) centre[3 * i + std::size_t(a)] = r.centre[a];
        height[i] = r.height / r.spacing;
        measured[i] = 1;
      }
    });
    part.refresh(height);
    part.refresh(measured);
  };
  // the neighbours of i that stand out on the same side by at least half as much
  const auto companions = [&](std::size_t i, std::vector<int>& out) {
    out.clear();
    std::vector<int> ring;
    read_ring(topo, i, ring);
    for(int j : ring)
      if(measured[std::size_t(j)] != 0 && height[std::size_t(j)] * height[i] > 0 &&
         std::abs(height[std::size_t(j)]) > 0.5 * std::abs(height[i]))
        out.push_back(j);
  };
  // the threshold: `outlier` robust deviations of the heights about their median (a curved surface's
  // heights are not centred on 0), read again each round, once the spikes found have stopped inflating it
  std::size_t measured_count = 0;
  const auto threshold = [&] {
    std::vector<double> sample;
    for(std::size_t i = 0; i < n; ++i)
      if(measured[i] != 0 && part.owns_vertex(i)) sample.push_back(height[i]);
    sample = part.gathered(std::move(sample));
    measured_count = sample.size();
    if(sample.empty()) return std::numeric_limits<double>::infinity();
    const auto mid = sample.begin() + std::ptrdiff_t(sample.size() / 2);
    std::nth_element(sample.begin(), mid, sample.end());
    const double median = *mid;
    for(double& x : sample) x = std::abs(x - median);
    std::nth_element(sample.begin(), mid, sample.end());
    return std::max(test.outlier * 1.4826 * *mid, test.least_height);
  };
  std::vector<char> moved(n, 0);
  for(int round = 0; round < test.rounds; ++round)
  {
    measure();
    const double least = threshold();
    std::vector<int> spikes, mine, theirs;
    for(std::size_t i = 0; i < n; ++i)
    {
      if(measured[i] == 0 || !part.owns_vertex(i) || !(std::abs(height[i]) >= least)) continue;
      companions(i, mine);
      bool alone = mine.empty();
      if(mine.size() == 1)   // a pair of spikes: each the other's only companion
      {
        companions(std::size_t(mine[0]), theirs);
        alone = theirs.size() == 1;
      }
      if(alone) spikes.push_back(int(i));
    }
    const std::size_t found = part.count(spikes.size());
    if(round == 0 && double(found) < test.population * double(measured_count)) return 0;
    if(found == 0) break;
    for(int i : spikes)
    {
      X.row(i).head(3) = vec3(&centre[3 * std::size_t(i)]).transpose();
      moved[std::size_t(i)] = 1;
    }
    part.refresh(X);
  }
  return part.count(std::size_t(std::count(moved.begin(), moved.end(), char(1))));
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_ISOLATED_SPIKES_H
