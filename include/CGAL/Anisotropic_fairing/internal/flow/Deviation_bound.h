// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The user's bound on how far a written vertex may move off the input (named parameter maximum_deviation).
// Bajaj & Xu leave the choice of the fidelity weight for such a bound open (their Section 7). Here each
// vertex gets a fidelity of its own, mu_i, on its written position (Output_fidelity.h), on top of the global
// one: mu_i is raised where a step would carry the written position past the bound, and that step is taken
// again. What mu leaves beyond the bound, within its cap, the write-back puts on the bound.
// That suits a run that stops at the noise level, while the flow still removes noise. A run that goes on to
// a steady state (or for a number of steps) also shrinks the surface as a whole, and vertices held one by
// one against that become tents. There each vertex also gets a uniform weight, chosen as the steady state
// of the flow with fidelity suggests: at rest omega (y_i - y0_i) balances the flow's own motion F_i, so
// omega = max |F_i| / (0.8 bound), from the last step, puts the steady state within 0.8 of the bound and
// leaves the per-vertex holding the rest. Bajaj & Xu leave this choice open; it is their omega chosen as
// the surface goes. It comes into force once a vertex is halfway to the bound: a bound the run stays far
// from changes nothing.
// On several processes each judges the rows it owns, and the decisions (a retake, the uniform weight) are
// taken over all of them (`largest`), so that every process decides alike.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_DEVIATION_BOUND_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_DEVIATION_BOUND_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The columns a bound applies to and its radius (model units; infinity: none).
struct Column_bound
{
  Eigen::Index first = 0, count = 0;
  double radius = std::numeric_limits<double>::infinity();
  bool active() const { return count > 0 && std::isfinite(radius); }
};

/// |Y_i - Y0_i| over the bound's columns
inline double row_deviation(const Control_matrix& Y, const Control_matrix& Y0, Eigen::Index i, const Column_bound& b)
{
  return (Y.row(i).segment(b.first, b.count) - Y0.row(i).segment(b.first, b.count)).norm();
}

/// Puts each written row of Y (`written[i]`) whose columns of the bound lie farther than its radius from the
/// input's on the bound, along the line to the input, and marks it in `moved`.
inline void clamp_to_bound(Control_matrix& Y, const Control_matrix& input, const Column_bound& b,
                           const std::vector<bool>& written, std::vector<bool>& moved)
{
  if(!b.active()) return;
  for(Eigen::Index i = 0; i < Y.rows(); ++i)
  {
    const double d = row_deviation(Y, input, i, b);
    if(!written[std::size_t(i)] || !(d > b.radius)) continue;
    // the point is rounded onto the grid of doubles near the input, whose spacing can be much more than
    // 1e-15 of a small radius: shrink by what the rounding left beyond the bound or by the spacing (shares
    // of the radius), whichever is larger, doubled at each attempt; a radius below the spacing leaves the input
    const Eigen::RowVectorXd away = Y.row(i).segment(b.first, b.count) - input.row(i).segment(b.first, b.count);
    double spacing = 0;
    for(double x : input.row(i).segment(b.first, b.count))
      spacing = std::max(spacing, std::nextafter(std::abs(x), std::numeric_limits<double>::infinity()) - std::abs(x));
    double scale = b.radius / d;
    for(int attempt = 0; ; ++attempt)
    {
      Y.row(i).segment(b.first, b.count) = input.row(i).segment(b.first, b.count) + scale * away;
      const double e = row_deviation(Y, input, i, b);
      if(e <= b.radius) break;
      if(attempt == 8) { Y.row(i).segment(b.first, b.count) = input.row(i).segment(b.first, b.count); break; }
      scale *= b.radius / e * std::max(0.0, 1 - std::ldexp(std::max(e / b.radius - 1, spacing / b.radius), attempt));
    }
    moved[std::size_t(i)] = true;
  }
}

