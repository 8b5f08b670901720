// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The named parameters read and checked in one place: what anisotropic_fairing() was asked for, as
// one struct that the driver reads before it touches the mesh (the quadrature through
// Quadrature_parameters.h, which Loop_limit_surface reads too). A value out of range is refused with
// Input_error::INVALID_PARAMETER and a message naming the parameter; the defaults are those
// documented with anisotropic_fairing() and Loop_limit_surface.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FAIRING_PARAMETERS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FAIRING_PARAMETERS_H

#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/Anisotropic_fairing/Input_error.h>
#include <CGAL/Anisotropic_fairing/named_function_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/element/Quadrature_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Stepper_settings.h>
#include <CGAL/Anisotropic_fairing/internal/solve/User_direct_solver.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// Without a time step the package chooses the time step, the stopping rule and (unless given) the
/// tensor from the mesh (Automatic_parameters.h). A constant: the default tensor's type depends on it.
template <typename NamedParameters>
struct uses_automatic_parameters
  : std::integral_constant<bool, parameters::is_default_parameter<NamedParameters, internal_np::time_step_t>::value &&
                                 parameters::is_default_parameter<NamedParameters, internal_np::relative_time_step_t>::value>
{};

/// What anisotropic_fairing() reads from its named parameters, but for those whose type the caller
/// chooses (the tensor, vertex_is_constrained and the callback), which fair() reads itself.
struct Fairing_parameters
{
  Stepper_settings settings;   // the stepper's numbers as given (the driver adds the noise and the automatic choices)
  Finite_element element = Finite_element::LOOP;
  Output_positions output = Output_positions::LIMIT_SURFACE;
  Attribute_mode mode = Attribute_mode::GEOMETRY_ONLY;
  double attribute_weight = 1;  // of the attribute columns in the coupled mode
  Boundary_handling boundary = Boundary_handling::HOLD_BOUNDARY_CURVE;
  Quadrature_spec quadrature;   // read and checked for the Loop element only (the linear element has none)
};

/// sparse_linear_solver: the user's factorisation, or none given
inline Direct_solver_factory direct_solver_of(CGAL::internal_np::Param_not_found) { return Direct_solver_factory(); }
template <typename SolverTraits>
Direct_solver_factory direct_solver_of(const SolverTraits& traits) { return user_direct_solver(traits); }

