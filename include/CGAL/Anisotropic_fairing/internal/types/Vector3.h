// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Eigen's 3-vectors over the raw coordinate arrays the element and the assembly fill (derivatives
// at a quadrature point, a row of a Control_matrix): cross products, normals and dot products
// written with Eigen's fixed-size algebra where the data already lives.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_VECTOR3_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_VECTOR3_H

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// the three doubles at p as an Eigen vector (no copy)
inline Eigen::Map<Eigen::Vector3d> vec3(double* p) { return Eigen::Map<Eigen::Vector3d>(p); }
inline Eigen::Map<const Eigen::Vector3d> vec3(const double* p) { return Eigen::Map<const Eigen::Vector3d>(p); }

/// n = a x b normalised (left as a x b when that is zero or not finite)
inline void unit_cross(const double* a, const double* b, double* n) { vec3(n) = vec3(a).cross(vec3(b)).normalized(); }

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_VECTOR3_H
