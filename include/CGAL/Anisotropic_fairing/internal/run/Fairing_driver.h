// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Everything anisotropic_fairing() does between reading the named parameters and returning:
// validate, read the maps into matrices, close the borders by a ghost layer and hold them, pick the
// element, run the time stepper, and write the result back only if the run succeeded.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FAIRING_DRIVER_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FAIRING_DRIVER_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/Anisotropic_fairing/Input_error.h>
#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/Uniform_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/Vector_attribute_traits.h>
#include <CGAL/Anisotropic_fairing/named_function_parameters.h>
#include <CGAL/Anisotropic_fairing/Anisotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/internal/run/Automatic_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/run/Fairing_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/run/Smoother_selection.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Boundary_constraints.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Deviation_bound.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Isolated_spikes.h>
#include <CGAL/Anisotropic_fairing/internal/element/Ghosted_patch_cache.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Indexed_mesh.h>
#include <CGAL/Anisotropic_fairing/internal/element/Linear_element_cache.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Locality_ordering.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Mesh_components.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Noise_estimate.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Tensor_hooks.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Time_stepper.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Vertex_limit_masks.h>

#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
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

/// Stands for "no attribute map" (geometry-only fairing).
struct No_attributes {};

template <typename Mesh>
Control_matrix read_attribute_columns(const Indexed_mesh<Mesh>&, No_attributes) { return Control_matrix(); }
template <typename Mesh, typename AttributeMap>
Control_matrix read_attribute_columns(const Indexed_mesh<Mesh>& im, AttributeMap map) { return im.read_attributes(map); }

template <typename Mesh>
void write_attribute_columns(const Indexed_mesh<Mesh>&, No_attributes, const Control_matrix&, Eigen::Index, const std::vector<bool>&) {}
template <typename Mesh, typename AttributeMap>
void write_attribute_columns(const Indexed_mesh<Mesh>& im, AttributeMap map, const Control_matrix& X, Eigen::Index first,
                             const std::vector<bool>& keep)
{
  typedef typename boost::property_traits<AttributeMap>::value_type Value;
  std::vector<Value> values;
  values.reserve(im.number_of_vertices());
  for(std::size_t i = 0; i < im.number_of_vertices(); ++i)
    values.push_back(Vector_attribute_traits<Value>::make(get(map, im.vertex(i)), X.row(Eigen::Index(i)).data() + first));
  for(std::size_t i = 0; i < im.number_of_vertices(); ++i)
    if(!keep[i]) put(map, im.vertex(i), values[i]);
}

/// Mean length of the edges of the real faces (an interior edge is seen from both sides, a border
/// edge from one).
inline double mean_edge_length(const Ghost_layer& gl, const Control_matrix& P)
{
  const Triangle_topology& topo = *gl.topology;
  double sum = 0;
  for(std::size_t f = 0; f < gl.real_faces; ++f)
    for(int k = 0; k < 3; ++k)
      sum += (P.row(topo.face(f)[k]) - P.row(topo.face(f)[(k + 1) % 3])).norm();
  return gl.real_faces > 0 ? sum / double(3 * gl.real_faces) : 0.0;
}


/// The mean edge length of each connected component (`edge[c]`) and of the whole mesh (returned), over
/// the real faces' edges (an interior edge is seen from both sides, a border edge from one).
inline double component_mean_edges(const Triangle_topology& topo, std::size_t real_faces, const Mesh_components& components,
                                   const Control_matrix& X, std::vector<double>& edge)
{
  edge.assign(components.count, 0.0);
  std::vector<double> counted(components.count, 0.0);
  for(std::size_t f = 0; f < real_faces; ++f)
    for(int k = 0; k < 3; ++k)
    {
      const auto& t = topo.face(f);
      edge[std::size_t(components.of_face[f])] += (X.row(t[k]).head(3) - X.row(t[(k + 1) % 3]).head(3)).norm();
      counted[std::size_t(components.of_face[f])] += 1;
    }
  double sum = 0, count = 0;
  for(std::size_t c = 0; c < components.count; ++c)
  {
    sum += edge[c];
    count += counted[c];
    edge[c] /= counted[c];
  }
  return count > 0 ? sum / count : 0.0;
}

