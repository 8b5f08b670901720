// The JSON report of anisotropic_fairing (see json_report.h). Written by hand rather than with a JSON
// library: the numbers must keep printf's %.17g and the layout (one line per step) its own.
#include "json_report.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

namespace af_tool {

namespace {

std::string json_string(const std::string& s)
{
  std::string r = "\"";
  for(unsigned char c : s)
  {
    switch(c)
    {
      case '"': r += "\\\""; break;
      case '\\': r += "\\\\"; break;
      case '\b': r += "\\b"; break;
      case '\f': r += "\\f"; break;
      case '\n': r += "\\n"; break;
      case '\r': r += "\\r"; break;
      case '\t': r += "\\t"; break;
      default:
        if(c < 0x20) { char buf[8]; std::snprintf(buf, sizeof buf, "\\u%04x", c); r += buf; }
        else r += char(c);
    }
  }
  return r + "\"";
}

std::string json_number(double x)
{
  if(!std::isfinite(x)) return "null";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string json_count(std::size_t n) { return std::to_string(n); }

const char* element_name(AF::Finite_element e) { return e == AF::Finite_element::LOOP ? "loop" : "linear"; }
const char* output_name(AF::Output_positions p) { return p == AF::Output_positions::LIMIT_SURFACE ? "limit" : "control"; }
const char* solver_name(AF::Linear_solver s)
{
  return s == AF::Linear_solver::AUTOMATIC ? "auto" : s == AF::Linear_solver::CHOLESKY ? "cholesky" : "cg";
}

} // namespace

std::string report_json(const Options& o, const Run_record& r, double wall_seconds)
{
  const AF::Fairing_report& f = r.report;
  const bool ran = r.fairing_ran;
  const double scale2 = f.scale * f.scale;
  std::ostringstream j;
  auto kv = [&](const char* key, const std::string& value, bool last = false) {
    j << "  " << json_string(key) << ": " << value << (last ? "\n" : ",\n");
  };
  j << "{\n";
  kv("status", json_string(r.status));
  kv("message", json_string(r.message));
  kv("input", o.input.empty() ? "null" : json_string(o.input));
  kv("output", r.output_written ? json_string(o.output) : "null");
  kv("vertices", r.mesh_read ? json_count(r.vertices) : "null");
  kv("faces", r.mesh_read ? json_count(r.faces) : "null");
  kv("element", json_string(element_name(o.element)));
  kv("output_positions", json_string(output_name(o.output_positions)));
  // the tensor the run used: with automatic parameters the package keeps the anisotropic, the
  // isotropic or the uniform result (selected_tensor)
  const bool isotropic_kept = ran && (f.selected_tensor == "isotropic" || f.selected_tensor == "uniform");
  kv("tensor", json_string(o.uniform || (ran && f.selected_tensor == "uniform") ? "uniform"
                           : o.anisotropic && !isotropic_kept ? "anisotropic" : "isotropic"));
  // the values the run used (chosen from the mesh when automatic), in units of l, l^2 and 1/length
  const bool lambda_known = o.anisotropic && !isotropic_kept && (!automatic_tensor(o) || ran);
  kv("lambda", lambda_known ? json_number(automatic_tensor(o) ? f.feature_threshold * f.scale : o.lambda) : "null");
  kv("lambda_model_units", lambda_known && ran && f.scale > 0 ? json_number(f.feature_threshold) : "null");
  kv("epsilon", lambda_known ? json_number(automatic_tensor(o) ? f.prefilter_time / scale2 : o.epsilon) : "null");
  kv("tangential_motion", json_string(o.anisotropic && !isotropic_kept && o.normal_motion_only ? "removed" : "kept"));
  kv("solver", ran ? json_string(f.used_cholesky ? "cholesky" : "cg") : "null");
  kv("requested_solver", json_string(solver_name(o.solver)));
  kv("stop", json_string(o.stop));
  kv("max_steps", json_count(o.steps));
  kv("quadrature_degree", std::to_string(o.quadrature_degree));
  kv("time_step", ran ? json_number(f.time_step) : (o.has_time_step ? json_number(o.time_step) : "null"));
  kv("order", std::to_string(ran ? f.flow_order : o.order));
  kv("relative_time_step", ran && scale2 > 0 ? json_number(f.time_step / std::pow(scale2, f.flow_order / 2))
                                             : (o.has_relative_time_step ? json_number(o.relative_time_step) : "null"));
  kv("scale", ran ? json_number(f.scale) : "null");
  kv("fidelity_weight", ran ? json_number(f.fidelity_weight) : (o.has_fidelity ? json_number(o.fidelity) : "null"));
  kv("relative_fidelity_weight", ran ? json_number(f.fidelity_weight * scale2)
                                     : (o.has_relative_fidelity ? json_number(o.relative_fidelity) : "null"));
  kv("mean_edge_length", ran ? json_number(f.mean_edge_length) : "null");
  kv("normals", json_string(r.normals));
  kv("curvature", r.curvature ? "true" : "false");
  kv("mode", json_string(mode_name(effective_mode(o))));
  {
    std::string names = "[";
    for(std::size_t i = 0; i < o.attributes.size(); ++i) names += (i ? ", " : "") + json_string(o.attributes[i]);
    kv("attributes", names + "]");
  }
  kv("attribute_dimension", ran ? json_count(f.attribute_dimension) : "null");
  kv("attribute_weight", json_number(o.attribute_weight));
  kv("boundary_handling", json_string(o.boundary == AF::Boundary_handling::HOLD_BOUNDARY_CURVE ? "curve" : "vertices"));
  kv("boundary_vertices", ran ? json_count(f.boundary_vertices) : "null");
  kv("boundary_held_vertices", ran ? json_count(f.boundary_held_vertices) : "null");
  kv("boundary_loops", ran ? json_count(f.boundary_loops) : "null");
  kv("isolated_vertices", ran ? json_count(f.isolated_vertices) : "null");
  kv("constrained_vertices", ran ? json_count(f.constrained_vertices) : "null");
  kv("stop_reason", ran ? json_string(AF::to_string(f.stop_reason)) : "null");
  kv("automatic_parameters", automatic_parameters(o) ? "true" : "false");
  kv("choices", ran ? json_string(f.choices) : "null");
  kv("noise_level", ran ? json_number(f.noise_level) : "null");
  kv("noise_deviation", ran ? json_number(f.noise_deviation) : "null");
  kv("noise_displacement", ran ? json_number(f.noise_displacement) : "null");
  kv("limit_weight", ran ? json_number(f.limit_weight) : "null");
  kv("components", ran ? json_count(f.components) : "null");
  kv("rejected_steps", ran ? json_count(f.rejected_steps) : "null");
  if(ran)
    kv("initial", "{\"area\": " + json_number(f.initial.area) + ", \"energy\": " + json_number(f.initial.energy) +
                  ", \"H_integral\": " + json_number(f.initial.H_integral) + "}");
  else
    kv("initial", "null");
  std::ostringstream steps;
  steps << "[";
  for(std::size_t i = 0; i < f.steps.size(); ++i)
  {
    const AF::Fairing_step& s = f.steps[i];
    steps << (i ? ",\n    " : "\n    ") << "{\"step\": " << s.step << ", \"time\": " << json_number(s.time)
          << ", \"solver_iterations\": " << s.solver_iterations << ", \"residual\": " << json_number(s.residual)
          << ", \"area\": " << json_number(s.area) << ", \"energy\": " << json_number(s.energy)
          << ", \"H_integral\": " << json_number(s.H_integral)
          << ", \"max_displacement\": " << json_number(s.max_displacement)
          << ", \"step_displacement\": " << json_number(s.step_displacement)
          << ", \"assemble_seconds\": " << json_number(s.assemble_seconds)
          << ", \"solve_seconds\": " << json_number(s.solve_seconds)
          << ", \"direct_solve\": " << (s.direct_solve ? "true" : "false")
          << ", \"time_step\": " << json_number(s.time_step)
          << ", \"noise_displacement\": " << json_number(s.noise_displacement) << "}";
  }
  steps << (f.steps.empty() ? "]" : "\n  ]");
  kv("steps", steps.str());
  kv("setup_seconds", ran ? json_number(f.setup_seconds) : "null");
  kv("total_seconds", ran ? json_number(f.total_seconds) : "null");
  kv("wall_seconds", json_number(wall_seconds), true);
  j << "}\n";
  return j.str();
}

} // namespace af_tool
