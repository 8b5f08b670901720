// The run of anisotropic_fairing: read the input, fair it with CGAL::Anisotropic_fairing::
// anisotropic_fairing(), write the output and the report; nothing is written unless all succeeded
// (output_commit.h). The normals and the curvature written: written_normals_and_curvature.h.
//
// Attributes (`--attributes NAME,...`, `--mode`, `--attribute-weight`): the named per-vertex properties
// (PLY: any numeric vertex property by its name, `red`/`green`/`blue`/`color` (and `alpha`) for the colour;
// OFF: `color`, `uv`; OBJ: `uv`, the vt of the file when they are one per vertex) are gathered, in the
// order given, into ONE std::vector<double> per vertex, so that the library faires all of them in one
// solve with the attribute mode asked for; the result is then scattered back into the original typed
// properties (integers rounded and clamped to their range, colour channels to 0..255 with alpha kept,
// floats as float). CGAL's OBJ reader and writer know no vt:
// this program reads them itself and, when they are one per vertex, keeps them as the "v:texcoord"
// property (as the OFF reader does) and writes OBJ itself ("f a/a", "f a/a/a" with normals).

#include "fairing_run.h"

#include "attribute_columns.h"
#include "fairing_call.h"
#include "held_vertices.h"
#include "mesh_io.h"
#include "output_commit.h"
#include "progress_heartbeat.h"
#include "resampled_output.h"
#include "written_normals_and_curvature.h"

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include <cstdio>
#include <string>
#include <vector>

namespace af_tool {

namespace {

typedef std::vector<std::vector<double>> Vertex_vectors;

std::string strip_library_prefix(const std::string& what)
{
  const std::string prefix = "Anisotropic_fairing: ";
  return what.compare(0, prefix.size(), prefix) == 0 ? what.substr(prefix.size()) : what;
}

// What the options ask to fair, and the per-vertex vectors of the attributes faired in one solve.
struct Fairing_plan
{
  AF::Attribute_mode mode = AF::Attribute_mode::GEOMETRY_ONLY;   // as asked
  std::vector<Attribute_column> columns;
  bool fair_attributes = false, fair_geometry = true;
  Vertex_vectors values;     // per vertex, the columns in order
  Vertex_vectors controls;   // their faired control values (--resample)
  std::vector<Point> control_points;   // the faired control points
  std::vector<unsigned char> held;     // held[v] != 0: --hold holds v