/// The user's two bounds on the columns of a matrix: the geometry's first 3 columns, if `geometry_moves`,
/// and the attributes' from `first_attribute` on; radii in model units, 0 for none.
inline std::array<Column_bound, 2> user_bounds(Eigen::Index columns, bool geometry_moves, Eigen::Index first_attribute,
                                               double geometry_radius, double attribute_radius)
{
  const double none = std::numeric_limits<double>::infinity();
  return { Column_bound{ 0, geometry_moves ? 3 : 0, geometry_radius > 0 ? geometry_radius : none },
           Column_bound{ first_attribute, columns - first_attribute, attribute_radius > 0 ? attribute_radius : none } };
}

/// The largest deviation of a written row over the bound's columns
inline double largest_written_deviation(const Control_matrix& Y, const Control_matrix& input, const Column_bound& b,
                                        const std::vector<bool>& written)
{
  double largest = 0;
  if(b.count > 0)
    for(Eigen::Index i = 0; i < Y.rows(); ++i)
      if(written[std::size_t(i)]) largest = std::max(largest, row_deviation(Y, input, i, b));
  return largest;
}

class Deviation_bound
{
public:
  /// `geometry`, `attributes`: the two bounds on the stepper's columns; `rows`: of the stepper's matrices;
  /// `uniform`: whether every vertex also gets the uniform weight of a run to a steady state; `largest`: the
  /// largest of every process's value (one process: the value itself).
  Deviation_bound(const Column_bound& geometry, const Column_bound& attributes, std::size_t rows, bool uniform,
                  std::function<double(double)> largest = [](double x) { return x; })
    : bounds_{ geometry, attributes }, uniform_(uniform), largest_(std::move(largest))
  {
    if(active()) { weight_.assign(rows, 0.0); own_.assign(rows, 0.0); }
  }

  bool active() const { return bounds_[0].active() || bounds_[1].active(); }

  /// The written positions of the input (its limit points, or the input itself), where the fidelity
  /// anchors them: a row held there cannot come closer to the input, so its target is the larger of the
  /// bound and where it starts (the write-back puts it on the bound). Holding the limit points at the
  /// input itself would make the control points interpolate the noise.
  void set_start(const Control_matrix& Y0, const Control_matrix& input)
  {
    if(!active()) return;
    for(int b = 0; b < 2; ++b)
    {
      start_[b].assign(std::size_t(Y0.rows()), 0.0);
      if(bounds_[b].active())
        for(Eigen::Index i = 0; i < Y0.rows(); ++i) start_[b][std::size_t(i)] = row_deviation(Y0, input, i, bounds_[b]);
    }
    previous_ = Y0;
    anchor_ = Y0;
  }

  /// Whether the candidate's written positions Y carry some free row past its bound (by more than 1%:
  /// the write-back puts what is left on the bound). Where they do, mu is raised on the row (raise()), and
  /// the step is to be taken again (if so on any process). `free`: the rows this process judges; `tau`: each
  /// row's time step of the step taken.
  bool exceeded_and_raised(const Control_matrix& Y, const Control_matrix& input, const std::vector<int>& free,
                           const std::vector<double>& tau)
  {
    bool exceeded = false;
    for_each_bounded(Y, input, free, [&](std::size_t r, int b, double radius, double d) {
      if(d > 1.01 * radius &&
         raise(r, d, row_deviation(previous_, input, Eigen::Index(r), bounds_[b]), radius, tau[r], 4))
        exceeded = true;
    });
    return largest_(exceeded ? 1.0 : 0.0) > 0;
  }

