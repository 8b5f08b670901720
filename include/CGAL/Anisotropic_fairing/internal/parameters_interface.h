// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's own named parameters: (enum type, enum value, function name).
// No include guard on purpose: named_function_parameters.h includes this list several times.
// CGAL_AF_add_deprecated_named_parameter: a spelling kept working, with a deprecation warning that says
// what to write instead.

CGAL_AF_add_named_parameter(quadrature_degree_t,       quadrature_degree,       quadrature_degree)
CGAL_AF_add_named_parameter(quadrature_tiling_depth_t, quadrature_tiling_depth, quadrature_tiling_depth)
CGAL_AF_add_named_parameter(time_step_t,                 time_step,                 time_step)
CGAL_AF_add_named_parameter(relative_time_step_t,        relative_time_step,        relative_time_step)
CGAL_AF_add_named_parameter(fidelity_weight_t,           fidelity_weight,           fidelity_weight)
CGAL_AF_add_named_parameter(relative_fidelity_weight_t,  relative_fidelity_weight,  relative_fidelity_weight)
CGAL_AF_add_named_parameter(stopping_criteria_t,         stopping_criteria,         stopping_criteria)
CGAL_AF_add_named_parameter(diffusion_tensor_t,          diffusion_tensor,          diffusion_tensor)
CGAL_AF_add_named_parameter(finite_element_t,            finite_element,            finite_element)
CGAL_AF_add_named_parameter(output_positions_t,          output_positions,          output_positions)
CGAL_AF_add_named_parameter(linear_solver_t,             linear_solver,             linear_solver)
CGAL_AF_add_named_parameter(boundary_handling_t,         boundary_handling,         boundary_handling)
CGAL_AF_add_named_parameter(attribute_mode_t,            attribute_mode,            attribute_mode)
CGAL_AF_add_named_parameter(attribute_weight_t,          attribute_weight,          attribute_weight)
CGAL_AF_add_named_parameter(solver_tolerance_t,          solver_tolerance,          solver_tolerance)
CGAL_AF_add_named_parameter(solver_maximum_iterations_t, solver_maximum_iterations, solver_maximum_iterations)
CGAL_AF_add_named_parameter(vertex_curvature_map_t,      vertex_curvature_map,      vertex_curvature_map)
CGAL_AF_add_named_parameter(flow_order_t,                flow_order,                flow_order)
CGAL_AF_add_named_parameter(relative_maximum_deviation_t, relative_maximum_deviation, relative_maximum_deviation)
CGAL_AF_add_deprecated_named_parameter(maximum_deviation_t, maximum_deviation, maximum_deviation,
  "maximum_deviation is relative (units of l); write relative_maximum_deviation, or absolute_maximum_deviation for model units, "
  "as the program's --relative-maximum-deviation and --maximum-deviation")
CGAL_AF_add_named_parameter(absolute_maximum_deviation_t, absolute_maximum_deviation, absolute_maximum_deviation)
CGAL_AF_add_named_parameter(attribute_maximum_deviation_t, attribute_maximum_deviation, attribute_maximum_deviation)
CGAL_AF_add_named_parameter(control_point_map_t,         control_point_map,         control_point_map)
CGAL_AF_add_named_parameter(attribute_control_map_t,     attribute_control_map,     attribute_control_map)
CGAL_AF_add_named_parameter(fairing_options_t,           fairing_options,           fairing_options)
CGAL_AF_add_named_parameter(strength_t,                  strength,                  strength)
