// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rows of a stencil, shared by every element (Loop and P1) and by the assembly that reads them.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_STENCIL_ROW_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_STENCIL_ROW_H

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// Rows of a stencil: value, d/dxi1, d/dxi2, d2/dxi1^2, d2/dxi1dxi2, d2/dxi2^2.
enum Stencil_row { VALUE = 0, D1 = 1, D2 = 2, D11 = 3, D12 = 4, D22 = 5, STENCIL_ROWS = 6 };

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_TYPES_STENCIL_ROW_H
