// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The noise a mesh has, estimated from the mesh alone, beyond the one deviation along the normals that
// Noise_estimate.h reads:
// - across the normals: the in-plane offsets of a vertex from its ring, differenced as the heights are; a
//   displacement within the surface changes no normal, so a model of noise along the normals only would charge a
//   flow that evens it out with motion it did not cause;
// - over the surface: each vertex's deviation from the samples around it (three rings of averaging of the
//   squared samples, each clipped at three deviations so that a crease or a spike does not carry its
//   neighbourhood), shrunk toward the global deviation by how much of the scales' spread the same differences and
//   averaging give to unit noise drawn at every vertex (what sampling alone makes): a homoscedastic mesh reads
//   nearly 1 everywhere, a scanner's depth-dependent noise keeps its variation;
// - impulses: the samples in units of their local deviation as a Gaussian core plus a wider component (a
//   two-component mixture fitted by EM, both deviations free, from a few starts), each vertex given its
//   probability of belonging to the wider one; a vertex two of whose ring neighbours stand out on the same side
//   lies on a feature line, not on a hit, and gets none;
// - quantisation: coordinates on a lattice (every value of an axis a whole number of steps from the smallest),
//   whose rounding is uniform within the cell; found only where the step is below the mean edge length and the
//   axis has at least 32 levels (a part designed on a grid is not noise).
// Reported in the run's `choices` and its report.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NOISE_MODEL_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NOISE_MODEL_H

#include <CGAL/Anisotropic_fairing/internal/flow/Noise_estimate.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Process_part.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Parallel_blocks.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

struct Noise_model
{
  double normal = 0;       // sigma_n / h, along the normals (Noise_estimate::relative_sigma)
  double tangential = 0;   // sigma_t / h, in each direction across the normal
  /// per vertex, the factor of the global deviation there (1 where not measured)
  std::vector<double> normal_scale, tangential_scale;
  double normal_spread = 1, tangential_spread = 1;   // the scales' 90th over their 10th percentile
  double hit_share = 0;        // impulses: the share of the measured vertices more likely hit than not
  double hit_deviation = 0;    // the hits' deviation in units of the samples' own (Noise_estimate::read_sigma)
  std::vector<double> hit_probability;
  std::array<double, 3> cell{ { 0, 0, 0 } };   // the lattice's step per axis, model units (0: none)
  double mean_edge = 0;                          // h, model units

  /// The deviation along the normal at vertex i in units of h, impulses included (their expected variance).
  double normal_at(std::size_t i) const
  {
    const double p = hit_probability.empty() ? 0.0 : hit_probability[i];
    return normal * normal_scale[i] * std::sqrt(1 + p * (hit_deviation * hit_deviation - 1));
  }
  double tangential_at(std::size_t i) const { return tangential * tangential_scale[i]; }

  /// One sentence for the report's `choices`.
  std::string description() const
  {
    char text[400];
    std::snprintf(text, sizeof text, "noise model: %.3g h along the normals and %.3g h across them, varying by "
                  "%.3gx and %.3gx over the surface (90th over 10th percentile)", normal, tangential, normal_spread,
                  tangential_spread);
    std::string s = text;
    if(hit_share > 0)
    {
      std::snprintf(text, sizeof text, "; impulses on %.2g%% of the vertices, %.3gx the deviation", 100 * hit_share,
                    hit_deviation);
      s += text;
    }
    if(cell[0] > 0 || cell[1] > 0 || cell[2] > 0)
    {
      const double largest = std::max({ cell[0], cell[1], cell[2] });
      std::snprintf(text, sizeof text, "; coordinates on a lattice of steps %.3g, %.3g, %.3g (0: none; rounding "
                    "uniform within the cell, of deviation up to %.2g h)", cell[0], cell[1], cell[2],
                    mean_edge > 0 ? largest / std::sqrt(12.0) / mean_edge : 0.0);
      s += text;
    }
    return s;
  }
};

