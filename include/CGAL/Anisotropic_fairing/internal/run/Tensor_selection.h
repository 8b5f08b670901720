// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Which result the default run keeps. The candidate flows each run to the noise level, and the one with the
// lowest estimated error to the unknown clean surface is kept: Stein's unbiased risk estimate (SURE; Stein
// 1981, by Monte Carlo as Ramani, Blu and Unser 2008). For noise of deviation sigma along the normals n, a
// result f(y) of the data y has the expected squared error along the normals
//   sum_i (n_i . (y_i - f_i))^2 - N sigma^2 + 2 sigma^2 div f,   div f ~ b . (f(y + e b) - f(y)) / e,
// b standard normal along each normal, e small: f is also made from the input moved by e b. Where the noise is
// correlated over the surface (Noise_correlation.h), b is unit noise as correlated (correlated_like): the
// divergence then reads tr(J C), C the noise's correlation, which is what the error holds (Eldar 2009).
// The error counts along the normals only, so a flow's tangential drift (the uniform weights move vertices
// along the surface) costs nothing. sigma is the package's own noise estimate; n, the normals of the input's
// prefiltered surface M_eps, or else of a candidate's result: the noisy mesh's own normals are too far off at
// high noise. No measure of one result at a time tells the better result apart (the manual's Validation page).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_TENSOR_SELECTION_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_TENSOR_SELECTION_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Keyed_normal.h>
#include <CGAL/Anisotropic_fairing/internal/types/Vector3.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_safety.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Process_part.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The finite difference of the risk estimate, in units of the noise's deviation.
constexpr double risk_probe = 0.05;

/// Area-weighted unit normals at the vertices of the first `real_faces` faces of Y (zero elsewhere); `part`: the
/// part of the mesh a process holds (the rows it does not own, its faces around them maybe not all, from their owners).
inline Control_matrix vertex_normals(const Triangle_topology& topo, std::size_t real_faces, const Control_matrix& Y,
                                     const Part_view& part = whole_mesh_view())
{
  Control_matrix N = Control_matrix::Zero(Y.rows(), 3);
  for(std::size_t f = 0; f < real_faces; ++f)
  {
    double n[3];
    face_cross_product(topo, f, Y, n);
    for(int v : topo.face(f)) N.row(v) += vec3(n).transpose();
  }
  for(Eigen::Index i = 0; i < N.rows(); ++i)
    if(N.row(i).norm() > 0) N.row(i).normalize();
  part.refresh(N);
  return N;
}

/// The mean of per-vertex values `t` over the whole mesh (each process's own rows, over the processes), and
/// their number.
inline std::pair<double, std::size_t> whole_mean(const std::vector<double>& t, const Part_view& part)
{
  std::vector<double> sums(2, 0.0);
  for(std::size_t i = 0; i < t.size(); ++i)
    if(part.owns_vertex(i))
    {
      sums[0] += t[i];
      sums[1] += 1;
    }
  part.sum(sums);
  return { sums[0] / sums[1], std::size_t(sums[1] + 0.5) };
}

/// The probe of the risk estimate: per vertex, a standard normal number drawn by its key (Vertex_keys.h; none: its
/// number), made as correlated as the noise by the caller.
inline std::vector<double> risk_probe_values(std::size_t n,
                                             const std::vector<std::uint64_t>& keys = std::vector<std::uint64_t>())
{
  std::vector<double> b(n);
  for(std::size_t i = 0; i < n; ++i) b[i] = keyed_normal(20261125u, keys.empty() ? std::uint64_t(i) : keys[i], 0);
  return b;
}

/// Y moved by risk_probe * sigma_i * b_i along N_i (geometry columns).
inline Control_matrix probed_input(const Control_matrix& Y, const Control_matrix& N, const std::vector<double>& sigma,
                                   const std::vector<double>& b)
{
  Control_matrix P = Y;
  for(Eigen::Index i = 0; i < Y.rows(); ++i)
    P.row(i).head(3) += risk_probe * sigma[std::size_t(i)] * b[std::size_t(i)] * N.row(i);
  return P;
}

