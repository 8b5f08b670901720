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

#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Parallel_blocks.h>
#include <CGAL/Anisotropic_fairing/internal/types/Sparse_structure.h>
#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cmath>
#include <functional>
#include <limits>
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

/// Rows [begin, end) of Y = A X (A compressed, stored in full, X and Y row-major with K columns); with
/// `Weighted`, of Y = W A W X, W = diag(w), each entry a_ij (w_i w_j) as it is formed. The sums stay in
/// registers: the product is the solvers' main cost, and writing through Y's row at every non-zero (which
/// may alias X as far as the compiler knows) makes it about twice as slow.
template <int K, bool Weighted>
void sparse_rows_product(const int* outer, const int* rows, const double* values, const double* w, const double* X,
                         double* Y,
                         Eigen::Index begin, Eigen::Index end)
{
  for(Eigen::Index i = begin; i < end; ++i)
  {
    double sum[K] = {};
    for(int p = outer[i]; p < outer[i + 1]; ++p)
    {
      const double a = Weighted ? values[p] * (w[rows[p]] * w[i]) : values[p];
      const double* x = X + std::ptrdiff_t(rows[p]) * K;
      for(int c = 0; c < K; ++c) sum[c] += a * x[c];
    }
    for(int c = 0; c < K; ++c) Y[i * K + c] = sum[c];
  }
}

template <bool Weighted>
void sparse_rows_product(const int* outer, const int* rows, const double* values, const double* w,
                         const Control_matrix& X,
                         Control_matrix& Y, Eigen::Index begin, Eigen::Index end)
{
  const Eigen::Index k = X.cols();
  switch(k)
  {
  case 1: sparse_rows_product<1, Weighted>(outer, rows, values, w, X.data(), Y.data(), begin, end); return;
  case 2: sparse_rows_product<2, Weighted>(outer, rows, values, w, X.data(), Y.data(), begin, end); return;
  case 3: sparse_rows_product<3, Weighted>(outer, rows, values, w, X.data(), Y.data(), begin, end); return;
  case 4: sparse_rows_product<4, Weighted>(outer, rows, values, w, X.data(), Y.data(), begin, end); return;
  case 6: sparse_rows_product<6, Weighted>(outer, rows, values, w, X.data(), Y.data(), begin, end); return;
  default: break;
  }
  for(Eigen::Index i = begin; i < end; ++i)
  {
    double* y = Y.row(i).data();
    std::fill(y, y + k, 0.0);
    for(int p = outer[i]; p < outer[i + 1]; ++p)
    {
      const double a = Weighted ? values[p] * (w[rows[p]] * w[i]) : values[p];
      const double* x = X.row(rows[p]).data();
      for(Eigen::Index c = 0; c < k; ++c) y[c] += a * x[c];
    }
  }
}

/// Y = A X for a symmetric matrix stored in full (column j = row j), A given by its structure and
/// values, X and Y with one row per unknown; with `weights` (not null), Y = W A W X, W = diag(weights).
inline void symmetric_product(const int* outer, const int* rows, const double* values, const Control_matrix& X,
                              Control_matrix& Y,
                              const double* weights = nullptr)
{
  Y.resize(X.rows(), X.cols());
  auto range = [&](Eigen::Index begin, Eigen::Index end) {
    if(weights) sparse_rows_product<true>(outer, rows, values, weights, X, Y, begin, end);
    else sparse_rows_product<false>(outer, rows, values, nullptr, X, Y, begin, end);
  };
  parallel_blocks(X.rows(), range);
}

/// The same with A's structure and values; `weights` empty: none.
inline void symmetric_product(const Sparse_structure& S, const Value_array& values, const Control_matrix& X,
                              Control_matrix& Y,
                              const std::vector<double>& weights = std::vector<double>())
{
  symmetric_product(S.outerIndexPtr(), S.innerIndexPtr(), values.data(), X, Y,
                    weights.empty() ? nullptr : weights.data());
}

inline void symmetric_product(const Eigen::SparseMatrix<double>& A, const Control_matrix& X, Control_matrix& Y)
{
  symmetric_product(A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr(), X, Y);
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
    Eigen::VectorXd diagonal(B.rows());
    for(Eigen::Index i = 0; i < B.rows(); ++i) diagonal[i] = A.coeff(i, i);
    return solve([&A](const Control_matrix& P, Control_matrix& AP) { symmetric_product(A, P, AP); }, diagonal, B, X);
  }

  /// The same for a matrix given by its product, `product(P, AP)` setting AP = A P, and its diagonal;
  /// `iteration_limit` > 0: at most that many iterations in this solve (below the constructor's maximum),
  /// and fewer when the rate of convergence so far says that the limit would not be enough (something
  /// faster stands by: a factorisation).
  template <typename Product>
  Solve_statistics solve(const Product& product, const Eigen::VectorXd& diagonal, const Control_matrix& B,
                         Control_matrix& X,
                         int iteration_limit)
  {
    const int kept = max_iterations_;
    if(iteration_limit > 0) max_iterations_ = std::min(max_iterations_, iteration_limit);
    give_up_on_rate_ = iteration_limit > 0;
    Solve_statistics st = solve(product, diagonal, B, X);
    max_iterations_ = kept;
    give_up_on_rate_ = false;
    return st;
  }

  template <typename Product>
  Solve_statistics solve(const Product& product, const Eigen::VectorXd& diagonal, const Control_matrix& B,
                         Control_matrix& X)
  {
    Solve_statistics st;
    if(!start(product, diagonal, B, X, st)) return st;
    int it = 0;
    while(!stopped(it, st))
    {
      ++it;
      if(!iterate(product, X))
      {
        st.ok = false;
        st.message = "conjugate gradients broke down (the matrix is not positive definite)";
        break;
      }
    }
    return finish(st, product, B, X, bnorm_, it);
  }

  /// Frees the iterations' vectors (a solve makes them anew).
  void release() { R_.resize(0, 0); P_.resize(0, 0); AP_.resize(0, 0); }