  /// The written positions of the accepted step: where the next step's motion starts. A row whose next
  /// step, as long as this one, would carry it past 0.9 of its bound is held before it gets there. `tau`:
  /// each row's time step of the next step; `taken`: the accepted step's, as a share of it.
  void accept(const Control_matrix& Y, const Control_matrix& input, const std::vector<int>& free,
              const std::vector<double>& tau, double taken)
  {
    double omega = 0;   // the uniform weight's new value
    bool halfway = false;
    for_each_bounded(Y, input, free, [&](std::size_t r, int b, double radius, double d) {
      halfway = halfway || d > 0.5 * radius;
      const Eigen::Index i = Eigen::Index(r);
      const double step = row_deviation(Y, previous_, i, bounds_[b]);
      if(uniform_)
      {
        // the flow's own motion: the step's, with the fidelity's pull added back
        const auto F = ((Y.row(i) - previous_.row(i)) / (taken * tau[r]) + weight_[r] * (Y.row(i) - anchor_.row(i)))
                         .segment(bounds_[b].first, bounds_[b].count);
        omega = std::max(omega, F.norm() / (0.8 * radius));
      }
      if(d + step > 0.9 * radius) raise(r, d + step, d, radius, tau[r], 1);
    });
    omega = largest_(omega);
    halfway = largest_(halfway ? 1.0 : 0.0) > 0;
    // a change of less than a tenth keeps the weights (and a fixed surface's factorised matrix) as they are
    if(uniform_ && (halfway || uniform_weight_ > 0) && std::abs(omega - uniform_weight_) > 0.1 * uniform_weight_)
    {
      uniform_weight_ = omega;
      for(int row : free) weight_[std::size_t(row)] = std::max(own_[std::size_t(row)], uniform_weight_);
    }
    if(active()) previous_ = Y;
  }

  /// mu per row (1/time, model units), empty without a bound
  const std::vector<double>& weights() const { return weight_; }
  /// the largest weight a row was given of its own (of every process's), and this process's rows given one
  double largest_weight() const
  {
    return largest_(own_.empty() ? 0.0 : *std::max_element(own_.begin(), own_.end()));
  }
  std::size_t held_rows() const
  {
    return std::size_t(std::count_if(own_.begin(), own_.end(), [](double w) { return w > 0; }));
  }
  /// the uniform weight of a run to a steady state, at its last value (0: none)
  double uniform_weight() const { return uniform_weight_; }

private:
  // body(row, bound, the row's radius, its deviation in Y) for each free row and each bound in force; a
  // row's radius is the bound, or where it starts if farther (set_start())
  template <typename Body>
  void for_each_bounded(const Control_matrix& Y, const Control_matrix& input, const std::vector<int>& free,
                        const Body& body) const
  {
    for(int b = 0; b < 2; ++b)
      if(bounds_[b].active())
        for(int row : free)
        {
          const std::size_t r = std::size_t(row);
          body(r, b, std::max(bounds_[b].radius, start_[b][r]), row_deviation(Y, input, Eigen::Index(row), bounds_[b]));
        }
  }

  // mu of row r to what cuts a motion from `before` to `d` to the room left below 0.9 radius (a step of tau
  // damps it by about 1 / (1 + tau mu)), at least `growth` times what it was, and at most tau mu = 1e3:
  // beyond, the row's fidelity only worsens the system's conditioning, and the write-back does the rest.
  // Whether mu grew.
  bool raise(std::size_t r, double d, double before, double radius, double tau, double growth)
  {
    if(weight_[r] * tau >= maximum_held) return false;
    const double room = std::max(0.9 * radius - before, 0.05 * radius);
    const double needed = std::max(std::max(d - before, 0.0) / room - 1, growth > 1 ? 1.0 : 0.0) / tau;
    const double raised = std::min(std::max(needed, growth * weight_[r]), maximum_held / tau);
    if(!(raised > weight_[r])) return false;
    own_[r] = weight_[r] = raised;
    return true;
  }

  static constexpr double maximum_held = 1e3;   // tau mu
  Column_bound bounds_[2];
  std::vector<double> start_[2];
  bool uniform_;
  std::function<double(double)> largest_;
  double uniform_weight_ = 0;
  std::vector<double> own_;      // each row's own weight
  std::vector<double> weight_;   // what holds each row: the larger of its own and the uniform one
  Control_matrix previous_, anchor_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_DEVIATION_BOUND_H