  // without attributes to fair, GEOMETRY_ONLY: the attribute map is then neither read nor written
  AF::Attribute_mode library_mode() const { return fair_attributes ? mode : AF::Attribute_mode::GEOMETRY_ONLY; }
};

// The counts the step lines print, shared by every copy of the callback.
struct Step_count
{
  std::size_t last_run = 0, steps_in_all = 0;
};

void read_mesh(const Options& o, Progress_heartbeat& heartbeat, Mesh& mesh, Input_info& info, Run_record& r)
{
  heartbeat.phase("reading " + o.input);
  const double read_from = elapsed_seconds();
  read_input(o.input, mesh, info, o.repair);
  r.read_seconds = elapsed_seconds() - read_from;
  r.mesh_read = true;
  r.vertices = info.split.empty() ? mesh.number_of_vertices() : info.split.file_vertices;   // as written
  r.faces = mesh.number_of_faces();
  r.input_changes = info.input_changes;
  r.split_vertices = info.split.split_vertices;
  r.triangulated_faces = info.triangulated_faces;
}

// The attributes named are checked in every mode, so that a misspelt name fails.
void plan_attributes(const Options& o, Mesh& mesh, const Input_info& info, Fairing_plan& plan)
{
  plan.mode = effective_mode(o);
  plan.columns = resolve_attributes(mesh, info, o.input, o.attributes);
  plan.fair_attributes = !plan.columns.empty() && plan.mode != AF::Attribute_mode::GEOMETRY_ONLY;
  plan.fair_geometry = plan.mode != AF::Attribute_mode::ATTRIBUTES_ONLY;
  if(plan.fair_attributes) gather(mesh, plan.columns, plan.values);
  plan.controls = plan.values;
}

// A split vertex's copies are held as it is.
void plan_held_vertices(const Options& o, const Mesh& mesh, const Input_info& info, Fairing_plan& plan,
                        Run_record& r)
{
  plan.control_points.resize(mesh.number_of_vertices());
  plan.held.assign(mesh.number_of_vertices(), 0);
  if(!o.hold.empty()) r.held_vertices = read_held_vertices(mesh, o.hold, plan.held);
  for(std::size_t i = 0; i < info.split.copy_of.size(); ++i)
    plan.held[info.split.file_vertices + i] = plan.held[info.split.copy_of[i]];
}

// A line per accepted step. The default run compares flows, each also on a probed copy of the input: the
// lines say which runs, and how much of the step budget (--steps bounds all runs together) is spent.
Step_callback step_lines(const Options& o, Step_count& count, Progress_heartbeat& heartbeat)
{
  const unsigned int max_steps = o.fairing.maximum_steps();
  const bool quiet = o.quiet;
  return [max_steps, quiet, &count, &heartbeat](const AF::Fairing_step& s) {
    ++count.steps_in_all;
    if(quiet) return true;
    if(s.runs > 1 && s.run != count.last_run)
      std::fprintf(stderr, "anisotropic_fairing: run %zu of at most %zu: the %s\n", s.run, s.runs, s.run_name.c_str());
    count.last_run = s.run;
    std::fprintf(stderr, "anisotropic_fairing: step %zu (%zu/%u in all)  t=%.6g  area=%.6g  int|H|^2=%.6g  "
                         "max disp=%.6g  %d %s  %.3fs+%.3fs\n",
                 s.step, count.steps_in_all, max_steps, s.time, s.area, s.H_integral, s.max_displacement,
                 s.solver_iterations, s.direct_solve ? "factorisation" : "its", s.assemble_seconds, s.solve_seconds);
    heartbeat.phase("still working after step " + std::to_string(s.step) +
                    (s.runs > 1 ? " of run " + std::to_string(s.run) + " (the " + s.run_name + ")" : std::string()) +
                    ": the next step, retried smaller when rejected, or the next run");
    return true;
  };
}

void fair(const Options& o, Mesh& mesh, Fairing_plan& plan, const Step_callback& progress,
          Progress_heartbeat& heartbeat, Run_record& r)
{
  heartbeat.phase("setting up " + o.input + " (topology, ghost layer, noise estimate) and its first step");
  const Attribute_vectors attribute_map{&plan.values};
  try
  {
    r.report = fair_with_options(mesh, o, plan.library_mode(), attribute_map, plan.controls, plan.control_points,
                                 plan.held, progress);
  }
  catch(const AF::Input_error& e)
  {
    fail(e.kind() == AF::Input_error::INVALID_PARAMETER ? "invalid_parameter" : "input_error",
         "cannot fair " + o.input + ": " + strip_library_prefix(e.what()));
  }
  r.fairing_ran = true;
  if(!r.report.succeeded())
    fail(AF::to_string(r.report.status),
         "fairing " + o.input + " failed (" + AF::to_string(r.report.status) + "): " +
         (r.report.message.empty() ? std::string("no detail") : r.report.message));
}

// The faired mesh as it is written: normals, curvature, split vertices merged, attributes back in their
// own properties, resampled.
void write_back(const Options& o, Fairing_plan& plan, Mesh& mesh, Input_info& info, Run_record& r)
{
  write_normals_and_curvature(o, info, plan.fair_geometry, plan.control_points, mesh, r);
  // a split vertex at the mean of its copies (the copies are dropped when the file is written)
  merge_copies(mesh, info.split);
  merge_copies(plan.values, info.split);
  // back into the input's own properties (rounded, clamped), which are written with the mesh
  if(plan.fair_attributes) scatter(mesh, plan.columns, plan.values);
  if(o.has_resample)
  {
    const std::vector<Attribute_column> none;
    resample_output(mesh, info, o.input, o.resample,
                    {&plan.control_points, plan.fair_attributes ? &plan.columns : &none, &plan.controls},
                    o.curvature, o.fairing.quadrature_degree);
    r.resampled_vertices = mesh.number_of_vertices();
    r.resampled_faces = mesh.number_of_faces();
  }
  if(o.has_attribute_weight && plan.mode != AF::Attribute_mode::COUPLED)
    info.warnings.push_back("--attribute-weight has no effect without --mode coupled");
}

std::vector<std::string> warnings_of(const Options& o, const Input_info& info, const Mesh& mesh, Format format)
{
  std::vector<std::string> warnings = o.deprecations;
  warnings.insert(warnings.end(), info.warnings.begin(), info.warnings.end());
  const std::vector<std::string> dropped = dropped_properties(mesh, format);
  if(!dropped.empty())
  {
    std::string list;
    for(const std::string& p : dropped) list += (list.empty() ? "" : ", ") + p;
    warnings.push_back(o.output + " cannot hold the input's " + list + ": not written");
  }
  return warnings;
}

// Printed once OUTPUT exists, so that on failure the failure is the only line starting with
// "anisotropic_fairing: ".
void print_summary(const Options& o, const std::vector<std::string>& warnings, const Input_info& info,
                   const Mesh& mesh, const Run_record& r)
{
  for(const std::string& w : warnings)
    std::fprintf(stderr, "anisotropic_fairing: warning: %s\n", one_line(w).c_str());
  for(const std::string& n : info.notes) std::fprintf(stderr, "anisotropic_fairing: %s\n", one_line(n).c_str());
  if(!o.quiet && !r.report.choices.empty())
    std::fprintf(stderr, "anisotropic_fairing: automatic parameters: %s\n", one_line(r.report.choices).c_str());
  if(r.report.stop_reason == AF::Stop_reason::STEP_REJECTED)
    std::fprintf(stderr, "anisotropic_fairing: warning: stopped early: %s\n", one_line(r.report.message).c_str());
  if(!o.quiet)
    std::fprintf(stderr, "anisotropic_fairing: wrote %s (%zu vertices, %zu steps, stopped: %s, %.3f s)%s%s\n",
                 o.output.c_str(), mesh.number_of_vertices(), r.report.steps.size(),
                 AF::to_string(r.report.stop_reason), r.report.total_seconds, o.snapshot.empty() ? "" : " and ",
                 o.snapshot.c_str());
}

} // namespace

int run(const Options& o, Run_record& r)
{
  Format out_format;
  format_of(o.output, out_format);
  const std::string renderer = check_outputs_writable(o);

  Progress_heartbeat heartbeat(o.quiet ? 0.0 : o.progress_interval);
  Mesh mesh;
  Input_info info;
  read_mesh(o, heartbeat, mesh, info, r);
  if(o.has_resample) check_resample_size(mesh, o.resample, o.fairing.memory_limit);
  check_curvature_properties_free(o, mesh);
  Fairing_plan plan;
  plan_attributes(o, mesh, info, plan);
  plan_held_vertices(o, mesh, info, plan, r);

  Step_count count;
  fair(o, mesh, plan, step_lines(o, count, heartbeat), heartbeat, r);

  heartbeat.phase("writing the result back (limit normals, curvature, attributes, resampling)");
  const double write_from = elapsed_seconds();
  write_back(o, plan, mesh, info, r);
  const std::vector<std::string> warnings = warnings_of(o, info, mesh, out_format);
  commit_outputs(o, renderer, mesh, info, out_format, write_from, heartbeat, r);
  print_summary(o, warnings, info, mesh, r);
  return 0;
}

} // namespace af_tool
