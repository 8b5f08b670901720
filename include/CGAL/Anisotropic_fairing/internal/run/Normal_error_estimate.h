// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The error users see, estimated from the noisy mesh alone: how far a result's face normals are off the
// unknown clean surface's. To first order a displacement e of the vertices turns the normal of face f by the
// in-face gradient of n_f . e (motion within the face's plane turns nothing), so
//   sum_f A_f theta_f^2 ~ sum_f e_f^T K_f e_f,   e_f = (n_f . e_i) over f's corners,
// K_f the face's cotangent stiffness: a quadratic form e^T A e of the displacement, A = sum_f P_f^T K_f P_f.
// Projected on each face's own normal, a result's drift along the surface costs nothing; projected on one
// normal per vertex it would leak into the loss wherever that normal is off the face's (measured:
// bench/results-estimate-soundness-2026-11-29.md). For noise of covariance Sigma (deviation sigma_i along the
// vertex normals N_i), generalized SURE (Eldar 2009) estimates that loss for a result f of the data y:
//   sum_f r_f^T K_f r_f + 2 tr(A Sigma J) - tr(A Sigma),   r = f - y,  J = df/dy,
// the trace by one probe: u = Sigma^(1/2) b (b standard normal), the data moved by eps A u, and
//   tr(A Sigma J) = E[u^T J A u] ~ u . (f(y + eps A u) - f(y)) / eps.
// A and N are read on a surface less noisy than y (the anisotropic run's prefiltered input). The estimates are
// given relative to tr(A Sigma), the noisy input's own error (1: no better than the input, 0: exact).
//
// Measured by the benchmarks (Risk_kind::FACE_NORMALS), not yet the default run's choice: an A read on a surface
// that still follows the noise makes it unsound between flows (bench/results-estimate-soundness-2026-11-29.md).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_NORMAL_ERROR_ESTIMATE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_NORMAL_ERROR_ESTIMATE_H

#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>
#include <CGAL/Anisotropic_fairing/internal/run/Tensor_selection.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// How the probe moves the data: along A u, which gives tr(A Sigma J) for any J; or along u itself (the noise's
/// directions, the probe SURE of the positions uses), which gives it as (A u) . J u where J Sigma is symmetric,
/// and leaves A free to be read on another surface once the candidates have run (`measure_on`).
enum class Normal_error_probe { STIFFNESS, NOISE };

class Normal_error_estimate : public Risk_estimate
{
public:
  /// `y`: the data (the input); `surface`: where the faces' normals and stiffness and the noise's directions are
  /// read; the first `real_faces` faces of `topo` are the surface; `sigma`: the noise's deviation per vertex;
  /// `b`: the probe's standard normal numbers, one per vertex.
  /// `tangential`: the noise's deviation across the normals per vertex, in each direction (empty: none).
  Normal_error_estimate(const Triangle_topology& topo, std::size_t real_faces, const Control_matrix& y,
                        const Control_matrix& surface, const std::vector<double>& sigma, const std::vector<double>& b,
                        Normal_error_probe probe = Normal_error_probe::STIFFNESS,
                        const std::vector<double>& tangential = std::vector<double>())
    : topo_(topo), real_faces_(real_faces), y_(y), sigma_(sigma), tangential_(tangential), probe_(probe),
      N_(vertex_normals(topo, real_faces, surface))
  {
    const Eigen::Index n = y.rows();
    u_ = Control_matrix::Zero(n, 3);
    for(Eigen::Index i = 0; i < n; ++i) u_.row(i) = sigma[std::size_t(i)] * b[std::size_t(i)] * N_.row(i);
    if(!tangential_.empty())
    {
      // the probe across the normals: two more standard normal numbers per vertex, in a frame of its plane
      for(Eigen::Index i = 0; i < n; ++i)
      {
        const Eigen::Vector3d nrm = N_.row(i).transpose();
        const Eigen::Vector3d t1 = nrm.unitOrthogonal(), t2 = nrm.cross(t1);
        const double c = keyed_normal(20261129u, std::uint64_t(i), 0), d = keyed_normal(20261129u, std::uint64_t(i), 1);
        if(nrm.squaredNorm() > 0) u_.row(i) += tangential_[std::size_t(i)] * (c * t1 + d * t2).transpose();
      }
    }
    measure_on(surface);
    if(probe_ == Normal_error_probe::NOISE)
    {
      eps_ = risk_probe;
      probed_ = y;
      probed_.leftCols(3) += risk_probe * u_;
      return;
    }
    // the probe moves the data by about risk_probe times the noise
    double noise2 = 0, direction2 = 0;
    for(Eigen::Index i = 0; i < n; ++i)
    {
      noise2 += sigma[std::size_t(i)] * sigma[std::size_t(i)];
      direction2 += Au_.row(i).squaredNorm();
    }
    eps_ = direction2 > 0 ? risk_probe * std::sqrt(noise2 / direction2) : 0.0;
    probed_ = y;
    probed_.leftCols(3) += eps_ * Au_;
  }

