// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Loop element's quadrature as the user asks for it (quadrature_degree, quadrature_tiling_depth),
// read and checked in one place for anisotropic_fairing() and Loop_limit_surface; the element's own
// code then only asserts it.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_ELEMENT_QUADRATURE_PARAMETERS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_ELEMENT_QUADRATURE_PARAMETERS_H

#include <CGAL/Anisotropic_fairing/Input_error.h>
#include <CGAL/Anisotropic_fairing/named_function_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/element/Patch_cache.h>

#include <string>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// Refuses a named parameter's value with Input_error::INVALID_PARAMETER and `message`.
inline void check_parameter(bool ok, const std::string& message)
{
  if(!ok) throw Input_error(Input_error::INVALID_PARAMETER, Input_error::no_element, message);
}

/// Refuses a quadrature of the Loop element that does not exist.
inline void check_quadrature_spec(const Quadrature_spec& spec)
{
  check_parameter(spec.degree == 4 || spec.degree == 6 || spec.degree == 8,
                  "quadrature degree " + std::to_string(spec.degree) + " is not available (use 4, 6 or 8)");
  check_parameter(spec.tiling_depth >= 0 && spec.tiling_depth <= 12, "quadrature tiling depth must lie in [0, 12]");
}

/// The quadrature of the Loop element, checked.
template <typename NamedParameters>
Quadrature_spec read_quadrature_spec(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Quadrature_spec spec;
  spec.degree = choose_parameter(get_parameter(np, internal_np::quadrature_degree), spec.degree);
  spec.tiling_depth = choose_parameter(get_parameter(np, internal_np::quadrature_tiling_depth), spec.tiling_depth);
  check_quadrature_spec(spec);
  return spec;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_ELEMENT_QUADRATURE_PARAMETERS_H
