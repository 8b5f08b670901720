// The run of anisotropic_fairing: read the input, fair it with CGAL::Anisotropic_fairing::
// anisotropic_fairing(), write the output and the report; nothing is written unless all succeeded.
//
// Normals: if the input carries vertex normals (NOFF, PLY nx/ny/nz, OBJ vn) the normals written are
// those of the faired surface, never the stale input ones:
//  - Loop element with `--output limit`: the fairing is run with Output_positions::CONTROL_POINTS,
//    then a Loop_limit_surface is built on the faired control mesh, and its limit_positions() and
//    limit_normals() are written. limit_positions() applies the same closed-form limit masks as the
//    library's Output_positions::LIMIT_SURFACE to the same control points, so the positions are the
//    ones a LIMIT_SURFACE run writes up to the order of the floating-point sums (about 1e-16
//    relative; the test cli_limit_normals_keep_positions checks 1e-14 absolute on bumpy.off), and the
//    normals are the exact normals of the faired limit surface at those points (write_limit_surface()
//    says where this differs from the library's write-back).
//  - `--output control` or the linear element: the written mesh is the surface itself (control
//    polygon or P1 surface), so the normals are CGAL::Polygon_mesh_processing::compute_vertex_normals.
// Without input normals (and without --curvature) the library's LIMIT_SURFACE output is used directly
// and no normal is written.
// Curvature (`--curvature`, PLY output): Loop_limit_surface::vertex_curvatures() of the limit surface of
// the faired control mesh (the same CONTROL_POINTS path as the normals above when the output is the
// limit surface), written as the double vertex properties k1, k2 and mean_curvature.
// With `--mode attributes` the geometry is not faired: positions and the input's normals are written
// unchanged (OBJ vn, which CGAL's reader does not read, are recomputed as for `--output control`).
//
// Attributes (`--attributes NAME,...`, `--mode`, `--attribute-weight`): the named per-vertex properties
// (PLY: any numeric vertex property by its name, `red`/`green`/`blue`/`color` (and `alpha`) for the colour;
// OFF: `color`, `uv`; OBJ: `uv`, the vt of the file when they are one per vertex) are gathered, in the
// order given, into ONE std::vector<double> per vertex, so that the library faires all of them in one
// solve with the attribute mode asked for; the result is then scattered back into the original typed
// properties (integers rounded and clamped to their range, colour channels to 0..255 with alpha kept,
// floats as float). The `--output limit` path with exact limit normals (above) also gives the
// attributes their limit values (Loop_limit_surface::limit_values()), boundary and isolated vertices
// keeping theirs, as the library's LIMIT_SURFACE output does. CGAL's OBJ reader and writer know no vt:
// this program reads them itself and, when they are one per vertex, keeps them as the "v:texcoord"
// property (as the OFF reader does) and writes OBJ itself ("f a/a", "f a/a/a" with normals).

#include "fairing_run.h"

#include "attribute_columns.h"
#include "mesh_io.h"

#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>
#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Deviation_bound.h>

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

// ------------------------------------------------------------------------------------------------
// Fairing: the named parameters differ in type with the time step and fidelity flags given
// ------------------------------------------------------------------------------------------------
// (the bounds always given, 0 for none, so that they add one variant of the call, not three)
template <typename NP, typename Run>
AF::Fairing_report with_bound(const NP& np, const Options& o, Run& run)
{
  const auto bounded = np.attribute_maximum_deviation(o.attribute_bound);
  if(o.has_bound) return run(bounded.absolute_maximum_deviation(o.bound));
  return run(bounded.maximum_deviation(o.relative_bound));
}

template <typename NP, typename Run>
AF::Fairing_report with_fidelity(const NP& np, const Options& o, Run& run)
{
  if(o.has_fidelity) return with_bound(np.fidelity_weight(o.fidelity), o, run);
  if(o.has_relative_fidelity) return with_bound(np.relative_fidelity_weight(o.relative_fidelity), o, run);
  return with_bound(np, o, run);
}

template <typename NP, typename Run>
AF::Fairing_report with_time_step(const NP& np, const Options& o, Run& run)
{
  if(o.has_time_step) return with_fidelity(np.time_step(o.time_step), o, run);
  if(o.has_relative_time_step) return with_fidelity(np.relative_time_step(o.relative_time_step), o, run);
  return with_fidelity(np, o, run);
}

