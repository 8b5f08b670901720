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
#include <CGAL/Anisotropic_fairing/internal/run/Automatic_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/run/Fairing_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/run/Run_log.h>
#include <CGAL/Anisotropic_fairing/internal/run/Normal_field_run.h>
#include <CGAL/Anisotropic_fairing/internal/run/Smoother_selection.h>
#include <CGAL/Anisotropic_fairing/internal/run/Stepper_call.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Boundary_constraints.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Deviation_bound.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Isolated_spikes.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Noise_estimate.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Noise_model.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Tensor_hooks.h>
#include <CGAL/Anisotropic_fairing/internal/element/Ghosted_patch_cache.h>
#include <CGAL/Anisotropic_fairing/internal/element/Linear_element_cache.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Vertex_limit_masks.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Locality_ordering.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Mesh_components.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Process_part.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Vertex_keys.h>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

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
/// chosen at run time (Package_diffusion_tensor) or a tensor type of the caller's own; `Elements`: where the
/// runs on the Loop element step (Stepper_call.h).
template <typename Tensor, typename Elements = Serial_elements>
class Fairing_core
{
public:
  Fairing_core(const Fairing_input& in, const Fairing_parameters& given, const Tensor& tensor,
               const std::function<bool(const Fairing_step&)>& callback, const Elements& elements = Elements())
    : in_(in), given_(given), s_(given.settings), tensor_(tensor), callback_(callback), elements_(elements),
      n_(std::size_t(in.points.rows())), setup_(started_timer()), ordering_(make_locality_ordering(in.layer)),
      layer_(ordering_.layer), part_(elements.part(), ordering_)
  {
    number_rows();   // after this, the run reads neither in.layer nor in.points
    mark_rows();
    scale_attribute_bound();
  }

  /// The choices from the mesh (units, spikes, noise, automatic parameters): before run() and the memory check
  void prepare()
  {
    measure_units();
    remove_spikes();
    estimate_noise();
    choose_measured_surface();
    choose_automatically();
  }
  /// The input's limit surface is off it by the noise already (Noise_level.h): the noise stop then ends every flow
  /// before its first step. X_ is the input until a run is kept.
  bool input_at_noise_level() const
  {
    Control_matrix Y = X_;
    if(s_.measure_limit_surface) limit_points(layer_, X_, Y);
    const double target = s_.stopping.noise_discrepancy * s_.strength * noise_->relative_sigma();
    return bool(Noise_level::before_first_step(Noise_level::at_start(*noise_, Y, X_), target));
  }

