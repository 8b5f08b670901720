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
// The part of x_i - c_i within the ring's plane, differenced in the same way, measures the noise across the
// normals (tangential): its per-vertex samples are kept for the noise model (Noise_model.h) with the normal ones.
//
// The same normals and edge lengths measure how far a result moved off the input along the normal,
// in the same robust statistic: the discrepancy principle stops diffusion when that reaches the noise.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NOISE_ESTIMATE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NOISE_ESTIMATE_H

#include <CGAL/Anisotropic_fairing/internal/flow/Noise_correlation.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Ring_plane.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Keyed_normal.h>
#include <CGAL/Anisotropic_fairing/internal/types/Parallel_blocks.h>
#include <CGAL/Anisotropic_fairing/internal/types/Vector3.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>


#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
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
  /// sampled (an interior vertex with a closed fan, not held by the user); `keys`: each vertex's of the topology,
  /// which the reference noise is drawn by (Vertex_keys.h; empty: the vertex's number); `part`: the part of the
  /// mesh a process holds (Process_part.h: its own vertices are its samples; none: the whole mesh).
  Noise_estimate(const Triangle_topology& topo, const Control_matrix& X, const std::vector<bool>& usable,
                 const std::vector<std::uint64_t>& keys = std::vector<std::uint64_t>(),
                 const Part_view* part = nullptr)
    : part_(part ? part : &whole_mesh_view())
  {
    const std::size_t n = std::size_t(X.rows());
    normal_.assign(3 * n, 0.0);
    edge_.assign(n, 0.0);
    has_height_.assign(n, 0);
    std::vector<double> height(n, 0.0), across(3 * n, 0.0);
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
        for(int a = 0; a < 3; ++a)
          across[3 * i + std::size_t(a)] = X(Eigen::Index(i), a) - r.centre[a] - r.height * r.normal[a];
        has_height_[i] = 1;
      }
    });
    measure_differences(topo, height, across, keys);
    // a process's samples are its own vertices', read with its neighbours' as their owners read them
    for(std::vector<double>* f : { &normal_sample_, &tangential_sample_, &normal_null_, &tangential_null_ })
      part_->refresh(*f);
    for(std::vector<double>& f : correlated_null_) part_->refresh(f);
    std::vector<double> samples = own_values(normal_sample_);
    samples_ = samples.size();
    read_sigma_ = robust_deviation(samples);
    std::array<double, correlation_steps + 1> null_sigma;
    for(std::size_t k = 0; k < null_sigma.size(); ++k)
    {
      std::vector<double> v = own_values(correlated_null_[k]);
      null_sigma[k] = robust_deviation(v);
    }
    correlation_ =
      measure_noise_correlation(topo, normal_sample_, read_sigma_, correlated_null_, null_sigma, *part_);
    relative_sigma_ = read_sigma_ * correlation_.factor();
  }

  /// sigma / h: the noise's deviation along the normal in units of the local mean edge length, its correlation
  /// over the surface taken into account (Noise_correlation.h)
  double relative_sigma() const { return relative_sigma_; }
  /// The robust deviation of the samples themselves: sigma / h for noise independent from vertex to vertex.
  double read_sigma() const { return read_sigma_; }
  const Noise_correlation& correlation() const { return correlation_; }
  std::size_t number_of_samples() const { return samples_; }
  /// Vertex i's second difference of heights in units of its own deviation under unit noise and of h_i: a sample of
  /// N(0, (sigma/h)^2) under noise of deviation sigma along the normals (NaN where not measured).
  double normal_sample(std::size_t i) const { return normal_sample_[i]; }
  /// The squared length of the same difference of the in-plane offsets, in the same units: (sigma_t/h)^2 times a
  /// chi-square with 2 degrees of freedom under noise of deviation sigma_t in each direction across the normal.
  double tangential_sample(std::size_t i) const { return tangential_sample_[i]; }
  /// The squares of both under unit noise drawn at every vertex (NaN where not measured): the samples of a mesh
  /// whose noise does not vary, which the noise model's local scales are measured against.
  const std::vector<double>& normal_null() const { return normal_null_; }
  const std::vector<double>& tangential_null() const { return tangential_null_; }
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
      if(!has_height_[i] || !part_->owns_vertex(i)) continue;
      const Eigen::Index r = row_of.empty() ? Eigen::Index(i) : Eigen::Index(row_of[i]);
      double s = 0;
      for(int a = 0; a < 3; ++a) s += (Y(r, a) - X0(r, a)) * normal_[3 * i + std::size_t(a)];
      v.push_back(s / edge_[i]);
    }
    if(rms)
    {
      std::vector<double> sums{ 0.0, double(v.size()) };
      for(double x : v) sums[0] += x * x;
      part_->sum(sums);
      return sums[1] > 0 ? std::sqrt(sums[0] / sums[1]) : 0.0;
    }
    v = part_->gathered(std::move(v));
    return robust_deviation(v);
  }