/// Reads and checks the named parameters of a run (`has_attributes`: an attribute map is given).
template <typename NamedParameters>
Fairing_parameters read_fairing_parameters(const NamedParameters& np, bool has_attributes)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  Fairing_parameters p;
  Stepper_settings& s = p.settings;
  const bool absolute_tau = !is_default_parameter<NamedParameters, internal_np::time_step_t>::value;
  const bool relative_tau = !is_default_parameter<NamedParameters, internal_np::relative_time_step_t>::value;
  constexpr bool automatic = uses_automatic_parameters<NamedParameters>::value;
  check_parameter(!(absolute_tau && relative_tau), "give either time_step or relative_time_step, not both");
  s.time_unit = absolute_tau ? Length_unit::MODEL : relative_tau ? Length_unit::SCALE : Length_unit::EDGE;
  s.time_step = absolute_tau ? double(choose_parameter(get_parameter(np, internal_np::time_step), 0.0))
                             : double(choose_parameter(get_parameter(np, internal_np::relative_time_step), 1e-3));
  check_parameter(std::isfinite(s.time_step) && s.time_step > 0, "the time step must be positive and finite");
  const bool absolute_w = !is_default_parameter<NamedParameters, internal_np::fidelity_weight_t>::value;
  const bool relative_w = !is_default_parameter<NamedParameters, internal_np::relative_fidelity_weight_t>::value;
  check_parameter(!(absolute_w && relative_w), "give either fidelity_weight or relative_fidelity_weight, not both");
  s.relative_fidelity = !absolute_w;
  s.fidelity_weight = absolute_w ? double(choose_parameter(get_parameter(np, internal_np::fidelity_weight), 0.0))
                                 : double(choose_parameter(get_parameter(np, internal_np::relative_fidelity_weight), 0.0));
  check_parameter(std::isfinite(s.fidelity_weight) && s.fidelity_weight >= 0, "the fidelity weight must be finite and >= 0");
  // relative_maximum_deviation, or its deprecated spelling maximum_deviation; or absolute_maximum_deviation
  const bool relative_bound = !is_default_parameter<NamedParameters, internal_np::relative_maximum_deviation_t>::value;
  const bool old_bound = !is_default_parameter<NamedParameters, internal_np::maximum_deviation_t>::value;
  const bool absolute_bound = !is_default_parameter<NamedParameters, internal_np::absolute_maximum_deviation_t>::value;
  check_parameter(int(relative_bound) + int(old_bound) + int(absolute_bound) <= 1,
                  "give one of relative_maximum_deviation and absolute_maximum_deviation (maximum_deviation: the relative one's "
                  "deprecated spelling), not more");
  s.relative_deviation = !absolute_bound;
  s.maximum_deviation = absolute_bound ? double(choose_parameter(get_parameter(np, internal_np::absolute_maximum_deviation), 0.0))
                        : old_bound    ? double(choose_parameter(get_parameter(np, internal_np::maximum_deviation), 0.0))
                                       : double(choose_parameter(get_parameter(np, internal_np::relative_maximum_deviation), 0.0));
  // 0: no bound
  check_parameter(std::isfinite(s.maximum_deviation) && s.maximum_deviation >= 0, "the maximum deviation must be finite and >= 0");
  s.attribute_maximum_deviation = double(choose_parameter(get_parameter(np, internal_np::attribute_maximum_deviation), 0.0));
  check_parameter(std::isfinite(s.attribute_maximum_deviation) && s.attribute_maximum_deviation >= 0,
                  "the attribute maximum deviation must be finite and >= 0");
  s.maximum_steps = std::size_t(choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations),
                                                  automatic ? automatic_maximum_steps : 10u));
  s.order = choose_parameter(get_parameter(np, internal_np::flow_order), 2);
  check_parameter(s.order == 2 || s.order == 4, "the flow's order must be 2 (diffusion) or 4");
  s.solver = choose_parameter(get_parameter(np, internal_np::linear_solver), Linear_solver::AUTOMATIC);
  s.solver_tolerance = choose_parameter(get_parameter(np, internal_np::solver_tolerance), 1e-8);
  check_parameter(s.solver_tolerance > 0 && s.solver_tolerance < 1, "the solver tolerance must lie in (0, 1)");
  s.solver_maximum_iterations = choose_parameter(get_parameter(np, internal_np::solver_maximum_iterations), 10000);
  check_parameter(s.solver_maximum_iterations >= 1, "the solver needs at least one iteration");
  s.direct_solver = direct_solver_of(get_parameter(np, CGAL::internal_np::sparse_linear_solver));
  s.verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  p.element = choose_parameter(get_parameter(np, internal_np::finite_element), Finite_element::LOOP);
  p.output = choose_parameter(get_parameter(np, internal_np::output_positions), Output_positions::LIMIT_SURFACE);
  p.mode = choose_parameter(get_parameter(np, internal_np::attribute_mode),
                            has_attributes ? Attribute_mode::SEPARATE : Attribute_mode::GEOMETRY_ONLY);
  check_parameter(has_attributes || p.mode == Attribute_mode::GEOMETRY_ONLY || p.mode == Attribute_mode::SEPARATE,
                  "the coupled and attributes-only modes need an attribute map");
  // (the noise criterion measures the geometry: with the geometry fixed, the paper's criteria)
  s.stopping = choose_parameter(get_parameter(np, internal_np::stopping_criteria),
                                automatic && p.mode != Attribute_mode::ATTRIBUTES_ONLY ? Stopping_criteria::automatic()
                                                                                       : Stopping_criteria());
  check_parameter(std::isfinite(s.stopping.curvature_rate_ratio) && std::isfinite(s.stopping.curvature_rate) &&
                  std::isfinite(s.stopping.displacement) && std::isfinite(s.stopping.steady_speed) &&
                  std::isfinite(s.stopping.noise_discrepancy), "stopping thresholds must be finite");
  p.attribute_weight = choose_parameter(get_parameter(np, internal_np::attribute_weight), 1.0);
  check_parameter(std::isfinite(p.attribute_weight) && p.attribute_weight > 0, "the attribute weight must be positive and finite");
  p.boundary = choose_parameter(get_parameter(np, internal_np::boundary_handling), Boundary_handling::HOLD_BOUNDARY_CURVE);
  if(p.element == Finite_element::LOOP) p.quadrature = read_quadrature_spec(np);
  return p;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FAIRING_PARAMETERS_H
