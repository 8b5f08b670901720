// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The parameters of a run, declared once. Each includer defines the row macros, includes this list and
// undefines them; no include guard on purpose. From it come the named parameter (parameters_interface.h),
// the Fairing_options member (Fairing_options.h) and its reading (read_fairing_options), the copy into the
// stepper's settings where it is a plain one (resolve_fairing_parameters), the program's option
// (tools/anisotropic_fairing/options.cpp) and the Python keyword (python/). The manual's list
// (doc/Anisotropic_fairing/Parameters.txt) and the Python stubs are checked against it by tests
// (test_parameter_table, python/tests/test_parameter_table.py).
//
// AF_PARAMETER(name, type, default, named, setting, check, flag, value, program, python, help)
//   name     the Fairing_options member, the named parameter and the Python keyword
//   type     the member's type; default: its initial value
//   named    OWN: a named parameter of the package; CGAL: \cgal's of that name
//   setting  &Stepper_settings::field it is copied into, checked by `check` (internal/run/Fairing_parameters.h);
//            nullptr: resolved by hand there
//   flag     the program's option (nullptr: none), `value` the name of its value, `program` how it is read
//            (option_kinds.h), `help` its text in --help
//   python   how the Python keyword is read (python/keyword_arguments.h; No_keyword: none)
// AF_TENSOR_SETTING(name, flag, value, program, python, help): an option and keyword that are no member of
//   their own but make the member diffusion_tensor together (the tensor's word and its settings).
// Names that only the program or Python reads (program, python, the check functions) mean nothing to the
// library, which drops those columns. The order of the rows is the members', the help's and Python's.

AF_PARAMETER(time_step, std::optional<double>, {}, OWN, nullptr, Unchecked(),
  "--time-step", "T", Number(false), Py_number(),
  "time step tau in model units (length^2), as in the paper (time_step)")
AF_PARAMETER(relative_time_step, std::optional<double>, {}, OWN, nullptr, Unchecked(),
  "--relative-time-step", "R", Number(false), Py_number(),
  "time step in units of l^2, l = sqrt(area/4pi) of the input (per connected\n"
  "component; relative_time_step); give at most one of the two. Neither:\n"
  "automatic parameters: the noise is estimated from the mesh, the tensor is\n"
  "the anisotropic one with its threshold and prefilter chosen from the mesh\n"
  "(unless --tensor is given), steps of 0.3 h^2 (h: the edge length) until\n"
  "the surface has moved off the input by the noise")
AF_PARAMETER(flow_order, int, 2, OWN, nullptr, Unchecked(),
  "--order", "2|4", Words(order_words), Py_integer(),
  "the flow's order: 2 (default: diffusion, as in the paper) or 4\n"
  "(dX/dt = -(M^-1 L)^2 X, which removes noise while rounding the shape less;\n"
  "the time step is then in length^4, --relative-time-step in l^4; automatic:\n"
  "0.1 h^4; flow_order). The automatic\n"
  "default run uses the fourth-order flow itself for its uniform candidate\n"
  "(the report's choices say so)")
AF_PARAMETER(number_of_iterations, std::optional<unsigned int>, {}, CGAL, nullptr, Unchecked(),
  "--steps", "N", Count(), Py_count(),
  "the most time steps to run, all runs of the automatic comparison\n"
  "together (default 10; with automatic parameters 200; number_of_iterations)")
AF_PARAMETER(stopping_criteria, std::optional<Stopping_criteria>, {}, OWN, nullptr, Unchecked(),
  "--stop", "auto|noise|paper|off", Stop_word(), Py_stop_word(),
  "auto (default): noise with automatic parameters, paper otherwise;\n"
  "noise: stop when the surface has moved off the input by the estimated\n"
  "noise (--order 4: or when that displacement levels off short of it);\n"
  "paper: the criteria (27)-(29) and a steady-state test; off: exactly\n"
  "N steps (Stopping_criteria::automatic(), Stopping_criteria(),\n"
  "Stopping_criteria::none()). Whatever the criteria, a step that would fold\n"
  "the surface is retried with a quarter of the time step, and the run ends\n"
  "on the last sound surface (step_rejected, with a warning) if even 1/1024\n"
  "of it fails")