namespace noise_model_detail {

constexpr double clip = 3;     // a sample counts at most this many deviations toward a local scale
constexpr int rings = 3;       // of averaging around each vertex
constexpr int clip_passes = 3; // the clip set by the global deviation, then twice by the local one
constexpr double core_ratio = 2;   // the wider component must be at least this much wider to be impulses

// value[i] averaged over the `rings`-ring of i (weights of repeated ring averaging), NaN samples left out; the rows
// a process does not own read from their owners after each ring
inline std::vector<double> ring_average(const Triangle_topology& topo, const std::vector<double>& value,
                                        const Part_view& part)
{
  const std::size_t n = value.size();
  std::vector<double> sum(n), weight(n), next_sum(n), next_weight(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const bool has = !std::isnan(value[i]);
    sum[i] = has ? value[i] : 0.0;
    weight[i] = has ? 1.0 : 0.0;
  }
  for(int r = 0; r < rings; ++r)
  {
    parallel_blocks(n, [&](std::size_t first, std::size_t last) {
      std::vector<int> ring;
      for(std::size_t i = first; i < last; ++i)
      {
        next_sum[i] = sum[i];
        next_weight[i] = weight[i];
        if(topo.outgoing(int(i)) < 0) continue;
        read_ring(topo, i, ring);
        for(int j : ring)
          if(std::size_t(j) < n)
          {
            next_sum[i] += sum[std::size_t(j)];
            next_weight[i] += weight[std::size_t(j)];
          }
      }
    });
    sum.swap(next_sum);
    weight.swap(next_weight);
    part.refresh(sum);
    part.refresh(weight);
  }
  for(std::size_t i = 0; i < n; ++i) sum[i] = weight[i] > 0 ? sum[i] / weight[i] : std::nan("");
  return sum;
}

// of every process's `v`
inline double percentile(std::vector<double> v, double q, const Part_view& part)
{
  v = part.gathered(std::move(v));
  if(v.empty()) return std::nan("");
  const std::size_t k = std::min(v.size() - 1, std::size_t(q * double(v.size())));
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
  return v[k];
}

// Each vertex's factor of the global deviation from its squared samples `square` (NaN: none; `unit`: their value
// under unit noise), shrunk toward 1 by what the same averaging gives `null`, the squares of the same differences
// of unit noise (their value 1 under unit noise). The samples are clipped at `clip` deviations of the global,
// then again of the local deviation so read.
inline std::vector<double> local_scales(const Triangle_topology& topo, const std::vector<double>& square, double unit,
                                        const std::vector<double>& null_square, double null_unit, double& spread,
                                        const Part_view& part, int passes = clip_passes)
{
  const std::size_t n = square.size();
  std::vector<double> scale(n, 1.0);
  spread = 1;
  const auto local_mean = [&](const std::vector<double>& v, double u) {
    std::vector<double> clipped(n, std::nan(""));
    for(std::size_t i = 0; i < n; ++i)
      if(!std::isnan(v[i])) clipped[i] = std::min(v[i], clip * clip * u);
    std::vector<double> mean = ring_average(topo, clipped, part);
    for(int pass = 1; pass < passes; ++pass)
    {
      for(std::size_t i = 0; i < n; ++i)
        if(!std::isnan(v[i])) clipped[i] = std::min(v[i], clip * clip * mean[i]);
      mean = ring_average(topo, clipped, part);
    }
    return mean;
  };
  if(!(unit > 0)) return scale;
  const std::vector<double> local = local_mean(square, unit), null = local_mean(null_square, null_unit);
  // the log-scales about their mean, and the variances of both
  const auto log_scales = [&](const std::vector<double>& m, double& variance) {
    std::vector<double> l(n, std::nan(""));
    std::vector<double> sums(3, 0.0);   // of the own rows' log-scales, their squares, their number
    for(std::size_t i = 0; i < n; ++i)
      if(!std::isnan(square[i]) && m[i] > 0)
      {
        l[i] = 0.5 * std::log(m[i]);
        if(!part.owns_vertex(i)) continue;
        sums[0] += l[i];
        sums[1] += l[i] * l[i];
        sums[2] += 1;
      }
    part.sum(sums);
    const double s = sums[0], s2 = sums[1], k = sums[2];
    variance = k > 1 ? (s2 - s * s / k) / (k - 1) : 0.0;
    for(double& x : l) x -= k > 0 ? s / k : 0.0;
    return l;
  };
  double total = 0, sampling = 0;
  const std::vector<double> l = log_scales(local, total);
  log_scales(null, sampling);
  const double kept = total > sampling ? 1 - sampling / total : 0.0;
  std::vector<double> kept_scales;
  for(std::size_t i = 0; i < n; ++i)
    if(!std::isnan(l[i]))
    {
      scale[i] = std::exp(kept * l[i]);
      if(part.owns_vertex(i)) kept_scales.push_back(scale[i]);
    }
  kept_scales = part.gathered(std::move(kept_scales));
  if(!kept_scales.empty())
    spread = percentile(kept_scales, 0.9, whole_mesh_view()) / percentile(kept_scales, 0.1, whole_mesh_view());
  return scale;
}

// The two-component mixture of z: the wider component's share, the core's and the wider one's deviations, each
// z's probability of belonging to the wider one. The core is free: on a part whose creases widen the robust
// deviation that scales z, or where hits are many, the core comes out below 1 (a unit core then read no
// impulses on a fandisk with a tenth of its vertices hit).
struct Mixture
{
  double share = 0, core = 1, wide = 0;
  std::vector<double> p;
  double log_likelihood = -HUGE_VAL;
};

// EM from one start (the core at 1); the sums over the own rows of every process, `rows` of them
inline Mixture fit_mixture_from(const std::vector<double>& z, double share, double wide, const Part_view& part,
                                double rows)
{
  Mixture m;
  m.share = share;
  m.wide = wide;
  m.p.assign(z.size(), 0.0);
  const double tiny = 1.0 / std::max(rows, 1.0);
  const auto density = [&m](double x, bool wider) {
    const double s = wider ? m.wide : m.core;
    return (wider ? m.share : 1 - m.share) / s * std::exp(-0.5 * x * x / (s * s));
  };
  for(int iteration = 0; iteration < 200; ++iteration)
  {
    // each probability on its own (on every core), the sums in vertex order
    parallel_blocks(z.size(), [&](std::size_t first, std::size_t last) {
      for(std::size_t i = first; i < last; ++i)
      {
        if(std::isnan(z[i])) continue;
        const double wider = density(z[i], true), core = density(z[i], false);
        m.p[i] = wider + core > 0 ? wider / (wider + core) : 1.0;
      }
    });
    std::vector<double> sums(4, 0.0);
    for(std::size_t i = 0; i < z.size(); ++i)
      if(!std::isnan(z[i]) && part.owns_vertex(i))
      {
        sums[0] += m.p[i];
        sums[1] += m.p[i] * z[i] * z[i];
        sums[2] += 1 - m.p[i];
        sums[3] += (1 - m.p[i]) * z[i] * z[i];
      }
    part.sum(sums);
    const double sp = sums[0], spz2 = sums[1], sq = sums[2], sqz2 = sums[3];
    if(!(sp > tiny) || !(sq > tiny) || !(sqz2 > 0)) return Mixture();
    const double next_share = sp / (sp + sq), core = std::sqrt(sqz2 / sq), next_wide = std::sqrt(spz2 / sp);
    const bool settled = std::abs(next_share - m.share) < 1e-4 * m.share &&
                         std::abs(core - m.core) < 1e-4 * m.core && std::abs(next_wide - m.wide) < 1e-4 * m.wide;
    m.share = next_share;
    m.core = core;
    m.wide = next_wide;
    if(settled) break;
  }
  double log_likelihood = 0;
  for(std::size_t i = 0; i < z.size(); ++i)
    if(!std::isnan(z[i]) && part.owns_vertex(i)) log_likelihood += std::log(density(z[i], true) + density(z[i], false));
  m.log_likelihood = part.sum(log_likelihood);
  return m;
}

// The mixture of highest likelihood from a few starts (a sparse, a common and a dominant wider component: EM
// from one start can settle on two equal components), none unless the wider one is core_ratio times the core.
inline Mixture fit_mixture(const std::vector<double>& z, const Part_view& part, double rows)
{
  Mixture best;
  for(const auto& start : { std::make_pair(0.01, 10.0), std::make_pair(0.1, 4.0), std::make_pair(0.5, 2.5) })
  {
    Mixture m = fit_mixture_from(z, start.first, start.second, part, rows);
    if(m.core > 0 && m.wide >= core_ratio * m.core && m.share * rows >= 1 &&
       m.log_likelihood > best.log_likelihood)
      best = std::move(m);
  }
  if(best.p.size() != z.size())
  {
    best = Mixture();
    best.p.assign(z.size(), 0.0);
  }
  return best;
}

// The probability of each z (NaN: none) being a hit: the mixture's, kept where z stands out of its ring most (its
// neighbours' differences echo a spike, smaller and on the other side) and not beside two others standing out on
// its side (a feature line). Returns the number of z (of every process's own rows, `rows` of them).
inline double find_hits(const Triangle_topology& topo, const std::vector<double>& z, std::vector<double>& p,
                        const Part_view& part, double rows)
{
  const std::size_t n = z.size();
  double count = 0;
  const Mixture mixture = fit_mixture(z, part, rows);
  p.assign(n, 0.0);
  std::vector<int> ring;
  for(std::size_t i = 0; i < n; ++i)
  {
    if(std::isnan(z[i]) || !part.owns_vertex(i)) continue;
    count += 1;
    if(!(mixture.p[i] > 0)) continue;
    read_ring(topo, i, ring);
    int beside = 0;
    bool largest = true;
    for(int j : ring)
    {
      if(std::size_t(j) >= n || std::isnan(z[std::size_t(j)])) continue;
      largest = largest && std::abs(z[std::size_t(j)]) <= std::abs(z[i]);
      beside += mixture.p[std::size_t(j)] > 0.5 && z[std::size_t(j)] * z[i] > 0;
    }
    p[i] = largest && beside < 2 ? mixture.p[i] : 0.0;
  }
  part.refresh(p);
  return part.sum(count);
}

// The lattice step of one axis, 0 if its values are not on one (`v`: a process's; its distinct values are gathered).
inline double lattice_step(std::vector<double> v, double mean_edge, const Part_view& part)
{
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  v = part.gathered(std::move(v));
  if(v.size() < 2) return 0;
  std::sort(v.begin(), v.end());
  const double range = v.back() - v.front();
  if(!(range > 0)) return 0;
  double step = range;
  std::size_t levels = 1;
  for(std::size_t k = 1; k < v.size(); ++k)
  {
    const double gap = v[k] - v[k - 1];
    if(gap > 1e-9 * range)
    {
      step = std::min(step, gap);
      ++levels;
    }
  }
  if(levels < 32 || !(step < mean_edge)) return 0;
  for(double x : v)
  {
    const double k = (x - v.front()) / step;
    if(std::abs(k - std::round(k)) > 1e-3) return 0;
  }
  return step;
}

} // namespace noise_model_detail

