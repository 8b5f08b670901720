// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The user's factorisation, given as the `sparse_linear_solver` named parameter in CGAL's convention (a
// model of SparseLinearAlgebraWithFactorTraits_d, e.g. CGAL::Eigen_solver_traits over Eigen's
// SimplicialLDLT, or a wrapper of CHOLMOD), behind the package's Direct_solver interface: the matrix is
// copied into the traits' Matrix, factorised, and each column solved with the factor.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_USER_DIRECT_SOLVER_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_USER_DIRECT_SOLVER_H

#include <CGAL/Anisotropic_fairing/internal/solve/Spd_solvers.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <Eigen/SparseCore>

#include <cstddef>
#include <memory>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

template <typename SolverTraits>
class User_direct_solver : public Direct_solver
{
public:
  explicit User_direct_solver(const SolverTraits& traits) : traits_(traits) {}

  Solve_statistics solve(const Eigen::SparseMatrix<double>& A, const Control_matrix& B, Control_matrix& X) override
  {
    typedef typename SolverTraits::Matrix Matrix;
    typedef typename SolverTraits::Vector Vector;
    typedef typename SolverTraits::NT NT;
    Solve_statistics st;
    const std::size_t n = std::size_t(A.rows());
    if(!(keep_factorisation_ && factorised_))
    {
      // the full symmetric matrix: a traits' symmetric Matrix keeps the lower triangle itself
      Matrix M(static_cast<int>(n));
      for(Eigen::Index j = 0; j < A.outerSize(); ++j)
        for(Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
          M.set_coef(std::size_t(it.row()), std::size_t(it.col()), NT(it.value()), true);
      NT D;
      factorised_ = traits_.factor(M, D);
      if(!factorised_)
      {
        st.ok = false;
        st.message = "the sparse_linear_solver's factorisation failed";
        return st;
      }
    }
    Eigen::MatrixXd b = B, x(B.rows(), B.cols());
    Vector bc(n), xc(n);
    for(Eigen::Index c = 0; c < B.cols(); ++c)
    {
      for(std::size_t i = 0; i < n; ++i) bc.set(i, NT(b(Eigen::Index(i), c)));
      if(!traits_.linear_solver(bc, xc))
      {
        st.ok = false;
        st.message = "the sparse_linear_solver's solve failed";
        return st;
      }
      for(std::size_t i = 0; i < n; ++i) x(Eigen::Index(i), c) = double(xc[int(i)]);
    }
    X = x;
    st.iterations = 1;
    st.residual = relative_residual(A, b, x);
    return st;
  }

private:
  SolverTraits traits_;
};

/// The factory of Stepper_settings::direct_solver for the user's traits
template <typename SolverTraits>
Direct_solver_factory user_direct_solver(const SolverTraits& traits)
{
  return [traits]() { return std::unique_ptr<Direct_solver>(new User_direct_solver<SolverTraits>(traits)); };
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_SOLVE_USER_DIRECT_SOLVER_H
