// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A time step that follows the mesh's density, for the automatic isotropic and uniform runs. A graded mesh
// is fine where its surface has detail, and one global time step smooths over one distance everywhere:
// the small parts of a graded scan lose their shape while the coarse parts are still noisy. Scaling the
// time at vertex i by s_i = (h_i / h)^2, with h_i the edge length around it and h its component's mean,
// smooths over about the same number of rings everywhere, as the umbrella operators do (the figures: the
// manual's Validation page, "Figures behind the defaults"). The anisotropic flow keeps one time step: it
// reads features from curvature, and a density-scaled step would leave the noise on refined creases.
//
// In the weak form, 1/tau becomes 1/(tau s(x)): the mass matrix M_ij becomes M_ij / sqrt(s_i s_j), which
// keeps the system symmetric. h_i is read on the input, averaged with its ring three times: noise
// lengthens an edge only a little, and the averaging removes most of that.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_LOCAL_TIME_SCALE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_LOCAL_TIME_SCALE_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Mesh_components.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Process_part.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// s_i per vertex (1 for a vertex on no real face); `edge[c]` is the mean edge length of component c; `part`: the
/// part of the mesh a process holds (its rows not owned take their owners' h after each averaging).
inline std::vector<double> local_time_scale(const Triangle_topology& topo, std::size_t real_faces,
                                            const Control_matrix& X, const Mesh_components& components,
                                            const std::vector<double>& edge,
                                            const Part_view& part = whole_mesh_view())
{
  const std::size_t n = std::size_t(X.rows());
  auto for_each_edge = [&](auto&& f) {   // each real face's three edges
    for(std::size_t t = 0; t < real_faces; ++t)
      for(int k = 0; k < 3; ++k) f(topo.face(t)[k], topo.face(t)[(k + 1) % 3]);
  };
  std::vector<double> h(n, 0.0), count(n, 0.0);
  for_each_edge([&](int a, int b) {
    const double l = (X.row(a).head(3) - X.row(b).head(3)).norm();
    h[std::size_t(a)] += l; h[std::size_t(b)] += l;
    count[std::size_t(a)] += 1; count[std::size_t(b)] += 1;
  });
  for(std::size_t i = 0; i < n; ++i) h[i] = count[i] > 0 ? h[i] / count[i] : 0.0;
  part.refresh(h);
  for(int pass = 0; pass < 3; ++pass)
  {
    std::vector<double> ring(n, 0.0);
    for_each_edge([&](int a, int b) {
      ring[std::size_t(a)] += h[std::size_t(b)];
      ring[std::size_t(b)] += h[std::size_t(a)];
    });
    for(std::size_t i = 0; i < n; ++i)
      if(count[i] > 0) h[i] = 0.5 * (h[i] + ring[i] / count[i]);
    part.refresh(h);
  }
  std::vector<double> s(n, 1.0);
  for(std::size_t i = 0; i < n; ++i)
  {
    const int c = components.of_vertex[i];
    if(c >= 0 && h[i] > 0 && edge[std::size_t(c)] > 0)
      s[i] = (h[i] / edge[std::size_t(c)]) * (h[i] / edge[std::size_t(c)]);
  }
  return s;
}

/// w_i = 1 / sqrt(s_i): the mass matrix of the step is M_ij w_i w_j (Step_system.h).
inline std::vector<double> mass_weights(std::vector<double> s)
{
  for(double& x : s) x = 1 / std::sqrt(x);
  return s;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_LOCAL_TIME_SCALE_H
