// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How far the noise is correlated over the surface, and how much of it the noise estimate therefore misses.
// A scanner's noise is correlated over neighbouring samples; the second differences the noise estimate reads
// (Noise_estimate.h) cancel part of such noise as they cancel shape, so it reads low (unit noise averaged once
// with its ring's mean reads 0.66 of its deviation) and the run stops short of the noise.
//
// The samples, clipped at three deviations, are correlated with their mean over the ring (lag 1) and over the
// next ring (lag 2). The same differences of unit noise drawn on the mesh's own connectivity and averaged k = 0,
// 1, 2 times with its ring's mean (half each) give a curve of such pairs (about (-0.89, 0.43), (-0.72, 0.05),
// (-0.35, -0.37) on any mesh) and of readings: independent noise lies at k = 0, correlated noise along the curve;
// shape lies off it (a clean mesh's pair is one the curve does not pass through). The noise is read as
// correlated, and its estimate divided by the reading of unit noise at that point of the curve, only where the
// pair lies within an eighth of the curve's first step of it and nearer averaged noise than independent noise
// (k >= 0.5): independent noise reads k = 0 to 0.35 within 0.03 of the curve on the benchmark (what the ring
// planes' fit does to it; its reading is nearly right and the runs are best there), clean meshes, quantised files
// and the remains of removed spikes lie 0.11 or more off it, noise averaged once at k = 0.9 to 1.1 within 0.01.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NOISE_CORRELATION_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NOISE_CORRELATION_H

#include <CGAL/Anisotropic_fairing/internal/flow/Ring_plane.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Process_part.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>
#include <CGAL/Anisotropic_fairing/internal/types/Parallel_blocks.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The times unit noise is averaged with its ring's mean along the null curve.
constexpr int correlation_steps = 2;

struct Noise_correlation
{
  double lag1 = std::nan(""), lag2 = std::nan("");   // the samples' correlations with the ring and the next
  double k = 0;                 // the point of the null curve nearest to (lag1, lag2)
  double distance = std::nan("");   // from it, in the pairs' units
  double reading = 1;           // what the noise estimate reads of noise so correlated (1: independent)
  bool corrected = false;       // the pair lies on the curve, nearer averaged noise: the reading is corrected

  /// The factor of the noise estimate's reading that gives the noise's deviation.
  double factor() const { return corrected && reading > 0 ? 1 / reading : 1.0; }

  /// One clause for the report's `choices`.
  std::string description() const
  {
    char text[300];
    if(std::isnan(lag1)) return "noise correlation not measured";
    std::snprintf(text, sizeof text, "noise correlation: as unit noise averaged %.2g times with its ring's mean "
                  "(second differences at lags 1 and 2: %.2f, %.2f; %.2f off that curve)%s", k, lag1, lag2, distance,
                  corrected ? "" : ": not corrected");
    std::string s = text;
    if(corrected && reading < 1)
    {
      std::snprintf(text, sizeof text, ": read at %.2f of its deviation, corrected by %.3gx", reading, 1 / reading);
      s += text;
    }
    return s;
  }
};

