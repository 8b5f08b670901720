// The JSON report of anisotropic_fairing (see json_report.h), built with nlohmann-json: numbers in the
// shortest form that reads back to the same double.
#include "json_report.h"
#include "option_words.h"

#include <nlohmann/json.hpp>

#include <sys/resource.h>

#include <cmath>
#include <fstream>
#include <string>
#include <variant>

namespace af_tool {

namespace {

typedef nlohmann::ordered_json Json;

// a value the run knows, or null
template <typename T>
Json known(bool is_known, const T& value) { return is_known ? Json(value) : Json(nullptr); }

// a number; null when it is not finite
Json number(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

const char* element_name(AF::Finite_element e) { return e == AF::Finite_element::LOOP ? "loop" : "linear"; }
const char* output_name(AF::Output_positions p)
{
  return p == AF::Output_positions::LIMIT_SURFACE ? "limit" : "control";
}
const char* solver_name(AF::Linear_solver s)
{
  return s == AF::Linear_solver::AUTOMATIC ? "auto" : s == AF::Linear_solver::CHOLESKY ? "cholesky" : "cg";
}

// what was read, and what was changed in it for the run
void add_input(Json& j, const Options& o, const Run_record& r)
{
  j["status"] = r.status;
  j["message"] = r.message;
  j["input"] = known(!o.input.empty(), o.input);
  j["output"] = known(r.output_written, o.output);
  j["vertices"] = known(r.mesh_read, r.vertices);
  j["faces"] = known(r.mesh_read, r.faces);
  j["input_changes"] = r.input_changes;
  j["split_vertices"] = known(r.mesh_read, r.split_vertices);
  j["triangulated_faces"] = known(r.mesh_read, r.triangulated_faces);
}

// The tensor the run used: with automatic parameters the package keeps the anisotropic, the isotropic or
// the uniform result (selected_tensor). Its values as the run used them (chosen from the mesh when
// automatic), in units of l, l^2 and 1/length.
void add_tensor(Json& j, const Options& o, const Run_record& r)
{
  const AF::Fairing_report& f = r.report;
  const bool ran = r.fairing_ran;
  const AF::Fairing_options& given = o.fairing;
  j["element"] = element_name(given.finite_element);
  j["output_positions"] = output_name(given.output_positions);
  const AF::Package_diffusion_tensor start = given.diffusion_tensor_or_default();
  const auto* anisotropic = std::get_if<AF::Anisotropic_diffusion_tensor>(&start);
  const bool isotropic_kept = ran && (f.selected_tensor == "isotropic" || f.selected_tensor == "uniform");
  j["tensor"] = std::holds_alternative<AF::Uniform_diffusion_tensor>(start) || (ran && f.selected_tensor == "uniform")
                  ? "uniform"
                : anisotropic && !isotropic_kept ? "anisotropic" : "isotropic";
  const bool chosen = automatic_tensor(given);
  const bool lambda_known = anisotropic && !isotropic_kept && (!chosen || ran);
  j["lambda"] = lambda_known ? number(chosen ? f.feature_threshold * f.scale : anisotropic->lambda()) : Json(nullptr);
  j["lambda_model_units"] = lambda_known && ran && f.scale > 0 ? number(f.feature_threshold) : Json(nullptr);
  j["epsilon"] = lambda_known ? number(chosen ? f.prefilter_time / (f.scale * f.scale) : anisotropic->epsilon())
                              : Json(nullptr);
  j["tangential_motion"] = anisotropic && !isotropic_kept && anisotropic->normal_motion_only() ? "removed" : "kept";
}

// the solver, the stop and the time step, as the run used them or else as given
void add_stepping(Json& j, const Options& o, const Run_record& r)
{
  const AF::Fairing_report& f = r.report;
  const bool ran = r.fairing_ran;
  const double scale2 = f.scale * f.scale;
  const AF::Fairing_options& given = o.fairing;
  j["solver"] = ran ? Json(f.used_cholesky ? "cholesky" : "cg") : Json(nullptr);
  j["requested_solver"] = solver_name(given.linear_solver);
  j["stop"] = o.stop;
  j["strength"] = number(given.strength);   // the factor of the noise stop's target (--strength)
  j["max_steps"] = given.maximum_steps();
  j["quadrature_degree"] = given.quadrature_degree;
  j["time_step"] = ran ? number(f.time_step) : given.time_step ? number(*given.time_step) : Json(nullptr);
  j["order"] = ran ? f.flow_order : given.flow_order;
  j["relative_time_step"] = ran && scale2 > 0 ? number(f.time_step / std::pow(scale2, f.flow_order / 2))
                            : given.relative_time_step ? number(*given.relative_time_step) : Json(nullptr);
  j["scale"] = ran ? number(f.scale) : Json(nullptr);
  j["fidelity_weight"] = ran ? number(f.fidelity_weight)
                         : given.fidelity_weight ? number(*given.fidelity_weight) : Json(nullptr);
  j["relative_fidelity_weight"] = ran ? number(f.fidelity_weight * scale2)
                                  : given.relative_fidelity_weight ? number(*given.relative_fidelity_weight)
                                                                   : Json(nullptr);
  j["mean_edge_length"] = ran ? number(f.mean_edge_length) : Json(nullptr);
}

// what was written besides the positions, the attributes, and the vertices held
void add_written(Json& j, const Options& o, const Run_record& r)
{
  const AF::Fairing_report& f = r.report;
  const bool ran = r.fairing_ran;
  const AF::Fairing_options& given = o.fairing;
  j["normals"] = r.normals;
  j["curvature"] = r.curvature;
  j["hold"] = o.hold.empty() ? Json(nullptr) : Json(o.hold);
  j["held_vertices"] = r.held_vertices;
  j["resample"] = o.has_resample ? Json(o.resample) : Json(nullptr);
  j["resampled_vertices"] = o.has_resample && r.resampled_faces > 0 ? Json(r.resampled_vertices) : Json(nullptr);
  j["resampled_faces"] = o.has_resample && r.resampled_faces > 0 ? Json(r.resampled_faces) : Json(nullptr);
  j["snapshot"] = o.snapshot.empty() ? Json(nullptr) : Json(o.snapshot);
  j["mode"] = mode_name(effective_mode(o));
  j["attributes"] = o.attributes;
  j["attribute_dimension"] = known(ran, f.attribute_dimension);
  j["attribute_weight"] = number(given.attribute_weight);
  j["boundary_handling"] =
      given.boundary_handling == AF::Boundary_handling::HOLD_BOUNDARY_CURVE ? "curve" : "vertices";
  j["boundary_vertices"] = known(ran, f.boundary_vertices);
  j["boundary_held_vertices"] = known(ran, f.boundary_held_vertices);
  j["boundary_loops"] = known(ran, f.boundary_loops);
  j["isolated_vertices"] = known(ran, f.isolated_vertices);
  j["constrained_vertices"] = known(ran, f.constrained_vertices);
}

// why the run stopped, and what it chose and estimated on the way
void add_outcome(Json& j, const Options& o, const Run_record& r)
{
  const AF::Fairing_report& f = r.report;
  const bool ran = r.fairing_ran;
  j["stop_reason"] = ran ? Json(AF::to_string(f.stop_reason)) : Json(nullptr);
  j["automatic_parameters"] = o.fairing.automatic_parameters();
  j["choices"] = known(ran, f.choices);
  j["noise_level"] = ran ? number(f.noise_level) : Json(nullptr);
  j["noise_deviation"] = ran ? number(f.noise_deviation) : Json(nullptr);
  j["noise_correlation"] = ran ? number(f.noise_correlation) : Json(nullptr);
  j["noise_correlation_factor"] = ran ? number(f.noise_correlation_factor) : Json(nullptr);
  j["noise_displacement"] = ran ? number(f.noise_displacement) : Json(nullptr);
  j["removed_spikes"] = known(ran, f.removed_spikes);
  if(ran && o.fairing.automatic_parameters())
    j["noise_model"] = { { "tangential_noise_level", number(f.tangential_noise_level) },
                         { "noise_level_spread", number(f.noise_level_spread) },
                         { "tangential_noise_level_spread", number(f.tangential_noise_level_spread) },
                         { "impulse_share", number(f.impulse_share) },
                         { "impulse_deviation", number(f.impulse_deviation) },
                         { "lattice_step", { number(f.lattice_step[0]), number(f.lattice_step[1]),
                                             number(f.lattice_step[2]) } } };
  else
    j["noise_model"] = nullptr;
  j["limit_weight"] = ran ? number(f.limit_weight) : Json(nullptr);
  j["components"] = known(ran, f.components);
  j["rejected_steps"] = known(ran, f.rejected_steps);
}

// the bounds the run used, model units (and in units of l), and the largest deviations written
void add_deviations(Json& j, const Options& o, const Run_record& r)
{
  const AF::Fairing_report& f = r.report;
  const bool ran = r.fairing_ran;
  const AF::Fairing_options& given = o.fairing;
  j["absolute_maximum_deviation"] =
      ran ? (f.absolute_maximum_deviation > 0 ? number(f.absolute_maximum_deviation) : Json(nullptr))
          : given.absolute_maximum_deviation ? number(*given.absolute_maximum_deviation) : Json(nullptr);
  // deprecated: the library's maximum_deviation is the relative bound
  j["maximum_deviation"] = j["absolute_maximum_deviation"];
  j["relative_maximum_deviation"] =
      given.relative_maximum_deviation.value_or(0) > 0 ? number(*given.relative_maximum_deviation)
      : ran && f.absolute_maximum_deviation > 0 && f.scale > 0 ? number(f.absolute_maximum_deviation / f.scale)
                                                               : Json(nullptr);
  j["largest_deviation"] = ran ? number(f.largest_deviation) : Json(nullptr);
  j["attribute_maximum_deviation"] =
      given.attribute_maximum_deviation > 0 ? number(given.attribute_maximum_deviation) : Json(nullptr);
  j["largest_attribute_deviation"] = ran && f.attribute_dimension > 0 ? number(f.largest_attribute_deviation)
                                                                      : Json(nullptr);
  j["bound_fidelity_weight"] = ran ? number(f.bound_fidelity_weight) : Json(nullptr);
  j["bound_held_vertices"] = known(ran, f.bound_held_vertices);
  j["bound_uniform_weight"] = ran ? number(f.bound_uniform_weight) : Json(nullptr);
  j["bound_retaken_steps"] = known(ran, f.bound_retaken_steps);
  j["clamped_vertices"] = known(ran, f.clamped_vertices);
}

void add_steps(Json& j, const Run_record& r)
{
  const AF::Fairing_report& f = r.report;
  j["initial"] = r.fairing_ran ? Json{ { "area", number(f.initial.area) }, { "energy", number(f.initial.energy) },
                                       { "H_integral", number(f.initial.H_integral) } }
                               : Json(nullptr);
  Json steps = Json::array();
  for(const AF::Fairing_step& s : f.steps)
    steps.push_back({ { "step", s.step }, { "time", number(s.time) }, { "solver_iterations", s.solver_iterations },
                      { "residual", number(s.residual) }, { "area", number(s.area) }, { "energy", number(s.energy) },
                      { "H_integral", number(s.H_integral) }, { "max_displacement", number(s.max_displacement) },
                      { "step_displacement", number(s.step_displacement) },
                      { "assemble_seconds", number(s.assemble_seconds) },
                      { "solve_seconds", number(s.solve_seconds) }, { "direct_solve", s.direct_solve },
                      { "time_step", number(s.time_step) }, { "noise_displacement", number(s.noise_displacement) } });
  j["steps"] = std::move(steps);
  Json runs = Json::array();
  for(const AF::Fairing_run& run : f.runs)
    runs.push_back({ { "name", run.name }, { "steps", run.steps }, { "rejected_steps", run.rejected_steps },
                     { "seconds", number(run.seconds) }, { "status", AF::to_string(run.status) },
                     { "stop_reason", AF::to_string(run.stop_reason) }, { "estimate", number(run.estimate) },
                     { "kept", run.kept } });
  j["runs"] = std::move(runs);
}

void add_times(Json& j, const Run_record& r, double wall_seconds)
{
  const AF::Fairing_report& f = r.report;
  const bool ran = r.fairing_ran;
  j["read_seconds"] = r.mesh_read ? number(r.read_seconds) : Json(nullptr);
  j["input_seconds"] = ran ? number(f.input_seconds) : Json(nullptr);
  j["setup_seconds"] = ran ? number(f.setup_seconds) : Json(nullptr);
  j["write_back_seconds"] = ran ? number(f.write_back_seconds) : Json(nullptr);
  j["total_seconds"] = ran ? number(f.total_seconds) : Json(nullptr);
  j["write_seconds"] = r.output_written ? number(r.write_seconds) : Json(nullptr);
  j["wall_seconds"] = number(wall_seconds);
}

// The process's largest resident set so far, kB: Linux's VmHWM, which (unlike getrusage's ru_maxrss) does not
// count the memory of the process that started this one before it became this program; NaN where unknown
double peak_resident_kb()
{
  std::ifstream status("/proc/self/status");
  std::string key;
  double kb = 0;
  while(status >> key)
    if(key == "VmHWM:" && status >> kb) return kb;
  rusage usage;
  return getrusage(RUSAGE_SELF, &usage) == 0 ? double(usage.ru_maxrss) : std::nan("");
}

// The run's memory: what it was predicted to take and could take (checked before its set-up), and what the
// process took at its peak (its maximum resident set so far), in MB
void add_memory(Json& j, const Run_record& r)
{
  const AF::Fairing_report& f = r.report;
  const bool ran = r.fairing_ran;
  const double mb = 1024.0 * 1024.0;
  j["memory_in_use_mb"] = ran ? number(f.memory_in_use / mb) : Json(nullptr);
  j["predicted_memory_mb"] = ran ? number(f.predicted_memory / mb) : Json(nullptr);
  j["predicted_peak_memory_mb"] = ran ? number((f.memory_in_use + f.predicted_memory) / mb) : Json(nullptr);
  j["available_memory_mb"] = ran ? number(f.available_memory / mb) : Json(nullptr);
  j["memory_limited_by"] = ran && std::isfinite(f.available_memory) ? Json(f.memory_limited_by) : Json(nullptr);
  j["peak_memory_mb"] = number(peak_resident_kb() / 1024.0);
}

} // namespace

std::string deviations_json(const Options& o, const Run_record& r)
{
  Json j = Json::object();
  add_deviations(j, o, r);
  return j.dump();
}

std::string report_json(const Options& o, const Run_record& r, double wall_seconds)
{
  Json j;   // the keys in the order of the calls: the order --help lists and the manual documents
  add_input(j, o, r);
  add_tensor(j, o, r);
  add_stepping(j, o, r);
  add_written(j, o, r);
  add_outcome(j, o, r);
  add_deviations(j, o, r);
  add_steps(j, r);
  add_times(j, r, wall_seconds);
  add_memory(j, r);
  // bytes that are not UTF-8 (a path, a message quoting the input) are replaced rather than refused
  return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::string report_keys()
{
  Run_record r;
  r.fairing_ran = true;
  r.report.steps.resize(1);
  const Json j = Json::parse(report_json(Options(), r, 0));
  const auto keys = [](const Json& object) {
    std::string list;
    for(auto k = object.begin(); k != object.end(); ++k) list += (list.empty() ? "" : ", ") + k.key();
    return list;
  };
  std::string list;
  for(auto k = j.begin(); k != j.end(); ++k)
  {
    list += (list.empty() ? "" : ", ") + k.key();
    if(k->is_object()) list += " {" + keys(*k) + "}";
    if(k->is_array() && !k->empty() && k->front().is_object()) list += " [{" + keys(k->front()) + "}]";
  }
  return list;
}

} // namespace af_tool