  Fairing_result run()
  {
    if(given_.element == Finite_element::LOOP)
    {
      const typename Elements::Loop_cache cache = elements_.loop_cache(layer_, given_.quadrature, part_);
      const bool curve = given_.boundary == Boundary_handling::HOLD_BOUNDARY_CURVE;
      boundary_held_ = hold(boundary_constrained_vertices(layer_, cache, curve));
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

  /// Benchmarks: every candidate of the default run once estimated, and the estimate (rows in the run's
  /// numbering: row i is the caller's vertex old_of_new[i]); the candidates chosen by `kind`, and with
  /// `normal_field` the normal-field candidate compared too (Normal_field_run.h).
  typedef std::function<void(const Candidate_list&, const Risk_estimate&, const std::vector<int>&)> Observer;
  void observe_candidates(Observer f, Risk_kind kind, bool normal_field)
  {
    observer_ = std::move(f);
    risk_kind_ = kind;
    normal_field_ = normal_field;
  }
  /// Benchmarks: the estimate measures on `surface` (the caller's numbering, e.g. the clean mesh: an oracle)
  /// instead of the anisotropic run's prefiltered input.
  void measure_on(const Control_matrix& surface)
  {
    oracle_surface_.resize(surface.rows(), surface.cols());
    for(std::size_t i = 0; i < n_; ++i)
      oracle_surface_.row(Eigen::Index(i)) = surface.row(ordering_.old_of_new_vertex[i]);
  }

private:
  // the runs on one element's cache, as the comparison asks for them
  template <typename Cache>
  class Element_runner
  {
  public:
    Element_runner(Fairing_core& core, const Cache& cache, bool loop) : core_(core), cache_(cache), loop_(loop) {}
    Flow_outcome run(const Flow_request& request)
    {
      return core_.log_.record(request.name, [&] { return core_.run_flow(cache_, loop_, request); });
    }
    std::size_t steps_left() const { return core_.steps_left_; }

  private:
    Fairing_core& core_;
    const Cache& cache_;
    bool loop_;
  };

  static CGAL::Real_timer started_timer() { CGAL::Real_timer t; t.start(); return t; }
  bool coupled() const { return given_.mode == Attribute_mode::COUPLED; }
  double attribute_scale() const { return coupled() ? given_.attribute_weight : 1.0; }

  // the solver works in a private, cache-friendly numbering (row i of X is vertex old_of_new_vertex[i])
  void number_rows()
  {
    const Eigen::Index d = in_.attributes.cols();
    X_.resize(Eigen::Index(n_), 3 + d);
    constrained_.assign(n_, false);
    for(std::size_t i = 0; i < n_; ++i)
    {
      const Eigen::Index old = ordering_.old_of_new_vertex[i];
      X_.row(Eigen::Index(i)).head(3) = in_.points.row(old);
      // coupled: attributes measured in lengths, so that they shape the manifold in R^(3+d)
      if(d > 0) X_.row(Eigen::Index(i)).tail(d) = attribute_scale() * in_.attributes.row(old);
      constrained_[i] = in_.held[std::size_t(old)];
    }
    keys_ = vertex_keys(layer_, X_);
  }

  // the layer's border and isolated rows; the rows written back: all but the user's held, border and isolated ones
  void mark_rows()
  {
    border_.assign(n_, false);
    isolated_.assign(n_, false);
    for(int v : layer_.boundary_vertices) border_[std::size_t(v)] = true;
    for(int v : layer_.isolated_vertices) isolated_[std::size_t(v)] = constrained_[std::size_t(v)] = true;   // no face
    written_.resize(n_);
    for(std::size_t i = 0; i < n_; ++i) written_[i] = !constrained_[i] && !border_[i];
  }

  // a bound on the attributes, in the units the stepper holds them in
  void scale_attribute_bound() { s_.attribute_maximum_deviation *= attribute_scale(); }

  // the units of relative parameters, per connected component
  void measure_units()
  {
    components_ = make_mesh_components(*layer_.topology, n_, layer_.real_faces, part_);
    mean_edge_ = component_mean_edges(*layer_.topology, layer_.real_faces, components_, X_, component_edge_, part_);
  }

  // the rows that sample the noise: neither held nor on the border
  std::vector<bool> sampled_rows() const
  {
    std::vector<bool> sampled(n_);
    for(std::size_t i = 0; i < n_; ++i) sampled[i] = !constrained_[i] && !border_[i];
    return sampled;
  }

  // impulsive noise: with the automatic stopping rule, isolated spikes go back to their rings' centroids
  // before the noise is estimated (Isolated_spikes.h); a bound on the motion leaves them as they are
  void remove_spikes()
  {
    const bool removes = given_.automatic && given_.mode != Attribute_mode::ATTRIBUTES_ONLY &&
                         s_.stopping.noise_discrepancy > 0 && !(s_.maximum_deviation > 0);
    removed_spikes_ = removes ? remove_isolated_spikes(*layer_.topology, sampled_rows(), X_, part_) : 0;
  }

  // the noise, from the mesh itself, and its deviation at each vertex in model units
  void estimate_noise()
  {
    noise_.reset(new Noise_estimate(*layer_.topology, X_, sampled_rows(), keys_, &part_));
    s_.noise = noise_.get();
    noise_sigma_.assign(n_, 0.0);
    for(std::size_t i = 0; i < n_; ++i)
      if(components_.of_vertex[i] >= 0)
        noise_sigma_[i] = noise_->relative_sigma() * component_edge_[std::size_t(components_.of_vertex[i])];
    // the risk estimate's probe, as correlated as the noise read (drawn at the ghosts too: border rings reach them)
    probe_values_ =
      correlated_like(*layer_.topology, risk_probe_values(keys_.size(), keys_), n_, noise_->correlation(), part_);
  }

  // the noise stop measures the limit surface, the surface faired, whichever positions are written: a
  // run that writes control points (the tool does, to give exact limit normals) then stops where the
  // limit-surface run stops, and `limit_weight` says how far toward the limit points the latter writes
  void choose_measured_surface()
  {
    const bool loop = given_.element == Finite_element::LOOP, limit = given_.output == Output_positions::LIMIT_SURFACE;
    s_.limit_written = loop && limit;
    s_.measure_limit_surface = loop && (limit || s_.stopping.noise_discrepancy > 0);
  }

  void choose_automatically()
  {
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
      const std::size_t vertices = whole_count(std::vector<bool>(n_, true), n_, part_);
      choices_ = automatic_choices(*noise_, s_, tensor_chosen, removed_spikes_, vertices, scaled_flow);
      if(given_.mode != Attribute_mode::ATTRIBUTES_ONLY)
      {
        noise_model_ = estimate_noise_model(*layer_.topology, X_, sampled_rows(), *noise_, mean_edge_, part_);
        choices_ += "; " + noise_model_.description() + "; " + noise_->correlation().description();
      }
    }
    // the automatic tensor's result is compared with the other flows' at the same discrepancy
    // (Tensor_selection.h): when both stop at the noise level
    select_tensor_ = compares_flows();
  }

  bool compares_flows() const { return internal::compares_flows(given_, tensor_); }

  // a bound on the motion: no probe rides along (Ride_along_probe.h)
  bool bounded() const { return s_.maximum_deviation > 0 || s_.attribute_maximum_deviation > 0; }

  // what the borders hold: the boundary vertices, and the influence set of the limit boundary curve
  std::size_t hold(const std::vector<bool>& held)
  {
    for(std::size_t i = 0; i < n_; ++i) constrained_[i] = constrained_[i] || held[i];
    return whole_count(held, n_, part_);
  }

  // the runs on one element's cache: the run's own flow, then the default run's comparison and strength
  template <typename Cache>
  void fair_with(const Cache& cache, bool loop)
  {
    input_ = X_;
    steps_left_ = s_.maximum_steps;
    Candidate_list candidates = default_candidates(s_.order, normal_field_);
    planned_runs_ = (select_tensor_ ? planned_runs(candidates, bounded()) : 1) + (strength_run() ? 1 : 0);
    Element_runner<Cache> runner(*this, cache, loop);
    if(!select_tensor_)
    {
      keep(runner.run(Flow_request{ Flow_settings{ Candidate_tensor::RUN_TENSOR, s_.order }, "", input_ }));
      return;
    }
    Smoother_choice choice = compare_flows(std::move(candidates), runner, cache);
    choices_ += choice.choices;
    for(const auto& e : choice.estimates) log_.estimated(e.first, e.second);
    keep(std::move(choice.kept.result));
    if(strength_run()) run_kept_flow_to_strength(runner, choice.kept);
  }

  // The estimate's surface first, the input's M_eps as the run's own flow reads it, so that every candidate
  // carries its probe from its start and the own flow, the costliest, runs last, where it can be dropped; with
  // a step budget of the user's, first, as the budget's first claim. An input at the noise level already: the
  // own flow alone (every flow stops before its first step).
  template <typename Runner, typename Cache>
  Smoother_choice compare_flows(Candidate_list candidates, Runner& runner, const Cache& cache)
  {
    const std::size_t own = own_candidate(candidates);
    if(input_at_noise_level())
    {
      candidates[own].result = runner.run(Flow_request{ candidates[own].settings, candidates[own].flow, input_ });
      candidates[own].made = true;
    }
    else estimate_surface_ = oracle_surface_.size() > 0 ? oracle_surface_ : prefiltered_input(cache);
    if(given_.steps_given) std::rotate(candidates.begin(), candidates.begin() + own, candidates.begin() + own + 1);
    Selection_context context{ layer_, input_, noise_sigma_, probe_values_, estimate_surface_, &part_ };
    context.kind = risk_kind_;
    context.model = noise_model_.normal_scale.empty() ? nullptr : &noise_model_;
    if(observer_)
      context.observe = [this](const Candidate_list& c, const Risk_estimate& e) {
        observer_(c, e, ordering_.old_of_new_vertex);
      };
    return select_smoother(std::move(candidates), context, runner);
  }

  // the input's M_eps, read by the run's own tensor (empty: it reads none)
  template <typename Cache>
  Control_matrix prefiltered_input(const Cache& cache) const
  {
    const Stepper_settings settings = with_order(s_, s_.order);
    return with_tensor(tensor_,
                       [&](const auto& t) { return prefiltered_start(flow_context(cache), t, settings, input_); });
  }

  void keep(Flow_outcome&& outcome)
  {
    log_.kept(outcome.run);
    X_ = std::move(outcome.Y);
    control_points_ = std::move(outcome.Z);
    report_ = std::move(outcome.report);
  }

  // A strength S other than 1: the flows are compared at the noise level, where the risk estimate measures
  // what it is made for, and the flow kept runs again to S times the noise. Compared at S times the noise,
  // a flow that cannot get there without folding stops early and loses its creases to a smoother one.
  bool strength_run() const { return select_tensor_ && given_.settings.strength != 1; }

  template <typename Runner>
  void run_kept_flow_to_strength(Runner& runner, const Flow_candidate& kept)
  {
    const double strength = given_.settings.strength;
    char text[160];
    const bool field = kept.settings.stage == Candidate_stage::NORMAL_FIELD;
    if(!report_.succeeded() || report_.stop_reason == Stop_reason::CALLBACK || steps_left_ == 0 || field)
    {
      std::snprintf(text, sizeof text, "; strength %.6g not applied (%s)", strength,
                    !report_.succeeded() ? "no flow succeeded"
                    : steps_left_ == 0   ? "the step budget is spent"
                    : field              ? "the normal field kept stops at its lowest estimated error, not at the noise"
                                         : "the callback ended the run");
      choices_ += text;
      return;
    }
    s_.strength = strength;
    std::snprintf(text, sizeof text, "%s flow at strength %.6g", kept.label, strength);
    const std::string name = text;
    Flow_outcome r = runner.run(Flow_request{ kept.settings, name, input_ });
    if(!r.report.succeeded())
    {
      // the result at the noise level stays; the report says why the strength's run was not kept
      std::snprintf(text, sizeof text, "; the %s failed (%s): the result at the noise level is kept", name.c_str(),
                    to_string(r.report.status));
      choices_ += text;
      return;
    }
    keep(std::move(r));
    report_.selected_tensor = kept.name;
    std::snprintf(text, sizeof text, "; then that flow ran again from the input to %.3g x the noise (strength %.6g): "
                  "%zu steps, %s", s_.stopping.noise_discrepancy * strength, strength, report_.steps.size(),
                  to_string(report_.stop_reason));
    choices_ += text;
  }

  template <typename Cache>
  Flow_context<Cache> flow_context(const Cache& cache) const
  {
    return { cache, ordering_, components_, component_edge_, mean_edge_, given_.mode, constrained_, border_ };
  }

  // One flow as `request` asks, on the given element's cache; the step budget pays for its steps.
  template <typename Cache>
  Flow_outcome run_flow(const Cache& cache, bool loop, const Flow_request& request)
  {
    if(request.flow.stage == Candidate_stage::NORMAL_FIELD) return run_normal_field_candidate(request);
    if(request.replay) return replay_flow(cache, loop, request);
    Probe_plan probe;
    probe.start = request.probe_start;
    const bool limit = loop && given_.output == Output_positions::LIMIT_SURFACE;
    if(request.keep_going) probe.keep_going = limit ? on_limit_points(request.keep_going, layer_) : request.keep_going;
    auto tagged = [this](const Fairing_step& step) { return this->tagged_callback(step); };
    const Stepper_settings settings = begin_run(request.name, request.flow.order, request.fixed_steps);
    const Flow_context<Cache> context = flow_context(cache);
    Stepper_outcome o = with_candidate_tensor(request.flow.tensor, tensor_, [&](const auto& t) {
      return with_tensor(t, [&](const auto& held) {
        return run_stepper(context, held, settings, request.start, probe, tagged);
      });
    });
    setup_seconds_ += o.setup_seconds;
    steps_left_ -= (std::min)(steps_left_, o.report.steps.size());
    return written_outcome(std::move(o), request, loop);
  }

  // a run's probe replaying its steps on an operator of its own (Probe_flow.h), written as the run is
  template <typename Cache>
  Flow_outcome replay_flow(const Cache& cache, bool loop, const Flow_request& request)
  {
    const Stepper_settings settings = begin_run(request.name, request.flow.order, 0);
    Stepper_outcome o = with_candidate_tensor(request.flow.tensor, tensor_, [&](const auto& t) {
      return with_tensor(t, [&](const auto& held) {
        return replayed_probe(flow_context(cache), held, settings, request.start, *request.replay);
      });
    });
    return written_outcome(std::move(o), request, loop);
  }

  // The normal field's passes (Normal_field_run.h): it writes its vertices, which are their own control points
  Flow_outcome run_normal_field_candidate(const Flow_request& request)
  {
    const std::size_t fixed = request.fixed_steps;
    begin_run(request.name, 2, fixed);
    auto tagged = [this](const Fairing_step& step) { return this->tagged_callback(step); };
    const Normal_field_context context{ layer_, written_, components_.of_face, component_edge_, steps_left_, tagged };
    Flow_outcome out = run_normal_field(request, context);
    steps_left_ -= (std::min)(steps_left_, out.report.steps.size());
    if(in_.wants_control && request.may_be_kept) out.Z = out.Y;
    bound_written(out.Y, request.start, out.report);
    return out;
  }

  // What a run writes: with the Loop element its limit points, `limit_weight` of the way (and its probe's,
  // which is written as the run is), within the bounds. The linear element writes its control points.
  Flow_outcome written_outcome(Stepper_outcome&& o, const Flow_request& request, bool loop) const
  {
    Flow_outcome out;
    out.report = std::move(o.report);
    out.Y = std::move(o.Y);
    out.probe = std::move(o.probe);
    out.schedule = std::move(o.schedule);
    const bool control = in_.wants_control && request.may_be_kept;
    const Control_matrix& start = request.start;
    if(loop) out.report.limit_weight = o.limit_weight;
    if(control && loop) out.Z = out.Y;
    if(loop && out.report.succeeded() && given_.output == Output_positions::LIMIT_SURFACE)
    {
      write_limit(out.Y, start, o.limit_weight);
      if(out.probe.size() > 0) write_limit(out.probe, *request.probe_start, o.limit_weight);
    }
    bound_written(out.Y, start, out.report);
    // the linear element's control points are its written positions; the Loop element's, when written
    if(control && (!loop || given_.output == Output_positions::CONTROL_POINTS)) out.Z = out.Y;
    return out;
  }

  // `fixed_steps` > 0: exactly that many steps, no stopping rule (a probe replaying a run: Smoother_selection.h);
  // number_of_iterations bounds the steps of the whole call, the comparison's runs included
  Stepper_settings begin_run(const std::string& name, int order, std::size_t fixed_steps)
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
    const bool moves_geometry = given_.mode != Attribute_mode::ATTRIBUTES_ONLY;
    const auto bounds = user_bounds(Y.cols(), moves_geometry, 3, r.absolute_maximum_deviation,
                                    s_.attribute_maximum_deviation);
    const Column_bound &geometry = bounds[0], &values = bounds[1];
    std::vector<bool> moved(n_, false);
    const std::vector<bool> own_written = part_.own(written_);
    clamp_to_bound(Y, start, geometry, written_, moved);
    clamp_to_bound(Y, start, values, written_, moved);
    r.clamped_vertices = whole_count(moved, n_, part_);
    r.largest_deviation = part_.maximum(largest_written_deviation(Y, start, geometry, own_written));
    r.largest_attribute_deviation =
      part_.maximum(largest_written_deviation(Y, start, values, own_written)) / attribute_scale();
    r.attribute_maximum_deviation = given_.settings.attribute_maximum_deviation;
  }