/// The model of the noise of X (the first 3 columns; `noise`: the estimate made on it; `usable`: the vertices
/// that sample it; `mean_edge`: the mesh's mean edge length, model units; `part`: the part of the mesh a process
/// holds, its own vertices its samples).
inline Noise_model estimate_noise_model(const Triangle_topology& topo, const Control_matrix& X,
                                        const std::vector<bool>& usable, const Noise_estimate& noise, double mean_edge,
                                        const Part_view& part = whole_mesh_view())
{
  namespace d = noise_model_detail;
  const std::size_t n = std::size_t(X.rows());
  const double rows = double(whole_count(std::vector<bool>(n, true), n, part));
  Noise_model m;
  m.normal = noise.relative_sigma();
  std::vector<double> normal2(n, std::nan("")), tangential2(n, std::nan("")), across;
  for(std::size_t i = 0; i < n; ++i)
    if(!std::isnan(noise.normal_sample(i)))
    {
      normal2[i] = noise.normal_sample(i) * noise.normal_sample(i);
      tangential2[i] = noise.tangential_sample(i);
      if(part.owns_vertex(i)) across.push_back(tangential2[i]);
    }
  // the median of a chi-square with 2 degrees of freedom is 2 ln 2
  const double median_across = d::percentile(across, 0.5, part);
  m.tangential = std::isnan(median_across) ? 0.0 : std::sqrt(median_across / (2 * std::log(2.0)));
  m.tangential_scale = d::local_scales(topo, tangential2, 2 * m.tangential * m.tangential, noise.tangential_null(),
                                       2.0, m.tangential_spread, part);
  // impulses against local scales clipped at the global deviation only (a spike widens them little); the local
  // scales then leave out those hits and their rings, and the impulses are read again against them
  double first_spread = 1;
  // the samples in units of the deviation they read (the noise's, less what its correlation hides from them)
  const double read = noise.read_sigma();
  const std::vector<double> first = d::local_scales(topo, normal2, read * read, noise.normal_null(), 1.0,
                                                    first_spread, part, 1);
  std::vector<double> z(n, std::nan(""));
  for(std::size_t i = 0; i < n; ++i)
    if(!std::isnan(normal2[i]) && read > 0) z[i] = noise.normal_sample(i) / (read * first[i]);
  d::find_hits(topo, z, m.hit_probability, part, rows);
  std::vector<double> quiet = normal2;
  std::vector<int> ring;
  for(std::size_t i = 0; i < n; ++i)
    if(m.hit_probability[i] > 0.5)
    {
      quiet[i] = std::nan("");
      read_ring(topo, i, ring);
      for(int j : ring)
        if(std::size_t(j) < n) quiet[std::size_t(j)] = std::nan("");
    }
  m.normal_scale = d::local_scales(topo, quiet, read * read, noise.normal_null(), 1.0, m.normal_spread, part);
  for(std::size_t i = 0; i < n; ++i)
    if(!std::isnan(z[i])) z[i] *= first[i] / m.normal_scale[i];
  const double count = d::find_hits(topo, z, m.hit_probability, part, rows);
  // the share of the vertices more likely hit than not, and their deviation in units of the global one
  std::vector<double> hit_sums(2, 0.0);
  for(std::size_t i = 0; i < n; ++i)
    if(m.hit_probability[i] > 0.5 && part.owns_vertex(i))
    {
      hit_sums[0] += 1;
      hit_sums[1] += std::pow(noise.normal_sample(i) / read, 2);
    }
  part.sum(hit_sums);
  const double hits = hit_sums[0], hits_z2 = hit_sums[1];
  m.hit_share = count > 0 ? hits / count : 0.0;
  m.hit_deviation = hits > 0 ? std::sqrt(hits_z2 / hits) : 0.0;
  for(int a = 0; a < 3; ++a)
  {
    std::vector<double> v;
    for(std::size_t i = 0; i < n; ++i)
      if(usable[i] && part.owns_vertex(i)) v.push_back(X(Eigen::Index(i), a));
    m.cell[std::size_t(a)] = d::lattice_step(v, mean_edge, part);
  }
  m.mean_edge = mean_edge;
  return m;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NOISE_MODEL_H