private:
  // the measured (not NaN) values of `field` at every process's own vertices
  std::vector<double> own_values(const std::vector<double>& field) const
  {
    std::vector<double> v;
    for(std::size_t i = 0; i < field.size(); ++i)
      if(!std::isnan(field[i]) && part_->owns_vertex(i)) v.push_back(field[i]);
    return part_->gathered(std::move(v));
  }

  // d_i and the norm of row i of (I - W)^2, over vertices whose whole ring has a height (NaN: none), the same of
  // the in-plane offsets and of unit noise; the samples are then taken in vertex order, as one loop would
  void measure_differences(const Triangle_topology& topo, const std::vector<double>& height,
                           const std::vector<double>& across, const std::vector<std::uint64_t>& keys)
  {
    const std::size_t n = edge_.size();
    normal_sample_.assign(n, std::nan(""));
    tangential_sample_.assign(n, std::nan(""));
    // the same differences of unit noise drawn at every vertex (of the topology: a ring may reach a ghost vertex
    // where the caller samples a border): what they give where the noise does not vary
    Control_matrix unit_noise(Eigen::Index(std::max(n, topo.number_of_vertices())), 3);
    for(Eigen::Index i = 0; i < unit_noise.rows(); ++i)
    {
      const std::uint64_t key = keys.empty() ? std::uint64_t(i) : keys[std::size_t(i)];
      for(int a = 0; a < 3; ++a) unit_noise(i, a) = keyed_normal(20261129u, key, unsigned(a));
    }
    normal_null_.assign(n, std::nan(""));
    tangential_null_.assign(n, std::nan(""));
    const Correlated_null_samples field = averaged_unit_noise(topo, unit_noise, n, *part_);
    for(auto& v : correlated_null_) v.assign(n, std::nan(""));
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
        Eigen::Vector3d t = vec3(&across[3 * i]);
        row.clear();
        row.emplace_back(int(i), 1.0);
        for(int j : ring)
        {
          d -= height[std::size_t(j)] / ki;
          t -= vec3(&across[3 * std::size_t(j)]) / ki;
          row.emplace_back(j, -2.0 / ki);   // -1/k_i from r_i, -1/k_i from r_j's own vertex
          inner.clear();
          topo.neighbours_ccw(topo.outgoing(j), std::back_inserter(inner));
          for(int m : inner) row.emplace_back(m, 1.0 / (ki * double(inner.size())));
        }
        std::sort(row.begin(), row.end());
        double norm2 = 0, acc = 0;
        Eigen::RowVector3d null(0, 0, 0);
        std::array<double, correlation_steps + 1> averaged{};
        for(std::size_t k = 0; k < row.size(); ++k)
        {
          acc += row[k].second;
          if(k + 1 == row.size() || row[k + 1].first != row[k].first)
          {
            norm2 += acc * acc;
            null += acc * unit_noise.row(row[k].first);
            for(std::size_t f = 0; f < averaged.size(); ++f) averaged[f] += acc * field[f][std::size_t(row[k].first)];
            acc = 0;
          }
        }
        const double unit2 = norm2 * edge_[i] * edge_[i];
        normal_sample_[i] = d / std::sqrt(unit2);
        const Eigen::Vector3d n_i = vec3(&normal_[3 * i]);
        tangential_sample_[i] = (t - t.dot(n_i) * n_i).squaredNorm() / unit2;
        normal_null_[i] = null(0) * null(0) / norm2;
        tangential_null_[i] = (null(1) * null(1) + null(2) * null(2)) / norm2;
        for(std::size_t f = 0; f < averaged.size(); ++f) correlated_null_[f][i] = averaged[f] / std::sqrt(norm2);
      }
    });
  }

  // The first column of `unit_noise` averaged k = 0..correlation_steps times with its ring's mean (half each) at
  // the first `n` vertices (a ghost vertex's fan is open: it keeps its value), each scaled to unit root mean square
  // over them.
  static Correlated_null_samples averaged_unit_noise(const Triangle_topology& topo, const Control_matrix& unit_noise,
                                                     std::size_t n, const Part_view& part)
  {
    const std::size_t m = std::size_t(unit_noise.rows());
    Correlated_null_samples field;
    field[0].resize(m);
    for(std::size_t i = 0; i < m; ++i) field[0][i] = unit_noise(Eigen::Index(i), 0);
    for(std::size_t k = 1; k < field.size(); ++k) field[k] = averaged_with_ring(topo, field[k - 1], n, part);
    for(std::vector<double>& f : field) to_unit_rms(f, n, part);
    return field;
  }

  const Part_view* part_;
  std::vector<double> normal_, edge_, normal_sample_, tangential_sample_, normal_null_, tangential_null_;
  std::vector<char> has_height_;   // (not vector<bool>: written from several threads)
  // the signed samples of unit noise averaged k times with its ring's mean, in units of its deviation
  Correlated_null_samples correlated_null_;
  double relative_sigma_ = 0, read_sigma_ = 0;
  Noise_correlation correlation_;
  std::size_t samples_ = 0;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NOISE_ESTIMATE_H