std::string strip_library_prefix(const std::string& what)
{
  const std::string prefix = "Anisotropic_fairing: ";
  return what.compare(0, prefix.size(), prefix) == 0 ? what.substr(prefix.size()) : what;
}

typedef AF::Loop_limit_surface<Mesh> Limit;

// The library's Output_positions::LIMIT_SURFACE write-back, redone on the faired control points that
// the mesh holds: the exact limit normals (and the curvature) need those control points, which that
// output replaces, and the library has no public call that writes the limit points and also returns
// the control points. As the library does, boundary and isolated vertices keep their (held) positions
// and attribute values. The positions agree with the library's to the order of the floating-point sums
// (about 1 ulp; cli_limit_normals_keep_positions checks 1e-14 on bumpy.off). When the noise stop ends a
// run before its first step (the input's own limit surface already off it by more than the noise), the
// positions are the same blend of the input and its limit points, `Fairing_report::limit_weight`; the
// normals are then the limit surface's at its own points.
void write_limit_surface(Mesh& mesh, const Limit& limit, bool normals, std::vector<std::vector<double>>* attribute_values,
                         double limit_weight)
{
  std::vector<Point> input;
  if(limit_weight < 1) input.assign(mesh.points().begin(), mesh.points().end());
  if(normals) limit.limit_normals(mesh.property_map<Vertex_index, Vector>("v:normal").first);
  std::vector<std::pair<Vertex_index, Point>> held;
  std::vector<std::pair<Vertex_index, std::vector<double>>> held_values;
  for(Vertex_index v : mesh.vertices())
    if(mesh.is_border(v) || mesh.is_isolated(v))
    {
      held.emplace_back(v, mesh.point(v));
      if(attribute_values) held_values.emplace_back(v, (*attribute_values)[std::size_t(v)]);
    }
  limit.limit_positions(mesh.points());
  if(limit_weight < 1)
    for(Vertex_index v : mesh.vertices())
    {
      const Point& p0 = input[std::size_t(v)];
      const Point& p = mesh.point(v);
      mesh.point(v) = Point(p0.x() + limit_weight * (p.x() - p0.x()), p0.y() + limit_weight * (p.y() - p0.y()),
                            p0.z() + limit_weight * (p.z() - p0.z()));
    }
  if(attribute_values)
  {
    const Attribute_vectors map{attribute_values};
    limit.limit_values(map, map);
  }
  for(const auto& h : held) mesh.point(h.first) = h.second;
  for(const auto& h : held_values) (*attribute_values)[std::size_t(h.first)] = h.second;
}

