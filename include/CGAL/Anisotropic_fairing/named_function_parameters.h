// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named parameters that chain with CGAL's: `CGAL::Anisotropic_fairing::parameters::...` starts a
// chain accepting both CGAL's names (vertex_point_map, number_of_iterations, ...) and the package's
// own (quadrature_degree, ...). The pack derives from CGAL::Named_function_parameters, so it can be
// passed to any CGAL function too. Out-of-tree packages cannot add members to CGAL's pack class,
// hence this derived class.

#ifndef CGAL_ANISOTROPIC_FAIRING_NAMED_FUNCTION_PARAMETERS_H
#define CGAL_ANISOTROPIC_FAIRING_NAMED_FUNCTION_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Anisotropic_fairing {

namespace internal_np {
#define CGAL_AF_add_named_parameter(X, Y, Z) enum X { Y };
#define CGAL_AF_add_deprecated_named_parameter(X, Y, Z, M) enum X { Y };
#include <CGAL/Anisotropic_fairing/internal/parameters_interface.h>
#undef CGAL_AF_add_named_parameter
#undef CGAL_AF_add_deprecated_named_parameter
} // namespace internal_np

/// \cond SKIP_IN_MANUAL
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Named_function_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  typedef CGAL::Named_function_parameters<T, Tag, Base> CGAL_np;
  typedef Named_function_parameters<T, Tag, Base> self;

  Named_function_parameters() : CGAL_np() {}
  Named_function_parameters(const T& v) : CGAL_np(v) {}
  Named_function_parameters(const T& v, const Base& b) : CGAL_np(v, b) {}

#define CGAL_AF_NP_MEMBER(TAG, Z)                                                        \
  template <typename K>                                                                  \
  Named_function_parameters<K, TAG, self> Z(const K& k) const                            \
  { return Named_function_parameters<K, TAG, self>(k, *this); }
#define CGAL_AF_NP_DEPRECATED_MEMBER(TAG, Z, M)                                          \
  template <typename K>                                                                  \
  [[deprecated(M)]] Named_function_parameters<K, TAG, self> Z(const K& k) const          \
  { return Named_function_parameters<K, TAG, self>(k, *this); }

#define CGAL_add_named_parameter(X, Y, Z) CGAL_AF_NP_MEMBER(CGAL::internal_np::X, Z)
#define CGAL_add_named_parameter_with_compatibility(X, Y, Z) CGAL_AF_NP_MEMBER(CGAL::internal_np::X, Z)
#define CGAL_add_named_parameter_with_compatibility_cref_only(X, Y, Z) CGAL_AF_NP_MEMBER(CGAL::internal_np::X, Z)
#define CGAL_add_named_parameter_with_compatibility_ref_only(X, Y, Z) CGAL_AF_NP_MEMBER(CGAL::internal_np::X, Z)
#define CGAL_add_extra_named_parameter_with_compatibility(X, Y, Z) CGAL_AF_NP_MEMBER(CGAL::internal_np::X, Z)
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter
#undef CGAL_add_named_parameter_with_compatibility
#undef CGAL_add_named_parameter_with_compatibility_cref_only
#undef CGAL_add_named_parameter_with_compatibility_ref_only
#undef CGAL_add_extra_named_parameter_with_compatibility

#define CGAL_AF_add_named_parameter(X, Y, Z) CGAL_AF_NP_MEMBER(Anisotropic_fairing::internal_np::X, Z)
#define CGAL_AF_add_deprecated_named_parameter(X, Y, Z, M) \
  CGAL_AF_NP_DEPRECATED_MEMBER(Anisotropic_fairing::internal_np::X, Z, M)
#include <CGAL/Anisotropic_fairing/internal/parameters_interface.h>
#undef CGAL_AF_add_named_parameter
#undef CGAL_AF_add_deprecated_named_parameter
#undef CGAL_AF_NP_MEMBER
#undef CGAL_AF_NP_DEPRECATED_MEMBER
};
/// \endcond

namespace parameters {

/// \cond SKIP_IN_MANUAL
typedef Named_function_parameters<bool, CGAL::internal_np::all_default_t> Default_named_parameters;
/// \endcond

/// An empty pack: every parameter takes its default.
inline Default_named_parameters default_values() { return Default_named_parameters(); }

/// \cond SKIP_IN_MANUAL
#define CGAL_AF_NP_FREE(TAG, Z)                                                          \
  template <typename K>                                                                  \
  Named_function_parameters<K, TAG> Z(const K& p)                                        \
  { return Named_function_parameters<K, TAG>(p); }
#define CGAL_AF_NP_DEPRECATED_FREE(TAG, Z, M)                                            \
  template <typename K>                                                                  \
  [[deprecated(M)]] Named_function_parameters<K, TAG> Z(const K& p)                      \
  { return Named_function_parameters<K, TAG>(p); }

#define CGAL_add_named_parameter(X, Y, Z) CGAL_AF_NP_FREE(CGAL::internal_np::X, Z)
#define CGAL_add_named_parameter_with_compatibility(X, Y, Z) CGAL_AF_NP_FREE(CGAL::internal_np::X, Z)
#define CGAL_add_named_parameter_with_compatibility_cref_only(X, Y, Z) CGAL_AF_NP_FREE(CGAL::internal_np::X, Z)
#define CGAL_add_named_parameter_with_compatibility_ref_only(X, Y, Z) CGAL_AF_NP_FREE(CGAL::internal_np::X, Z)
#define CGAL_add_extra_named_parameter_with_compatibility(X, Y, Z) CGAL_AF_NP_FREE(CGAL::internal_np::X, Z)
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter
#undef CGAL_add_named_parameter_with_compatibility
#undef CGAL_add_named_parameter_with_compatibility_cref_only
#undef CGAL_add_named_parameter_with_compatibility_ref_only
#undef CGAL_add_extra_named_parameter_with_compatibility

#define CGAL_AF_add_named_parameter(X, Y, Z) CGAL_AF_NP_FREE(Anisotropic_fairing::internal_np::X, Z)
#define CGAL_AF_add_deprecated_named_parameter(X, Y, Z, M) \
  CGAL_AF_NP_DEPRECATED_FREE(Anisotropic_fairing::internal_np::X, Z, M)
#include <CGAL/Anisotropic_fairing/internal/parameters_interface.h>
#undef CGAL_AF_add_named_parameter
#undef CGAL_AF_add_deprecated_named_parameter
#undef CGAL_AF_NP_FREE
#undef CGAL_AF_NP_DEPRECATED_FREE

using CGAL::parameters::choose_parameter;
using CGAL::parameters::is_default_parameter;

// Reads a parameter from any pack, a plain CGAL one or ours.
template <typename NP, typename Query_tag>
typename CGAL::internal_np::Get_param<typename NP::base, Query_tag>::type
get_parameter(const NP& np, Query_tag tag)
{
  return CGAL::internal_np::get_parameter_impl(static_cast<const typename NP::base&>(np), tag);
}
/// \endcond

} // namespace parameters
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_NAMED_FUNCTION_PARAMETERS_H
