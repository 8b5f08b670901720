// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Which entries of a square compressed (column-major) matrix exist, without values. M, L and every
// system made of them share one structure and keep only their values: with 37 entries a row, a copy of
// the structure costs 150 bytes a vertex and a matrix that brings its own 450. The accessors are named
// as Eigen's, so that the sparse kernels read a structure as they read an Eigen::SparseMatrix.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_SPARSE_STRUCTURE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_SPARSE_STRUCTURE_H

#include <CGAL/Anisotropic_fairing/internal/types/Value_array.h>

#include <Eigen/SparseCore>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

class Sparse_structure
{
public:
  Sparse_structure() : outer_(1, 0) {}
  /// n x n; `outer`: n + 1 offsets, `inner`: the rows of each column, increasing within a column.
  Sparse_structure(Eigen::Index n, std::vector<int> outer, std::vector<int> inner)
    : n_(n), outer_(std::move(outer)), inner_(std::move(inner)) {}

  // the structure is shared by pointer (Free_block): never copied by accident
  Sparse_structure(const Sparse_structure&) = delete;
  Sparse_structure& operator=(const Sparse_structure&) = delete;
  Sparse_structure(Sparse_structure&&) = default;
  Sparse_structure& operator=(Sparse_structure&&) = default;

  Eigen::Index rows() const { return n_; }
  Eigen::Index cols() const { return n_; }
  Eigen::Index outerSize() const { return n_; }
  Eigen::Index nonZeros() const { return Eigen::Index(inner_.size()); }
  const int* outerIndexPtr() const { return outer_.data(); }
  const int* innerIndexPtr() const { return inner_.data(); }

  /// The entry (row, col), or -1 when the structure has none there.
  std::ptrdiff_t find(Eigen::Index row, Eigen::Index col) const
  {
    const int* first = inner_.data() + outer_[std::size_t(col)];
    const int* last = inner_.data() + outer_[std::size_t(col) + 1];
    const int* it = std::lower_bound(first, last, int(row));
    return it != last && *it == row ? it - inner_.data() : -1;
  }

  /// The diagonal of the matrix with these `values` (absent entries: 0).
  Eigen::VectorXd diagonal(const double* values) const
  {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(n_);
    for(Eigen::Index j = 0; j < n_; ++j)
    {
      const std::ptrdiff_t p = find(j, j);
      if(p >= 0) d[j] = values[p];
    }
    return d;
  }

  /// An Eigen matrix of this structure with `values` (null: zeros), for Eigen's own algorithms (a
  /// factorisation, dense tests): a copy.
  Eigen::SparseMatrix<double> matrix(const double* values = nullptr) const
  {
    Eigen::SparseMatrix<double> A(n_, n_);
    A.data().resize(nonZeros());
    std::copy(outer_.begin(), outer_.end(), A.outerIndexPtr());
    std::copy(inner_.begin(), inner_.end(), A.innerIndexPtr());
    if(values) std::copy(values, values + inner_.size(), A.valuePtr());
    else std::fill(A.valuePtr(), A.valuePtr() + inner_.size(), 0.0);
    return A;
  }
  Eigen::SparseMatrix<double> matrix(const Value_array& values) const { return matrix(values.data()); }

private:
  Eigen::Index n_ = 0;
  std::vector<int> outer_, inner_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_SPARSE_STRUCTURE_H