AF_PARAMETER(strength, double, 1, OWN, nullptr, Unchecked(),
  "--strength", "S", Number(false), Py_number(),
  "how far the noise stop goes: until the surface has moved off the input\n"
  "by S times the estimated noise (default 1; 2 smooths more, 0.5 less).\n"
  "The rest stays automatic: the flows are compared at the noise level,\n"
  "and the one kept runs again to S times it. Needs the noise stop:\n"
  "automatic parameters, or --stop noise with a time step (strength)")
AF_PARAMETER(fidelity_weight, std::optional<double>, {}, OWN, nullptr, Unchecked(),
  "--fidelity", "W", Number(true), Py_number(),
  "fidelity weight omega in model units (1/time), as in the paper (default 0;\n"
  "fidelity_weight)")
AF_PARAMETER(relative_fidelity_weight, std::optional<double>, {}, OWN, nullptr, Unchecked(),
  "--relative-fidelity", "W", Number(true), Py_number(),
  "fidelity weight in units of 1/l^2 (relative_fidelity_weight); give at most\n"
  "one of the two")
AF_PARAMETER(relative_maximum_deviation, std::optional<double>, {}, OWN, nullptr, Unchecked(),
  "--relative-maximum-deviation", "R", Number(true), Py_number(),
  "no written vertex moves farther than R (units of l) off its input\n"
  "position: the vertices nearing it are held by a fidelity weight of\n"
  "their own, and one it cannot hold is written on the bound (default:\n"
  "no bound; 0: none; relative_maximum_deviation)")
AF_PARAMETER(absolute_maximum_deviation, std::optional<double>, {}, OWN, nullptr, Unchecked(),
  "--absolute-maximum-deviation", "D", Number(true), Py_number(),
  "the same in model units (absolute_maximum_deviation); give at most one\n"
  "of the two. --maximum-deviation, its former spelling, is deprecated:\n"
  "in the library and Python that name is the relative bound")
AF_PARAMETER(attribute_maximum_deviation, double, 0, OWN, &Stepper_settings::attribute_maximum_deviation,
  Finite_non_negative(), "--attribute-maximum-deviation", "D", Number(true), Py_number(),
  "no vertex's attribute values move farther than D (their units,\n"
  "Euclidean over the components) off the input's (default: no bound;\n"
  "attribute_maximum_deviation)")
AF_PARAMETER(diffusion_tensor, std::optional<Package_diffusion_tensor>, {}, OWN, nullptr, Unchecked(),
  nullptr, nullptr, No_flag(), No_keyword(), "")
AF_TENSOR_SETTING(tensor, "--tensor", "isotropic|anisotropic|uniform", Tensor_word(), Py_tensor_word(),
  "the diffusion tensor: isotropic (mean-curvature flow; the\n"
  "default with a time step), anisotropic (curvature-driven, feature-preserving:\n"
  "Anisotropic_diffusion_tensor; the default with automatic parameters, its\n"
  "threshold and prefilter then chosen from the mesh unless given, and the\n"
  "isotropic (or uniform) result kept instead when its estimated error at the\n"
  "noise level is lower: the report's tensor and choices say which) or uniform (the\n"
  "uniform Laplacian's weights, Uniform_diffusion_tensor: for noisy scans with a\n"
  "graded triangulation; it rounds creases like the isotropic tensor);\n"
  "diffusion_tensor")
AF_TENSOR_SETTING(lambda_, "--lambda", "L", Tensor_lambda(), Py_tensor_lambda(),
  "the anisotropic tensor's feature threshold, a curvature in units of 1/l\n"
  "(default 2): principal curvatures above it are diffused less\n"
  "(Anisotropic_diffusion_tensor::set_lambda)")
AF_TENSOR_SETTING(epsilon, "--epsilon", "E", Tensor_epsilon(), Py_tensor_epsilon(),
  "the anisotropic tensor reads curvature on the surface after an isotropic\n"
  "step of E (units of l^2; the paper's prefiltered M_eps); default 1e-3;\n"
  "0: on the current surface (set_epsilon)")
AF_TENSOR_SETTING(tangential_motion, "--tangential-motion", "remove|keep", Tensor_tangential(), Py_tensor_tangential(),
  "the anisotropic flow moves control points along the surface's\n"
  "normal only (remove, the default: the tangential part of div(D grad x)\n"
  "folds noisy meshes) or also within it, as the paper does (keep;\n"
  "set_normal_motion_only)")
