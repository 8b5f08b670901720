// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The parameters of anisotropic_fairing() as one plain value: what the named parameters give, read once,
// so that a program or a binding can build it directly (the named parameter `fairing_options`) and the
// run decides what is automatic from the value, not from the type of a parameter pack.

#ifndef CGAL_ANISOTROPIC_FAIRING_FAIRING_OPTIONS_H
#define CGAL_ANISOTROPIC_FAIRING_FAIRING_OPTIONS_H

#include <CGAL/Anisotropic_fairing/Anisotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/Uniform_diffusion_tensor.h>

#include <optional>
#include <variant>

namespace CGAL {
namespace Anisotropic_fairing {

/// \ingroup PkgAnisotropicFairingFunctions
/// One of the package's diffusion tensors, chosen at run time (a tensor type of one's own is given as
/// the named parameter `diffusion_tensor` instead).
typedef std::variant<Anisotropic_diffusion_tensor, Isotropic_diffusion_tensor, Uniform_diffusion_tensor>
  Package_diffusion_tensor;

/*!
\ingroup PkgAnisotropicFairingFunctions
The parameters of `anisotropic_fairing()` as one value. Every member is the named parameter of the
same name, with the same meaning and default (listed on the page \ref af_parameters_page); an empty
`std::optional` is a parameter not given, whose default the run chooses (those marked "automatic" there
depend on whether a time step is given, see `automatic_parameters()`). Pass it as the named parameter
`fairing_options`: the named parameters given beside it are applied on top. The maps, the callback, a tensor
type of one's own and the user's factorisation (`sparse_linear_solver`) stay named parameters.
*/
struct Fairing_options
{
  // one member per row of internal/parameter_table.h, of its type and default: declared there once for
  // the named parameters, the program and Python alike
#define AF_PARAMETER(name, type, default_value, ...) type name = default_value;
#define AF_TENSOR_SETTING(...)
#include <CGAL/Anisotropic_fairing/internal/parameter_table.h>
#undef AF_PARAMETER
#undef AF_TENSOR_SETTING

  /// whether the run chooses its parameters from the mesh: no time step was given
  bool automatic_parameters() const { return !time_step && !relative_time_step; }

  /// the tensor the run starts from: `diffusion_tensor`, or its default (chosen from the mesh with
  /// automatic parameters)
  Package_diffusion_tensor diffusion_tensor_or_default() const
  {
    if(diffusion_tensor) return *diffusion_tensor;
    if(automatic_parameters()) return Anisotropic_diffusion_tensor::automatic();
    return Isotropic_diffusion_tensor();
  }

  /// the most steps of the run: `number_of_iterations`, or its default
  unsigned int maximum_steps() const
  {
    return number_of_iterations.value_or(automatic_parameters() ? automatic_maximum_steps : 10u);
  }
};

} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_FAIRING_OPTIONS_H
