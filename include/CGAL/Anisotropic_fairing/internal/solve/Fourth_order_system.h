// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The linear system of one semi-implicit step of the fourth-order flow dX/dt = -(M^-1 L)^2 X:
// ((1 + tau w) M + tau Q) dX = tau (w M (X_0 - X_n) - Q X_n), Q = L D^-1 L, D the lumped (row-sum) mass.
// A step damps a mode of M^-1 L with eigenvalue mu by 1 / (1 + tau mu^2), where the second-order step
// damps it by 1 / (1 + tau mu): the cut between the noise (large mu) and the shape (small mu) is sharper,
// so a run that removes the noise rounds the shape less. Q couples the 6-ring of a vertex (L the 3-ring).
// The lumped inverse keeps Q sparse; D_i is the integral of the basis function of i (the Loop basis is a
// partition of unity), positive on a surface. M carries the local time scale as in Step_system.h.
// Conjugate gradients use the system through its product, M x and L (D^-1 (L x)) on the 3-ring pattern:
// three sparse products cost less than one with the 6-ring Q, and Q is never formed unless the system is
// factorised (forming it costs most of a step).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_FOURTH_ORDER_SYSTEM_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_FOURTH_ORDER_SYSTEM_H

#include <CGAL/Anisotropic_fairing/internal/solve/Spd_solvers.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Step_system.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

class Fourth_order_system
{
public:
  /// `pattern`: the n x n symmetric pattern of M and L; `free`: the unknowns' rows (increasing).
  Fourth_order_system(const Sparse_structure& pattern, const std::vector<int>& free)
    : pattern_(pattern), select_(Eigen::Index(free.size()), pattern.rows()), is_free_(std::size_t(pattern.rows()),
                                                                                      false), free_(free)
  {
    for(int i : free) is_free_[std::size_t(i)] = true;
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(free.size());
    for(std::size_t k = 0; k < free.size(); ++k) t.emplace_back(Eigen::Index(k), free[k], 1.0);
    select_.setFromTriplets(t.begin(), t.end());
  }

  /// Takes M (with the local time scale `mass_weight`, empty: none, applied as M is used) and L where they
  /// are: the three must stay unchanged until release() or the next set_operator(). Forms D^-1.
  void set_operator(const Value_array& M, const Value_array& L, const std::vector<double>& mass_weight)
  {
    M_ = &M;
    L_ = &L;
    mass_weight_ = &mass_weight;
    const int* outer = pattern_.outerIndexPtr();
    const int* inner = pattern_.innerIndexPtr();
    const Eigen::Index n = pattern_.rows();
    Eigen::VectorXd d = lumped_mass(pattern_, M, mass_weight);
    // a vertex on no surface (held, isolated) has no mass and no Laplacian row: any positive D will do
    const double largest = d.size() > 0 ? d.maxCoeff() : 1.0;
    for(Eigen::Index i = 0; i < n; ++i) d[i] = is_free_[std::size_t(i)] ? 1 / std::max(d[i], 1e-12 * largest) : 0.0;
    inverse_mass_ = d;
    // the diagonals of M and of Q: Q_ii = sum_j L_ij^2 / D_j (L symmetric)
    m_diagonal_ = Eigen::VectorXd::Zero(n);
    q_diagonal_ = Eigen::VectorXd::Zero(n);
    for(Eigen::Index j = 0; j < n; ++j)
      for(int p = outer[j]; p < outer[j + 1]; ++p)
      {
        const double l = L[std::size_t(p)];
        q_diagonal_[inner[p]] += l * l * d[j];
        if(inner[p] == j)
          m_diagonal_[j] =
            M[std::size_t(p)] * (mass_weight.empty() ? 1.0 : mass_weight[std::size_t(j)] * mass_weight[std::size_t(j)]);
      }
    Q_formed_ = A_formed_ = false;
  }

  /// The system's coefficients: A (free x free) = (((1 + f tau_i w_i) M + f tau_i Q) restricted to the free
  /// rows) / sys, each row and column i in units of unknown_scale[i] (empty: none), as fill_step_matrix does
  /// for the second order. tau, w and the unit are constant within a component, and M and Q have no entry
  /// between two, so A is symmetric.
  void set_coefficients(const std::vector<double>& tau, const std::vector<double>& omega, double f, double sys,
                        const std::vector<double>& unknown_scale)
  {
    const Eigen::Index n = pattern_.rows();
    a_.resize(n);
    b_.resize(n);
    for(Eigen::Index i = 0; i < n; ++i)
    {
      const double t = f * tau[std::size_t(i)];
      const double u = unknown_scale.empty() ? 1.0 : unknown_scale[std::size_t(i)];
      a_[i] = (1 + t * omega[std::size_t(i)]) / (sys * u * u);
      b_[i] = t / (sys * u * u);
    }
    A_formed_ = false;
    diagonal_.resize(Eigen::Index(free_.size()));
    for(std::size_t k = 0; k < free_.size(); ++k)
    {
      const int i = free_[k];
      diagonal_[Eigen::Index(k)] = a_[i] * m_diagonal_[i] + b_[i] * q_diagonal_[i];
    }
  }

