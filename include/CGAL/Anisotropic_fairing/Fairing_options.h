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
typedef std::variant<Anisotropic_diffusion_tensor, Isotropic_diffusion_tensor, Uniform_diffusion_tensor> Package_diffusion_tensor;

/*!
\ingroup PkgAnisotropicFairingFunctions
The parameters of `anisotropic_fairing()` as one value. Every member is the named parameter of the
same name, with the same meaning and default; an empty `std::optional` is a parameter not given, whose
default the run chooses (those marked "automatic" depend on whether a time step is given, see
`automatic_parameters()`). Pass it as the named parameter `fairing_options`: the named parameters given
beside it are applied on top. The maps, the callback, a tensor type of one's own and the user's
factorisation (`sparse_linear_solver`) stay named parameters.
*/
struct Fairing_options
{
  std::optional<double> time_step;                   ///< model units; excludes `relative_time_step`
  std::optional<double> relative_time_step;          ///< units of \f$\ell^2\f$ (\f$\ell^4\f$ for the fourth-order flow)
  int flow_order = 2;                                ///< 2 or 4
  std::optional<unsigned int> number_of_iterations;  ///< automatic: `automatic_maximum_steps`, or 10 with a time step
  std::optional<Stopping_criteria> stopping_criteria;    ///< automatic: the noise level, or the paper's criteria
  double strength = 1;                               ///< multiplies the noise criterion's target: > 1 smooths more, < 1 less (> 0)
  std::optional<double> fidelity_weight;             ///< model units; excludes `relative_fidelity_weight`
  std::optional<double> relative_fidelity_weight;    ///< units of \f$1/\ell^2\f$; 0 when neither is given
  std::optional<double> relative_maximum_deviation;  ///< units of \f$\ell\f$; excludes `absolute_maximum_deviation`
  std::optional<double> absolute_maximum_deviation;  ///< model units; neither given: no bound
  double attribute_maximum_deviation = 0;            ///< 0: none
  std::optional<Package_diffusion_tensor> diffusion_tensor;  ///< automatic: `Anisotropic_diffusion_tensor::automatic()`, or isotropic
  Finite_element finite_element = Finite_element::LOOP;
  Output_positions output_positions = Output_positions::LIMIT_SURFACE;
  std::optional<Attribute_mode> attribute_mode;      ///< `SEPARATE` with an attribute map, `GEOMETRY_ONLY` without
  double attribute_weight = 1;
  Boundary_handling boundary_handling = Boundary_handling::HOLD_BOUNDARY_CURVE;
  Linear_solver linear_solver = Linear_solver::AUTOMATIC;
  double solver_tolerance = 1e-8;
  int solver_maximum_iterations = 10000;
  int quadrature_degree = 8;
  int quadrature_tiling_depth = 0;
  bool verbose = false;

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
  unsigned int maximum_steps() const { return number_of_iterations.value_or(automatic_parameters() ? automatic_maximum_steps : 10u); }
};

} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_FAIRING_OPTIONS_H
