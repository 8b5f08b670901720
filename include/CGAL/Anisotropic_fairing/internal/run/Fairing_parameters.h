// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The named parameters read in one place into a Fairing_options value, which is then checked and
// resolved into what the driver runs with, before it touches the mesh. A value out of range is refused
// with Input_error::INVALID_PARAMETER and a message naming the parameter; the defaults are those
// documented with anisotropic_fairing() and Fairing_options.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FAIRING_PARAMETERS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FAIRING_PARAMETERS_H

#include <CGAL/Anisotropic_fairing/Fairing_options.h>
#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/Anisotropic_fairing/Input_error.h>
#include <CGAL/Anisotropic_fairing/named_function_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/element/Quadrature_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Tensor_hooks.h>
#include <CGAL/Anisotropic_fairing/internal/solve/User_direct_solver.h>

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// What anisotropic_fairing() runs with, resolved from a `Fairing_options` (the tensor, the maps and the
/// callback, whose types are the caller's, are read by fair() itself).
struct Fairing_parameters
{
  Stepper_settings settings;   // the stepper's numbers as given (the driver adds the noise and the automatic choices)
  bool automatic = true;       // no time step given: the run chooses its parameters from the mesh
  bool steps_given = false;    // number_of_iterations given: the default run's own flow runs first
  Finite_element element = Finite_element::LOOP;
  Output_positions output = Output_positions::LIMIT_SURFACE;
  Attribute_mode mode = Attribute_mode::GEOMETRY_ONLY;
  double attribute_weight = 1;  // of the attribute columns in the coupled mode
  Boundary_handling boundary = Boundary_handling::HOLD_BOUNDARY_CURVE;
  Quadrature_spec quadrature;   // checked for the Loop element only (the linear element has none)
  std::optional<double> memory_limit;   // bytes the run may take (empty: what the process may; infinity: no check)
};

/// The default run: it compares the anisotropic, the isotropic and the uniform fourth-order flow (Fairing_core.h)
template <typename Tensor>
bool compares_flows(const Fairing_parameters& given, const Tensor& tensor)
{
  return given.automatic && is_automatic_tensor(tensor) && given.mode != Attribute_mode::ATTRIBUTES_ONLY &&
         given.settings.stopping.noise_discrepancy > 0;
}

/// sparse_linear_solver: the user's factorisation, or none given
inline Direct_solver_factory direct_solver_of(CGAL::internal_np::Param_not_found) { return Direct_solver_factory(); }
template <typename SolverTraits>
Direct_solver_factory direct_solver_of(const SolverTraits& traits) { return user_direct_solver(traits); }

/// Whether T is one of a std::variant's alternatives.
template <typename T, typename Variant> struct is_alternative_of : std::false_type {};
template <typename T, typename... A>
struct is_alternative_of<T, std::variant<A...>> : std::disjunction<std::is_same<T, A>...> {};

/// The tensors a `Package_diffusion_tensor` holds (and that value itself): a tensor added to the variant is one.
template <typename T>
struct is_package_tensor
  : std::integral_constant<bool, is_alternative_of<T, Package_diffusion_tensor>::value ||
                                 std::is_same<T, Package_diffusion_tensor>::value>
{};

template <typename T, typename V> void assign_option(T& field, const V& value) { field = T(value); }
template <typename T, typename V> void assign_option(std::optional<T>& field, const V& value) { field = T(value); }
// a tensor of a type of one's own is read by fair() itself: the value holds the package's only
template <typename V> void assign_option(std::optional<Package_diffusion_tensor>& field, const V& value)
{
  if constexpr(is_package_tensor<V>::value) field = Package_diffusion_tensor(value);
}

/// `field` = the named parameter `tag`, if it is given.
template <typename NamedParameters, typename Tag, typename T>
void take_option(const NamedParameters& np, Tag tag, T& field)
{
  if constexpr(!parameters::is_default_parameter<NamedParameters, Tag>::value)
    assign_option(field, parameters::get_parameter(np, tag));
}

