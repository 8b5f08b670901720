// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The two solvers of the symmetric positive definite system of a time step, behind one interface:
// block conjugate gradients with a diagonal preconditioner (every column shares each product with
// the matrix), and a sparse LDL^T whose symbolic analysis is done once because the pattern is fixed
// by the topology. Both solve for the step's displacement, whose right-hand side does not depend on
// where the model sits in space, so a relative residual means the same on every model.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_SPD_SOLVERS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_SPD_SOLVERS_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {


struct Solve_statistics
{
  bool ok = true;
  int iterations = 0;
  double residual = 0;   // largest relative residual over the columns
  double analysis_seconds = 0;   // one-off symbolic work included in this call
  std::string message;
};

/// Y = A X for a symmetric matrix stored in full (column j = row j), X and Y with one row per unknown.
inline void symmetric_product(const Eigen::SparseMatrix<double>& A, const Control_matrix& X, Control_matrix& Y)
{
  Y.resize(X.rows(), X.cols());
  const int* outer = A.outerIndexPtr();
  const int* rows = A.innerIndexPtr();
  const double* values = A.valuePtr();
  const Eigen::Index k = X.cols();
  auto range = [&](Eigen::Index begin, Eigen::Index end) {
    for(Eigen::Index i = begin; i < end; ++i)
    {
      double* y = Y.row(i).data();
      std::fill(y, y + k, 0.0);
      for(int p = outer[i]; p < outer[i + 1]; ++p)
      {
        const double a = values[p];
        const double* x = X.row(rows[p]).data();
        for(Eigen::Index c = 0; c < k; ++c) y[c] += a * x[c];
      }
    }
  };
#ifdef CGAL_LINKED_WITH_TBB
  if(X.rows() > 20000)
  {
    tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, X.rows(), 4096),
                      [&](const tbb::blocked_range<Eigen::Index>& r) { range(r.begin(), r.end()); });
    return;
  }
#endif
  range(0, X.rows());
}

/// Jacobi-preconditioned conjugate gradients on all columns at once; a column stops updating once
/// its residual is below tolerance * |b|.
class Block_conjugate_gradient
{
public:
  Block_conjugate_gradient(double tolerance, int max_iterations)
    : tolerance_(tolerance), max_iterations_(max_iterations) {}

  Solve_statistics solve(const Eigen::SparseMatrix<double>& A, const Control_matrix& B, Control_matrix& X)
  {
    Solve_statistics st;
    const Eigen::Index n = B.rows(), k = B.cols();
    Eigen::VectorXd inv_diag(n);
    for(Eigen::Index i = 0; i < n; ++i)
    {
      const double d = A.coeff(i, i);
      if(!(d > 0))
      {
        st.ok = false;
        st.message = "the system matrix has a non-positive diagonal entry at unknown " + std::to_string(i);
        return st;
      }
      inv_diag[i] = 1.0 / d;
    }
    symmetric_product(A, X, AP_);
    R_ = B - AP_;
    Z_ = inv_diag.asDiagonal() * R_;
    P_ = Z_;
    const std::size_t kk = std::size_t(k);
    std::vector<double> bnorm(kk), rz(kk), rnorm(kk);
    std::vector<bool> active(kk, true);
    for(Eigen::Index c = 0; c < k; ++c)
    {
      bnorm[std::size_t(c)] = B.col(c).norm();
      rz[std::size_t(c)] = R_.col(c).dot(Z_.col(c));
      rnorm[std::size_t(c)] = R_.col(c).norm();
    }
    auto converged = [&](Eigen::Index c) {
      return rnorm[std::size_t(c)] <= tolerance_ * bnorm[std::size_t(c)] || rnorm[std::size_t(c)] == 0;
    };
    int it = 0;
    for(;;)
    {
      bool any = false;
      for(Eigen::Index c = 0; c < k; ++c)
        if(active[std::size_t(c)] && converged(c)) active[std::size_t(c)] = false;
        else any = any || active[std::size_t(c)];
      if(!any) break;
      if(it == max_iterations_)
      {
        st.ok = false;
        st.message = "conjugate gradients did not converge in " + std::to_string(max_iterations_) + " iterations";
        break;
      }
      ++it;
      symmetric_product(A, P_, AP_);
      for(Eigen::Index c = 0; c < k; ++c)
      {
        if(!active[std::size_t(c)]) continue;
        const double pap = P_.col(c).dot(AP_.col(c));
        if(!(pap > 0) || !std::isfinite(pap))
        {
          st.ok = false;
          st.message = "conjugate gradients broke down (the matrix is not positive definite)";
          return finish(st, A, B, X, bnorm, it);
        }
        const double alpha = rz[std::size_t(c)] / pap;
        X.col(c) += alpha * P_.col(c);
        R_.col(c) -= alpha * AP_.col(c);
        Z_.col(c) = inv_diag.cwiseProduct(R_.col(c));
        const double rz_new = R_.col(c).dot(Z_.col(c));
        P_.col(c) = Z_.col(c) + (rz_new / rz[std::size_t(c)]) * P_.col(c);
        rz[std::size_t(c)] = rz_new;
        rnorm[std::size_t(c)] = R_.col(c).norm();
      }
    }
    return finish(st, A, B, X, bnorm, it);
  }

private:
  // the reported residual is recomputed from scratch, not the recurrence's
  Solve_statistics& finish(Solve_statistics& st, const Eigen::SparseMatrix<double>& A, const Control_matrix& B,
                           const Control_matrix& X, const std::vector<double>& bnorm, int it)
  {
    st.iterations = it;
    symmetric_product(A, X, AP_);
    for(Eigen::Index c = 0; c < B.cols(); ++c)
    {
      const double r = (B.col(c) - AP_.col(c)).norm();
      st.residual = std::max(st.residual, bnorm[std::size_t(c)] > 0 ? r / bnorm[std::size_t(c)] : r);
    }
    return st;
  }