private:
  // the preconditioner, the first residual and direction, and the norms the iterations are judged by
  template <typename Product>
  bool start(const Product& product, const Eigen::VectorXd& diagonal, const Control_matrix& B, const Control_matrix& X,
             Solve_statistics& st)
  {
    const Eigen::Index n = B.rows(), k = B.cols();
    inv_diag_.resize(n);
    for(Eigen::Index i = 0; i < n; ++i)
    {
      const double d = diagonal[i];
      if(!(d > 0))
      {
        st.ok = false;
        st.message = "the system matrix has a non-positive diagonal entry at unknown " + std::to_string(i);
        return false;
      }
      inv_diag_[i] = 1.0 / d;
    }
    product(X, AP_);
    R_ = B - AP_;
    P_ = inv_diag_.asDiagonal() * R_;
    const std::size_t kk = std::size_t(k);
    bnorm_.assign(kk, 0.0);
    rz_.assign(kk, 0.0);
    rnorm_.assign(kk, 0.0);
    active_.assign(kk, 1);
    alpha_.assign(kk, 0.0);
    beta_.assign(kk, 0.0);
    for(Eigen::Index c = 0; c < k; ++c)
    {
      bnorm_[std::size_t(c)] = B.col(c).norm();
      rz_[std::size_t(c)] = R_.col(c).dot(P_.col(c));
      rnorm_[std::size_t(c)] = R_.col(c).norm();
    }
    rnorm0_ = rnorm_;
    return true;
  }

  // whether the iterations end after `it`: every column converged, the limit reached, or (with a
  // factorisation standing by) a column's rate says that the limit would not be enough
  bool stopped(int it, Solve_statistics& st)
  {
    const auto converged = [this](std::size_t c) { return rnorm_[c] <= tolerance_ * bnorm_[c] || rnorm_[c] == 0; };
    // the iterations a column needs at its mean rate so far (from trial_iterations on: CG's first
    // iterations are not its pace; its later ones are faster if anything, so this errs toward giving way)
    const auto predicted = [this](std::size_t c, int done) {
      const double reached = rnorm_[c] / rnorm0_[c], wanted = tolerance_ * bnorm_[c] / rnorm0_[c];
      return reached < 1 ? done * std::log(wanted) / std::log(reached) : HUGE_VAL;
    };
    bool any = false;
    for(std::size_t c = 0; c < active_.size(); ++c)
      if(active_[c] && converged(c)) active_[c] = 0;
      else any = any || active_[c];
    if(!any) return true;
    if(it == max_iterations_)
    {
      st.ok = false;
      st.message = "conjugate gradients did not converge in " + std::to_string(max_iterations_) + " iterations";
      return true;
    }
    if(give_up_on_rate_ && it >= automatic_cholesky_trial_iterations && it % 25 == 0)
    {
      bool slow = false;
      for(std::size_t c = 0; c < active_.size(); ++c) slow = slow || (active_[c] && predicted(c, it) > max_iterations_);
      if(slow)
      {
        st.ok = false;
        st.message =
          "conjugate gradients would not converge in " + std::to_string(max_iterations_) + " iterations at their rate";
        return true;
      }
    }
    return false;
  }

  // one iteration on the active columns; false when it breaks down (p^T A p not positive)
  template <typename Product>
  bool iterate(const Product& product, Control_matrix& X)
  {
    const Eigen::Index n = X.rows(), k = X.cols();
    product(P_, AP_);
    // the vector work in row chunks on every core, fused into two passes over the rows
    const double* p = P_.data();
    const double* ap = AP_.data();
    chunked_sums(n, k, [&](Eigen::Index i, double* sums) {
      for(Eigen::Index c = 0; c < k; ++c) sums[c] += p[i * k + c] * ap[i * k + c];
    }, pap_);
    for(std::size_t c = 0; c < active_.size(); ++c)
    {
      alpha_[c] = 0;
      if(!active_[c]) continue;
      if(!(pap_[c] > 0) || !std::isfinite(pap_[c])) return false;
      alpha_[c] = rz_[c] / pap_[c];
    }
    double* x = X.data();
    double* r = R_.data();
    const double* id = inv_diag_.data();
    chunked_sums(n, 2 * k, [&](Eigen::Index i, double* sums) {   // sums: r.z, then r.r, per column
      for(Eigen::Index c = 0; c < k; ++c)
      {
        if(!active_[std::size_t(c)]) continue;
        const Eigen::Index e = i * k + c;
        x[e] += alpha_[std::size_t(c)] * p[e];
        r[e] -= alpha_[std::size_t(c)] * ap[e];
        sums[c] += r[e] * r[e] * id[i];
        sums[k + c] += r[e] * r[e];
      }
    }, sums_);
    for(std::size_t c = 0; c < active_.size(); ++c)
    {
      beta_[c] = active_[c] ? sums_[c] / rz_[c] : 0.0;
      if(!active_[c]) continue;
      rz_[c] = sums_[c];
      rnorm_[c] = std::sqrt(sums_[std::size_t(k) + c]);
    }
    double* pw = P_.data();
    parallel_blocks(n, [&](Eigen::Index begin, Eigen::Index end) {
      for(Eigen::Index i = begin; i < end; ++i)
        for(Eigen::Index c = 0; c < k; ++c)
          if(active_[std::size_t(c)]) pw[i * k + c] = id[i] * r[i * k + c] + beta_[std::size_t(c)] * pw[i * k + c];
    });
    return true;
  }

  // the reported residual is recomputed from scratch, not the recurrence's
  template <typename Product>
  Solve_statistics& finish(Solve_statistics& st, const Product& product, const Control_matrix& B,
                           const Control_matrix& X, const std::vector<double>& bnorm, int it)
  {
    st.iterations = it;
    product(X, AP_);
    for(Eigen::Index c = 0; c < B.cols(); ++c)
    {
      const double r = (B.col(c) - AP_.col(c)).norm();
      st.residual = std::max(st.residual, bnorm[std::size_t(c)] > 0 ? r / bnorm[std::size_t(c)] : r);
    }
    return st;
  }

  // out[w] = sum over rows i of what row(i, sums) adds to sums[w], w < width. Each fixed chunk of rows has
  // its own partial sums, added in chunk order: the result does not depend on the number of threads.
  template <typename Row>
  void chunked_sums(Eigen::Index n, Eigen::Index width, const Row& row, std::vector<double>& out)
  {
    const Eigen::Index chunk = 4096, chunks = (n + chunk - 1) / chunk;
    partial_.assign(std::size_t(chunks * width), 0.0);
    auto run = [&](Eigen::Index first, Eigen::Index last) {
      for(Eigen::Index q = first; q < last; ++q)
      {
        double* sums = partial_.data() + q * width;
        for(Eigen::Index i = q * chunk; i < std::min(n, (q + 1) * chunk); ++i) row(i, sums);
      }
    };
    parallel_blocks(chunks, run, Eigen::Index(1), Eigen::Index(4));   // a chunk per task from 5 chunks on
    out.assign(std::size_t(width), 0.0);
    for(Eigen::Index q = 0; q < chunks; ++q)
      for(Eigen::Index w = 0; w < width; ++w) out[std::size_t(w)] += partial_[std::size_t(q * width + w)];
  }

  double tolerance_;
  int max_iterations_;
  bool give_up_on_rate_ = false;
  Control_matrix R_, P_, AP_;
  Eigen::VectorXd inv_diag_;
  std::vector<double> alpha_, beta_, pap_, sums_, partial_, bnorm_, rz_, rnorm_, rnorm0_;
  std::vector<char> active_;
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
  /// The kept factorisation no longer fits the matrix: factorise at the next solve.
  void matrix_changed() { factorised_ = false; }
  /// The floating-point operations of the last factorisation and of a solve with it for `columns` right-hand
  /// sides, counted from the factor; NaN when the solver cannot count them (then it is timed).
  virtual double operations(Eigen::Index columns) const
  {
    (void)columns;
    return std::numeric_limits<double>::quiet_NaN();
  }

