// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's own named parameters: (enum type, enum value, function name), those of a run from
// parameter_table.h.
// No include guard on purpose: named_function_parameters.h includes this list several times.
// CGAL_AF_add_deprecated_named_parameter: a spelling kept working, with a deprecation warning that says
// what to write instead.

// The parameters of a run: the rows of parameter_table.h whose named parameter is the package's own
#define AF_NAMED_OWN(name) CGAL_AF_add_named_parameter(name##_t, name, name)
#define AF_NAMED_CGAL(name)
#define AF_PARAMETER(name, type, default_value, named, ...) AF_NAMED_##named(name)
#define AF_TENSOR_SETTING(...)
#include <CGAL/Anisotropic_fairing/internal/parameter_table.h>
#undef AF_PARAMETER
#undef AF_TENSOR_SETTING
#undef AF_NAMED_OWN
#undef AF_NAMED_CGAL

// The maps, the value of all parameters at once, and a deprecated spelling
CGAL_AF_add_named_parameter(vertex_curvature_map_t,      vertex_curvature_map,      vertex_curvature_map)
CGAL_AF_add_deprecated_named_parameter(maximum_deviation_t, maximum_deviation, maximum_deviation,
  "maximum_deviation is relative (units of l); write relative_maximum_deviation, "
  "or absolute_maximum_deviation for model units, as the program's --relative-maximum-deviation "
  "and --maximum-deviation")
CGAL_AF_add_named_parameter(control_point_map_t,         control_point_map,         control_point_map)
CGAL_AF_add_named_parameter(attribute_control_map_t,     attribute_control_map,     attribute_control_map)
CGAL_AF_add_named_parameter(fairing_options_t,           fairing_options,           fairing_options)