/// The default tensor: chosen from the mesh when the time step is too (automatic parameters).
inline Anisotropic_diffusion_tensor default_tensor(std::true_type) { return Anisotropic_diffusion_tensor::automatic(); }
inline Isotropic_diffusion_tensor default_tensor(std::false_type) { return Isotropic_diffusion_tensor(); }

template <typename Cache, typename Tensor, typename Callback>
Fairing_report run_stepper(const Cache& cache, const Locality_ordering& ordering, const Mesh_components& components,
                           const std::vector<double>& component_edge, double mean_edge, Control_matrix& X, Attribute_mode mode,
                           const std::vector<bool>& constrained, const std::vector<bool>& border,
                           const Tensor& tensor, const Stepper_settings& s, Callback& callback, double& setup_seconds,
                           double& limit_weight, const Control_matrix* probe_start = nullptr, Control_matrix* probe_end = nullptr,
                           const std::function<Control_matrix(const Control_matrix&)>* probe_maker = nullptr)
{
  CGAL::Real_timer clock;
  clock.start();
  // with automatic parameters, the isotropic and the uniform flow's time step follows the mesh's density
  // (Local_time_scale.h)
  Stepper_settings settings = s;
  settings.local_time_scale = s.local_time_scale && (std::is_same<Tensor, Isotropic_diffusion_tensor>::value ||
                                                     std::is_same<Tensor, Uniform_diffusion_tensor>::value);
  Time_stepper<Cache> stepper(cache, std::size_t(X.rows()), constrained, ordering.layer, components, component_edge, mean_edge);
  const Tangential_motion_filter filter(ordering.layer);
  const bool normal_motion = wants_normal_motion(tensor) && mode != Attribute_mode::ATTRIBUTES_ONLY;
  if(normal_motion) stepper.set_tangential_filter(&filter);
  stepper.assembler().use_original_indices(&ordering.old_of_new_vertex, &ordering.old_of_new_face);
  stepper.assembler().exclude_from_curvature(&border);
  const int metric_columns = mode == Attribute_mode::COUPLED ? int(X.cols()) : 3;
  setup_seconds += clock.time();
  if(probe_end) probe_end->resize(0, 0);
  if(mode == Attribute_mode::ATTRIBUTES_ONLY) return stepper.run_on_fixed_surface(X, tensor, settings, callback);
  if(probe_start) stepper.set_probe(*probe_start);
  if(probe_maker) stepper.set_probe_maker(*probe_maker);
  Fairing_report report = stepper.run(X, metric_columns, tensor, settings, callback);
  report.normal_motion_only = normal_motion;
  limit_weight = stepper.limit_weight();
  if(probe_end) *probe_end = stepper.probe_result();
  return report;
}

/// The settings of a run of the given order; with automatic parameters, its time step too.
inline Stepper_settings with_order(Stepper_settings s, int order)
{
  if(order != s.order && s.time_unit == Length_unit::EDGE)
    s.time_step = order == 4 ? Automatic_parameters().time_step4 : Automatic_parameters().time_step;
  s.order = order;
  return s;
}

/// Puts the control points Z (rows in the private numbering) into the caller's control_point_map, every
/// vertex (the held ones at their input); nothing without a map.
template <typename Mesh, typename ControlMap>
void write_control_points(const Mesh& im, ControlMap map, const Control_matrix& Z, const std::vector<int>& old_of_new)
{
  typedef typename boost::property_traits<ControlMap>::value_type Point;
  for(Eigen::Index i = 0; i < Z.rows(); ++i)
    put(map, im.vertex(std::size_t(old_of_new[std::size_t(i)])), Point(Z(i, 0), Z(i, 1), Z(i, 2)));
}
template <typename Mesh>
void write_control_points(const Mesh&, CGAL::internal_np::Param_not_found, const Control_matrix&, const std::vector<int>&) {}

