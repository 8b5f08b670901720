// The run of anisotropic_fairing: read the input, fair it with CGAL::Anisotropic_fairing::
// anisotropic_fairing(), write the output and the report; nothing is written unless all succeeded.
//
// Normals: if the input carries vertex normals (NOFF, PLY nx/ny/nz, OBJ vn) the normals written are
// those of the faired surface, never the stale input ones:
//  - Loop element with `--output limit`: the library writes the limit points (held within the bounds)
//    and gives the faired control points through its control_point_map; a Loop_limit_surface built on
//    those gives the exact normals of the faired limit surface at the points written.
//  - `--output control` or the linear element: the written mesh is the surface itself (control
//    polygon or P1 surface), so the normals are CGAL::Polygon_mesh_processing::compute_vertex_normals.
// Curvature (`--curvature`, PLY output): Loop_limit_surface::vertex_curvatures() of the limit surface of
// the faired control mesh (the control_point_map above), written as the double vertex properties k1, k2
// and mean_curvature.
// With `--mode attributes` the geometry is not faired: positions and the input's normals are written
// unchanged (OBJ vn, which CGAL's reader does not read, are recomputed as for `--output control`).
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
#include "progress_heartbeat.h"
#include "resampled_output.h"
#include "snapshot.h"

#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>
#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