/// The options of a run: the named parameter `fairing_options` (or the defaults), and on top of it every
/// other named parameter given; a tensor of the package's own types goes into the value too.
template <typename NamedParameters>
Fairing_options read_fairing_options(const NamedParameters& np)
{
  using parameters::is_default_parameter;
  Fairing_options o =
    parameters::choose_parameter(parameters::get_parameter(np, internal_np::fairing_options), Fairing_options());
  // relative_maximum_deviation, or its deprecated spelling maximum_deviation; or absolute_maximum_deviation
  check_parameter(int(!is_default_parameter<NamedParameters, internal_np::relative_maximum_deviation_t>::value) +
                  int(!is_default_parameter<NamedParameters, internal_np::maximum_deviation_t>::value) +
                  int(!is_default_parameter<NamedParameters, internal_np::absolute_maximum_deviation_t>::value) <= 1,
                  "give one of relative_maximum_deviation and absolute_maximum_deviation (maximum_deviation: "
                  "the relative one's deprecated spelling), not more");
#define AF_TAG_OWN(name) internal_np::name
#define AF_TAG_CGAL(name) CGAL::internal_np::name
#define AF_PARAMETER(name, type, default_value, named, ...) take_option(np, AF_TAG_##named(name), o.name);
#define AF_TENSOR_SETTING(...)
#include <CGAL/Anisotropic_fairing/internal/parameter_table.h>
#undef AF_PARAMETER
#undef AF_TENSOR_SETTING
#undef AF_TAG_OWN
#undef AF_TAG_CGAL
  take_option(np, internal_np::maximum_deviation, o.relative_maximum_deviation);
  return o;
}

// The checks of the table's column `check`: whether a value holds, and what the message says if not.
struct Unchecked
{
  template <typename T> bool holds(const T&) const { return true; }
  const char* says() const { return ""; }
};
struct Finite_non_negative
{
  bool holds(double x) const { return std::isfinite(x) && x >= 0; }
  const char* says() const { return " must be finite and >= 0"; }
};
struct Open_unit_interval
{
  bool holds(double x) const { return x > 0 && x < 1; }
  const char* says() const { return " must lie in (0, 1)"; }
};
struct At_least_one
{
  bool holds(int n) const { return n >= 1; }
  const char* says() const { return " must be at least 1"; }
};

/// A parameter that the stepper takes as it is: checked, then copied into its field (nullptr: resolved by hand).
template <typename T, typename Check>
void resolve_setting(Stepper_settings&, std::nullptr_t, const T&, const char*, const Check&)
{}
template <typename Field, typename T, typename Check>
void resolve_setting(Stepper_settings& s, Field Stepper_settings::*field, const T& value, const char* name,
                     const Check& check)
{
  check_parameter(check.holds(value), std::string(name) + check.says());
  s.*field = Field(value);
}

