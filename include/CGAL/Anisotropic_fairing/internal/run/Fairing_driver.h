// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Everything anisotropic_fairing() does between its named parameters and its return: the options read and
// resolved, the mesh and maps read and checked, the run on matrices (Fairing_core.h), and the result
// written back only if the run succeeded.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FAIRING_DRIVER_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FAIRING_DRIVER_H

#include <CGAL/Anisotropic_fairing/Fairing_options.h>
#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/Input_error.h>
#include <CGAL/Anisotropic_fairing/named_function_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Indexed_mesh.h>
#include <CGAL/Anisotropic_fairing/internal/run/Caller_maps.h>
#include <CGAL/Anisotropic_fairing/internal/run/Fairing_core.h>
#include <CGAL/Anisotropic_fairing/internal/run/Fairing_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/run/Memory_estimate.h>

#include <CGAL/Real_timer.h>

#include <boost/graph/graph_traits.hpp>

#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// True for CGAL named-parameter packs (ours derive from CGAL's).
template <typename T, typename Tag, typename Base>
std::true_type named_parameters_test(const CGAL::Named_function_parameters<T, Tag, Base>*);
std::false_type named_parameters_test(...);
template <typename X>
struct is_named_parameters : decltype(named_parameters_test(static_cast<const X*>(nullptr))) {};

/// What decides the memory of a run of `given` with `tensor` on `vertices` and `attributes` columns.
template <typename Tensor>
Memory_plan memory_plan(const Fairing_parameters& given, const Tensor& tensor, std::size_t vertices,
                        Eigen::Index attributes)
{
  Memory_plan p;
  p.vertices = vertices;
  p.columns = given.mode == Attribute_mode::GEOMETRY_ONLY     ? 3
              : given.mode == Attribute_mode::ATTRIBUTES_ONLY ? int(attributes)
                                                              : 3 + int(attributes);
  p.comparison = compares_flows(given, tensor);
  p.flow = with_tensor(tensor, [](const auto& t) {
    typedef std::decay_t<decltype(t)> T;
    return std::is_same<T, Uniform_diffusion_tensor>::value     ? Memory_plan::UNIFORM
           : std::is_same<T, Isotropic_diffusion_tensor>::value ? Memory_plan::ISOTROPIC
                                                                : Memory_plan::ANISOTROPIC;
  });
  p.order = given.settings.order;
  p.loop = given.element == Finite_element::LOOP;
  p.factorised = given.settings.solver == Linear_solver::CHOLESKY;
  // a fixed surface's constant system is factorised once by AUTOMATIC where it may (Solver_choice.h)
  p.constant_factorised = given.settings.solver == Linear_solver::AUTOMATIC &&
                          given.mode == Attribute_mode::ATTRIBUTES_ONLY &&
                          vertices <= std::size_t(automatic_cholesky_limit);
  return p;
}

inline void report_memory(Fairing_report& r, double expected, const Available_memory& a)
{
  r.memory_in_use = a.in_use;
  r.predicted_memory = expected;
  r.available_memory = a.bytes;
  r.memory_limited_by = a.source;
}

/// The report of a run refused for its memory (`why`): nothing was done
inline Fairing_report memory_refused(const std::string& why, double need, const Available_memory& available,
                                     std::size_t vertices, std::size_t faces, double seconds)
{
  Fairing_report refused;
  refused.status = Fairing_status::INSUFFICIENT_MEMORY;
  refused.stop_reason = Stop_reason::FAILURE;
  refused.message = why;
  refused.vertices = vertices;
  refused.faces = faces;
  report_memory(refused, need, available);
  refused.input_seconds = refused.total_seconds = seconds;
  return refused;
}

/// The run of anisotropic_fairing() on `options` with `tensor` (a package tensor chosen at run time, or a
/// tensor type of the caller's own); `elements`: where its runs step (Stepper_call.h: here, or the distributed
/// program's processes).
template <typename TriangleMesh, typename VertexPointMap, typename AttributeMap, typename Tensor,
          typename Elements = Serial_elements>