  /// The loss read on the faces of `surface` from now on (the noise's directions and the probe stay): only with
  /// the probe along the noise, whose runs do not depend on A.
  void measure_on(const Control_matrix& surface)
  {
    faces_.clear();
    faces_.reserve(real_faces_);
    for(std::size_t f = 0; f < real_faces_; ++f)
    {
      Face_form form;
      if(make_face_form(topo_.face(f), surface, form)) faces_.push_back(form);
    }
    // tr(A Sigma) and A u
    input_error_ = 0;
    Au_ = Control_matrix::Zero(u_.rows(), 3);
    for(const Face_form& form : faces_)
      for(int a = 0; a < 3; ++a)
      {
        const int i = form.corner[a];
        const double along = form.normal.dot(N_.row(i).transpose()), s = sigma_[std::size_t(i)];
        const double t = tangential_.empty() ? 0.0 : tangential_[std::size_t(i)];
        input_error_ += form.K[a][a] * (s * s * along * along + t * t * (1 - along * along));
        for(int c = 0; c < 3; ++c)
        {
          const double along_u = form.normal.dot(u_.row(form.corner[c]).transpose());
          Au_.row(i) += form.K[a][c] * along_u * form.normal.transpose();
        }
      }
  }

  bool measure_on_result(const Control_matrix& surface) override
  {
    if(probe_ != Normal_error_probe::NOISE) return false;
    measure_on(surface);
    return true;
  }

  /// The data moved by the probe: every candidate's probed run starts there.
  const Control_matrix& probed() const override { return probed_; }

  /// tr(A Sigma): the expected loss of the noisy input itself, the unit of the estimates.
  double input_error() const { return input_error_; }

  /// The estimate of result f whose probed run ended at f_probed, relative to the input's.
  double relative(const Control_matrix& f, const Control_matrix& f_probed) const override
  {
    if(!(input_error_ > 0) || !(eps_ > 0)) return std::nan("");
    const Control_matrix& weight = probe_ == Normal_error_probe::STIFFNESS ? u_ : Au_;
    double divergence = 0;
    for(Eigen::Index i = 0; i < f.rows(); ++i)
      divergence += weight.row(i).dot(f_probed.row(i).head(3) - f.row(i).head(3));
    return (loss(f, y_) + 2 * divergence / eps_ - input_error_) / input_error_;
  }

  /// The loss itself, were the clean surface x known, relative to the input's (benchmarks and tests measure the
  /// estimate against it).
  double relative_loss(const Control_matrix& f, const Control_matrix& x) const override
  {
    return loss(f, x) / input_error_;
  }
  const char* description() const override
  {
    return "the face normals' error estimated by generalized SURE, relative to the noisy input's";
  }

private:
  // one face's part of A: its corners, its unit normal and its cotangent stiffness
  struct Face_form
  {
    std::array<int, 3> corner;
    Eigen::Vector3d normal;
    double K[3][3];
  };

  static bool make_face_form(const std::array<int, 3>& t, const Control_matrix& Y, Face_form& form)
  {
    const Eigen::Vector3d p[3] = { Y.row(t[0]).head<3>().transpose(), Y.row(t[1]).head<3>().transpose(),
                                   Y.row(t[2]).head<3>().transpose() };
    const Eigen::Vector3d cross = (p[1] - p[0]).cross(p[2] - p[0]);
    const double twice_area = cross.norm();
    if(!(twice_area > 0) || !std::isfinite(twice_area)) return false;   // no normal: no part of the loss
    form.corner = t;
    form.normal = cross / twice_area;
    for(int a = 0; a < 3; ++a) form.K[a][a] = 0;
    for(int c = 0; c < 3; ++c)
    {
      // the corner c faces the edge (a, b): weight cot(c) / 2
      const int a = (c + 1) % 3, b = (c + 2) % 3;
      const double w = (p[a] - p[c]).dot(p[b] - p[c]) / (2 * twice_area);
      form.K[a][b] = form.K[b][a] = -w;
      form.K[a][a] += w;
      form.K[b][b] += w;
    }
    return true;
  }

  // sum_f e_f^T K_f e_f, e_f = (n_f . (f_i - x_i)) over the face's corners
  double loss(const Control_matrix& f, const Control_matrix& x) const
  {
    double sum = 0;
    for(const Face_form& form : faces_)
    {
      double e[3];
      for(int a = 0; a < 3; ++a)
        e[a] = form.normal.dot((f.row(form.corner[a]).head(3) - x.row(form.corner[a]).head(3)).transpose());
      for(int a = 0; a < 3; ++a)
        for(int c = 0; c < 3; ++c) sum += e[a] * form.K[a][c] * e[c];
    }
    return sum;
  }

  const Triangle_topology& topo_;
  std::size_t real_faces_;
  const Control_matrix& y_;
  std::vector<double> sigma_, tangential_;
  Normal_error_probe probe_;
  Control_matrix N_, u_, Au_, probed_;
  std::vector<Face_form> faces_;
  double input_error_ = 0, eps_ = 0;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_NORMAL_ERROR_ESTIMATE_H