/// The terms of SURE of a result f of y (f_probed: of the probed input), one per vertex in units of
/// sigma_i^2, without the constant -1 per vertex: ((n_i . (y_i - f_i)) / sigma_i)^2 + 2 div_i (0 where
/// sigma_i is 0). Their sum is the estimate.
inline std::vector<double> risk_terms(const Control_matrix& y, const Control_matrix& f, const Control_matrix& f_probed,
                                      const Control_matrix& N, const std::vector<double>& sigma,
                                      const std::vector<double>& b)
{
  std::vector<double> t(std::size_t(y.rows()), 0.0);
  for(Eigen::Index i = 0; i < y.rows(); ++i)
  {
    const double s = sigma[std::size_t(i)];
    if(!(s > 0)) continue;
    const double residual = N.row(i).dot(y.row(i).head(3) - f.row(i).head(3)) / s;
    const double along = N.row(i).dot(f_probed.row(i).head(3) - f.row(i).head(3));
    const double divergence = b[std::size_t(i)] * along / (risk_probe * s);
    t[std::size_t(i)] = residual * residual + 2 * divergence;
  }
  return t;
}

/// What the comparison measures its candidates with: the data moved by a probe, and the estimated error of a
/// result f whose probed run ended at f_probed; `relative_loss` is what it estimates, were the clean surface x
/// known (benchmarks and tests measure the estimate against it).
class Risk_estimate
{
public:
  virtual ~Risk_estimate() = default;
  virtual const Control_matrix& probed() const = 0;
  virtual double relative(const Control_matrix& f, const Control_matrix& f_probed) const = 0;
  /// Its terms, one per vertex, whose mean less 1 is relative() (empty: the estimate has no such terms, and
  /// no standard error of a difference of two estimates)
  virtual std::vector<double> terms(const Control_matrix& f, const Control_matrix& f_probed) const
  {
    (void)f;
    (void)f_probed;
    return {};
  }
  virtual double relative_loss(const Control_matrix& f, const Control_matrix& x) const = 0;
  /// how `choices` names it and its unit
  virtual const char* description() const = 0;
  /// Measures on `surface` from now on, when the estimate can (its probe does not depend on where it measures).
  virtual bool measure_on_result(const Control_matrix& surface) { (void)surface; return false; }
  /// The part of the mesh whose rows it reads (its terms' means are over every process's own rows)
  virtual const Part_view& part() const { return whole_mesh_view(); }
};

/// SURE of the positions along the normals N of a surface, per vertex in units of the noise: the sum of
/// risk_terms / rows - 1 (0: exact, about 1: no better than the input); `part`: the part of the mesh a process
/// holds, whose own rows it sums.
class Position_error_estimate : public Risk_estimate
{
public:
  Position_error_estimate(const Triangle_topology& topo, std::size_t real_faces, const Control_matrix& y,
                          const Control_matrix& surface, const std::vector<double>& sigma, const std::vector<double>& b,
                          const Part_view& part = whole_mesh_view())
    : y_(y), N_(vertex_normals(topo, real_faces, surface, part)), probed_(probed_input(y, N_, sigma, b)),
      sigma_(sigma), b_(b), part_(part)
  {}
  const Control_matrix& probed() const override { return probed_; }
  double relative(const Control_matrix& f, const Control_matrix& f_probed) const override
  {
    return whole_mean(terms(f, f_probed), part_).first - 1;
  }
  std::vector<double> terms(const Control_matrix& f, const Control_matrix& f_probed) const override
  {
    return risk_terms(y_, f, f_probed, N_, sigma_, b_);
  }
  double relative_loss(const Control_matrix& f, const Control_matrix& x) const override
  {
    std::vector<double> loss(std::size_t(f.rows()), 0.0);
    for(Eigen::Index i = 0; i < f.rows(); ++i)
    {
      const double s = sigma_[std::size_t(i)];
      if(s > 0) loss[std::size_t(i)] = std::pow(N_.row(i).dot(f.row(i).head(3) - x.row(i).head(3)) / s, 2);
    }
    return whole_mean(loss, part_).first;
  }
  const Part_view& part() const override { return part_; }
  const char* description() const override
  {
    return "Stein's unbiased risk estimate per vertex, in units of the noise";
  }

private:
  const Control_matrix& y_;
  Control_matrix N_, probed_;
  const std::vector<double>& sigma_;
  std::vector<double> b_;
  const Part_view& part_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_TENSOR_SELECTION_H
