// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The run of anisotropic_fairing() once the mesh is read: from the ghost layer and the input's matrices
// to the result, with no mesh or map type left, so that it is compiled once per tensor type. In order:
// a cache-friendly numbering, the noise estimated from the mesh itself, the automatic choices, the runs on
// one element (the default run's comparison: Smoother_selection.h), and the result in the caller's numbering.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FAIRING_CORE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FAIRING_CORE_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/Uniform_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/internal/run/Automatic_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/run/Fairing_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/run/Smoother_selection.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Boundary_constraints.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Deviation_bound.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Isolated_spikes.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Noise_estimate.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Tensor_hooks.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Time_stepper.h>
#include <CGAL/Anisotropic_fairing/internal/element/Ghosted_patch_cache.h>
#include <CGAL/Anisotropic_fairing/internal/element/Linear_element_cache.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Vertex_limit_masks.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Locality_ordering.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Mesh_components.h>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

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

/// The flow whose time step follows the mesh's density with automatic parameters (Local_time_scale.h):
/// the isotropic or the uniform one; null for any other tensor.
template <typename Tensor>
const char* density_scaled_flow(const Tensor&)
{
  return std::is_same<Tensor, Isotropic_diffusion_tensor>::value ? "isotropic"
         : std::is_same<Tensor, Uniform_diffusion_tensor>::value ? "uniform" : nullptr;
}
template <typename... Tensors>
const char* density_scaled_flow(const std::variant<Tensors...>& t)
{
  return std::visit([](const auto& held) { return density_scaled_flow(held); }, t);
}

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
  settings.local_time_scale = s.local_time_scale && density_scaled_flow(tensor) != nullptr;
  Assembly_context numbering;
  numbering.original_vertex = &ordering.old_of_new_vertex;
  numbering.original_face = &ordering.old_of_new_face;
  numbering.border = &border;
  Time_stepper<Cache> stepper(cache, std::size_t(X.rows()), constrained, ordering.layer, components, component_edge, mean_edge,
                              numbering);
  const Tangential_motion_filter filter(ordering.layer);
  const bool normal_motion = wants_normal_motion(tensor) && mode != Attribute_mode::ATTRIBUTES_ONLY;
  if(normal_motion) stepper.set_tangential_filter(&filter);
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

