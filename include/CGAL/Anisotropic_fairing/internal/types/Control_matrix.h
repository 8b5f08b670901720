// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Control points (or any per-vertex data) as a dense matrix: one row per vertex, one column per
// coordinate. Row-major, so a vertex's kappa values are contiguous when gathered into a ring.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_CONTROL_MATRIX_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_CONTROL_MATRIX_H

#include <Eigen/Core>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

typedef Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Control_matrix;

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_CONTROL_MATRIX_H
