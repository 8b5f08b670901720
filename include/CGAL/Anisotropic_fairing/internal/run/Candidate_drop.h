// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A candidate of the default run's comparison ended early: its risk estimate is read after each of its steps
// from the probe it carries (Ride_along_probe.h; for a flow whose operator follows the data, a lower bound of
// it), and the run ends as soon as that estimate rises while above the leader's (the lowest estimate of the
// runs made, at the noise level, that is an estimate) by more than twice the standard error of their
// difference. Along every run of the benchmark the estimate falls to one lowest value and then rises to the
// noise level, where the runs are compared (bench/results-speed-2026-11-29.md): once it rises above the
// leader's, the run can only end higher. The standard error is that of the mean of the per-vertex differences
// of the two estimates' terms (Tensor_selection.h), read as independent.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_CANDIDATE_DROP_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_CANDIDATE_DROP_H

#include <CGAL/Anisotropic_fairing/internal/run/Tensor_selection.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// How far, in standard errors of their difference, an estimate must lie above the leader's to be dropped.
constexpr double drop_standard_errors = 2;

/// The mean of a - b and its standard error (the per-vertex differences read as independent) over the whole
/// mesh (`part`: each process's own rows), when there are at least two; a and b of the same size.
inline std::optional<std::pair<double, double>> mean_difference(const std::vector<double>& a,
                                                                const std::vector<double>& b,
                                                                const Part_view& part = whole_mesh_view())
{
  const std::size_t rows = a.size();
  std::vector<double> d(rows);
  for(std::size_t i = 0; i < rows; ++i) d[i] = a[i] - b[i];
  const std::pair<double, std::size_t> mean = whole_mean(d, part);
  const double n = double(mean.second);
  if(mean.second < 2) return std::nullopt;
  double squares = 0;
  for(std::size_t i = 0; i < rows; ++i)
    if(part.owns_vertex(i)) squares += (d[i] - mean.first) * (d[i] - mean.first);
  return std::make_pair(mean.first, std::sqrt(part.sum(squares) / (n - 1) / n));
}

/// Whether an estimate with terms `t`, `rising` from the last step's, lies above the leader's terms by more
/// than drop_standard_errors standard errors.
inline bool worse_than_leader(const std::vector<double>& t, const std::vector<double>& leader, bool rising,
                              const Part_view& part = whole_mesh_view())
{
  if(!rising || t.size() != leader.size()) return false;
  const std::optional<std::pair<double, double>> d = mean_difference(t, leader, part);
  return d && d->first > drop_standard_errors * d->second;
}

/// A candidate's test after each step, on its written positions Y and its probe's P: false drops it. Its
/// last estimate goes to `last` (the estimate it was dropped at).
inline std::function<bool(const Control_matrix&, const Control_matrix&)>
drop_test(const Risk_estimate& estimate, const std::vector<double>& leader, double& last)
{
  auto previous = std::make_shared<double>(std::numeric_limits<double>::infinity());
  return [&estimate, &leader, &last, previous](const Control_matrix& Y, const Control_matrix& P) {
    const std::vector<double> t = estimate.terms(Y, P);
    if(t.empty()) return true;
    last = whole_mean(t, estimate.part()).first - 1;
    const bool rising = last > *previous;
    *previous = last;
    return !worse_than_leader(t, leader, rising, estimate.part());
  };
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_CANDIDATE_DROP_H