// The library holds within the bounds what it writes, here the control points; the limit points computed
// from them are put within the bounds the same way (internal::clamp_to_bound: a vertex farther off goes
// onto the bound along the line to its input position), and the report's largest deviations and clamped
// vertices are those written.
void bound_limit_points(Mesh& mesh, const std::vector<Point>& input, std::vector<std::vector<double>>* values,
                        const std::vector<std::vector<double>>& input_values, const Options& o, AF::Fairing_report& report)
{
  namespace I = AF::internal;
  if(input.empty()) return;
  const std::size_t n = mesh.number_of_vertices();
  const Eigen::Index d = values && n > 0 ? Eigen::Index((*values)[0].size()) : 0;
  I::Control_matrix Y(Eigen::Index(n), 3 + d), Y0(Eigen::Index(n), 3 + d);
  for(Vertex_index v : mesh.vertices())
  {
    const Eigen::Index i = Eigen::Index(v);
    Y.row(i).head(3) << mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z();
    Y0.row(i).head(3) << input[std::size_t(i)].x(), input[std::size_t(i)].y(), input[std::size_t(i)].z();
    for(Eigen::Index k = 0; k < d; ++k) { Y(i, 3 + k) = (*values)[std::size_t(i)][std::size_t(k)]; Y0(i, 3 + k) = input_values[std::size_t(i)][std::size_t(k)]; }
  }
  const double none = std::numeric_limits<double>::infinity();
  const I::Column_bound geometry{ 0, 3, report.maximum_deviation > 0 ? report.maximum_deviation : none };
  const I::Column_bound attributes{ 3, d, o.attribute_bound > 0 ? o.attribute_bound : none };
  const std::vector<bool> written(n, true);   // held vertices kept their input values: deviation 0
  std::vector<bool> moved(n, false);
  I::clamp_to_bound(Y, Y0, geometry, written, moved);
  I::clamp_to_bound(Y, Y0, attributes, written, moved);
  for(Vertex_index v : mesh.vertices())
  {
    const Eigen::Index i = Eigen::Index(v);
    mesh.point(v) = Point(Y(i, 0), Y(i, 1), Y(i, 2));
    for(Eigen::Index k = 0; k < d; ++k) (*values)[std::size_t(i)][std::size_t(k)] = Y(i, 3 + k);
  }
  report.largest_deviation = I::largest_written_deviation(Y, Y0, geometry, written);
  report.largest_attribute_deviation = I::largest_written_deviation(Y, Y0, attributes, written);
  report.clamped_vertices = std::size_t(std::count(moved.begin(), moved.end(), true));
}

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

  Mesh mesh;
  Input_info info;
  read_input(o.input, mesh, info, o.repair);
  r.mesh_read = true;
  r.vertices = mesh.number_of_vertices();
  r.faces = mesh.number_of_faces();

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
  // with a bound and the limit points computed here from the control points the library wrote (below),
  // the bound is applied to those limit points again: the input, to measure them against
  const bool bounded = o.has_bound || o.has_relative_bound || o.attribute_bound > 0;
  std::vector<Point> input_points;
  std::vector<std::vector<double>> input_values;
  if(bounded) { input_points.assign(mesh.points().begin(), mesh.points().end()); input_values = attribute_values; }
  // without attributes to fair, GEOMETRY_ONLY: the attribute map is then neither read nor written
  const AF::Attribute_mode library_mode = fair_attributes ? mode : AF::Attribute_mode::GEOMETRY_ONLY;

  // Exact limit normals need the control points: see the comment at the top of this file. With
  // --mode attributes the geometry is fixed: positions and input normals are written as they are.
  // The curvature of the faired limit surface needs its control points too.
  const bool limit_output = o.element == AF::Finite_element::LOOP && o.output_positions == AF::Output_positions::LIMIT_SURFACE;
  const bool exact_limit_normals = info.has_normals && limit_output && fair_geometry;
  const bool limit_from_control = (exact_limit_normals || o.curvature) && limit_output && fair_geometry;
  const AF::Output_positions library_output = limit_from_control ? AF::Output_positions::CONTROL_POINTS : o.output_positions;

  const unsigned int max_steps = o.steps;
  const bool quiet = o.quiet;
  std::size_t last_step = 0;
  auto progress = [max_steps, quiet, &last_step](const AF::Fairing_step& s) {
    // with automatic parameters the library also runs the isotropic and the uniform fourth-order flow, and
    // each flow once more on a perturbed copy of the input (to estimate its error), to keep the best result
    if(!quiet && s.step <= last_step)
      std::fprintf(stderr, "another run of the comparison (anisotropic, isotropic, uniform fourth-order flow; then each on a perturbed copy):\n");
    last_step = s.step;
    if(!quiet)
      std::fprintf(stderr, "step %zu/%u  t=%.6g  area=%.6g  int|H|^2=%.6g  max disp=%.6g  %d %s  %.3fs+%.3fs\n",
                   s.step, max_steps, s.time, s.area, s.H_integral, s.max_displacement, s.solver_iterations,
                   s.direct_solve ? "factorisation" : "its",
                   s.assemble_seconds, s.solve_seconds);
    return true;
  };
  auto fair = [&mesh, &attribute_map](const auto& np) {
    return AF::anisotropic_fairing(mesh, mesh.points(), attribute_map, np);
  };

  const AF::Stopping_criteria stop = o.stop == "off" ? AF::Stopping_criteria::none()
                                  : o.stop == "paper" ? AF::Stopping_criteria()
                                  : o.stop == "noise" || (automatic_parameters(o) && effective_mode(o) != AF::Attribute_mode::ATTRIBUTES_ONLY)
                                    ? AF::Stopping_criteria::automatic()
                                  : AF::Stopping_criteria();
  const auto base = AF::parameters::number_of_iterations(max_steps)
                      .stopping_criteria(stop)
                      .finite_element(o.element)
                      .output_positions(library_output)
                      .linear_solver(o.solver)
                      .boundary_handling(o.boundary)
                      .quadrature_degree(o.quadrature_degree)
                      .attribute_mode(library_mode)
                      .attribute_weight(o.attribute_weight)
                      .flow_order(o.order)
                      .callback(progress);
  try
  {
    AF::Anisotropic_diffusion_tensor tensor(o.lambda, true, o.epsilon, o.normal_motion_only);
    if(automatic_tensor(o)) tensor = AF::Anisotropic_diffusion_tensor::automatic();
    r.report = o.anisotropic ? with_time_step(base.diffusion_tensor(tensor), o, fair)
               : o.uniform   ? with_time_step(base.diffusion_tensor(AF::Uniform_diffusion_tensor()), o, fair)
                             : with_time_step(base.diffusion_tensor(AF::Isotropic_diffusion_tensor()), o, fair);
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

  if(o.curvature || limit_from_control)
  {
    // The mesh holds the faired control points (or, with --output control or --mode attributes, the
    // points written, whose limit surface is the faired or fixed surface). The limit surface is a
    // snapshot: one serves the curvature and the limit positions and normals. Only the curvature's
    // averages use the quadrature (the run's degree); otherwise degree 4 is the cheapest set-up.
    const Limit limit(mesh, AF::parameters::quadrature_degree(o.curvature ? o.quadrature_degree : 4));
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
    if(limit_from_control)
    {
      write_limit_surface(mesh, limit, exact_limit_normals, fair_attributes ? &attribute_values : nullptr,
                          r.report.limit_weight);
      bound_limit_points(mesh, input_points, fair_attributes ? &attribute_values : nullptr, input_values, o, r.report);
    }
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
  // back into the input's own properties (rounded, clamped), which are written with the mesh
  if(fair_attributes) scatter(mesh, columns, attribute_values);
  if(o.has_attribute_weight && mode != AF::Attribute_mode::COUPLED)
    info.warnings.push_back("--attribute-weight has no effect without --mode coupled");

  // printed once OUTPUT exists, so that on failure the failure is the only line starting with "anisotropic_fairing: "
  std::vector<std::string> warnings = info.warnings;
  const std::vector<std::string> dropped = dropped_properties(mesh, out_format);
  if(!dropped.empty())
  {
    std::string list;
    for(const std::string& p : dropped) list += (list.empty() ? "" : ", ") + p;
    warnings.push_back(o.output + " cannot hold the input's " + list + ": not written");
  }

  // write next to OUTPUT, then write the report, then rename: OUTPUT appears only if all succeeded
  const fs::path tmp = temporary_next_to(o.output);
  try
  {
    write_mesh(tmp.string(), out_format, mesh, info, info.has_normals);
  }
  catch(const Failure&)
  {
    std::error_code ec;
    fs::remove(tmp, ec);
    fail("write_error", "cannot write " + o.output);
  }
  r.output_written = true;  // as far as the report is concerned
  if(!o.report.empty())
  {
    // wall time up to here; the rename is negligible
    if(!write_file_atomically(o.report, report_json(o, r, elapsed_seconds())))
    {
      std::error_code ec;
      fs::remove(tmp, ec);
      r.output_written = false;
      throw Failure{1, "write_error", "cannot write the report " + o.report};
    }
  }
  std::error_code ec;
  fs::rename(tmp, o.output, ec);
  if(ec)
  {
    std::error_code ec2;
    fs::remove(tmp, ec2);
    r.output_written = false;
    if(!o.report.empty()) fs::remove(o.report, ec2);  // it described an output that does not exist
    fail("write_error", "cannot write " + o.output + ": " + ec.message());
  }
  for(const std::string& w : warnings)
    std::fprintf(stderr, "anisotropic_fairing: warning: %s\n", one_line(w).c_str());
  for(const std::string& n : info.notes) std::fprintf(stderr, "anisotropic_fairing: %s\n", one_line(n).c_str());
  if(!quiet && !r.report.choices.empty())
    std::fprintf(stderr, "anisotropic_fairing: automatic parameters: %s\n", one_line(r.report.choices).c_str());
  if(r.report.stop_reason == AF::Stop_reason::STEP_REJECTED)
    std::fprintf(stderr, "anisotropic_fairing: warning: stopped early: %s\n", one_line(r.report.message).c_str());
  if(!quiet)
    std::fprintf(stderr, "anisotropic_fairing: wrote %s (%zu vertices, %zu steps, stopped: %s, %.3f s)\n",
                 o.output.c_str(), r.vertices, r.report.steps.size(), AF::to_string(r.report.stop_reason),
                 r.report.total_seconds);
  return 0;
}

} // namespace af_tool
