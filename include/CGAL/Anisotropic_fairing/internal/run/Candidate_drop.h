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
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// How far, in standard errors of their difference, an estimate must lie above the leader's to be dropped.
constexpr double drop_standard_errors = 2;

/// The mean of a - b and its standard error (the per-vertex differences read as independent); a and b of
/// the same size, at least two.
inline std::pair<double, double> mean_difference(const std::vector<double>& a, const std::vector<double>& b)
{
  const std::size_t n = a.size();
  double sum = 0;
  for(std::size_t i = 0; i < n; ++i) sum += a[i] - b[i];
  const double mean = sum / double(n);
  double squares = 0;
  for(std::size_t i = 0; i < n; ++i) squares += (a[i] - b[i] - mean) * (a[i] - b[i] - mean);
  return { mean, std::sqrt(squares / double(n - 1) / double(n)) };
}

/// Whether an estimate with terms `t`, `rising` from the last step's, lies above the leader's terms by more
/// than drop_standard_errors standard errors.
inline bool worse_than_leader(const std::vector<double>& t, const std::vector<double>& leader, bool rising)
{
  if(!rising || t.size() != leader.size() || t.size() < 2) return false;
  const std::pair<double, double> d = mean_difference(t, leader);
  return d.first > drop_standard_errors * d.second;
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
    double sum = 0;
    for(double x : t) sum += x;
    last = sum / double(t.size()) - 1;
    const bool rising = last > *previous;
    *previous = last;
    return !worse_than_leader(t, leader, rising);
  };
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_CANDIDATE_DROP_H