Fairing_report fair_with_options(TriangleMesh& tm, VertexPointMap vpm, AttributeMap attributes,
                                 const Fairing_options& options, const Mesh_hooks<TriangleMesh>& hooks,
                                 const Tensor& tensor, const Elements& elements = Elements())
{
  typedef Indexed_mesh<TriangleMesh> Mesh;
  CGAL::Real_timer total;
  total.start();
  Input_agreement agreement(elements.part());   // a part of a mesh: every process's input checked, or none goes on
  // parameters (Fairing_parameters.h); without a time step the package chooses the time step, the
  // stopping rule and (unless given) the tensor from the mesh (Automatic_parameters.h)
  Fairing_parameters given = resolve_fairing_parameters(options, !std::is_same<AttributeMap, No_attributes>::value);
  given.settings.direct_solver = hooks.direct_solver;
  const Attribute_mode mode = given.mode;
  const double weight = given.attribute_weight;

  // input, read and checked before anything is touched
  Mesh im(tm, Borders::GHOSTED, true);   // isolated vertices: held, never written
  Control_matrix P = im.read_points(vpm);
  const Control_matrix A =
    mode == Attribute_mode::GEOMETRY_ONLY ? Control_matrix() : read_attribute_columns(im, attributes);
  const double largest = A.size() > 0 ? A.cwiseAbs().maxCoeff() : 0.0;
  // coupled, the weighted attributes are coordinates of the manifold: the same range as the points
  if(mode == Attribute_mode::COUPLED && weight * largest > Mesh::coordinate_limit)
    throw Input_error(Input_error::INVALID_PARAMETER, Input_error::no_element,
                      "the attribute weight " + Mesh::to_text(weight) + " times the largest attribute value " +
                      Mesh::to_text(largest) + " is a coordinate beyond 1e70 in the coupled manifold, where the "
                      "fairing's fourth powers of lengths overflow; "
                      "give a weight of at most " + Mesh::to_text(Mesh::coordinate_limit / largest));
  std::vector<bool> held(im.number_of_vertices(), false);
  if(hooks.constrained)
    for(std::size_t i = 0; i < held.size(); ++i) held[i] = hooks.constrained(im.vertex(i));

  const Fairing_input in{ im.ghost_layer(), P, A, held, bool(hooks.control_point) || bool(hooks.attribute_control) };
  agreement.passed();
  const double input_seconds = total.time();
  Memory_plan plan = memory_plan(given, tensor, im.number_of_vertices(), A.cols());
  // what an automatic factorisation may take beside the run (Solver_choice.h)
  given.settings.factor_budget = available_memory(given.memory_limit).bytes - predicted_memory(plan);
  Fairing_core<Tensor, Elements> core(in, given, tensor, hooks.callback, elements);
  im.release_ghost_layer();   // the run has its own numbering's, and its own copy of the points
  P.resize(0, 0);
  core.prepare();
  // what the run will take, against what the process may: refused before its set-up, where its cost begins
  plan.at_noise_level = given.settings.stopping.noise_discrepancy > 0 && mode != Attribute_mode::ATTRIBUTES_ONLY &&
                        core.input_at_noise_level();
  const double need = predicted_memory(plan);
  const Available_memory available = available_memory(given.memory_limit);
  const double expected = expected_memory(plan, available.bytes);
  const std::string refusal = memory_refusal(need, available);
  if(!refusal.empty())
    return memory_refused(refusal, need, available, im.number_of_vertices(), im.number_of_faces(), total.time());
  Fairing_result result = core.run();
  Fairing_report& report = result.report;
  report.input_seconds = input_seconds;
  report_memory(report, expected, available);
  if(mode == Attribute_mode::COUPLED && A.cols() > 0 && report.status == Fairing_status::DEGENERATE_METRIC)
    report.message += "; in the coupled mode the surface is that of the points and the attributes times the "
                      "attribute weight (" + Mesh::to_text(weight) + "): a weight that makes the attributes dwarf or "
                      "drown the coordinates leaves no "
                      "surface, try a weight near 1 / (the attributes' range per edge length)";
  if(report.succeeded())
  {
    const double written_from = total.time();
    write_back(im, result.values, mode, result.kept, vpm, attributes);
    write_control_values(im, hooks.control_point, result.control_values, 0);
    if(A.cols() > 0 && result.control_values.cols() == 3 + A.cols())
      write_control_values(im, hooks.attribute_control, result.control_values, 3);
    report.write_back_seconds = total.time() - written_from;
  }
  report.total_seconds = total.time();
  return report;
}

/// anisotropic_fairing() with named parameters: their options, and the caller's maps behind functions.
template <typename TriangleMesh, typename VertexPointMap, typename AttributeMap, typename NamedParameters>
Fairing_report fair(TriangleMesh& tm, VertexPointMap vpm, AttributeMap attributes, const NamedParameters& np)
{
  const Fairing_options options = read_fairing_options(np);
  const auto hooks = caller_hooks<TriangleMesh>(attributes, np);
  typedef typename std::decay<decltype(parameters::get_parameter(np, internal_np::diffusion_tensor))>::type Tensor;
  if constexpr(parameters::is_default_parameter<NamedParameters, internal_np::diffusion_tensor_t>::value ||
               is_package_tensor<Tensor>::value)
    return fair_with_options(tm, vpm, attributes, options, hooks, options.diffusion_tensor_or_default());
  else
    return fair_with_options(tm, vpm, attributes, options, hooks,
                             parameters::get_parameter(np, internal_np::diffusion_tensor));
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FAIRING_DRIVER_H