/// What the default run chose from the mesh: the start of the report's `choices`. `tensor_chosen`: the
/// anisotropic tensor's threshold and prefilter were chosen; `scaled_flow`: the flow whose time step
/// follows the mesh's density, if any. The target is that of `s` (its strength named when not 1).
inline std::string automatic_choices(const Noise_estimate& noise, const Stepper_settings& s, bool tensor_chosen,
                                     std::size_t removed_spikes, std::size_t n, const char* scaled_flow)
{
  const Automatic_parameters a;
  char text[400];
  char scaled[80] = "";
  if(s.strength != 1) std::snprintf(scaled, sizeof scaled, " (strength %.6g)", s.strength);
  std::snprintf(text, sizeof text, "noise %.3g h (robust estimate over %zu vertices); time step %.3g h^%d per step until the surface "
                "has moved by %.3g x the noise%s%s", noise.relative_sigma(), noise.number_of_samples(), s.time_step, s.order,
                s.stopping.noise_discrepancy * s.strength, scaled, tensor_chosen ? "" : "; the tensor given");
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

/// What a run starts from: the mesh as a ghost layer and the input's matrices, in the caller's numbering.
struct Fairing_input
{
  const Ghost_layer& layer;            // read by the constructor only
  const Control_matrix& points;        // n x 3, read by the constructor only
  const Control_matrix& attributes;    // n x d, in their own units (d = 0: none faired)
  const std::vector<bool>& held;       // the caller's constrained vertices
  bool wants_control = false;          // the control values of the result are asked for
};

/// What a run gives back, in the caller's numbering.
struct Fairing_result
{
  Fairing_report report;
  Control_matrix values;           // the written positions and attribute values (these in their own units)
  Control_matrix control_values;   // the result's control points and attribute values (empty unless asked for)
  std::vector<bool> kept;          // the rows not to write: boundary, isolated and held vertices
};

/// One run of anisotropic_fairing() on matrices (see the top of this file); `Tensor`: a package tensor
/// chosen at run time (Package_diffusion_tensor) or a tensor type of the caller's own.
template <typename Tensor>
class Fairing_core
{
public:
  Fairing_core(const Fairing_input& in, const Fairing_parameters& given, const Tensor& tensor,
               const std::function<bool(const Fairing_step&)>& callback)
    : in_(in), given_(given), s_(given.settings), tensor_(tensor), callback_(callback), n_(std::size_t(in.points.rows())),
      setup_(started_timer()), ordering_(make_locality_ordering(in.layer)), layer_(ordering_.layer)
  {
    number_rows();   // after this, the run reads neither in.layer nor in.points
  }

  Fairing_result run()
  {
    estimate_noise();
    choose_automatically();
    if(given_.element == Finite_element::LOOP)
    {
      Ghosted_patch_cache cache(layer_, given_.quadrature);
      boundary_held_ = hold(boundary_constrained_vertices(layer_, cache, given_.boundary == Boundary_handling::HOLD_BOUNDARY_CURVE));
      setup_seconds_ = setup_.time();
      fair_with(cache, true);
    }
    else
    {
      Linear_element_cache cache(*layer_.topology, layer_.real_faces);
      boundary_held_ = hold(border_);
      setup_seconds_ = setup_.time();
      fair_with(cache, false);
    }
    return finish();
  }

private:
  static CGAL::Real_timer started_timer()
  {
    CGAL::Real_timer t;
    t.start();
    return t;
  }
  bool coupled() const { return given_.mode == Attribute_mode::COUPLED; }
  double attribute_scale() const { return coupled() ? given_.attribute_weight : 1.0; }

  // the solver works in a private, cache-friendly numbering (row i of X is vertex old_of_new_vertex[i])
  void number_rows()
  {
    const Eigen::Index d = in_.attributes.cols();
    X_.resize(Eigen::Index(n_), 3 + d);
    constrained_.assign(n_, false);
    border_.assign(n_, false);
    isolated_.assign(n_, false);
    for(std::size_t i = 0; i < n_; ++i)
    {
      const Eigen::Index old = ordering_.old_of_new_vertex[i];
      X_.row(Eigen::Index(i)).head(3) = in_.points.row(old);
      // coupled: attributes measured in lengths, so that they shape the manifold in R^(3+d)
      if(d > 0) X_.row(Eigen::Index(i)).tail(d) = attribute_scale() * in_.attributes.row(old);
      constrained_[i] = in_.held[std::size_t(old)];
    }
    for(int v : layer_.boundary_vertices) border_[std::size_t(v)] = true;
    // on no surface: nothing to fair
    for(int v : layer_.isolated_vertices) isolated_[std::size_t(v)] = constrained_[std::size_t(v)] = true;
    // the rows written back: the user's constrained, boundary and isolated vertices keep their values
    written_.resize(n_);
    for(std::size_t i = 0; i < n_; ++i) written_[i] = !constrained_[i] && !border_[i];
    // a bound on the attributes, in the units the stepper holds them in
    s_.attribute_maximum_deviation *= attribute_scale();
  }

  // the units of relative parameters, per connected component; the noise, from the mesh itself
  void estimate_noise()
  {
    components_ = make_mesh_components(*layer_.topology, n_, layer_.real_faces);
    mean_edge_ = component_mean_edges(*layer_.topology, layer_.real_faces, components_, X_, component_edge_);
    std::vector<bool> sampled(n_);
    for(std::size_t i = 0; i < n_; ++i) sampled[i] = !constrained_[i] && !border_[i];
    // impulsive noise: with the automatic stopping rule, isolated spikes go back to their rings' centroids
    // before the noise is estimated (Isolated_spikes.h); a bound on the motion leaves them as they are
    removed_spikes_ = given_.automatic && given_.mode != Attribute_mode::ATTRIBUTES_ONLY && s_.stopping.noise_discrepancy > 0 &&
                      !(s_.maximum_deviation > 0) ? remove_isolated_spikes(*layer_.topology, sampled, X_) : 0;
    noise_.reset(new Noise_estimate(*layer_.topology, X_, sampled));
    s_.noise = noise_.get();
    noise_sigma_.assign(n_, 0.0);   // the noise's deviation at each vertex, in model units
    for(std::size_t i = 0; i < n_; ++i)
      if(components_.of_vertex[i] >= 0) noise_sigma_[i] = noise_->relative_sigma() * component_edge_[std::size_t(components_.of_vertex[i])];
  }

  void choose_automatically()
  {
    // the noise stop measures the limit surface, the surface faired, whichever positions are written: a
    // run that writes control points (the tool does, to give exact limit normals) then stops where the
    // limit-surface run stops, and `limit_weight` says how far toward the limit points the latter writes
    const bool loop = given_.element == Finite_element::LOOP, limit = given_.output == Output_positions::LIMIT_SURFACE;
    s_.limit_written = loop && limit;
    s_.measure_limit_surface = loop && (limit || s_.stopping.noise_discrepancy > 0);
    if(given_.automatic)
    {
      const Automatic_parameters a;
      s_.time_step = s_.order == 4 ? a.time_step4 : a.time_step;
      s_.local_time_scale = true;
      const bool tensor_chosen = is_automatic_tensor(tensor_);
      if(tensor_chosen) choose_tensor(tensor_, a.lambda, a.epsilon);
      const char* scaled_flow = given_.mode == Attribute_mode::ATTRIBUTES_ONLY ? nullptr
                                : tensor_chosen ? "isotropic" : density_scaled_flow(tensor_);
      // the comparison of flows runs at the noise level itself, the strength's run after it (fair_with)
      if(compares_flows()) s_.strength = 1;
      choices_ = automatic_choices(*noise_, s_, tensor_chosen, removed_spikes_, n_, scaled_flow);
    }
    // the automatic tensor's result is compared with the isotropic one's at the same discrepancy
    // (Tensor_selection.h): when both stop at the noise level
    select_tensor_ = compares_flows();
  }

  // the default run compares the anisotropic, the isotropic and the uniform fourth-order flow
  bool compares_flows() const
  {
    return given_.automatic && is_automatic_tensor(tensor_) && given_.mode != Attribute_mode::ATTRIBUTES_ONLY &&
           s_.stopping.noise_discrepancy > 0;
  }

  // what the borders hold: the boundary vertices, and the influence set of the limit boundary curve
  std::size_t hold(const std::vector<bool>& held)
  {
    std::size_t count = 0;
    for(std::size_t i = 0; i < n_; ++i)
    {
      count += held[i] ? 1 : 0;
      constrained_[i] = constrained_[i] || held[i];
    }
    return count;
  }

  // the runs on one element's cache: the default run's first, then its comparison (Smoother_selection.h)
  template <typename Cache>
  void fair_with(const Cache& cache, bool loop)
  {
    input_ = X_;
    steps_left_ = s_.maximum_steps;
    // (the three flows and two probe runs; the uniform flow's probe rides along, not under a deviation bound)
    const bool bounded = s_.maximum_deviation > 0 || s_.attribute_maximum_deviation > 0;
    planned_runs_ = (select_tensor_ ? (bounded ? 6 : 5) : 1) + (strength_run() ? 1 : 0);
    auto run = [&](const char* name, const auto& t, Control_matrix& Y, int order, const Control_matrix& start, Control_matrix* control,
                   std::size_t fixed_steps = 0, Control_matrix* probe = nullptr) {
      return run_flow(cache, loop, name, t, Y, order, start, control, fixed_steps, probe);
    };
    Control_matrix* control = in_.wants_control ? &control_points_ : nullptr;
    Control_matrix anisotropic_probe;   // empty: made by the run itself (make_probe)
    report_ = run(select_tensor_ ? "anisotropic flow" : "", tensor_, X_, s_.order, input_, control, 0,
                  select_tensor_ ? &anisotropic_probe : nullptr);
    if(select_tensor_)
      select_smoother(run, tensor_, layer_, input_, noise_sigma_, X_, control, report_, choices_, steps_left_, estimate_normals_,
                      anisotropic_probe);
    if(strength_run()) run_kept_flow_to_strength(run, control);
  }

  // The default run with a strength S other than 1. Its flows are compared at the noise level itself, where
  // the risk estimate measures what it is made for, the error of a denoised surface (sigma is the noise's,
  // whatever the target); then the flow kept runs again from the input, to S times the noise, and the run
  // keeps the flow the default run keeps. Running every candidate to S times the noise and comparing there
  // lost the creases of the Block CAD pair at S = 2: its anisotropic flow cannot reach twice the noise without
  // folding (it ends at 0.59 of 0.70 h, step_rejected), a candidate that stops early is not preferred, and the
  // isotropic result was kept, 21.4 degrees of mean face-normal error against 7.95 for the anisotropic one.
  // (On the Julius face it kept the anisotropic result, 10.8 degrees against the uniform flow's 11.9; on the
  // Fandisk pair the same as here.)
  bool strength_run() const { return select_tensor_ && given_.settings.strength != 1; }

  template <typename Run>
  void run_kept_flow_to_strength(Run& run, Control_matrix* control)
  {
    const double strength = given_.settings.strength;
    char text[160];
    if(!report_.succeeded() || report_.stop_reason == Stop_reason::CALLBACK || steps_left_ == 0)
    {
      std::snprintf(text, sizeof text, "; strength %.6g not applied (%s)", strength,
                    !report_.succeeded() ? "no flow succeeded" : steps_left_ == 0 ? "the step budget is spent" : "the callback ended the run");
      choices_ += text;
      return;
    }
    s_.strength = strength;
    const std::string kept = report_.selected_tensor;
    std::snprintf(text, sizeof text, "%s flow at strength %.6g", kept == "uniform" ? "uniform fourth-order" : kept.c_str(), strength);
    const std::string name = text;
    Control_matrix Y, Z;
    Control_matrix* Zp = control ? &Z : nullptr;
    const Fairing_report r = kept == "isotropic" ? run(name.c_str(), Isotropic_diffusion_tensor(), Y, 2, input_, Zp)
                             : kept == "uniform" ? run(name.c_str(), Uniform_diffusion_tensor(), Y, 4, input_, Zp)
                                                 : run(name.c_str(), tensor_, Y, report_.flow_order, input_, Zp);
    if(!r.succeeded())
    {
      // the result at the noise level stays; the report says why the strength's run was not kept
      std::snprintf(text, sizeof text, "; the %s failed (%s): the result at the noise level is kept", name.c_str(), to_string(r.status));
      choices_ += text;
      return;
    }
    X_.swap(Y);
    if(control) control->swap(Z);
    report_ = r;
    report_.selected_tensor = kept;
    std::snprintf(text, sizeof text, "; then that flow ran again from the input to %.3g x the noise (strength %.6g): %zu steps, %s",
                  s_.stopping.noise_discrepancy * strength, strength, r.steps.size(), to_string(r.stop_reason));
    choices_ += text;
  }

  // One flow from `start` into Y, with tensor `t`. `probe`: a probed start carried along (Ride_along_probe.h;
  // empty: made by make_probe), replaced by the probe's written positions (empty when it could not ride
  // along). The linear element writes its control points: no limit surface to approach
  template <typename Cache, typename T>
  Fairing_report run_flow(const Cache& cache, bool loop, const char* name, const T& t, Control_matrix& Y, int order,
                          const Control_matrix& start, Control_matrix* control, std::size_t fixed_steps, Control_matrix* probe)
  {
    Y = start;
    double limit_weight = 1;
    const bool make = probe && probe->size() == 0;
    Control_matrix probe_start;   // the probe's start, taken out of *probe, which receives its end
    if(probe && !make) probe_start.swap(*probe);
    const std::function<Control_matrix(const Control_matrix&)> make_probe = [this](const Control_matrix& surface) {
      return this->make_probe(surface);
    };
    auto tagged = [this](const Fairing_step& step) { return this->tagged_callback(step); };
    Fairing_report r = with_tensor(t, [&](const auto& held) {
      return run_stepper(cache, ordering_, components_, component_edge_, mean_edge_, Y, given_.mode, constrained_, border_, held,
                         begin_run(name, order, fixed_steps), tagged, setup_seconds_, limit_weight,
                         probe && !make ? &probe_start : nullptr, probe, make ? &make_probe : nullptr);
    });
    if(make) probe_start.swap(made_probe_);
    steps_left_ -= (std::min)(steps_left_, r.steps.size());
    if(!loop)
    {
      bound_written(Y, start, r);
      if(control) *control = Y;
      return r;
    }
    r.limit_weight = limit_weight;
    if(control) *control = Y;
    if(r.succeeded() && given_.output == Output_positions::LIMIT_SURFACE)
    {
      write_limit(Y, start, limit_weight);
      if(probe && probe->size() > 0) write_limit(*probe, probe_start, limit_weight);
    }
    bound_written(Y, start, r);
    if(control && given_.output == Output_positions::CONTROL_POINTS) *control = Y;   // as written, within the bounds
    return r;
  }

  // `fixed_steps` > 0: exactly that many steps, no stopping rule (a probe replaying a run: Smoother_selection.h);
  // number_of_iterations bounds the steps of the whole call, the comparison's runs included
  Stepper_settings begin_run(const char* name, int order, std::size_t fixed_steps)
  {
    run_name_ = name;
    ++run_number_;
    Stepper_settings settings = with_order(s_, order);
    // a strength above 1: the automatic fourth-order flow steps at the scale strength x h (Step_control.h)
    if(order == 4 && settings.time_unit == Length_unit::EDGE && settings.strength > 1)
      settings.time_step *= std::pow(fourth_order_scale(settings.strength), 4);
    settings.maximum_steps = steps_left_;
    if(fixed_steps > 0)
    {
      settings.maximum_steps = (std::min)(steps_left_, fixed_steps);
      settings.stopping = Stopping_criteria::none();
    }
    return settings;
  }

  // the callback learns which run a step belongs to
  bool tagged_callback(const Fairing_step& step) const
  {
    Fairing_step tagged = step;
    tagged.run = run_number_;
    tagged.runs = planned_runs_;
    tagged.run_name = run_name_;
    return callback_(tagged);
  }

  // the risk estimate's normals (Tensor_selection.h): those of the input's prefiltered surface, which the
  // first run makes before its first step, so that every candidate's probe can ride along from the start
  Control_matrix make_probe(const Control_matrix& surface)
  {
    estimate_normals_ = vertex_normals(*layer_.topology, layer_.real_faces, surface);
    made_probe_ = probed_input(input_, estimate_normals_, noise_sigma_, risk_probe_values(n_));
    return made_probe_;
  }

  // the written positions of control points Y of a run from `start`: their limit points, `limit_weight` of the way
  void write_limit(Control_matrix& Y, const Control_matrix& start, double limit_weight) const
  {
    Control_matrix limit;
    limit_points(layer_, Y, limit);
    Y = limit;
    if(limit_weight < 1) Y.leftCols(3) = start.leftCols(3) + limit_weight * (Y.leftCols(3) - start.leftCols(3));
  }

  // the bounds on what is written, once the run's result is: a vertex its fidelity could not hold goes on
  // the bound (Deviation_bound.h); the largest deviations written, in the user's units
  void bound_written(Control_matrix& Y, const Control_matrix& start, Fairing_report& r) const
  {
    if(!r.succeeded()) return;
    const auto bounds = user_bounds(Y.cols(), given_.mode != Attribute_mode::ATTRIBUTES_ONLY, 3, r.absolute_maximum_deviation,
                                    s_.attribute_maximum_deviation);
    const Column_bound& geometry = bounds[0];
    const Column_bound& values = bounds[1];
    std::vector<bool> moved(n_, false);
    clamp_to_bound(Y, start, geometry, written_, moved);
    clamp_to_bound(Y, start, values, written_, moved);
    r.clamped_vertices = std::size_t(std::count(moved.begin(), moved.end(), true));
    r.largest_deviation = largest_written_deviation(Y, start, geometry, written_);
    r.largest_attribute_deviation = largest_written_deviation(Y, start, values, written_) / attribute_scale();
    r.attribute_maximum_deviation = given_.settings.attribute_maximum_deviation;
  }

  // the report completed, and the result back in the caller's numbering and units
  Fairing_result finish()
  {
    Fairing_result out;
    Fairing_report& report = out.report = report_;
    const Eigen::Index d = in_.attributes.cols();
    report.boundary_vertices = layer_.boundary_vertices.size();
    report.boundary_held_vertices = boundary_held_;
    report.boundary_loops = layer_.boundary_loops;
    report.isolated_vertices = layer_.isolated_vertices.size();
    report.attribute_mode = given_.mode;
    report.attribute_dimension = std::size_t(d);
    report.setup_seconds = setup_seconds_;
    report.mean_edge_length = mean_edge_;
    report.automatic_parameters = given_.automatic;
    report.choices = choices_;
    report.noise_level = noise_->relative_sigma();
    report.strength = given_.settings.strength;
    report.removed_spikes = removed_spikes_;
    report.noise_deviation = noise_->relative_sigma() * report.mean_edge_length;
    if(d > 0) X_.rightCols(d) /= attribute_scale();
    if(d > 0 && control_points_.cols() == 3 + d) control_points_.rightCols(d) /= attribute_scale();
    const std::vector<int>& old_of_new = ordering_.old_of_new_vertex;
    out.values.resize(X_.rows(), X_.cols());
    out.control_values.resize(control_points_.rows(), control_points_.cols());
    out.kept.assign(n_, false);
    for(std::size_t i = 0; i < n_; ++i)
    {
      out.values.row(old_of_new[i]) = X_.row(Eigen::Index(i));
      if(control_points_.rows() > 0) out.control_values.row(old_of_new[i]) = control_points_.row(Eigen::Index(i));
      out.kept[std::size_t(old_of_new[i])] = border_[i] || isolated_[i] || in_.held[std::size_t(old_of_new[i])];
    }
    return out;
  }

  const Fairing_input& in_;
  const Fairing_parameters& given_;
  Stepper_settings s_;
  Tensor tensor_;
  const std::function<bool(const Fairing_step&)>& callback_;
  const std::size_t n_;
  CGAL::Real_timer setup_;   // from before the numbering to the element's cache
  const Locality_ordering ordering_;
  const Ghost_layer& layer_;
  Control_matrix X_, input_, control_points_, estimate_normals_, made_probe_;
  std::vector<bool> constrained_, border_, isolated_, written_;
  Mesh_components components_;
  std::vector<double> component_edge_, noise_sigma_;
  double mean_edge_ = 0;
  std::size_t removed_spikes_ = 0;
  std::unique_ptr<Noise_estimate> noise_;
  std::string choices_;
  bool select_tensor_ = false;
  Fairing_report report_;
  double setup_seconds_ = 0;
  std::size_t boundary_held_ = 0, steps_left_ = 0, run_number_ = 0, planned_runs_ = 1;
  std::string run_name_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FAIRING_CORE_H