/// Puts the attribute columns of the control points Z (from column `first`, rows in the private
/// numbering, in the attributes' own units) into the caller's attribute_control_map, every vertex;
/// nothing without a map or without faired attributes.
template <typename Mesh, typename AttributeMap, typename ControlMap>
void write_attribute_controls(const Indexed_mesh<Mesh>& im, AttributeMap attributes, ControlMap map, const Control_matrix& Z,
                              Eigen::Index first, const std::vector<int>& old_of_new)
{
  typedef typename boost::property_traits<ControlMap>::value_type Value;
  for(Eigen::Index i = 0; i < Z.rows(); ++i)
  {
    const auto v = im.vertex(std::size_t(old_of_new[std::size_t(i)]));
    put(map, v, Vector_attribute_traits<Value>::make(get(attributes, v), Z.row(i).data() + first));
  }
}
template <typename Mesh, typename AttributeMap>
void write_attribute_controls(const Indexed_mesh<Mesh>&, AttributeMap, CGAL::internal_np::Param_not_found, const Control_matrix&,
                              Eigen::Index, const std::vector<int>&) {}
template <typename Mesh, typename ControlMap>
void write_attribute_controls(const Indexed_mesh<Mesh>&, No_attributes, ControlMap, const Control_matrix&, Eigen::Index,
                              const std::vector<int>&) {}
template <typename Mesh>
void write_attribute_controls(const Indexed_mesh<Mesh>&, No_attributes, CGAL::internal_np::Param_not_found, const Control_matrix&,
                              Eigen::Index, const std::vector<int>&) {}

/// What the default run chose from the mesh: the start of the report's `choices`. `tensor_chosen`: the
/// anisotropic tensor's threshold and prefilter were chosen; `scaled_flow`: the flow whose time step
/// follows the mesh's density, if any.
inline std::string automatic_choices(const Noise_estimate& noise, const Stepper_settings& s, bool tensor_chosen,
                                     std::size_t removed_spikes, std::size_t n, const char* scaled_flow)
{
  const Automatic_parameters a;
  char text[400];
  std::snprintf(text, sizeof text, "noise %.3g h (robust estimate over %zu vertices); time step %.3g h^%d per step until the surface "
                "has moved by %.3g x the noise%s", noise.relative_sigma(), noise.number_of_samples(), s.time_step, s.order,
                s.stopping.noise_discrepancy, tensor_chosen ? "" : "; the tensor given");
  std::string choices = text;
  if(removed_spikes > 0)
  {
    std::snprintf(text, sizeof text, "; first %zu isolated spikes (%.2g%% of the vertices: impulsive noise) moved to the centroids of "
                  "their rings", removed_spikes, 100.0 * double(removed_spikes) / double(n));
    choices += text;
  }
  if(tensor_chosen)
  {
    std::snprintf(text, sizeof text, "; anisotropic tensor: principal curvatures above %.3g / h are features, read on M_eps, "
                  "the surface after an isotropic step of %.3g h^2", a.lambda, a.epsilon);
    choices += text;
  }
  if(scaled_flow)
    choices += std::string("; the ") + scaled_flow + " flow's time step follows the mesh's density (h: the edge length around each vertex)";
  return choices;
}

/// Writes the result X (rows in the private numbering `old_of_new`) into the caller's maps, in the order of
/// vertices(tm): the points (unless only attributes were faired) and the attribute columns, from column 3.
/// Neither the user's constrained vertices nor boundary or isolated vertices are written.
template <typename Mesh, typename ConstrainedMap, typename VertexPointMap, typename AttributeMap>
void write_back(const Indexed_mesh<Mesh>& im, const std::vector<int>& old_of_new, const Control_matrix& X, Attribute_mode mode,
                const std::vector<bool>& border, const std::vector<bool>& isolated, ConstrainedMap vcm, VertexPointMap vpm,
                AttributeMap attributes)
{
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  const std::size_t n = im.number_of_vertices();
  Control_matrix result(X.rows(), X.cols());   // back to the order of vertices(tm)
  for(std::size_t i = 0; i < n; ++i) result.row(old_of_new[i]) = X.row(Eigen::Index(i));
  std::vector<bool> keep(n);
  for(std::size_t i = 0; i < n; ++i) keep[std::size_t(old_of_new[i])] = border[i] || isolated[i];
  for(std::size_t i = 0; i < n; ++i)
  {
    keep[i] = keep[i] || bool(get(vcm, im.vertex(i)));
    const Eigen::Index r = Eigen::Index(i);
    if(!keep[i] && mode != Attribute_mode::ATTRIBUTES_ONLY) put(vpm, im.vertex(i), Point(result(r, 0), result(r, 1), result(r, 2)));
  }
  if(X.cols() > 3) write_attribute_columns(im, attributes, result, 3, keep);
}