  /// E (free x free, in A's units, null: none) added to A: a vertex's own fidelity (Output_fidelity.h). After
  /// set_coefficients; E must outlive the solves.
  void set_extra(const Eigen::SparseMatrix<double>* E)
  {
    extra_ = E;
    A_formed_ = false;
    if(E)
      for(Eigen::Index k = 0; k < E->outerSize(); ++k)
        for(Eigen::SparseMatrix<double>::InnerIterator it(*E, k); it; ++it)
          if(it.row() == it.col()) diagonal_[k] += it.value();
  }

  /// The diagonal of A, for the preconditioner.
  const Eigen::VectorXd& diagonal() const { return diagonal_; }

  /// Y = A X over the free rows, without forming Q.
  void product(const Control_matrix& X, Control_matrix& Y) const
  {
    const Eigen::Index n = pattern_.rows(), c = X.cols();
    const bool whole = free_.size() == std::size_t(n);   // every row free: X has all rows, Y takes Q X
    if(!whole)
    {
      full_.setZero(n, c);
      for(std::size_t k = 0; k < free_.size(); ++k) full_.row(free_[k]) = X.row(Eigen::Index(k));
    }
    const Control_matrix& all = whole ? X : full_;
    symmetric_product(pattern_, *M_, all, mass_, *mass_weight_);
    symmetric_product(pattern_, *L_, all, laplace_);
    for(Eigen::Index i = 0; i < n; ++i) laplace_.row(i) *= inverse_mass_[i];
    Control_matrix& QX = whole ? Y : full_;
    symmetric_product(pattern_, *L_, laplace_, QX);
    if(!whole) Y.resize(Eigen::Index(free_.size()), c);
    for(std::size_t k = 0; k < free_.size(); ++k)
    {
      const int i = free_[k];
      Y.row(Eigen::Index(k)) = a_[i] * mass_.row(i) + b_[i] * QX.row(i);
    }
    if(extra_) Y += *extra_ * X;
  }

  /// A formed, for a factorisation (once per operator and coefficients).
  const Eigen::SparseMatrix<double>& matrix()
  {
    if(A_formed_) return A_;
    if(!Q_formed_)
    {
      const Eigen::SparseMatrix<double> L = pattern_.matrix(*L_);
      Q_ = L * inverse_mass_.asDiagonal() * L;
      Q_formed_ = true;
    }
    A_formed_ = true;
    Eigen::SparseMatrix<double> M = pattern_.matrix(*M_);
    if(!mass_weight_->empty())
      for(Eigen::Index j = 0; j < M.outerSize(); ++j)
        for(Eigen::SparseMatrix<double>::InnerIterator it(M, j); it; ++it)
          it.valueRef() *= (*mass_weight_)[std::size_t(it.row())] * (*mass_weight_)[std::size_t(j)];
    const Eigen::SparseMatrix<double> S = a_.asDiagonal() * M + b_.asDiagonal() * Q_;
    A_ = select_ * S * select_.transpose();
    if(extra_) A_ += *extra_;
    return A_;
  }

  /// Frees what set_operator() formed and the products' scratch, and lets go of M and L.
  void release()
  {
    M_ = L_ = nullptr;
    mass_weight_ = nullptr;
    Q_ = A_ = Eigen::SparseMatrix<double>();
    Q_formed_ = A_formed_ = false;
    full_.resize(0, 0);
    mass_.resize(0, 0);
    laplace_.resize(0, 0);
  }

  /// R = f tau_i (w_i M (X0 - X) - Q X)_i for all rows.
  void residual(const std::vector<double>& tau, const std::vector<double>& omega, const Control_matrix& X,
                const Control_matrix& X0,
                double f, Control_matrix& R) const
  {
    Eigen::VectorXd w(X.rows()), t(X.rows());
    for(Eigen::Index i = 0; i < X.rows(); ++i) { w[i] = omega[std::size_t(i)]; t[i] = f * tau[std::size_t(i)]; }
    symmetric_product(pattern_, *L_, X, laplace_);
    for(Eigen::Index i = 0; i < X.rows(); ++i) laplace_.row(i) *= inverse_mass_[i];
    symmetric_product(pattern_, *L_, laplace_, full_);   // Q X
    laplace_ = X0 - X;
    symmetric_product(pattern_, *M_, laplace_, mass_, *mass_weight_);
    R = t.asDiagonal() * (w.asDiagonal() * mass_ - full_);
    if(free_.size() == std::size_t(X.rows())) full_.resize(0, 0);   // product() needs it only when rows are held
  }

private:
  const Sparse_structure& pattern_;
  Eigen::SparseMatrix<double> select_;
  std::vector<bool> is_free_;
  std::vector<int> free_;
  // the operator's (values over pattern_) and the local time scale's weights: unchanged while a step is solved
  const Value_array* M_ = nullptr;
  const Value_array* L_ = nullptr;
  const std::vector<double>* mass_weight_ = nullptr;
  Eigen::SparseMatrix<double> Q_, A_;   // formed for a factorisation only
  bool Q_formed_ = false, A_formed_ = false;
  const Eigen::SparseMatrix<double>* extra_ = nullptr;
  Eigen::VectorXd inverse_mass_, m_diagonal_, q_diagonal_, a_, b_, diagonal_;
  mutable Control_matrix full_, mass_, laplace_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_FOURTH_ORDER_SYSTEM_H