AF_PARAMETER(finite_element, Finite_element, Finite_element::LOOP, OWN, nullptr, Unchecked(),
  "--element", "loop|linear", Words(element_words), Py_words(element_words),
  "Loop limit-surface elements (default) or linear (P1) elements\n"
  "(finite_element)")
AF_PARAMETER(output_positions, Output_positions, Output_positions::LIMIT_SURFACE, OWN, nullptr, Unchecked(),
  "--output", "limit|control", Words(output_words), Py_words(output_words),
  "write the points of the faired limit surface (default) or the faired\n"
  "control points (the mesh whose Loop limit surface is the faired surface;\n"
  "output_positions)")
AF_PARAMETER(attribute_mode, std::optional<Attribute_mode>, {}, OWN, nullptr, Unchecked(),
  "--mode", "separate|coupled|attributes|geometry", Words(mode_words), Py_words(mode_words),
  "how the attributes (--attributes) are faired: separate (the default\n"
  "with --attributes): with the operator of the geometry's surface; coupled:\n"
  "as one surface with the geometry in R^(3+d); attributes: the geometry is\n"
  "fixed (not written) and only the attributes diffuse on it; geometry (the\n"
  "default without --attributes): the attributes are not faired. coupled and\n"
  "attributes need --attributes (attribute_mode)")
AF_PARAMETER(attribute_weight, double, 1, OWN, nullptr, Unchecked(),
  "--attribute-weight", "W", Attribute_weight(), Py_attribute_weight(),
  "coupled: the length that one attribute unit counts for (> 0, default 1;\n"
  "attribute_weight)")
AF_PARAMETER(boundary_handling, Boundary_handling, Boundary_handling::HOLD_BOUNDARY_CURVE, OWN, nullptr, Unchecked(),
  "--boundary", "curve|vertices", Words(boundary_words), Py_words(boundary_words),
  "on a mesh with borders, hold the limit boundary curve (default: the\n"
  "boundary vertices and the interior vertices that shape the curve) or only\n"
  "the boundary vertices (the paper's choice; the border may slide;\n"
  "boundary_handling). Boundary vertices are written unchanged either way")
AF_PARAMETER(linear_solver, Linear_solver, Linear_solver::AUTOMATIC, OWN, &Stepper_settings::solver, Unchecked(),
  "--solver", "auto|cg|cholesky", Words(solver_words), Py_words(solver_words),
  "linear solver: automatic (default), conjugate gradients, sparse LDL^T\n"
  "(linear_solver)")
AF_PARAMETER(solver_tolerance, double, 1e-8, OWN, &Stepper_settings::solver_tolerance, Open_unit_interval(),
  nullptr, nullptr, No_flag(), No_keyword(), "")
AF_PARAMETER(solver_maximum_iterations, int, 10000, OWN, &Stepper_settings::solver_maximum_iterations, At_least_one(),
  nullptr, nullptr, No_flag(), No_keyword(), "")
AF_PARAMETER(quadrature_degree, int, 8, OWN, nullptr, Unchecked(),
  "--quadrature-degree", "4|6|8", Words(quadrature_words), Py_integer(),
  "Gauss rule per face for the Loop element (default 8; quadrature_degree)")
AF_PARAMETER(quadrature_tiling_depth, int, 0, OWN, nullptr, Unchecked(),
  nullptr, nullptr, No_flag(), No_keyword(), "")
AF_PARAMETER(memory_limit, std::optional<double>, {}, OWN, nullptr, Unchecked(),
  "--memory-limit", "SIZE|off", Memory_size(), Py_memory_size(),
  "the memory the run may take, e.g. 6G or 500M (K, M, G, T: powers of 1024;\n"
  "default: what the process may still take, the tightest of its cgroup's\n"
  "limit, ulimit -v and the memory the system has available). A run\n"
  "predicted to need more is refused before it starts, naming both; off:\n"
  "no check (memory_limit, in bytes; infinity: no check)")
AF_PARAMETER(verbose, bool, false, CGAL, &Stepper_settings::verbose, Unchecked(),
  nullptr, nullptr, No_flag(), No_keyword(), "")
