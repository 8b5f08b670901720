// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The noise level of a mesh, estimated from the mesh alone, in units of the local edge length.
//
// r_i = (x_i - c_i) . n_i is the height of vertex i over its ring (c_i the ring's centroid, n_i the
// ring's normal, which does not depend on x_i). On a smooth surface r_i is the curvature times h^2 and
// varies slowly; noise makes it jump from vertex to vertex. So the second difference
// d_i = r_i - mean_j r_j cancels the smooth part, and for independent noise of deviation sigma along
// the normals d = (I - W)^2 n has deviation sigma |row_i (I - W)^2| (W the ring average), which is
// computed exactly per vertex. The estimate is the robust deviation (1.4826 x median absolute
// value) of d_i / (|row_i| h_i): features and outliers (impulses) do not move it.
//
// The same normals and edge lengths measure how far a result moved off the input along the normal,
// in the same robust statistic: the discrepancy principle stops diffusion when that reaches the noise.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NOISE_ESTIMATE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NOISE_ESTIMATE_H

#include <CGAL/Anisotropic_fairing/internal/flow/Ring_plane.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Parallel_blocks.h>
#include <CGAL/Anisotropic_fairing/internal/types/Vector3.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>


#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// 1.4826 x the median of |v| (v is reordered): the deviation of a centred normal sample, robustly.
inline double robust_deviation(std::vector<double>& v)
{
  if(v.empty()) return 0.0;
  for(double& x : v) x = std::abs(x);
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(mid), v.end());
  return 1.4826 * v[mid];
}

class Noise_estimate
{
public:
  /// `X`: the input's real vertices (first 3 columns: the geometry); `usable[i]`: vertex i may be
  /// sampled (an interior vertex with a closed fan, not held by the user).
  Noise_estimate(const Triangle_topology& topo, const Control_matrix& X, const std::vector<bool>& usable)
  {
    const std::size_t n = std::size_t(X.rows());
    normal_.assign(3 * n, 0.0);
    edge_.assign(n, 0.0);
    has_height_.assign(n, 0);
    std::vector<double> height(n, 0.0);
    // each vertex on its own (in blocks on every core): its ring's normal, edge length and its height
    parallel_blocks(n, [&](std::size_t first, std::size_t last) {
      std::vector<int> ring;
      Ring_plane r;
      for(std::size_t i = first; i < last; ++i)
      {
        if(!usable[i] || topo.outgoing(int(i)) < 0) continue;
        read_ring(topo, i, ring);
        if(!measure_ring_plane(X, i, ring, r)) continue;
        for(int a = 0; a < 3; ++a) normal_[3 * i + std::size_t(a)] = r.normal[a];
        edge_[i] = r.spacing;
        height[i] = r.height;
        has_height_[i] = 1;
      }
    });
    // d_i and the norm of row i of (I - W)^2, over vertices whose whole ring has a height (NaN: none);
    // the samples are then taken in vertex order, as one loop would
    std::vector<double> sample(n, std::nan(""));
    parallel_blocks(n, [&](std::size_t first, std::size_t last) {
      std::vector<int> ring, inner;
      std::vector<std::pair<int, double>> row;
      for(std::size_t i = first; i < last; ++i)
      {
        if(!has_height_[i]) continue;
        read_ring(topo, i, ring);
        bool complete = true;
        for(int j : ring) complete = complete && has_height_[std::size_t(j)];
        if(!complete) continue;
        const double ki = double(ring.size());
        double d = height[i];
        row.clear();
        row.emplace_back(int(i), 1.0);
        for(int j : ring)
        {
          d -= height[std::size_t(j)] / ki;
          row.emplace_back(j, -2.0 / ki);   // -1/k_i from r_i, -1/k_i from r_j's own vertex
          inner.clear();
          topo.neighbours_ccw(topo.outgoing(j), std::back_inserter(inner));
          for(int m : inner) row.emplace_back(m, 1.0 / (ki * double(inner.size())));
        }
        std::sort(row.begin(), row.end());
        double norm2 = 0, acc = 0;
        for(std::size_t k = 0; k < row.size(); ++k)
        {
          acc += row[k].second;
          if(k + 1 == row.size() || row[k + 1].first != row[k].first) { norm2 += acc * acc; acc = 0; }
        }
        sample[i] = d / (std::sqrt(norm2) * edge_[i]);
      }
    });
    std::vector<double> samples;
    for(double v : sample)
      if(!std::isnan(v)) samples.push_back(v);
    samples_ = samples.size();
    relative_sigma_ = robust_deviation(samples);
  }

  /// sigma / h: the noise's deviation along the normal in units of the local mean edge length
  double relative_sigma() const { return relative_sigma_; }
  std::size_t number_of_samples() const { return samples_; }
  /// h_i (0 where vertex i was not usable)
  double edge_length(std::size_t i) const { return edge_[i]; }

  /// The robust deviation of (Y_i - X0_i) . n_i / h_i over the sampled vertices, rows given in `row_of`
  /// (row_of[i]: the row of vertex i in Y and X0): how far Y moved off X0 along the input's normals.
  /// With `rms`, the root mean square instead: it also sees the few vertices a feature's rounding
  /// moves far.
  template <typename MatrixY, typename Matrix0>
  double relative_displacement(const MatrixY& Y, const Matrix0& X0, const std::vector<int>& row_of,
                               bool rms = false) const
  {
    std::vector<double> v;
    v.reserve(edge_.size());
    for(std::size_t i = 0; i < edge_.size(); ++i)
    {
      if(!has_height_[i]) continue;
      const Eigen::Index r = row_of.empty() ? Eigen::Index(i) : Eigen::Index(row_of[i]);
      double s = 0;
      for(int a = 0; a < 3; ++a) s += (Y(r, a) - X0(r, a)) * normal_[3 * i + std::size_t(a)];
      v.push_back(s / edge_[i]);
    }
    if(rms)
    {
      double sum = 0;
      for(double x : v) sum += x * x;
      return v.empty() ? 0.0 : std::sqrt(sum / double(v.size()));
    }
    return robust_deviation(v);
  }

private:
  std::vector<double> normal_, edge_;
  std::vector<char> has_height_;   // (not vector<bool>: written from several threads)
  double relative_sigma_ = 0;
  std::size_t samples_ = 0;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NOISE_ESTIMATE_H