namespace noise_correlation_detail {

// Each field's correlations (NaN: none), clipped at its `clip`, with its mean over each vertex's ring and next
// ring; the fields are measured at the same vertices (the first one's), whose two rings are read once for all.
template <std::size_t F>
std::array<std::pair<double, double>, F> lag_correlations(const Triangle_topology& topo,
                                                          const std::array<const std::vector<double>*, F>& field,
                                                          const std::array<double, F>& clip, const Part_view& part)
{
  const std::size_t n = field[0]->size();
  const auto value = [&](std::size_t f, int j) {
    const std::vector<double>& v = *field[f];
    return std::size_t(j) < n && !std::isnan(v[std::size_t(j)]) ? std::clamp(v[std::size_t(j)], -clip[f], clip[f])
                                                                 : std::nan("");
  };
  std::array<std::vector<double>, F> first, second;
  for(std::size_t f = 0; f < F; ++f)
  {
    first[f].assign(n, std::nan(""));
    second[f].assign(n, std::nan(""));
  }
  parallel_blocks(n, [&](std::size_t begin, std::size_t end) {
    std::vector<int> ring, inner, next;
    for(std::size_t i = begin; i < end; ++i)
    {
      if(std::isnan((*field[0])[i]) || topo.outgoing(int(i)) < 0) continue;
      read_ring(topo, i, ring);
      next.clear();
      for(int j : ring)
      {
        if(std::size_t(j) >= n || topo.outgoing(j) < 0) continue;   // a ghost vertex's fan is open
        inner.clear();
        topo.neighbours_ccw(topo.outgoing(j), std::back_inserter(inner));
        next.insert(next.end(), inner.begin(), inner.end());
      }
      std::sort(next.begin(), next.end());
      next.erase(std::unique(next.begin(), next.end()), next.end());
      next.erase(std::remove_if(next.begin(), next.end(), [&](int m) {
                   return std::size_t(m) == i || std::find(ring.begin(), ring.end(), m) != ring.end();
                 }), next.end());
      const auto mean = [&](std::size_t f, const std::vector<int>& around) {
        double sum = 0, count = 0;
        for(int j : around)
        {
          const double x = value(f, j);
          if(!std::isnan(x)) { sum += x; count += 1; }
        }
        return count > 0 ? sum / count : std::nan("");
      };
      for(std::size_t f = 0; f < F; ++f)
      {
        first[f][i] = mean(f, ring);
        second[f][i] = mean(f, next);
      }
    }
  });
  // Pearson's correlation over the vertices that have both, summed in vertex order (a process: its own vertices'
  // sums, summed over the processes)
  const auto correlation = [&](std::size_t f, const std::vector<double>& mean) {
    std::vector<double> sums(6, 0.0);
    for(std::size_t i = 0; i < n; ++i)
    {
      const double x = value(f, int(i)), y = mean[i];
      if(std::isnan(x) || std::isnan(y) || !part.owns_vertex(i)) continue;
      sums[0] += x; sums[1] += y; sums[2] += x * x; sums[3] += y * y; sums[4] += x * y; sums[5] += 1;
    }
    part.sum(sums);
    const double sx = sums[0], sy = sums[1], sxx = sums[2], syy = sums[3], sxy = sums[4], count = sums[5];
    if(count < 3) return std::nan("");
    const double cxy = sxy - sx * sy / count, cxx = sxx - sx * sx / count, cyy = syy - sy * sy / count;
    return cxx > 0 && cyy > 0 ? cxy / std::sqrt(cxx * cyy) : std::nan("");
  };
  std::array<std::pair<double, double>, F> lags;
  for(std::size_t f = 0; f < F; ++f) lags[f] = { correlation(f, first[f]), correlation(f, second[f]) };
  return lags;
}

} // namespace noise_correlation_detail

/// `field` averaged once with its ring's mean (half each) at the first `n` vertices of the topology; a vertex
/// without a fan keeps its value; a process's own vertices' values then go to the others (`part`).
inline std::vector<double> averaged_with_ring(const Triangle_topology& topo, const std::vector<double>& field,
                                              std::size_t n, const Part_view& part = Part_view())
{
  std::vector<double> out = field;
  parallel_blocks(std::min(field.size(), n), [&](std::size_t first, std::size_t last) {
    std::vector<int> ring;
    for(std::size_t i = first; i < last; ++i)
    {
      if(topo.outgoing(int(i)) < 0) continue;
      read_ring(topo, i, ring);
      double sum = 0;
      for(int j : ring) sum += field[std::size_t(j)];
      if(!ring.empty()) out[i] = 0.5 * field[i] + 0.5 * sum / double(ring.size());
    }
  });
  part.refresh(out);
  return out;
}

/// `field` scaled to unit root mean square over its first `n` values (all: n = 0), the whole field with them (left as
/// it is when they are zero).
inline void to_unit_rms(std::vector<double>& field, std::size_t n = 0, const Part_view& part = Part_view())
{
  const std::size_t m = n > 0 ? std::min(n, field.size()) : field.size();
  std::vector<double> sums(2, 0.0);   // of squares, and the values counted: a process's own vertices'
  for(std::size_t i = 0; i < m; ++i)
    if(part.owns_vertex(i))
    {
      sums[0] += field[i] * field[i];
      sums[1] += 1;
    }
  part.sum(sums);
  const double rms = std::sqrt(sums[0] / std::max(sums[1], 1.0));
  if(rms > 0)
    for(double& x : field) x /= rms;
}