protected:
  bool keep_factorisation_ = false;
  bool factorised_ = false;
};

/// Makes the direct solver to use; empty: Sparse_cholesky.
typedef std::function<std::unique_ptr<Direct_solver>()> Direct_solver_factory;

/// The largest relative residual |b - A x| / |b| over the columns (A: the lower triangle is read)
inline double relative_residual(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& b,
                                const Eigen::MatrixXd& x)
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

  /// sum over the factor's columns of (entries)^2 for the factorisation, 4 per entry and column to solve
  double operations(Eigen::Index columns) const override
  {
    if(!factorised_) return std::numeric_limits<double>::quiet_NaN();
    const auto& factor = ldlt_.matrixL().nestedExpression();
    double work = 0;
    for(Eigen::Index j = 0; j < factor.outerSize(); ++j)
    {
      const double c = double(factor.outerIndexPtr()[j + 1] - factor.outerIndexPtr()[j]);
      work += c * c;
    }
    return work + 4.0 * double(factor.nonZeros()) * double(columns);
  }

private:
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt_;
  bool analysed_ = false;
};

inline std::unique_ptr<Direct_solver> make_direct_solver(const Direct_solver_factory& factory)
{
  return factory ? factory() : std::unique_ptr<Direct_solver>(new Sparse_cholesky());
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_SPD_SOLVERS_H