  // the report completed, and the result back in the caller's numbering and units
  Fairing_result finish()
  {
    Fairing_result out;
    Fairing_report& report = out.report = report_;
    const Eigen::Index d = in_.attributes.cols();
    report.boundary_vertices = whole_count(layer_.boundary_vertices, part_);
    report.boundary_held_vertices = boundary_held_;
    report.boundary_loops = whole_boundary_loops(layer_, part_);
    report.isolated_vertices = whole_count(layer_.isolated_vertices, part_);
    report.faces = whole_face_count(layer_.real_faces, part_);
    report.attribute_mode = given_.mode;
    report.attribute_dimension = std::size_t(d);
    report.setup_seconds = setup_seconds_;
    report.mean_edge_length = mean_edge_;
    report.automatic_parameters = given_.automatic;
    report.choices = choices_;
    report.runs = log_.runs();
    report.strength = given_.settings.strength;
    report.removed_spikes = removed_spikes_;
    report_noise(*noise_, noise_model_, report);
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
  const Elements elements_;
  const std::size_t n_;
  CGAL::Real_timer setup_;   // from before the numbering to the element's cache
  const Locality_ordering ordering_;
  const Ghost_layer& layer_;
  const Part_view part_;   // of the mesh this process holds (none: the whole mesh)
  Control_matrix X_, input_, control_points_, estimate_surface_, oracle_surface_;
  std::vector<bool> constrained_, border_, isolated_, written_;
  Mesh_components components_;
  std::vector<double> component_edge_, noise_sigma_, probe_values_;
  std::vector<std::uint64_t> keys_;   // each vertex's, which its random numbers are drawn by (Vertex_keys.h)
  double mean_edge_ = 0;
  std::size_t removed_spikes_ = 0;
  std::unique_ptr<Noise_estimate> noise_;
  Noise_model noise_model_;   // with automatic parameters
  std::string choices_;
  Run_log log_;
  bool select_tensor_ = false;
  Fairing_report report_;
  double setup_seconds_ = 0;
  std::size_t boundary_held_ = 0, steps_left_ = 0, run_number_ = 0, planned_runs_ = 1;
  std::string run_name_;
  Observer observer_;
  bool normal_field_ = false;
  Risk_kind risk_kind_ = Risk_kind::POSITIONS;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_FAIRING_CORE_H