/// Independent unit noise `b` made as correlated as the noise read (`c`), so that a risk estimate probes the
/// flows with noise of the mesh's kind: averaged with its ring's mean as many times as the curve's point c.k (its
/// whole numbers of averagings on either side weighted by the fraction), at unit root mean square over the first
/// `n` vertices, which it returns. `b` holds a number for every vertex of the topology (a border vertex's ring
/// reaches ghosts, Ghost_layer.h); its first `n` where the reading is not corrected.
inline std::vector<double> correlated_like(const Triangle_topology& topo, const std::vector<double>& b, std::size_t n,
                                           const Noise_correlation& c, const Part_view& part = Part_view())
{
  CGAL_precondition(b.size() >= topo.number_of_vertices() && b.size() >= n);
  std::vector<double> lower = b;
  if(c.corrected && c.k > 0)
  {
    const int below = int(std::floor(c.k));
    const double t = c.k - below;
    for(int k = 0; k < below; ++k) lower = averaged_with_ring(topo, lower, n, part);
    to_unit_rms(lower, n, part);
    if(t > 0)
    {
      std::vector<double> upper = averaged_with_ring(topo, lower, n, part);
      to_unit_rms(upper, n, part);
      for(std::size_t i = 0; i < lower.size(); ++i) lower[i] = (1 - t) * lower[i] + t * upper[i];
      to_unit_rms(lower, n, part);
    }
  }
  lower.resize(n);
  return lower;
}

/// The signed samples of unit noise averaged k = 0..correlation_steps times, in units of its deviation.
typedef std::array<std::vector<double>, correlation_steps + 1> Correlated_null_samples;

/// The correlation of the noise whose samples are `samples` (read at a robust deviation `sigma`), against the
/// same differences of unit noise averaged k times (`null[k]`, NaN where not measured; `null_sigma[k]`: their
/// robust deviation).
inline Noise_correlation measure_noise_correlation(const Triangle_topology& topo, const std::vector<double>& samples,
                                                   double sigma, const Correlated_null_samples& null,
                                                   const std::array<double, correlation_steps + 1>& null_sigma,
                                                   const Part_view& part = Part_view())
{
  namespace d = noise_correlation_detail;
  Noise_correlation c;
  if(!(sigma > 0)) return c;
  // the samples and the null's fields in one pass over the rings: all are measured at the same vertices
  constexpr std::size_t F = correlation_steps + 2;
  std::array<const std::vector<double>*, F> field{ { &samples } };
  std::array<double, F> clip{ { 3 * sigma } };
  for(std::size_t k = 0; k + 1 < F; ++k)
  {
    field[k + 1] = &null[k];
    clip[k + 1] = 3 * null_sigma[k];
  }
  const std::array<std::pair<double, double>, F> lags = d::lag_correlations(topo, field, clip, part);
  std::tie(c.lag1, c.lag2) = lags[0];
  const std::pair<double, double>* curve = lags.data() + 1;
  if(std::isnan(c.lag1) || std::isnan(c.lag2)) return c;
  // the nearest point of the polyline through the curve's points
  for(int k = 0; k < correlation_steps; ++k)
  {
    const auto& a = curve[std::size_t(k)];
    const auto& b = curve[std::size_t(k) + 1];
    const double dx = b.first - a.first, dy = b.second - a.second, length2 = dx * dx + dy * dy;
    if(!(length2 > 0)) continue;
    const double t = std::clamp(((c.lag1 - a.first) * dx + (c.lag2 - a.second) * dy) / length2, 0.0, 1.0);
    const double distance = std::hypot(c.lag1 - a.first - t * dx, c.lag2 - a.second - t * dy);
    if(!(distance >= c.distance))
    {
      c.distance = distance;
      c.k = k + t;
      c.reading = ((1 - t) * null_sigma[std::size_t(k)] + t * null_sigma[std::size_t(k) + 1]) / null_sigma[0];
    }
  }
  const double step = std::hypot(curve[1].first - curve[0].first, curve[1].second - curve[0].second);
  c.corrected = c.distance <= step / 8 && c.k >= 0.5;
  return c;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NOISE_CORRELATION_H