namespace af_tool {
namespace fs = std::filesystem;

namespace {

std::string strip_library_prefix(const std::string& what)
{
  const std::string prefix = "Anisotropic_fairing: ";
  return what.compare(0, prefix.size(), prefix) == 0 ? what.substr(prefix.size()) : what;
}

typedef AF::Loop_limit_surface<Mesh> Limit;

} // namespace

int run(const Options& o, Run_record& r)
{
  Format out_format;
  format_of(o.output, out_format);

  // fail early on an output or a report that cannot be created (the final writes check again)
  const auto check_writable = [](const std::string& path, const std::string& what) {
    const fs::path out(path);
    const fs::path dir = out.has_parent_path() ? out.parent_path() : fs::path(".");
    std::error_code ec;
    if(!fs::is_directory(dir, ec)) fail("write_error", "cannot write " + what + path + ": no directory " + dir.string());
    if(::access(dir.c_str(), W_OK) != 0) fail("write_error", "cannot write " + what + path + ": directory " + dir.string() + " is not writable");
    if(fs::is_directory(out, ec)) fail("write_error", "cannot write " + what + path + ": it is a directory");
    if(fs::exists(out, ec) && ::access(out.c_str(), W_OK) != 0) fail("write_error", "cannot write " + what + path + ": it is not writable");
  };
  check_writable(o.output, "");
  if(!o.report.empty()) check_writable(o.report, "the report ");
  if(!o.snapshot.empty()) check_writable(o.snapshot, "the snapshot ");
  const std::string renderer = o.snapshot.empty() ? std::string() : render_script();
  if(!o.snapshot.empty() && renderer.empty())
    fail("snapshot_error", "--snapshot: the renderer render_mesh.py was not found (installed next to the program, or set AF_RENDER_SCRIPT)");

  Progress_heartbeat heartbeat(o.quiet ? 0.0 : o.progress_interval);
  heartbeat.phase("reading " + o.input);
  Mesh mesh;
  Input_info info;
  const double read_from = elapsed_seconds();
  read_input(o.input, mesh, info, o.repair);
  r.read_seconds = elapsed_seconds() - read_from;
  r.mesh_read = true;
  r.vertices = info.split.empty() ? mesh.number_of_vertices() : info.split.file_vertices;   // as written
  r.faces = mesh.number_of_faces();
  r.input_changes = info.input_changes;
  r.split_vertices = info.split.split_vertices;
  r.triangulated_faces = info.triangulated_faces;
  if(o.has_resample) check_resample_size(mesh, o.resample);

  // --curvature adds three vertex properties; never overwrite the input's own
  static const char* const curvature_properties[3] = { "v:k1", "v:k2", "v:mean_curvature" };
  if(o.curvature)
    for(const std::string& p : mesh.properties<Vertex_index>())
      for(const char* c : curvature_properties)
        if(p == c)
          fail("input_error", "--curvature: " + o.input + " already has a vertex property '" + p.substr(2) + "', which it would overwrite");

  // the attributes named (checked in every mode, so that a misspelt name fails), and what is faired
  const AF::Attribute_mode mode = effective_mode(o);
  const std::vector<Attribute_column> columns = resolve_attributes(mesh, info, o.input, o.attributes);
  const bool fair_attributes = !columns.empty() && mode != AF::Attribute_mode::GEOMETRY_ONLY;
  const bool fair_geometry = mode != AF::Attribute_mode::ATTRIBUTES_ONLY;
  std::vector<std::vector<double>> attribute_values;   // per vertex, the columns in order
  if(fair_attributes) gather(mesh, columns, attribute_values);
  const Attribute_vectors attribute_map{&attribute_values};
  std::vector<std::vector<double>> attribute_controls = attribute_values;   // their faired control values (--resample)
  // without attributes to fair, GEOMETRY_ONLY: the attribute map is then neither read nor written
  const AF::Attribute_mode library_mode = fair_attributes ? mode : AF::Attribute_mode::GEOMETRY_ONLY;

  // Exact limit normals and the curvature need the faired control points: see the comment at the top of
  // this file. With --mode attributes the geometry is fixed: positions and input normals are written as they are.
  const bool limit_written = o.fairing.finite_element == AF::Finite_element::LOOP &&
                             o.fairing.output_positions == AF::Output_positions::LIMIT_SURFACE;
  const bool exact_limit_normals = info.has_normals && limit_written && fair_geometry;
  std::vector<Point> control_points(mesh.number_of_vertices());
  std::vector<unsigned char> held(mesh.number_of_vertices(), 0);
  if(!o.hold.empty()) r.held_vertices = read_held_vertices(mesh, o.hold, held);
  for(std::size_t i = 0; i < info.split.copy_of.size(); ++i) held[info.split.file_vertices + i] = held[info.split.copy_of[i]];

  const unsigned int max_steps = o.fairing.maximum_steps();
  const bool quiet = o.quiet;
  std::size_t last_run = 0, steps_in_all = 0;
  auto progress = [max_steps, quiet, &last_run, &steps_in_all, &heartbeat](const AF::Fairing_step& s) {
    // the default run compares flows, each also on a probed copy of the input: say which runs, and how
    // much of the step budget (--steps bounds all runs together) is spent
    ++steps_in_all;
    if(quiet) return true;
    if(s.runs > 1 && s.run != last_run)
      std::fprintf(stderr, "anisotropic_fairing: run %zu of at most %zu: the %s\n", s.run, s.runs, s.run_name.c_str());
    last_run = s.run;
    std::fprintf(stderr, "anisotropic_fairing: step %zu (%zu/%u in all)  t=%.6g  area=%.6g  int|H|^2=%.6g  max disp=%.6g  %d %s  %.3fs+%.3fs\n",
                 s.step, steps_in_all, max_steps, s.time, s.area, s.H_integral, s.max_displacement, s.solver_iterations,
                 s.direct_solve ? "factorisation" : "its", s.assemble_seconds, s.solve_seconds);
    heartbeat.phase("still working after step " + std::to_string(s.step) +
                    (s.runs > 1 ? " of run " + std::to_string(s.run) + " (the " + s.run_name + ")" : std::string()) +
                    ": the next step, retried smaller when rejected, or the next run");
    return true;
  };
  heartbeat.phase("setting up " + o.input + " (topology, ghost layer, noise estimate) and its first step");
  try
  {
    r.report = fair_with_options(mesh, o, library_mode, attribute_map, attribute_controls, control_points, held, progress);
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

  heartbeat.phase("writing the result back (limit normals, curvature, attributes, resampling)");
  const double write_from = elapsed_seconds();
  if(o.curvature || exact_limit_normals)
  {
    // The limit surface of the faired control points serves the curvature and the normals. Only the
    // curvature's averages use the quadrature (the run's degree); otherwise degree 4 is the cheapest set-up.
    Mesh control = mesh;
    for(Vertex_index v : control.vertices()) control.point(v) = control_points[std::size_t(v)];
    const Limit limit(control, AF::parameters::quadrature_degree(o.curvature ? o.fairing.quadrature_degree : 4));
    if(o.curvature)
    {
      std::vector<Limit::Curvature> values(mesh.number_of_vertices());
      limit.vertex_curvatures(CGAL::make_property_map(values));
      auto k1 = mesh.add_property_map<Vertex_index, double>(curvature_properties[0], 0.0).first;
      auto k2 = mesh.add_property_map<Vertex_index, double>(curvature_properties[1], 0.0).first;
      auto h = mesh.add_property_map<Vertex_index, double>(curvature_properties[2], 0.0).first;
      for(Vertex_index v : mesh.vertices())
      {
        const Limit::Curvature& c = values[std::size_t(v)];
        k1[v] = c.k1;
        k2[v] = c.k2;
        h[v] = 0.5 * (c.k1 + c.k2);
      }
      r.curvature = true;
    }
    if(exact_limit_normals) limit.limit_normals(mesh.property_map<Vertex_index, Vector>("v:normal").first);
  }
  if(info.has_normals)
  {
    Normal_map normals = mesh.property_map<Vertex_index, Vector>("v:normal").first;
    if(exact_limit_normals)
      r.normals = "limit_surface";   // written above, with the limit positions
    else if(fair_geometry || !info.normals_read)
    {
      CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);
      r.normals = "vertex_normals";
    }
    else
      r.normals = "input";   // the geometry was not faired: the input's normals are still right
  }
  // a split vertex at the mean of its copies (the copies are dropped when the file is written)
  merge_copies(mesh, info.split);
  merge_copies(attribute_values, info.split);
  // back into the input's own properties (rounded, clamped), which are written with the mesh
  if(fair_attributes) scatter(mesh, columns, attribute_values);
  if(o.has_resample)
  {
    const std::vector<Attribute_column> none;
    resample_output(mesh, info, o.input, o.resample, {&control_points, fair_attributes ? &columns : &none, &attribute_controls},
                    o.curvature, o.fairing.quadrature_degree);
    r.resampled_vertices = mesh.number_of_vertices();
    r.resampled_faces = mesh.number_of_faces();
  }
  if(o.has_attribute_weight && mode != AF::Attribute_mode::COUPLED)
    info.warnings.push_back("--attribute-weight has no effect without --mode coupled");

  // printed once OUTPUT exists, so that on failure the failure is the only line starting with "anisotropic_fairing: "
  std::vector<std::string> warnings = o.deprecations;
  warnings.insert(warnings.end(), info.warnings.begin(), info.warnings.end());
  const std::vector<std::string> dropped = dropped_properties(mesh, out_format);
  if(!dropped.empty())
  {
    std::string list;
    for(const std::string& p : dropped) list += (list.empty() ? "" : ", ") + p;
    warnings.push_back(o.output + " cannot hold the input's " + list + ": not written");
  }

  // write next to OUTPUT, then write the report, then rename: OUTPUT appears only if all succeeded
  const fs::path tmp = temporary_next_to(o.output);
  heartbeat.phase("writing " + o.output);
  try
  {
    write_mesh(tmp.string(), out_format, mesh, info, info.has_normals, o.text_output);
    if(!o.has_resample) merge_copies_in_file(tmp.string(), out_format, info.split);   // resampled: a new mesh, copies and all
  }
  catch(const Failure&)
  {
    std::error_code ec;
    fs::remove(tmp, ec);
    fail("write_error", "cannot write " + o.output);
  }
  // the snapshot next to its file, renamed with OUTPUT
  const fs::path snapshot_tmp = o.snapshot.empty() ? fs::path() : temporary_next_to(o.snapshot);
  auto remove_temporaries = [&] {
    std::error_code ec;
    fs::remove(tmp, ec);
    if(!o.snapshot.empty()) fs::remove(snapshot_tmp, ec);
  };
  if(!o.snapshot.empty())
  {
    char result_title[200];
    std::snprintf(result_title, sizeof result_title, "faired: %s, %zu steps, %s", r.report.selected_tensor.empty() ? "" : r.report.selected_tensor.c_str(),
                  r.report.steps.size(), AF::to_string(r.report.stop_reason));
    heartbeat.phase("rendering the snapshot " + o.snapshot);
    try
    {
      render_snapshot(renderer, o.input, tmp.string(), "input: " + fs::path(o.input).filename().string(), result_title, snapshot_tmp.string(),
                      o.snapshot);
    }
    catch(const Failure&)
    {
      remove_temporaries();
      throw;
    }
  }
  r.output_written = true;  // as far as the report is concerned
  r.write_seconds = elapsed_seconds() - write_from;
  if(!o.report.empty())
  {
    // wall time up to here; the rename is negligible
    if(!write_file_atomically(o.report, report_json(o, r, elapsed_seconds())))
    {
      remove_temporaries();
      r.output_written = false;
      throw Failure{1, "write_error", "cannot write the report " + o.report};
    }
  }
  std::error_code ec;
  fs::rename(tmp, o.output, ec);
  const bool output_moved = !ec;
  if(output_moved && !o.snapshot.empty()) fs::rename(snapshot_tmp, o.snapshot, ec);
  if(ec)
  {
    std::error_code ec2;
    remove_temporaries();
    if(output_moved) fs::remove(o.output, ec2);   // the snapshot could not be put in place: nothing stays
    r.output_written = false;
    if(!o.report.empty()) fs::remove(o.report, ec2);  // it described an output that does not exist
    fail("write_error", "cannot write " + (output_moved ? o.snapshot : o.output) + ": " + ec.message());
  }
  for(const std::string& w : warnings)
    std::fprintf(stderr, "anisotropic_fairing: warning: %s\n", one_line(w).c_str());
  for(const std::string& n : info.notes) std::fprintf(stderr, "anisotropic_fairing: %s\n", one_line(n).c_str());
  if(!quiet && !r.report.choices.empty())
    std::fprintf(stderr, "anisotropic_fairing: automatic parameters: %s\n", one_line(r.report.choices).c_str());
  if(r.report.stop_reason == AF::Stop_reason::STEP_REJECTED)
    std::fprintf(stderr, "anisotropic_fairing: warning: stopped early: %s\n", one_line(r.report.message).c_str());
  if(!quiet)
    std::fprintf(stderr, "anisotropic_fairing: wrote %s (%zu vertices, %zu steps, stopped: %s, %.3f s)%s%s\n",
                 o.output.c_str(), mesh.number_of_vertices(), r.report.steps.size(), AF::to_string(r.report.stop_reason),
                 r.report.total_seconds, o.snapshot.empty() ? "" : " and ", o.snapshot.c_str());
  return 0;
}

} // namespace af_tool