/// Checks the options of a run and resolves what was not given (`has_attributes`: an attribute map is
/// given); whether the parameters are automatic is read from the value: no time step given.
inline Fairing_parameters resolve_fairing_parameters(const Fairing_options& o, bool has_attributes)
{
  Fairing_parameters p;
  Stepper_settings& s = p.settings;
  p.automatic = o.automatic_parameters();
  check_parameter(!(o.time_step && o.relative_time_step), "give either time_step or relative_time_step, not both");
  s.time_unit = o.time_step ? Length_unit::MODEL : o.relative_time_step ? Length_unit::SCALE : Length_unit::EDGE;
  s.time_step = o.time_step ? *o.time_step : o.relative_time_step.value_or(1e-3);
  check_parameter(std::isfinite(s.time_step) && s.time_step > 0,
                  std::string(o.time_step ? "time_step" : "relative_time_step") + " must be positive and finite");
  check_parameter(!(o.fidelity_weight && o.relative_fidelity_weight),
                  "give either fidelity_weight or relative_fidelity_weight, not both");
  s.relative_fidelity = !o.fidelity_weight;
  s.fidelity_weight = o.fidelity_weight ? *o.fidelity_weight : o.relative_fidelity_weight.value_or(0.0);
  check_parameter(std::isfinite(s.fidelity_weight) && s.fidelity_weight >= 0,
                  std::string(o.fidelity_weight ? "fidelity_weight" : "relative_fidelity_weight") +
                    " must be finite and >= 0");
  check_parameter(!(o.relative_maximum_deviation && o.absolute_maximum_deviation),
                  "give one of relative_maximum_deviation and absolute_maximum_deviation (maximum_deviation: "
                  "the relative one's deprecated spelling), not more");
  s.relative_deviation = !o.absolute_maximum_deviation;
  s.maximum_deviation =
    o.absolute_maximum_deviation ? *o.absolute_maximum_deviation : o.relative_maximum_deviation.value_or(0.0);
  // 0: no bound
  check_parameter(std::isfinite(s.maximum_deviation) && s.maximum_deviation >= 0,
                  std::string(o.absolute_maximum_deviation ? "absolute" : "relative") +
                    "_maximum_deviation must be finite and >= 0");
  // the plain ones, in the table's order: attribute_maximum_deviation, the solver's, verbose
#define AF_PARAMETER(name, type, default_value, named, setting, check, ...) \
  resolve_setting(s, setting, o.name, #name, check);
#define AF_TENSOR_SETTING(...)
#include <CGAL/Anisotropic_fairing/internal/parameter_table.h>
#undef AF_PARAMETER
#undef AF_TENSOR_SETTING
  s.maximum_steps = o.maximum_steps();
  p.steps_given = bool(o.number_of_iterations);
  s.order = o.flow_order;
  check_parameter(s.order == 2 || s.order == 4, "flow_order must be 2 (diffusion) or 4");
  p.element = o.finite_element;
  p.output = o.output_positions;
  p.mode = o.attribute_mode.value_or(has_attributes ? Attribute_mode::SEPARATE : Attribute_mode::GEOMETRY_ONLY);
  check_parameter(has_attributes || p.mode == Attribute_mode::GEOMETRY_ONLY || p.mode == Attribute_mode::SEPARATE,
                  "attribute_mode: the coupled and attributes-only modes need an attribute map");
  // (the noise criterion measures the geometry: with the geometry fixed, the paper's criteria)
  const bool noise_default = p.automatic && p.mode != Attribute_mode::ATTRIBUTES_ONLY;
  s.stopping = o.stopping_criteria.value_or(noise_default ? Stopping_criteria::automatic() : Stopping_criteria());
  check_parameter(std::isfinite(s.stopping.curvature_rate_ratio) && std::isfinite(s.stopping.curvature_rate) &&
                  std::isfinite(s.stopping.displacement) && std::isfinite(s.stopping.steady_speed) &&
                  std::isfinite(s.stopping.noise_discrepancy), "stopping_criteria: the thresholds must be finite");
  // strength: the noise criterion's target times it (Stepper_settings::strength; the default run compares its
  // flows at the noise level itself, then runs the one kept to this target: Fairing_core.h). Without the noise
  // criterion it would change nothing, so anything but 1 is refused
  check_parameter(std::isfinite(o.strength) && o.strength > 0, "strength must be positive and finite");
  const bool noise_criterion = s.stopping.noise_discrepancy > 0 && p.mode != Attribute_mode::ATTRIBUTES_ONLY;
  check_parameter(o.strength == 1 || noise_criterion,
                  "strength scales the noise criterion's target, and this run does not stop at the noise level (" +
                  std::string(p.mode == Attribute_mode::ATTRIBUTES_ONLY
                                ? "the attributes-only mode fairs on a fixed surface"
                              : o.stopping_criteria ? "stopping_criteria has no noise_discrepancy"
                                                    : "a time step is given: the paper's criteria") +
                  "); leave strength at 1, or give the noise criterion (Stopping_criteria::automatic())");
  s.strength = o.strength;
  p.attribute_weight = o.attribute_weight;
  check_parameter(std::isfinite(p.attribute_weight) && p.attribute_weight > 0,
                  "attribute_weight must be positive and finite");
  p.boundary = o.boundary_handling;
  p.quadrature.degree = o.quadrature_degree;
  p.quadrature.tiling_depth = o.quadrature_tiling_depth;
  if(p.element == Finite_element::LOOP) check_quadrature_spec(p.quadrature);
  check_parameter(!o.memory_limit || *o.memory_limit >= 0, "memory_limit must be >= 0 bytes (infinity: no check)");
  p.memory_limit = o.memory_limit;
  return p;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FAIRING_PARAMETERS_H