template <typename TriangleMesh, typename VertexPointMap, typename AttributeMap, typename NamedParameters>
Fairing_report fair(TriangleMesh& tm, VertexPointMap vpm, AttributeMap attributes, const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  CGAL::Real_timer total;
  total.start();

  // parameters (Fairing_parameters.h); without a time step the package chooses the time step, the
  // stopping rule and (unless given) the tensor from the mesh (Automatic_parameters.h). The tensor, the
  // constrained-vertex map and the callback are read here: their types are the caller's.
  const Fairing_parameters given = read_fairing_parameters(np, !std::is_same<AttributeMap, No_attributes>::value);
  Stepper_settings s = given.settings;
  constexpr bool automatic = uses_automatic_parameters<NamedParameters>::value;
  const Finite_element element = given.element;
  const Output_positions output = given.output;
  const Attribute_mode mode = given.mode;
  const double attribute_weight = given.attribute_weight;
  const Boundary_handling boundary = given.boundary;
  const Quadrature_spec& spec = given.quadrature;
  auto tensor = choose_parameter(get_parameter(np, internal_np::diffusion_tensor),
                                 default_tensor(std::integral_constant<bool, automatic>()));
  auto vcm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_is_constrained),
                              CGAL::Static_boolean_property_map<vertex_descriptor, false>());
  auto callback = choose_parameter(get_parameter(np, CGAL::internal_np::callback),
                                   [](const Fairing_step&) { return true; });

  // input, read and checked before anything is touched
  const Indexed_mesh<TriangleMesh> im(tm, Borders::GHOSTED, true);   // isolated vertices: held, never written
  Control_matrix P = im.read_points(vpm);
  const Control_matrix A = mode == Attribute_mode::GEOMETRY_ONLY ? Control_matrix() : read_attribute_columns(im, attributes);
  const std::size_t n = im.number_of_vertices();
  if(mode == Attribute_mode::COUPLED && A.size() > 0)
  {
    // coupled, the weighted attributes are coordinates of the manifold: the same range as the points
    const double largest = A.cwiseAbs().maxCoeff();
    if(attribute_weight * largest > Indexed_mesh<TriangleMesh>::coordinate_limit)
      throw Input_error(Input_error::INVALID_PARAMETER, Input_error::no_element,
                        "the attribute weight " + Indexed_mesh<TriangleMesh>::to_text(attribute_weight) + " times the largest attribute value " +
                        Indexed_mesh<TriangleMesh>::to_text(largest) + " is a coordinate beyond 1e70 in the coupled manifold, where the fairing's "
                        "fourth powers of lengths overflow; give a weight of at most " +
                        Indexed_mesh<TriangleMesh>::to_text(Indexed_mesh<TriangleMesh>::coordinate_limit / largest));
  }

  CGAL::Real_timer setup;
  setup.start();
  // the solver works in a private, cache-friendly numbering (row i of X is vertex old_of_new_vertex[i])
  // (the topology and the ghost layer, checked in the user's numbering, permuted into it)
  const Locality_ordering ordering = make_locality_ordering(im.ghost_layer());
  const Ghost_layer& layer = ordering.layer;
  Control_matrix X(Eigen::Index(n), 3 + A.cols());
  std::vector<bool> constrained(n), border(n, false);
  for(std::size_t i = 0; i < n; ++i)
  {
    const Eigen::Index old = ordering.old_of_new_vertex[i];
    X.row(Eigen::Index(i)).head(3) = P.row(old);
    // coupled: attributes measured in lengths, so that they shape the manifold in R^(3+d)
    if(A.cols() > 0) X.row(Eigen::Index(i)).tail(A.cols()) = (mode == Attribute_mode::COUPLED ? attribute_weight : 1.0) * A.row(old);
    constrained[i] = bool(get(vcm, im.vertex(std::size_t(old))));
  }
  for(int v : layer.boundary_vertices) border[std::size_t(v)] = true;
  std::vector<bool> isolated(n, false);   // on no surface: nothing to fair
  for(int v : layer.isolated_vertices) isolated[std::size_t(v)] = constrained[std::size_t(v)] = true;
  // the rows written back: the user's constrained, boundary and isolated vertices keep their values
  std::vector<bool> written(n);
  for(std::size_t i = 0; i < n; ++i) written[i] = !constrained[i] && !border[i];
  // a bound on the attributes, in the units the stepper holds them in
  if(mode == Attribute_mode::COUPLED) s.attribute_maximum_deviation *= attribute_weight;
  // the bounds on what is written, once the run's result is: a vertex its fidelity could not hold goes on
  // the bound (Deviation_bound.h); the largest deviations written, in the user's units
  auto bound_written = [&](Control_matrix& Y, const Control_matrix& start, Fairing_report& r) {
    if(!r.succeeded()) return;
    const double none = std::numeric_limits<double>::infinity();
    const Column_bound geometry{ 0, mode == Attribute_mode::ATTRIBUTES_ONLY ? 0 : 3, r.maximum_deviation > 0 ? r.maximum_deviation : none };
    const Column_bound values{ 3, Y.cols() - 3, s.attribute_maximum_deviation > 0 ? s.attribute_maximum_deviation : none };
    std::vector<bool> moved(n, false);
    clamp_to_bound(Y, start, geometry, written, moved);
    clamp_to_bound(Y, start, values, written, moved);
    r.clamped_vertices = std::size_t(std::count(moved.begin(), moved.end(), true));
    r.largest_deviation = largest_written_deviation(Y, start, geometry, written);
    r.largest_attribute_deviation = largest_written_deviation(Y, start, values, written) /
                                    (mode == Attribute_mode::COUPLED ? attribute_weight : 1.0);
    r.attribute_maximum_deviation = given.settings.attribute_maximum_deviation;
  };
  // what the borders hold: the boundary vertices, and the influence set of the limit boundary curve
  auto hold = [&](const std::vector<bool>& held) {
    std::size_t count = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      count += held[i] ? 1 : 0;
      constrained[i] = constrained[i] || held[i];
    }
    return count;
  };

  // the units of relative parameters, per connected component; the noise, from the mesh itself
  const Mesh_components components = make_mesh_components(*layer.topology, n, layer.real_faces);
  std::vector<double> component_edge;
  const double mean_edge = component_mean_edges(*layer.topology, layer.real_faces, components, X, component_edge);
  std::vector<bool> sampled(n);
  for(std::size_t i = 0; i < n; ++i) sampled[i] = !constrained[i] && !border[i];
  // impulsive noise: with the automatic stopping rule, isolated spikes go back to their rings' centroids
  // before the noise is estimated (Isolated_spikes.h); a bound on the motion leaves them as they are
  const std::size_t removed_spikes = automatic && mode != Attribute_mode::ATTRIBUTES_ONLY && s.stopping.noise_discrepancy > 0 &&
                                     !(s.maximum_deviation > 0) ? remove_isolated_spikes(*layer.topology, sampled, X) : 0;
  const Noise_estimate noise(*layer.topology, X, sampled);
  s.noise = &noise;
  std::vector<double> noise_sigma(n, 0.0);   // the noise's deviation at each vertex, in model units
  for(std::size_t i = 0; i < n; ++i)
    if(components.of_vertex[i] >= 0) noise_sigma[i] = noise.relative_sigma() * component_edge[std::size_t(components.of_vertex[i])];
  // the noise stop measures the limit surface, the surface faired, whichever positions are written: a
  // run that writes control points (the tool does, to give exact limit normals) then stops where the
  // limit-surface run stops, and `limit_weight` says how far toward the limit points the latter writes
  s.limit_written = element == Finite_element::LOOP && output == Output_positions::LIMIT_SURFACE;
  s.measure_limit_surface = element == Finite_element::LOOP &&
                   (output == Output_positions::LIMIT_SURFACE || s.stopping.noise_discrepancy > 0);
  std::string choices;
  if(automatic)
  {
    const Automatic_parameters a;
    s.time_step = a.time_step;
    if(s.order == 4) s.time_step = a.time_step4;
    s.local_time_scale = true;
    const bool tensor_chosen = is_automatic_tensor(tensor);
    if(tensor_chosen) choose_tensor(tensor, a.lambda, a.epsilon);
    const char* scaled_flow = mode == Attribute_mode::ATTRIBUTES_ONLY ? nullptr
                              : tensor_chosen || std::is_same<decltype(tensor), Isotropic_diffusion_tensor>::value ? "isotropic"
                              : std::is_same<decltype(tensor), Uniform_diffusion_tensor>::value ? "uniform" : nullptr;
    choices = automatic_choices(noise, s, tensor_chosen, removed_spikes, n, scaled_flow);
  }

  Fairing_report report;
  double setup_seconds = 0;
  std::size_t boundary_held = 0;
  // the automatic tensor's result is compared with the isotropic one's at the same discrepancy
  // (Tensor_selection.h): when both stop at the noise level
  const bool select_tensor = automatic && is_automatic_tensor(tensor) && mode != Attribute_mode::ATTRIBUTES_ONLY &&
                             s.stopping.noise_discrepancy > 0;
  const Control_matrix input = X;
  // the control points of the result, for the caller's control_point_map
  auto control_map = get_parameter(np, internal_np::control_point_map);
  auto attribute_control_map = get_parameter(np, internal_np::attribute_control_map);
  constexpr bool wants_control = !parameters::is_default_parameter<NamedParameters, internal_np::control_point_map_t>::value ||
                                 !parameters::is_default_parameter<NamedParameters, internal_np::attribute_control_map_t>::value;
  Control_matrix control_points;
  // number_of_iterations bounds the steps of the whole call, the comparison's runs included; the
  // callback learns which run a step belongs to
  std::size_t steps_left = s.maximum_steps, run_number = 0;
  // (the three flows and two probe runs; the uniform flow's probe rides along, not under a deviation bound)
  const bool bounded = s.maximum_deviation > 0 || s.attribute_maximum_deviation > 0;
  const std::size_t planned_runs = select_tensor ? (bounded ? 6 : 5) : 1;
  std::string run_name;
  auto counted_callback = [&](const Fairing_step& step) {
    Fairing_step tagged = step;
    tagged.run = run_number;
    tagged.runs = planned_runs;
    tagged.run_name = run_name;
    return callback(tagged);
  };
  // `fixed_steps` > 0: exactly that many steps, no stopping rule (a probe replaying a run: Smoother_selection.h)
  auto begin_run = [&](const char* name, int order, std::size_t fixed_steps) {
    run_name = name;
    ++run_number;
    Stepper_settings settings = with_order(s, order);
    settings.maximum_steps = steps_left;
    if(fixed_steps > 0)
    {
      settings.maximum_steps = (std::min)(steps_left, fixed_steps);
      settings.stopping = Stopping_criteria::none();
    }
    return settings;
  };
  // the risk estimate's normals (Tensor_selection.h): those of the input's prefiltered surface, which the
  // first run makes before its first step, so that every candidate's probe can ride along from the start
  Control_matrix estimate_normals, made_probe;
  const std::function<Control_matrix(const Control_matrix&)> make_probe = [&](const Control_matrix& surface) {
    estimate_normals = vertex_normals(*layer.topology, layer.real_faces, surface);
    made_probe = probed_input(input, estimate_normals, noise_sigma, risk_probe_values(n));
    return made_probe;
  };
  // the runs on one element's cache: the default run's first, then its comparison (Smoother_selection.h)
  const auto fair_with = [&](const auto& cache, bool loop) {
    // the written positions of control points Y of a run from `start`
    const auto limit_written = [&](Control_matrix& Y, const Control_matrix& start, double limit_weight) {
      const Control_matrix extended = layer.extend(Y);
      for(std::size_t i = 0; i < n; ++i)
        if(!isolated[i]) vertex_limit_value(*layer.topology, extended, int(i), Y.row(Eigen::Index(i)).data());
      if(limit_weight < 1) Y.leftCols(3) = start.leftCols(3) + limit_weight * (Y.leftCols(3) - start.leftCols(3));
    };
    // `probe`: a probed start carried along (Ride_along_probe.h; empty: made by make_probe), replaced by the
    // probe's written positions (empty when it could not ride along). The linear element writes its control
    // points: no limit surface to approach
    auto run = [&](const char* name, const auto& t, Control_matrix& Y, int order, const Control_matrix& start, Control_matrix* control,
                   std::size_t fixed_steps = 0, Control_matrix* probe = nullptr) {
      Y = start;
      double limit_weight = 1;
      const bool make = probe && probe->size() == 0;
      Control_matrix probe_start = probe && !make ? *probe : Control_matrix();
      Fairing_report r = run_stepper(cache, ordering, components, component_edge, mean_edge, Y, mode, constrained, border, t,
                                     begin_run(name, order, fixed_steps), counted_callback, setup_seconds, limit_weight,
                                     probe && !make ? &probe_start : nullptr, probe, make ? &make_probe : nullptr);
      if(make) probe_start = made_probe;
      steps_left -= (std::min)(steps_left, r.steps.size());
      if(!loop)
      {
        bound_written(Y, start, r);
        if(control) *control = Y;
        return r;
      }
      r.limit_weight = limit_weight;
      if(control) *control = Y;
      if(r.succeeded() && output == Output_positions::LIMIT_SURFACE)
      {
        limit_written(Y, start, limit_weight);
        if(probe && probe->size() > 0) limit_written(*probe, probe_start, limit_weight);
      }
      bound_written(Y, start, r);
      if(control && output == Output_positions::CONTROL_POINTS) *control = Y;   // as written, within the bounds
      return r;
    };
    Control_matrix anisotropic_probe;   // empty: made by the run itself (make_probe)
    report = run(select_tensor ? "anisotropic flow" : "", tensor, X, s.order, input, wants_control ? &control_points : nullptr, 0,
                 select_tensor ? &anisotropic_probe : nullptr);
    if(select_tensor)
      select_smoother(run, tensor, layer, input, noise_sigma, X, wants_control ? &control_points : nullptr, report, choices, steps_left,
                      estimate_normals, anisotropic_probe);
  };
  if(element == Finite_element::LOOP)
  {
    Ghosted_patch_cache cache(layer, spec);
    boundary_held = hold(boundary_constrained_vertices(layer, cache, boundary == Boundary_handling::HOLD_BOUNDARY_CURVE));
    setup_seconds = setup.time();
    fair_with(cache, true);
  }
  else
  {
    Linear_element_cache cache(*layer.topology, layer.real_faces);
    boundary_held = hold(border);
    setup_seconds = setup.time();
    fair_with(cache, false);
  }
  if(mode == Attribute_mode::COUPLED && A.cols() > 0) X.rightCols(A.cols()) /= attribute_weight;
  if(mode == Attribute_mode::COUPLED && A.cols() > 0 && report.status == Fairing_status::DEGENERATE_METRIC)
    report.message += "; in the coupled mode the surface is that of the points and the attributes times the attribute weight (" +
                      Indexed_mesh<TriangleMesh>::to_text(attribute_weight) + "): a weight that makes the attributes dwarf or "
                      "drown the coordinates leaves no surface, try a weight near 1 / (the attributes' range per edge length)";
  report.faces = im.number_of_faces();
  report.boundary_vertices = layer.boundary_vertices.size();
  report.boundary_held_vertices = boundary_held;
  report.boundary_loops = layer.boundary_loops;
  report.isolated_vertices = layer.isolated_vertices.size();
  report.attribute_mode = mode;
  report.attribute_dimension = std::size_t(A.cols());
  report.setup_seconds = setup_seconds;
  report.mean_edge_length = mean_edge;
  report.automatic_parameters = automatic;
  report.choices = choices;
  report.noise_level = noise.relative_sigma();
  report.removed_spikes = removed_spikes;
  report.noise_deviation = noise.relative_sigma() * report.mean_edge_length;

  if(report.succeeded())
  {
    write_back(im, ordering.old_of_new_vertex, X, mode, border, isolated, vcm, vpm, attributes);
    write_control_points(im, control_map, control_points, ordering.old_of_new_vertex);
    if(A.cols() > 0 && control_points.cols() == 3 + A.cols())
    {
      if(mode == Attribute_mode::COUPLED) control_points.rightCols(A.cols()) /= attribute_weight;
      write_attribute_controls(im, attributes, attribute_control_map, control_points, 3, ordering.old_of_new_vertex);
    }
  }
  report.total_seconds = total.time();
  return report;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FAIRING_DRIVER_H
