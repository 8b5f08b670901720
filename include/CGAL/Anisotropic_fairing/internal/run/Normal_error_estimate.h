// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The error users see, estimated from the noisy mesh alone: how far a result's face normals are off the
// unknown clean surface's. A displacement e of the vertices along their normals n tilts a face's normal by
// the in-face gradient of e_n = n . e, so  sum_f A_f theta_f^2 ~ e_n^T K e_n,  K the cotangent stiffness
// matrix. For noise of deviation sigma_i along the normals (covariance S^2 along N), generalized SURE
// (Eldar 2009) estimates that loss for a result f of the data y without the clean surface:
//   r^T K r + 2 tr(K S^2 N J N^T) - tr(K S^2),   r = N (f - y),  J = df/dy,
// the trace by the probe of Tensor_selection.h: y moved by eps S b along N, and
//   tr(K S^2 N J N^T) ~ p . (N (f(y + eps S b) - f(y))) / eps,   p = S^2 K S^-1 b.
// Weighting by K is what tells the results apart as users do: a result whose positions are closer but whose
// normals are faceted has the larger K-weighted error. The estimates are given relative to tr(K S^2), the
// noisy input's own (1: no better than the input).
//
// Measured beside the default run's choice, not yet used for it: bench/bench_estimate_soundness.cpp and
// bench/results-estimate-soundness-2026-11-29.md show where it is not sound between flows. The normal-field
// candidate uses it to choose its number of passes (within one family, where it is).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_NORMAL_ERROR_ESTIMATE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_NORMAL_ERROR_ESTIMATE_H

#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>
#include <CGAL/Anisotropic_fairing/internal/run/Tensor_selection.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Vector3.h>

#include <Eigen/Sparse>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The cotangent stiffness matrix of the first `real_faces` faces of Y: e^T K e = the integral of |grad e|^2
/// of the piecewise linear e (positive semi-definite on any triangle mesh; a zero-area face adds nothing).
inline Eigen::SparseMatrix<double> stiffness_matrix(const Triangle_topology& topo, std::size_t real_faces,
                                                   const Control_matrix& Y)
{
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(9 * real_faces);
  for(std::size_t f = 0; f < real_faces; ++f)
  {
    const auto& t = topo.face(f);
    const Eigen::Vector3d p[3] = { Y.row(t[0]).head<3>().transpose(), Y.row(t[1]).head<3>().transpose(),
                                   Y.row(t[2]).head<3>().transpose() };
    const double twice_area = (p[1] - p[0]).cross(p[2] - p[0]).norm();
    if(!(twice_area > 0)) continue;
    for(int c = 0; c < 3; ++c)
    {
      // the corner c faces the edge (a, b): weight cot(c) / 2 = (u . v) / (2 |u x v|)
      const int a = (c + 1) % 3, b = (c + 2) % 3;
      const double w = (p[a] - p[c]).dot(p[b] - p[c]) / (2 * twice_area);
      entries.emplace_back(t[a], t[b], -w);
      entries.emplace_back(t[b], t[a], -w);
      entries.emplace_back(t[a], t[a], w);
      entries.emplace_back(t[b], t[b], w);
    }
  }
  Eigen::SparseMatrix<double> K(Y.rows(), Y.rows());
  K.setFromTriplets(entries.begin(), entries.end());
  return K;
}

/// What every estimate reads: the data y, the normals N and stiffness K it is measured with, the noise's
/// deviation per vertex and the probe's values b (y probed = probed_input(y, N, sigma, b)).
class Normal_error_estimate
{
public:
  Normal_error_estimate(const Control_matrix& y, const Control_matrix& N, Eigen::SparseMatrix<double> K,
                        const std::vector<double>& sigma, const std::vector<double>& b)
    : y_(y), N_(N), K_(std::move(K)), sigma_(sigma)
  {
    const Eigen::Index n = y.rows();
    Eigen::VectorXd scaled(n), s2(n);
    for(Eigen::Index i = 0; i < n; ++i)
    {
      const double s = sigma[std::size_t(i)];
      scaled[i] = s > 0 ? b[std::size_t(i)] / s : 0.0;
      s2[i] = s > 0 ? s * s : 0.0;
    }
    p_ = s2.cwiseProduct(K_ * scaled);
    diagonal_ = K_.diagonal();
    input_error_ = s2.dot(diagonal_);
  }

  /// tr(K S^2): the expected loss of the noisy input itself, the unit of the estimates.
  double input_error() const { return input_error_; }

  /// The terms of the estimate of result f whose probed input ended at f_probed, one per vertex (their sum
  /// is the estimate, in squared length): r_i (K r)_i + 2 p_i delta_i / eps - K_ii sigma_i^2.
  std::vector<double> terms(const Control_matrix& f, const Control_matrix& f_probed) const
  {
    const Eigen::Index n = y_.rows();
    Eigen::VectorXd r(n), delta(n);
    for(Eigen::Index i = 0; i < n; ++i)
    {
      r[i] = N_.row(i).dot(f.row(i).head(3) - y_.row(i).head(3));
      delta[i] = N_.row(i).dot(f_probed.row(i).head(3) - f.row(i).head(3));
    }
    const Eigen::VectorXd Kr = K_ * r;
    std::vector<double> t(static_cast<std::size_t>(n));
    for(Eigen::Index i = 0; i < n; ++i)
    {
      const double s = sigma_[std::size_t(i)];
      t[std::size_t(i)] = r[i] * Kr[i] + 2 * p_[i] * delta[i] / risk_probe - diagonal_[i] * s * s;
    }
    return t;
  }

  /// The estimate of result f relative to the input's (1: the input's own error, 0: none).
  double relative(const std::vector<double>& terms) const
  {
    double sum = 0;
    for(double x : terms) sum += x;
    return input_error_ > 0 ? sum / input_error_ : std::nan("");
  }

private:
  const Control_matrix& y_;
  const Control_matrix& N_;
  Eigen::SparseMatrix<double> K_;
  const std::vector<double>& sigma_;
  Eigen::VectorXd p_, diagonal_;
  double input_error_ = 0;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_NORMAL_ERROR_ESTIMATE_H
