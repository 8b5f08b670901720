// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's own named parameters: (enum type, enum value, function name).
// No include guard on purpose: named_function_parameters.h includes this list several times.

CGAL_AF_add_named_parameter(quadrature_degree_t,       quadrature_degree,       quadrature_degree)
CGAL_AF_add_named_parameter(quadrature_tiling_depth_t, quadrature_tiling_depth, quadrature_tiling_depth)
