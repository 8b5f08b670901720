// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The risk estimate's probe (run/Tensor_selection.h) carried along a run: the probed input takes the run's
// own steps, each solved with the run's own matrix as more right-hand sides, its tangential motion removed
// in the run's tangent planes, shortened where the run's steps are and rewound where the run is. So the
// probe costs a few more columns per solve instead of a second run: what the estimate then measures is
// the divergence of the run's steps with their operators as the run found them (the operators' own
// dependence on the data, a higher-order term for a probe of a twentieth of the noise, is left out).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_RIDE_ALONG_PROBE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_RIDE_ALONG_PROBE_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

class Ride_along_probe
{
public:
  /// The probe starts from P (the run's start, moved); empty: no probe.
  void start(const Control_matrix& P)
  {
    Z_ = P;
    Z0_ = P;
    candidate_.resize(0, 0);
    previous_.resize(0, 0);
    unfolded_ = P;
  }
  bool active() const { return Z_.size() > 0; }
  /// Where the probe is: its control points, after the run.
  const Control_matrix& result() const { return Z_; }

  /// [Z | probe] and [Z0 | its start]: the unknowns and the fidelity's anchor of one solve for both.
  void augment(const Control_matrix& Z, const Control_matrix& Z0, Control_matrix& ZZ, Control_matrix& ZZ0) const
  {
    ZZ.resize(Z.rows(), 2 * Z.cols());
    ZZ << Z, Z_;
    ZZ0.resize(Z0.rows(), 2 * Z0.cols());
    ZZ0 << Z0, Z0_;
  }

  /// The probe's candidate: its place moved by `add`, which adds the probe's columns of a solve of
  /// [Z | probe] (less their tangential part where the run removes its own).
  template <typename Add>
  void make_candidate(const Add& add)
  {
    if(!active()) return;
    candidate_ = Z_;
    add(candidate_);
  }
  // What the run does, the probe does (nothing without a probe):
  /// the run's candidate ends theta of the way into its step;
  void shorten(double theta) { if(active()) candidate_ = Z_ + theta * (candidate_ - Z_); }
  void accept() { if(active()) { previous_.swap(Z_); Z_.swap(candidate_); candidate_.resize(0, 0); } }
  /// the run's accepted step is taken back to theta of its length;
  void rewind(double theta) { if(active()) Z_ = previous_ + theta * (Z_ - previous_); }
  /// the run's last surface without new folds is this one; the run falls back to it.
  void mark_unfolded() { if(active()) unfolded_ = Z_; }
  void fall_back() { if(active()) Z_ = unfolded_; }

private:
  Control_matrix Z_, Z0_, candidate_, previous_, unfolded_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_RIDE_ALONG_PROBE_H