  double tolerance_;
  int max_iterations_;
  Control_matrix R_, Z_, P_, AP_;
};

/// A factorising solver of the symmetric positive definite system (the matrix stored in full): the
/// package's Sparse_cholesky, or the user's `sparse_linear_solver` (User_direct_solver.h).
class Direct_solver
{
public:
  virtual ~Direct_solver() {}
  virtual Solve_statistics solve(const Eigen::SparseMatrix<double>& A, const Control_matrix& B, Control_matrix& X) = 0;
  /// For a matrix that does not change between solves: factorise at the first solve only.
  void keep_factorisation(bool keep) { keep_factorisation_ = keep; }

protected:
  bool keep_factorisation_ = false;
};

/// Makes the direct solver to use; empty: Sparse_cholesky.
typedef std::function<std::unique_ptr<Direct_solver>()> Direct_solver_factory;

/// The largest relative residual |b - A x| / |b| over the columns (A: the lower triangle is read)
inline double relative_residual(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& b, const Eigen::MatrixXd& x)
{
  const Eigen::MatrixXd r = b - A.selfadjointView<Eigen::Lower>() * x;
  double largest = 0;
  for(Eigen::Index c = 0; c < b.cols(); ++c)
  {
    const double bn = b.col(c).norm();
    largest = std::max(largest, bn > 0 ? r.col(c).norm() / bn : r.col(c).norm());
  }
  return largest;
}

/// Sparse LDL^T (fill-reducing ordering and symbolic analysis on the first call, numeric
/// factorisation on every call).
class Sparse_cholesky : public Direct_solver
{
public:
  Solve_statistics solve(const Eigen::SparseMatrix<double>& A, const Control_matrix& B, Control_matrix& X) override
  {
    Solve_statistics st;
    if(!analysed_)
    {
      const auto start = std::chrono::steady_clock::now();
      ldlt_.analyzePattern(A);
      analysed_ = true;
      st.analysis_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    if(!(keep_factorisation_ && factorised_))
    {
      ldlt_.factorize(A);
      factorised_ = ldlt_.info() == Eigen::Success && ldlt_.vectorD().minCoeff() > 0;
      if(!factorised_)
      {
        st.ok = false;
        st.message = "the sparse LDL^T factorisation failed (the matrix is not positive definite)";
        return st;
      }
    }
    Eigen::MatrixXd b = B, x(B.rows(), B.cols());
    x = ldlt_.solve(b);
    X = x;
    st.iterations = 1;
    st.residual = relative_residual(A, b, x);
    return st;
  }

private:
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt_;
  bool analysed_ = false;
  bool factorised_ = false;
};

inline std::unique_ptr<Direct_solver> make_direct_solver(const Direct_solver_factory& factory)
{
  return factory ? factory() : std::unique_ptr<Direct_solver>(new Sparse_cholesky());
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_SPD_SOLVERS_H
