// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_ANISOTROPIC_FAIRING_ANISOTROPIC_FAIRING_H
#define CGAL_ANISOTROPIC_FAIRING_ANISOTROPIC_FAIRING_H

#include <CGAL/Anisotropic_fairing/Fairing_options.h>
#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/Anisotropic_fairing/Input_error.h>
#include <CGAL/Anisotropic_fairing/Anisotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/Uniform_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/named_function_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/run/Fairing_driver.h>

#include <CGAL/boost/graph/properties.h>

#include <type_traits>

namespace CGAL {
namespace Anisotropic_fairing {

/// \cond SKIP_IN_MANUAL
namespace internal {
// the attribute overloads: one sentence, not pages of template errors, for a value type without traits
template <typename TriangleMesh, typename VertexPointMap, typename VertexAttributeMap, typename NamedParameters>
Fairing_report fair_attributes(TriangleMesh& tm, VertexPointMap vpm, VertexAttributeMap attr_map,
                               const NamedParameters& np)
{
  typedef typename boost::property_traits<VertexAttributeMap>::value_type Attribute;
  constexpr bool has_traits = has_vector_attribute_traits<Attribute>::value;
  static_assert(has_traits,
                "the attribute map's value type has no CGAL::Anisotropic_fairing::Vector_attribute_traits: "
                "specialise it for the type (see Vector_attribute_traits.h) or use a vector type that has one");
  if constexpr(has_traits) return fair(tm, vpm, attr_map, np);
  else return Fairing_report();
}
} // namespace internal
/// \endcond

/*!
\ingroup PkgAnisotropicFairingFunctions

fairs the surface of `tm`, and the per-vertex attribute `attr_map` with it, by geometric diffusion
discretised with Loop-subdivision finite elements (Bajaj & Xu 2003). Each step solves
\f[ \big((1+\tau\omega) M + \tau L(D)\big)\, X_{n+1} = M\,(X_n + \tau\omega X_0) \f]
where the control points \f$X\f$ are the vertices of `tm`, \f$M_{ij} = \int \phi_i\phi_j\,dA\f$ and
\f$L_{ij} = \int D\nabla\phi_i\cdot\nabla\phi_j\,dA\f$ are integrated over the current limit
surface \f$M(t_n)\f$, and \f$\omega\f$ pulls towards the input. With the default isotropic tensor the
geometry follows mean-curvature flow \f$\partial_t x = \Delta_M x = 2H\f$. The attribute is carried
along with the geometry's operator (every component solved with the same matrix).

The result is written into `vpm` and `attr_map` only if the run succeeds; on failure (see
`Fairing_report::status`) the mesh and maps are left exactly as they were.

<b>Units.</b> By default the time step and the fidelity weight are relative to the model's scale
\f$\ell = \sqrt{\mathrm{Area}/4\pi}\f$ of the input's limit surface (the radius of the sphere of equal
area): \f$\tau = \tau_{rel}\,\ell^2\f$, \f$\omega = \omega_{rel}/\ell^2\f$. So the same parameters do
the same thing to a model at any scale; with \f$\tau_{rel} = 10^{-3}\f$ a unit sphere loses about 0.4%
of its area per step. `time_step` and `fidelity_weight` give them in model units instead, as in the paper.

\tparam TriangleMesh a model of `FaceListGraph` (e.g. `CGAL::Surface_mesh`, `CGAL::Polyhedron_3`)
\tparam VertexPointMap a model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
        as key and a CGAL `Point_3` as value
\tparam VertexAttributeMap a model of `ReadWritePropertyMap` with the same key and a value type that
        has a `Vector_attribute_traits` (numbers, `std::array`, Eigen vectors, CGAL points and vectors,
        `CGAL::IO::Color`)
\tparam NamedParameters a sequence of named parameters, started from `CGAL::Anisotropic_fairing::parameters`
        (which also accepts CGAL's own names)

\param tm the mesh: 2-manifold, triangles, every interior valence at least 3; it may have borders and
          holes (held fixed, see `boundary_handling`) and vertices on no face (left as they are)
\param vpm its vertex positions, read and written
\param attr_map per-vertex data faired with the geometry
\param np optional named parameters among:

\cgalNamedParamsBegin
  \cgalParamNBegin{fairing_options}
    \cgalParamDescription{all the parameters below but the maps, the callback, a tensor type of one's own and
                          `sparse_linear_solver`, as one value; the named parameters given beside it apply on top
                          (giving both parameters of a pair, one in the value and one beside it, is refused)}
    \cgalParamType{`Fairing_options`} \cgalParamDefault{`Fairing_options()`: every default below}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{the positions of the vertices, read and written; only in the overloads without a point-map
                          argument (with one, passing it too is a compile-time error)}
    \cgalParamType{a `ReadWritePropertyMap` with `vertex_descriptor` key and a point of a CGAL kernel as value}
    \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{relative_time_step}
    \cgalParamDescription{the time step \f$\tau\f$ in units of \f$\ell^2\f$. Giving it (or `time_step`) turns the
                          automatic parameters off: the defaults below marked "with a time step" then apply}
    \cgalParamType{double > 0} \cgalParamDefault{none: automatic parameters, the time step chosen from the mesh's
                          noise (Section \ref sec_AF_default)}
  \cgalParamNEnd
  \cgalParamNBegin{time_step}
    \cgalParamDescription{the time step \f$\tau\f$ in model units (length squared); excludes `relative_time_step`}
    \cgalParamType{double > 0} \cgalParamDefault{unused}
  \cgalParamNEnd
  \cgalParamNBegin{flow_order}
    \cgalParamDescription{2: the paper's diffusion, \f$\partial_t x = -M^{-1}L(D)\,x\f$; 4: the fourth-order flow
                          \f$\partial_t x = -(M^{-1}L(D))^2 x\f$ with the lumped inverse mass, whose step damps a mode
                          of
                          \f$M^{-1}L\f$ with eigenvalue \f$\mu\f$ by \f$1/(1+\tau\mu^2)\f$ instead of
                          \f$1/(1+\tau\mu)\f$ :
                          noise goes, the shape is rounded less. Its time step is in length\f$^4\f$
                          (`relative_time_step`
                          in \f$\ell^4\f$; automatic: \f$0.1\,h^4\f$). Held vertices (borders, constraints) carry no
                          curvature penalty of their own, so that a noisy held border does not bend the surface next to
                          it}
    \cgalParamType{int, 2 or 4} \cgalParamDefault{`2`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the largest number of time steps of the whole call: the default run's comparison of flows
                          counts every step of every run it makes, and makes no run once they are spent;
                          `stopping_criteria` may end a run earlier}
    \cgalParamType{unsigned int} \cgalParamDefault{`automatic_maximum_steps` (200) with automatic parameters, `10` with
    a time step}
  \cgalParamNEnd
  \cgalParamNBegin{relative_fidelity_weight}
    \cgalParamDescription{\f$\omega\f$ in units of \f$1/\ell^2\f$ (0: pure diffusion). A sphere of radius \f$r_0\f$
                          settles at \f$r^* = (r_0 + \sqrt{r_0^2 - 8/\omega})/2\f$ if \f$\omega \ge 8/r_0^2\f$ and
                          collapses otherwise}
    \cgalParamType{double >= 0} \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{fidelity_weight}
    \cgalParamDescription{\f$\omega\f$ in model units (1/time); excludes `relative_fidelity_weight`}
    \cgalParamType{double >= 0} \cgalParamDefault{unused}
  \cgalParamNEnd
  \cgalParamNBegin{relative_maximum_deviation}
    \cgalParamDescription{a bound \f$\varepsilon\f$, in units of \f$\ell\f$, on how far any written vertex moves off
                          its input position: \f$\|x_i(t) - x_i(0)\| \le \varepsilon\f$ for every vertex, at every step.
                          A vertex nearing it gets a fidelity weight of its own on its written position, raised (the
                          step taken again) where a step would carry it past; one that weight cannot hold (its cap,
                          or the input's own limit point lying farther off) is written on the bound, along the line
                          to its input position. With automatic parameters a run that the bound holds short of the
                          noise level ends when its displacement levels off (`Stop_reason::DEVIATION_BOUND`). A run
                          not stopped at the noise level (to a steady state, or a number of steps) also gives every
                          vertex a fidelity weight, once a vertex is halfway to the bound, that puts the flow's steady
                          state within 0.8 of it (`Fairing_report::bound_uniform_weight`). The
                          report gives the bound in model units, the largest deviation written and how many
                          vertices were held and put on the bound (Section \ref sec_AF_deviation_bound). 0: none}
    \cgalParamType{double >= 0} \cgalParamDefault{`0` (no bound)}
  \cgalParamNEnd
  \cgalParamNBegin{absolute_maximum_deviation}
    \cgalParamDescription{the same bound in model units; excludes `relative_maximum_deviation`}
    \cgalParamType{double >= 0} \cgalParamDefault{unused}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_deviation}
    \cgalParamDescription{deprecated (a compiler warning says so): the former spelling of `relative_maximum_deviation`,
                          with its meaning; the program's `--maximum-deviation` is in model units}
    \cgalParamType{double >= 0} \cgalParamDefault{unused}
  \cgalParamNEnd
  \cgalParamNBegin{attribute_maximum_deviation}
    \cgalParamDescription{the same bound on each vertex's attribute values, the Euclidean distance over their
                          components in the attribute's own units (in every attribute mode; in the coupled mode
                          before `attribute_weight` is applied). 0: none}
    \cgalParamType{double >= 0} \cgalParamDefault{`0` (no bound)}
  \cgalParamNEnd
  \cgalParamNBegin{stopping_criteria}
    \cgalParamDescription{the criteria (27)-(29) and a steady-state test, relative to \f$\ell\f$ by default}
    \cgalParamType{`Stopping_criteria`; `Stopping_criteria::none()` runs exactly `number_of_iterations` steps}
    \cgalParamDefault{`Stopping_criteria::automatic()` (the noise level) with automatic parameters, except in
                      `Attribute_mode::ATTRIBUTES_ONLY`; otherwise `Stopping_criteria()`: the paper's thresholds 0.005,
                      8 and 0.2 read at unit scale}
  \cgalParamNEnd
  \cgalParamNBegin{strength}
    \cgalParamDescription{how far the noise criterion goes: its target, `Stopping_criteria::noise_discrepancy` times the
                          estimated noise, times this (2 smooths more, 0.5 less). Everything else stays automatic. In
                          the
                          default run the flows are compared at the noise level itself, where the risk estimate measures
                          the error of a denoised surface, and the flow kept (`Fairing_report::selected_tensor`) then
                          runs
                          again from the input to `strength` times the noise; its run is the report's, and `choices`
                          ends
                          with it. A run with a tensor given or a time step, stopped by the noise criterion, aims at the
                          scaled target directly. Above 1 the automatic fourth-order flow steps at the scale `strength`
                          \f$\times h\f$ (time step \f$0.1\,(\mathrm{strength}\,h)^4\f$ , its levelling off read on
                          waves of
                          \f$4\pi\,\mathrm{strength}\,h\f$ ), so that it reaches the farther target in about as many
                          steps.
                          Where no run stops at the noise level (the paper's criteria, `Stopping_criteria::none()`,
                          `Attribute_mode::ATTRIBUTES_ONLY`) any value but 1 is refused, since it would change nothing
                          (Section \ref sec_AF_strength)}
    \cgalParamType{double > 0, finite} \cgalParamDefault{`1`: the estimated noise itself}
  \cgalParamNEnd
  \cgalParamNBegin{diffusion_tensor}
    \cgalParamDescription{the tensor \f$D\f$}
    \cgalParamType{a model of `DiffusionTensor`}
    \cgalParamDefault{`Anisotropic_diffusion_tensor::automatic()` with automatic parameters (the isotropic and uniform
                      flows' results compared with it, the best kept: `Fairing_report::selected_tensor`);
                      `Isotropic_diffusion_tensor()` with a time step}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_is_constrained_map}
    \cgalParamDescription{vertices that must not move (their control points and attributes are kept, and
                          they are written back unchanged whatever `output_positions` says)}
    \cgalParamType{a `ReadablePropertyMap` with `vertex_descriptor` key and `bool` value}
    \cgalParamDefault{no vertex is constrained}
  \cgalParamNEnd
  \cgalParamNBegin{attribute_mode}
    \cgalParamDescription{how `attr_map` is faired: with the geometry's operator (b), as one manifold with the
                          geometry in \f$\mathbb{R}^{3+d}\f$ (a), alone on the fixed geometry (c, a linear problem:
                          one assembly and one factorisation, then one solve per step; the point map is not
                          written), or not at all (d)}
    \cgalParamType{`Attribute_mode`}
    \cgalParamDefault{`Attribute_mode::SEPARATE` with an attribute map, `GEOMETRY_ONLY` without}
  \cgalParamNEnd
  \cgalParamNBegin{attribute_weight}
    \cgalParamDescription{`COUPLED` only: the length that one attribute unit counts for in the metric of the
                          manifold in \f$\mathbb{R}^{3+d}\f$ ; larger values let attribute edges hold back the diffusion
                          more}
    \cgalParamType{double > 0} \cgalParamDefault{`1`}
  \cgalParamNEnd
  \cgalParamNBegin{boundary_handling}
    \cgalParamDescription{what the borders hold: the limit boundary curve (the boundary vertices and the interior
                          vertices that shape the curve), or the boundary vertices only (the paper's choice; the
                          border may then slide). Boundary vertices are never written.}
    \cgalParamType{`Boundary_handling`} \cgalParamDefault{`Boundary_handling::HOLD_BOUNDARY_CURVE`}
  \cgalParamNEnd
  \cgalParamNBegin{finite_element}
    \cgalParamDescription{Loop limit-surface elements, or linear (P1) elements on the mesh itself}
    \cgalParamType{`Finite_element`} \cgalParamDefault{`Finite_element::LOOP`}
  \cgalParamNEnd
  \cgalParamNBegin{output_positions}
    \cgalParamDescription{what is written back: points of the faired limit surface at the vertices, or the faired
    control points}
    \cgalParamType{`Output_positions`} \cgalParamDefault{`Output_positions::LIMIT_SURFACE`}
  \cgalParamNEnd
  \cgalParamNBegin{control_point_map}
    \cgalParamDescription{receives, on success, the faired control points of every vertex: the mesh whose Loop limit
                          surface is the faired surface (held vertices: their input). With
                          `Output_positions::LIMIT_SURFACE`
                          the point map gets the limit points, held within `relative_maximum_deviation`, and this map
                          the control
                          points they come from: what `Loop_limit_surface` needs for the exact normals and curvatures of
                          the result. With the control points or the linear element written, the same points as the
                          point map}
    \cgalParamType{a `WritablePropertyMap` with `vertex_descriptor` key and the point type as value}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{attribute_control_map}
    \cgalParamDescription{receives, on success, the faired control values of every vertex's attribute (held vertices:
                          their input), in the attributes' own units: the function whose Loop limit on the faired
                          surface gives the attribute values written with `Output_positions::LIMIT_SURFACE`. With
                          `Loop_limit_surface::resample()` on the faired control mesh (`control_point_map`) it
                          resamples the faired attributes. Nothing is written without faired attributes
                          (no attribute map, or `Attribute_mode::GEOMETRY_ONLY`)}
    \cgalParamType{a `WritablePropertyMap` with `vertex_descriptor` key and the attribute map's value type as value}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{linear_solver}
    \cgalParamDescription{the solver of each step's symmetric positive definite system}
    \cgalParamType{`Linear_solver`} \cgalParamDefault{`Linear_solver::AUTOMATIC`}
  \cgalParamNEnd
  \cgalParamNBegin{sparse_linear_solver}
    \cgalParamDescription{the factorisation used wherever the package factorises (`Linear_solver::CHOLESKY`,
                          `AUTOMATIC` when it decides to, the prefilter of the anisotropic tensor): to plug in
                          CHOLMOD, a supernodal or an out-of-core solver. It receives each symmetric positive
                          definite system in full and is asked to factor it, then to solve one column at a time}
    \cgalParamType{a model of `SparseLinearAlgebraWithFactorTraits_d`, e.g.
                   `CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType>>`}
    \cgalParamDefault{the package's sparse \f$LDL^T\f$ (Eigen's `SimplicialLDLT`, analysed once per run)}
  \cgalParamNEnd
  \cgalParamNBegin{solver_tolerance}
    \cgalParamDescription{relative residual at which conjugate gradients stop (the prefilter's: a hundredth of it)}
    \cgalParamType{double in (0, 1)} \cgalParamDefault{`1e-8` (the error it leaves in a step is far below the
    time-discretisation error)}
  \cgalParamNEnd
  \cgalParamNBegin{solver_maximum_iterations}
    \cgalParamDescription{conjugate-gradient iterations after which the step fails}
    \cgalParamType{int >= 1} \cgalParamDefault{`10000`}
  \cgalParamNEnd
  \cgalParamNBegin{callback}
    \cgalParamDescription{called after every step with its `Fairing_step`; returning `false` ends the run
    (successfully)}
    \cgalParamType{a functor `bool(const Fairing_step&)`} \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{verbose}
    \cgalParamDescription{prints one line per step on `std::cerr`}
    \cgalParamType{bool} \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{quadrature_degree}
    \cgalParamDescription{degree of the Gauss rule on each face (Loop element)}
    \cgalParamType{int, 4, 6 or 8} \cgalParamDefault{`8`}
  \cgalParamNEnd
  \cgalParamNBegin{quadrature_tiling_depth}
    \cgalParamDescription{adaptive quadrature near extraordinary vertices (see `Loop_limit_surface`)}
    \cgalParamType{int in [0, 12]} \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{memory_limit}
    \cgalParamDescription{the bytes the run may take: a run whose predicted memory (`Fairing_report::predicted_memory`)
      is larger is refused before its set-up with `Fairing_status::INSUFFICIENT_MEMORY` and a message naming both;
      infinity: no check}
    \cgalParamType{double, >= 0}
    \cgalParamDefault{what the process may still take: the tightest of its cgroup's memory limit, its address-space
      and data limits (`ulimit -v`, `ulimit -d`) and the memory the system has available}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns a `Fairing_report`: the status, why the run stopped, and per step the solver's iterations and
         residual, the area, energy, \f$\int|H|^2\f$, displacement and timings.
\throws Input_error, before anything is modified, if the mesh is not a 2-manifold triangle mesh
        with interior valences \f$\geq 3\f$ (e.g. a bow-tie vertex on a border, named in the message), if a coordinate
        or attribute is not finite, if attribute dimensions differ,
        or if a parameter is out of range.
*/
template <typename TriangleMesh, typename VertexPointMap, typename VertexAttributeMap,
          typename NamedParameters = parameters::Default_named_parameters>
#ifdef DOXYGEN_RUNNING
Fairing_report
#else
typename std::enable_if<!internal::is_named_parameters<VertexAttributeMap>::value, Fairing_report>::type
#endif
anisotropic_fairing(TriangleMesh& tm, VertexPointMap vpm, VertexAttributeMap attr_map,
                    const NamedParameters& np = parameters::default_values())
{
  static_assert(parameters::is_default_parameter<NamedParameters, CGAL::internal_np::vertex_point_t>::value,
                "the point map is the second argument: do not also pass vertex_point_map");
  return internal::fair_attributes(tm, vpm, attr_map, np);
}

/*!
\ingroup PkgAnisotropicFairingFunctions
as above, with the point map given by the named parameter `vertex_point_map`
(default: `get(CGAL::vertex_point, tm)`).
*/
template <typename TriangleMesh, typename VertexAttributeMap,
          typename NamedParameters = parameters::Default_named_parameters>
#ifdef DOXYGEN_RUNNING
Fairing_report
#else
typename std::enable_if<!internal::is_named_parameters<VertexAttributeMap>::value &&
                        internal::is_named_parameters<NamedParameters>::value, Fairing_report>::type
#endif
anisotropic_fairing(TriangleMesh& tm, VertexAttributeMap attr_map,
                    const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  return internal::fair_attributes(tm, choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                        get_property_map(CGAL::vertex_point, tm)), attr_map, np);
}

/*!
\ingroup PkgAnisotropicFairingFunctions
fairs the geometry only; the point map is given by the named parameter `vertex_point_map`
(default: `get(CGAL::vertex_point, tm)`). Other parameters, result and errors as above.
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
#ifdef DOXYGEN_RUNNING
Fairing_report
#else
typename std::enable_if<internal::is_named_parameters<NamedParameters>::value, Fairing_report>::type
#endif
anisotropic_fairing(TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  return internal::fair(tm, choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                             get_property_map(CGAL::vertex_point, tm)),
                        internal::No_attributes(), np);
}

} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_ANISOTROPIC_FAIRING_H
