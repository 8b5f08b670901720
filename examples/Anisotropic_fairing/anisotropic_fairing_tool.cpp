// anisotropic_fairing -- the command-line program of the Anisotropic_fairing package.
//
//   anisotropic_fairing INPUT OUTPUT [options]        (anisotropic_fairing --help for the options)
//
// Reads a triangle mesh (OFF, OBJ or PLY; closed or with borders), fairs it with CGAL::Anisotropic_fairing::
// anisotropic_fairing() and writes the result (OFF, OBJ or PLY, chosen by OUTPUT's extension) with
// full double precision, the vertices in their input order and every vertex property of the input
// that the output format can hold. Optionally writes a JSON report with the statistics of every step.
//
// Failure policy: on any failure the program prints ONE line starting with "anisotropic_fairing: " on
// stderr, exits non-zero (2 for usage errors, 1 otherwise) and creates no OUTPUT: the mesh is written
// to a temporary file next to OUTPUT, which is renamed to OUTPUT only when everything succeeded.
//
// Normals: if the input carries vertex normals (NOFF, PLY nx/ny/nz, OBJ vn) the normals written are
// those of the faired surface, never the stale input ones:
//  - Loop element with `--output limit`: the fairing is run with Output_positions::CONTROL_POINTS,
//    then a Loop_limit_surface is built on the faired control mesh, and its limit_positions() and
//    limit_normals() are written. limit_positions() applies the same closed-form limit masks as the
//    library's Output_positions::LIMIT_SURFACE to the same control points, so the positions are the
//    ones a LIMIT_SURFACE run writes up to the order of the floating-point sums (about 1e-16
//    relative; the test cli_limit_normals_keep_positions checks 1e-14 absolute on bumpy.off), and the
//    normals are the exact normals of the faired limit surface at those points.
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

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/OFF.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/boost/graph/IO/OBJ.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>
#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>

#include "mesh_file_check.h"
#include "mesh_repair.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace AF = CGAL::Anisotropic_fairing;
namespace fs = std::filesystem;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef Mesh::Face_index Face_index;
typedef Mesh::Property_map<Vertex_index, Vector> Normal_map;

namespace {

const char* const usage_text =
"usage: anisotropic_fairing INPUT OUTPUT [options]\n"
"\n"
"Fairs the triangle mesh INPUT by geometric diffusion with Loop-subdivision finite elements\n"
"(Bajaj & Xu 2003; isotropic tensor: mean-curvature flow, or the anisotropic, feature-preserving one)\n"
"and writes the result to OUTPUT.\n"
"INPUT and OUTPUT are OFF, OBJ or PLY files (by extension; the formats may differ); INPUT may also be\n"
"STL (coincident corners are merged into vertices) or a PLY of triangle strips. Every file is checked\n"
"before it is read: a bad count, index, number or a face set that is not an oriented 2-manifold is\n"
"refused with the line or element named (see --repair). The output keeps\n"
"the vertex order, full double precision and every vertex property of the input that its format can\n"
"hold (PLY: normals, colours, numeric properties; OFF: colours, texture coordinates, face colours;\n"
"OBJ: normals, texture coordinates; a warning names the dropped ones).\n"
"If the input has vertex normals, the normals of the faired surface are written: for the Loop element\n"
"with --output limit the exact normals of the faired limit surface (and the limit points), otherwise\n"
"the vertex normals of the output mesh (CGAL::Polygon_mesh_processing::compute_vertex_normals);\n"
"with --mode attributes (geometry unchanged) the input's normals (OBJ: recomputed).\n"
"Borders (holes, scan boundaries) are held fixed, and boundary vertices are written unchanged;\n"
"vertices on no face are left as they are.\n"
"With --attributes, per-vertex attributes (a function on the surface: scalars, colours, texture\n"
"coordinates) are faired too, all in one solve, and written back into their own properties with their\n"
"own types (integers rounded and clamped, colours to 0..255 with alpha kept); boundary and isolated\n"
"vertices keep their values. Like the positions, the values written are those of the faired limit\n"
"function at the vertices (--output limit: Loop limit masks; even 0 steps smooth them) or the\n"
"control values (--output control).\n"
"\n"
"Without --time-step and --relative-time-step the parameters are automatic: the program estimates\n"
"the noise of the mesh itself, fairs with the anisotropic tensor (unless --tensor says otherwise) in\n"
"steps of 0.1 h^2 (h: the mean edge length) and stops when the surface has moved off the input by\n"
"the noise (a noise-free mesh is left nearly as it is); the report's choices say what was chosen.\n"
"\n"
"options:\n"
"  --time-step T             time step tau in model units (length^2), as in the paper\n"
"  --relative-time-step R    time step in units of l^2, l = sqrt(area/4pi) of the input (per connected\n"
"                            component); give at most one of the two (neither: automatic parameters)\n"
"  --steps N                 the most time steps to run (default 10; with automatic parameters 200)\n"
"  --stop auto|noise|paper|off   auto (default): noise with automatic parameters, paper otherwise;\n"
"                            noise: stop when the surface has moved off the input by the estimated\n"
"                            noise; paper: the criteria (27)-(29) and a steady-state test; off: exactly\n"
"                            N steps. A step that would fold the surface is retried with a smaller\n"
"                            time step, and the run ends on the last sound surface if that fails\n"
"  --fidelity W              fidelity weight omega in model units (1/time), as in the paper (default 0)\n"
"  --relative-fidelity W     fidelity weight in units of 1/l^2; give at most one of the two\n"
"  --element loop|linear     Loop limit-surface elements (default) or linear (P1) elements\n"
"  --output limit|control    write the points of the faired limit surface (default) or the faired\n"
"                            control points (the mesh whose Loop limit surface is the faired surface)\n"
"  --tensor isotropic|anisotropic|uniform   the diffusion tensor: isotropic (mean-curvature flow; the\n"
"                            default with a time step), anisotropic (curvature-driven, feature-preserving:\n"
"                            Anisotropic_diffusion_tensor; the default with automatic parameters, its\n"
"                            threshold and prefilter then chosen from the mesh unless given, and the\n"
"                            isotropic (or uniform) result kept instead when its normals vary clearly\n"
"                            less at the noise level: the report's tensor and choices say which) or uniform (the\n"
"                            uniform Laplacian's weights, Uniform_diffusion_tensor: for noisy scans with a\n"
"                            graded triangulation; it rounds creases like the isotropic tensor)\n"
"  --lambda L                the anisotropic tensor's feature threshold, a curvature in units of 1/l\n"
"                            (default 2): principal curvatures above it are diffused less\n"
"  --epsilon E               the anisotropic tensor reads curvature on the surface after an isotropic\n"
"                            step of E (units of l^2; the paper's prefiltered M_eps); default 1e-3;\n"
"                            0: on the current surface\n"
"  --tangential-motion remove|keep  the anisotropic flow moves control points along the surface's\n"
"                            normal only (remove, the default: the tangential part of div(D grad x)\n"
"                            folds noisy meshes) or also within it, as the paper does (keep)\n"
"  --solver auto|cg|cholesky        linear solver: automatic (default), conjugate gradients, sparse LDL^T\n"
"  --boundary curve|vertices        on a mesh with borders, hold the limit boundary curve (default: the\n"
"                            boundary vertices and the interior vertices that shape the curve) or only\n"
"                            the boundary vertices (the paper's choice; the border may slide)\n"
"  --quadrature-degree 4|6|8        Gauss rule per face for the Loop element (default 8)\n"
"  --attributes NAME,...     the per-vertex attributes to fair, in this order, as one vector per\n"
"                            vertex: PLY: any numeric vertex property by name (quality, u, v, s, t,\n"
"                            ...), red, green, blue, alpha, or color (= red,green,blue); OFF: color\n"
"                            (COFF), red, green, blue, uv (texture coordinates); OBJ: uv (the vt, if\n"
"                            one per vertex). Not x, y, z, nx, ny, nz. A name the input does not have\n"
"                            fails (exit 1) and the message lists the available ones\n"
"  --mode separate|coupled|attributes|geometry   how they are faired: separate (the default with\n"
"                            --attributes): with the operator of the geometry's surface; coupled: as one\n"
"                            surface with the geometry in R^(3+d); attributes: the geometry is fixed (not\n"
"                            written) and only the attributes diffuse on it; geometry (the default\n"
"                            without --attributes): the attributes are not faired. coupled and\n"
"                            attributes need --attributes\n"
"  --attribute-weight W      coupled: the length that one attribute unit counts for (> 0, default 1)\n"
"  --curvature               also write the curvature of the faired Loop limit surface at each vertex\n"
"                            as the PLY vertex properties k1, k2 (principal curvatures, k1 <= k2) and\n"
"                            mean_curvature ((k1 + k2)/2), w.r.t. the oriented normal (negative on a\n"
"                            convex surface oriented outward); at vertices of valence other than 6,\n"
"                            where the limit surface has no finite curvature, an average over the\n"
"                            vertex's faces (Loop_limit_surface::vertex_curvatures). Needs a .ply\n"
"                            OUTPUT and the Loop element\n"
"  --report FILE.json        write per-step statistics (also, with status and message, on failure)\n"
"  --repair                  if the faces are not an oriented 2-manifold, repair them with CGAL's\n"
"                            Polygon_mesh_processing (drop faces that repeat a vertex, orient, split\n"
"                            non-manifold vertices and edges; the input's vertex properties other\n"
"                            than positions are then not kept), and on any mesh stitch coinciding\n"
"                            borders and remove vertices on no face; each change is printed\n"
"  --quiet                   no progress line per step on stderr\n"
"  --help                    print this help and exit\n"
"Options also accept the form --option=value.\n"
"\n"
"JSON report: status, message, input, output, vertices, faces, element, output_positions, tensor, lambda,\n"
"lambda_model_units, epsilon, tangential_motion, automatic_parameters, choices, noise_level,\n"
"noise_deviation, noise_displacement, components, rejected_steps,\n"
"solver, requested_solver, stop, max_steps, quadrature_degree, time_step, relative_time_step, scale,\n"
"fidelity_weight, relative_fidelity_weight, mean_edge_length, normals, curvature, mode, attributes,\n"
"attribute_dimension, attribute_weight, boundary_handling,\n"
"boundary_vertices, boundary_held_vertices, boundary_loops, isolated_vertices, constrained_vertices,\n"
"stop_reason, initial {area,\n"
"energy, H_integral}, steps [{step, time, solver_iterations, residual, area, energy, H_integral,\n"
"max_displacement, step_displacement, assemble_seconds, solve_seconds, direct_solve, time_step,\n"
"noise_displacement}], setup_seconds,\n"
"total_seconds (the fairing call), wall_seconds (the whole program). Unknown values are null.\n"
"\n"
"exit status: 0 success; 1 failure (unreadable input, a mesh that is not a 2-manifold triangle mesh,\n"
"an attribute the input does not have, fairing failure, unwritable output or report); 2 usage error\n"
"(including OUTPUT or --report naming the INPUT or each other).\n"
"On failure one line starting with\n"
"\"anisotropic_fairing: \" is printed on stderr and OUTPUT is not created (an existing one is left as is).\n";

const std::chrono::steady_clock::time_point program_start = std::chrono::steady_clock::now();

double elapsed_seconds()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - program_start).count();
}

// Thrown to end the program: the one-line message, the exit code and the report's status.
struct Failure
{
  int exit_code;
  std::string status;
  std::string message;
};

[[noreturn]] void usage_error(const std::string& message) { throw Failure{2, "usage_error", message + " (see --help)"}; }
[[noreturn]] void fail(const std::string& status, const std::string& message) { throw Failure{1, status, message}; }

std::string one_line(std::string s)
{
  for(char& c : s)
    if(c == '\n' || c == '\r' || c == '\t') c = ' ';
  while(!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

// ------------------------------------------------------------------------------------------------
// Options
// ------------------------------------------------------------------------------------------------
enum class Format { OFF, OBJ, PLY, STL };   // in the order of af_tool::Mesh_format

struct Options;
bool automatic_parameters(const Options& o);

struct Options
{
  std::string input, output, report;
  bool has_time_step = false, has_relative_time_step = false;
  double time_step = 0, relative_time_step = 0;
  unsigned int steps = 10;
  bool has_steps = false;
  std::string stop = "auto";   // auto, noise, paper, off
  bool has_fidelity = false, has_relative_fidelity = false;
  double fidelity = 0, relative_fidelity = 0;
  AF::Finite_element element = AF::Finite_element::LOOP;
  AF::Output_positions output_positions = AF::Output_positions::LIMIT_SURFACE;
  AF::Linear_solver solver = AF::Linear_solver::AUTOMATIC;
  AF::Boundary_handling boundary = AF::Boundary_handling::HOLD_BOUNDARY_CURVE;
  int quadrature_degree = 8;
  bool anisotropic = false, uniform = false, has_tensor = false, has_lambda = false, has_epsilon = false;
  bool normal_motion_only = true, has_tangential_motion = false;   // --tangential-motion remove|keep
  double lambda = 2.0, epsilon = 1e-3;
  std::vector<std::string> attributes;   // the names given to --attributes, in their order
  bool has_mode = false;
  AF::Attribute_mode mode = AF::Attribute_mode::GEOMETRY_ONLY;
  bool has_attribute_weight = false;
  double attribute_weight = 1;
  bool curvature = false;   // --curvature: k1, k2, mean_curvature written as PLY vertex properties
  bool quiet = false;
  bool repair = false;           // --repair: make a non-manifold or inconsistently oriented input usable
  bool report_refused = false;   // the report's path collides with the input or the output: never written
  bool help = false;
};

bool automatic_parameters(const Options& o) { return !o.has_time_step && !o.has_relative_time_step; }
// the anisotropic tensor whose threshold and prefilter are chosen from the mesh
bool automatic_tensor(const Options& o)
{
  return automatic_parameters(o) && o.anisotropic && !o.has_lambda && !o.has_epsilon && o.normal_motion_only;
}

// --mode, or its default: separate with --attributes, geometry without
AF::Attribute_mode effective_mode(const Options& o)
{
  if(o.has_mode) return o.mode;
  return o.attributes.empty() ? AF::Attribute_mode::GEOMETRY_ONLY : AF::Attribute_mode::SEPARATE;
}

const char* mode_name(AF::Attribute_mode m)
{
  switch(m)
  {
    case AF::Attribute_mode::COUPLED: return "coupled";
    case AF::Attribute_mode::SEPARATE: return "separate";
    case AF::Attribute_mode::ATTRIBUTES_ONLY: return "attributes";
    default: return "geometry";
  }
}

// "quality,red" -> {"quality", "red"}; blanks around a name are ignored
std::vector<std::string> parse_attribute_list(const std::string& text)
{
  std::vector<std::string> names;
  std::string::size_type start = 0;
  for(;;)
  {
    const std::string::size_type comma = text.find(',', start);
    std::string name = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::string::size_type b = name.find_first_not_of(" \t"), e = name.find_last_not_of(" \t");
    name = b == std::string::npos ? std::string() : name.substr(b, e - b + 1);
    if(name.empty()) usage_error("--attributes expects NAME,NAME,..., not '" + text + "'");
    if(std::find(names.begin(), names.end(), name) != names.end())
      usage_error("--attributes names '" + name + "' twice");
    names.push_back(name);
    if(comma == std::string::npos) break;
    start = comma + 1;
  }
  return names;
}

double parse_double(const std::string& flag, const std::string& text)
{
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if(text.empty() || end != text.c_str() + text.size() || (errno != ERANGE && !std::isfinite(v)))
    usage_error(flag + " expects a finite number, not '" + text + "'");
  if(errno == ERANGE && std::abs(v) > 1) usage_error(flag + " " + text + " is beyond the range of double precision");
  if(errno == ERANGE)   // strtod says so below the smallest normal double, where the arithmetic loses its digits
    usage_error(flag + " " + text + " is below the smallest normal double (2.2e-308), too small to compute with");
  return v;
}

unsigned int parse_unsigned(const std::string& flag, const std::string& text)
{
  errno = 0;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
  if(text.empty() || text[0] == '-' || text[0] == '+' || end != text.c_str() + text.size() || errno == ERANGE ||
     v > (std::numeric_limits<unsigned int>::max)())
    usage_error(flag + " expects a non-negative integer, not '" + text + "'");
  return static_cast<unsigned int>(v);
}

std::string extension(const std::string& path)
{
  std::string e = fs::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return e;
}

bool format_of(const std::string& path, Format& f)
{
  const std::string e = extension(path);
  if(e == ".off") f = Format::OFF;
  else if(e == ".obj") f = Format::OBJ;
  else if(e == ".ply") f = Format::PLY;
  else if(e == ".stl") f = Format::STL;
  else return false;
  return true;
}

// Whether two paths name one file: the same file if both exist (links included), else the same path.
bool same_file(const std::string& a, const std::string& b)
{
  std::error_code ec1, ec2;
  if(fs::exists(a, ec1) && fs::exists(b, ec2))
  {
    std::error_code ec;
    return fs::equivalent(a, b, ec);
  }
  return fs::weakly_canonical(a, ec1) == fs::weakly_canonical(b, ec2);
}

// Reads the options. `o.report` is set as soon as it is seen, so that a later usage error can still
// be written into the report.
void parse_arguments(int argc, char** argv, Options& o)
{
  std::vector<std::string> positional;
  Failure first_error{0, "", ""};
  bool has_error = false;
  for(int i = 1; i < argc; ++i)
  {
    std::string arg = argv[i];
    if(arg.size() < 2 || arg[0] != '-') { positional.push_back(arg); continue; }
    if(arg == "--") { for(++i; i < argc; ++i) positional.push_back(argv[i]); break; }
    std::string value;
    bool has_inline_value = false;
    const std::size_t eq = arg.find('=');
    if(arg.compare(0, 2, "--") == 0 && eq != std::string::npos)
    {
      value = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
      has_inline_value = true;
    }
    auto flag_without_value = [&]() {
      if(has_inline_value) usage_error(arg + " takes no value");
    };
    auto next = [&]() -> std::string {
      if(has_inline_value) return value;
      if(i + 1 >= argc) usage_error(arg + " needs a value");
      return argv[++i];
    };
    try
    {
      if(arg == "--help" || arg == "-h") { flag_without_value(); o.help = true; }
      else if(arg == "--quiet" || arg == "-q") { flag_without_value(); o.quiet = true; }
      else if(arg == "--repair") { flag_without_value(); o.repair = true; }
      else if(arg == "--curvature") { flag_without_value(); o.curvature = true; }
      else if(arg == "--report") o.report = next();
      else if(arg == "--time-step")
      {
        o.time_step = parse_double(arg, next());
        if(!(o.time_step > 0)) usage_error("--time-step must be positive");
        o.has_time_step = true;
      }
      else if(arg == "--relative-time-step")
      {
        o.relative_time_step = parse_double(arg, next());
        if(!(o.relative_time_step > 0)) usage_error("--relative-time-step must be positive");
        o.has_relative_time_step = true;
      }
      else if(arg == "--steps") { o.steps = parse_unsigned(arg, next()); o.has_steps = true; }
      else if(arg == "--stop")
      {
        o.stop = next();
        if(o.stop != "auto" && o.stop != "noise" && o.stop != "paper" && o.stop != "off")
          usage_error("--stop expects auto, noise, paper or off, not '" + o.stop + "'");
      }
      else if(arg == "--fidelity")
      {
        o.fidelity = parse_double(arg, next());
        if(!(o.fidelity >= 0)) usage_error("--fidelity must be >= 0");
        o.has_fidelity = true;
      }
      else if(arg == "--relative-fidelity")
      {
        o.relative_fidelity = parse_double(arg, next());
        if(!(o.relative_fidelity >= 0)) usage_error("--relative-fidelity must be >= 0");
        o.has_relative_fidelity = true;
      }
      else if(arg == "--element")
      {
        const std::string v = next();
        if(v == "loop") o.element = AF::Finite_element::LOOP;
        else if(v == "linear") o.element = AF::Finite_element::LINEAR;
        else usage_error("--element expects loop or linear, not '" + v + "'");
      }
      else if(arg == "--output")
      {
        const std::string v = next();
        if(v == "limit") o.output_positions = AF::Output_positions::LIMIT_SURFACE;
        else if(v == "control") o.output_positions = AF::Output_positions::CONTROL_POINTS;
        else usage_error("--output expects limit or control, not '" + v + "'");
      }
      else if(arg == "--tensor")
      {
        const std::string v = next();
        o.has_tensor = true;
        o.anisotropic = v == "anisotropic";
        o.uniform = v == "uniform";
        if(v != "anisotropic" && v != "isotropic" && v != "uniform")
          usage_error("--tensor expects isotropic, anisotropic or uniform, not '" + v + "'");
      }
      else if(arg == "--solver")
      {
        const std::string v = next();
        if(v == "auto") o.solver = AF::Linear_solver::AUTOMATIC;
        else if(v == "cg") o.solver = AF::Linear_solver::CONJUGATE_GRADIENT;
        else if(v == "cholesky") o.solver = AF::Linear_solver::CHOLESKY;
        else usage_error("--solver expects auto, cg or cholesky, not '" + v + "'");
      }
      else if(arg == "--boundary")
      {
        const std::string v = next();
        if(v == "curve") o.boundary = AF::Boundary_handling::HOLD_BOUNDARY_CURVE;
        else if(v == "vertices") o.boundary = AF::Boundary_handling::HOLD_BOUNDARY_VERTICES;
        else usage_error("--boundary expects curve or vertices, not '" + v + "'");
      }
      else if(arg == "--lambda")
      {
        o.lambda = parse_double(arg, next());
        o.has_lambda = true;
        if(!(o.lambda > 0)) usage_error("--lambda must be positive");
      }
      else if(arg == "--epsilon")
      {
        o.epsilon = parse_double(arg, next());
        o.has_epsilon = true;
        if(!(o.epsilon >= 0)) usage_error("--epsilon must be >= 0");
      }
      else if(arg == "--tangential-motion")
      {
        const std::string v = next();
        if(v == "remove") o.normal_motion_only = true;
        else if(v == "keep") o.normal_motion_only = false;
        else usage_error("--tangential-motion expects remove or keep, not '" + v + "'");
        o.has_tangential_motion = true;
      }
      else if(arg == "--quadrature-degree")
      {
        const std::string v = next();
        if(v == "4" || v == "6" || v == "8") o.quadrature_degree = std::atoi(v.c_str());
        else usage_error("--quadrature-degree expects 4, 6 or 8, not '" + v + "'");
      }
      else if(arg == "--attributes") o.attributes = parse_attribute_list(next());
      else if(arg == "--mode")
      {
        const std::string v = next();
        if(v == "separate") o.mode = AF::Attribute_mode::SEPARATE;
        else if(v == "coupled") o.mode = AF::Attribute_mode::COUPLED;
        else if(v == "attributes") o.mode = AF::Attribute_mode::ATTRIBUTES_ONLY;
        else if(v == "geometry") o.mode = AF::Attribute_mode::GEOMETRY_ONLY;
        else usage_error("--mode expects separate, coupled, attributes or geometry, not '" + v + "'");
        o.has_mode = true;
      }
      else if(arg == "--attribute-weight")
      {
        o.attribute_weight = parse_double(arg, next());
        if(!(o.attribute_weight > 0)) usage_error("--attribute-weight must be positive");
        o.has_attribute_weight = true;
      }
      else usage_error("unknown option " + arg);
    }
    catch(const Failure& f)
    {
      // keep reading, so that a --report given later is still honoured, then report the first problem
      if(!has_error) { first_error = f; has_error = true; }
    }
  }
  if(o.help) return;
  if(has_error) throw first_error;
  if(positional.size() < 2) usage_error("INPUT and OUTPUT are required");
  if(positional.size() > 2) usage_error("unexpected argument '" + positional[2] + "'");
  o.input = positional[0];
  o.output = positional[1];
  if(o.has_time_step && o.has_relative_time_step) usage_error("give either --time-step or --relative-time-step, not both");
  if(o.has_fidelity && o.has_relative_fidelity) usage_error("give either --fidelity or --relative-fidelity, not both");
  if(o.attributes.empty() && (o.mode == AF::Attribute_mode::COUPLED || o.mode == AF::Attribute_mode::ATTRIBUTES_ONLY))
    usage_error(std::string("--mode ") + mode_name(o.mode) + " needs --attributes");
  // without a time step the parameters are automatic: the anisotropic tensor unless --tensor is given
  if(automatic_parameters(o) && !o.has_tensor) o.anisotropic = true;
  if(!o.has_steps && automatic_parameters(o)) o.steps = AF::automatic_maximum_steps;
  const bool asked_anisotropic = o.has_tensor && o.anisotropic;   // the tensor's options need it said
  if(o.has_lambda && !asked_anisotropic) usage_error("--lambda needs --tensor anisotropic");
  if(o.has_epsilon && !asked_anisotropic) usage_error("--epsilon needs --tensor anisotropic");
  if(o.has_tangential_motion && !asked_anisotropic) usage_error("--tangential-motion needs --tensor anisotropic");
  Format f;
  if(!format_of(o.input, f)) usage_error("INPUT must be an .off, .obj, .ply or .stl file: " + o.input);
  if(!format_of(o.output, f) || f == Format::STL) usage_error("OUTPUT must be an .off, .obj or .ply file: " + o.output);
  // nothing written may overwrite the input or another file written (the report is not written either)
  if(same_file(o.output, o.input)) usage_error("OUTPUT " + o.output + " is the INPUT: it would be overwritten");
  if(!o.report.empty() && same_file(o.report, o.input))
  {
    o.report_refused = true;
    usage_error("the report " + o.report + " is the INPUT: it would be overwritten");
  }
  if(!o.report.empty() && same_file(o.report, o.output))
  {
    o.report_refused = true;
    usage_error("the report " + o.report + " is the OUTPUT: one would overwrite the other");
  }
  if(o.curvature && f != Format::PLY)
    usage_error("--curvature needs a .ply OUTPUT (k1, k2 and mean_curvature are written as vertex properties)");
  if(o.curvature && o.element != AF::Finite_element::LOOP)
    usage_error("--curvature needs --element loop (the linear element has no curvature)");
}

// ------------------------------------------------------------------------------------------------
// Capturing what CGAL's readers and writers print, so that a failure stays a one-line message
// ------------------------------------------------------------------------------------------------
class Capture_streams
{
public:
  Capture_streams() : cerr_(std::cerr.rdbuf(err_.rdbuf())), cout_(std::cout.rdbuf(out_.rdbuf())) {}
  ~Capture_streams() { std::cerr.rdbuf(cerr_); std::cout.rdbuf(cout_); }
  // the first non-empty line printed, if any
  std::string first_line() const
  {
    std::istringstream in(err_.str() + "\n" + out_.str());
    std::string line;
    while(std::getline(in, line))
      if(!one_line(line).empty()) return one_line(line);
    return std::string();
  }
private:
  std::ostringstream err_, out_;
  std::streambuf* cerr_;
  std::streambuf* cout_;
};

// ------------------------------------------------------------------------------------------------
// Input
// ------------------------------------------------------------------------------------------------
struct Input_info
{
  Format format = Format::OFF;
  bool ply_binary = false;
  std::string ply_comments;
  bool has_normals = false;       // the input carries vertex normals (v:normal exists)
  bool normals_read = false;      // ... and their values were read (not for OBJ: CGAL's reader skips vn)
  bool vertex_alpha = false;      // PLY: the vertex alpha was folded into v:color (selectable as "alpha")
  std::string uv_problem;         // OBJ: why its vt could not be kept (empty: none, or kept as v:texcoord)
  std::vector<std::string> warnings;
  std::vector<std::string> notes;   // what was done to read the file (STL corners merged, strips split)
};

typedef K::Point_2 Texcoord;
typedef Mesh::Property_map<Vertex_index, Texcoord> Texcoord_map;   // "v:texcoord", as CGAL's OFF reader makes it

// The texture coordinates of an OBJ file (CGAL's OBJ reader skips vt and the /vt of the faces).
// They are kept only when they are one per vertex: every face corner of a vertex refers to the same
// value (`f a/a` with as many vt as v is the usual case); a texture seam (a vertex with two values)
// or a corner without vt makes them unmatched.
struct Obj_texcoords
{
  bool present = false;   // the file has vt lines
  bool matched = false;   // one value per vertex: `uv` is filled
  std::string problem;    // why not
  bool dropped_w = false; // some vt had a non-zero third component (not kept)
  std::vector<std::array<double, 2>> uv;
};

Obj_texcoords read_obj_texcoords(const std::string& path, std::size_t mesh_vertices)
{
  Obj_texcoords t;
  std::ifstream in(path);
  std::vector<std::array<double, 2>> vt;
  std::vector<long> vt_of;   // per vertex: the vt index it uses, -1 none yet
  std::size_t nv = 0, line_number = 0;
  bool corner_without_vt = false;
  std::string line, token;
  auto set_problem = [&t](const std::string& p) { if(t.problem.empty()) t.problem = p; };
  // an OBJ index (1-based, or negative: relative to the `count` elements read so far) -> 0-based, -1 if invalid
  auto index = [](const std::string& text, std::size_t count) -> long {
    errno = 0;
    char* end = nullptr;
    const long i = std::strtol(text.c_str(), &end, 10);
    if(text.empty() || *end != '\0' || errno == ERANGE || i == 0) return -1;
    const long r = i > 0 ? i - 1 : long(count) + i;
    return r >= 0 && r < long(count) ? r : -1;
  };
  while(std::getline(in, line))
  {
    ++line_number;
    std::istringstream ls(line);
    if(!(ls >> token)) continue;
    if(token == "v") { ++nv; vt_of.push_back(-1); }
    else if(token == "vt")
    {
      t.present = true;
      double c[3] = {0, 0, 0};
      int k = 0;
      while(k < 3 && ls >> token)
      {
        char* end = nullptr;
        c[k] = std::strtod(token.c_str(), &end);
        if(*end != '\0' || !std::isfinite(c[k])) { set_problem("line " + std::to_string(line_number) + ": malformed vt"); break; }
        ++k;
      }
      if(k == 0) set_problem("line " + std::to_string(line_number) + ": malformed vt");
      if(c[2] != 0) t.dropped_w = true;
      vt.push_back({{c[0], c[1]}});
    }
    else if(token == "f")
    {
      while(ls >> token)
      {
        const std::string::size_type s1 = token.find('/');
        const long v = index(token.substr(0, s1), nv);
        if(v < 0) { set_problem("line " + std::to_string(line_number) + ": bad vertex index '" + token + "'"); continue; }
        std::string tex;
        if(s1 != std::string::npos)
        {
          const std::string::size_type s2 = token.find('/', s1 + 1);
          tex = token.substr(s1 + 1, s2 == std::string::npos ? std::string::npos : s2 - s1 - 1);
        }
        if(tex.empty()) { corner_without_vt = true; continue; }
        const long ti = index(tex, vt.size());
        if(ti < 0) { set_problem("line " + std::to_string(line_number) + ": bad texture index '" + token + "'"); continue; }
        long& used = vt_of[std::size_t(v)];
        if(used < 0) used = ti;
        else if(used != ti && vt[std::size_t(used)] != vt[std::size_t(ti)])
          set_problem("vertex " + std::to_string(v) + " (OBJ index " + std::to_string(v + 1) +
                      ") has two texture coordinates, vt " + std::to_string(used + 1) + " and " + std::to_string(ti + 1) +
                      ": a texture seam");
      }
    }
  }
  if(!t.present) return t;
  if(corner_without_vt) set_problem("some face corners have no texture coordinate");
  if(nv != mesh_vertices) set_problem("the file has " + std::to_string(nv) + " v lines but the mesh " + std::to_string(mesh_vertices) + " vertices");
  if(!t.problem.empty()) return t;
  t.uv.resize(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    if(vt_of[i] >= 0) t.uv[i] = vt[std::size_t(vt_of[i])];
    else if(vt.size() == nv) t.uv[i] = vt[i];   // a vertex on no face: its own vt if there is one per v
    else t.uv[i] = {{0, 0}};                    // otherwise (a vertex on no face, never referenced) 0 0
  }
  t.matched = true;
  return t;
}

// What CGAL's OBJ reader drops (it reads only v and f): look for vn, vt and per-vertex colours.
void scan_obj(const std::string& path, bool& normals, bool& textures, bool& colors)
{
  normals = textures = colors = false;
  std::ifstream in(path);
  std::string line;
  while(std::getline(in, line))
  {
    if(line.compare(0, 3, "vn ") == 0 || line.compare(0, 3, "vn\t") == 0) normals = true;
    else if(line.compare(0, 3, "vt ") == 0 || line.compare(0, 3, "vt\t") == 0) textures = true;
    else if(!colors && (line.compare(0, 2, "v ") == 0 || line.compare(0, 2, "v\t") == 0))
    {
      std::istringstream ls(line.substr(2));
      double x;
      int n = 0;
      while(ls >> x) ++n;
      if(n >= 6) colors = true;
    }
  }
}

bool ply_is_binary(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for(int i = 0; i < 4 && std::getline(in, line); ++i)
    if(line.compare(0, 6, "format") == 0) return line.find("binary") != std::string::npos;
  return false;
}

// PLY files with red/green/blue/alpha: CGAL's reader puts rgb into "v:color" (alpha 255) and alpha
// into a separate "v:alpha" map, and its writer would then write two "alpha" properties. Fold the
// alpha back into the colour (same for faces). Returns whether it did.
template <typename Index, typename Range>
bool fold_alpha(Mesh& mesh, const Range& range, const std::string& color_name, const std::string& alpha_name)
{
  Mesh::Property_map<Index, CGAL::IO::Color> color;
  Mesh::Property_map<Index, boost::uint8_t> alpha;
  bool has_color = false, has_alpha = false;
  std::tie(color, has_color) = mesh.property_map<Index, CGAL::IO::Color>(color_name);
  std::tie(alpha, has_alpha) = mesh.property_map<Index, boost::uint8_t>(alpha_name);
  if(!has_color || !has_alpha) return false;
  for(Index i : range)
  {
    const CGAL::IO::Color c = color[i];
    color[i] = CGAL::IO::Color(c.red(), c.green(), c.blue(), alpha[i]);
  }
  mesh.remove_property_map(alpha);
  return true;
}

// CGAL 5.5's ASCII OFF scanner reads texture coordinates at an index it computes only for files with
// colours: an "STOFF" (or STNOFF, ...) file without "C" makes it read uninitialised memory (a crash).
// For such a file, `patched` is its text with "C" inserted after "ST" in the header keyword: with no
// colour entries on the lines, the scanner then finds the texture coordinates right after the
// coordinates (and normals), and reads no colour.
bool stoff_without_colors(const std::string& path, std::string& patched)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  patched = text.str();
  std::string::size_type k = 0;
  for(;;)   // skip blanks and comment lines before the keyword
  {
    k = patched.find_first_not_of(" \t\r\n", k);
    if(k == std::string::npos) return false;
    if(patched[k] != '#') break;
    k = patched.find('\n', k);
    if(k == std::string::npos) return false;
  }
  const std::string::size_type end = patched.find_first_of(" \t\r\n", k);
  const std::string keyword = patched.substr(k, end == std::string::npos ? std::string::npos : end - k);
  if(keyword.size() < 5 || keyword.compare(0, 2, "ST") != 0 || keyword[2] == 'C' ||
     keyword.compare(keyword.size() - 3, 3, "OFF") != 0)
    return false;
  const std::string::size_type eol = patched.find('\n', k);
  const std::string header_line = patched.substr(k, eol == std::string::npos ? std::string::npos : eol - k);
  if(header_line.find("BINARY") != std::string::npos) return false;   // the binary scanner has no such problem
  patched.insert(k + 2, "C");
  return true;
}

// The mesh of a soup that CGAL's Surface_mesh readers cannot read (STL, PLY triangle strips), after
// check_oriented_manifold(): the vertices in the file's order.
void add_soup_faces(const af_tool::Polygon_soup& soup, Mesh& mesh)
{
  if(mesh.number_of_vertices() == 0)
    for(const auto& p : soup.points) mesh.add_vertex(Point(p[0], p[1], p[2]));
  std::vector<Vertex_index> face;
  for(const auto& f : soup.faces)
  {
    face.clear();
    for(std::size_t v : f) face.push_back(Vertex_index(static_cast<Mesh::size_type>(v)));
    if(mesh.add_face(face) == Mesh::null_face()) fail("read_error", "cannot build the mesh of " + soup.path);
  }
}

void read_input(const std::string& path, Mesh& mesh, Input_info& info, bool repair)
{
  if(!format_of(path, info.format)) usage_error("INPUT must be an .off, .obj, .ply or .stl file: " + path);
  std::error_code ec;
  if(!fs::is_regular_file(path, ec)) fail("read_error", "cannot open " + path + ": no such file");
  std::ifstream probe(path);
  if(!probe) fail("read_error", "cannot open " + path + ": " + std::strerror(errno));
  probe.close();

  // the file is read and checked before CGAL's readers see it (mesh_file_check.h)
  af_tool::Polygon_soup soup;
  try { soup = af_tool::read_checked_soup(path, af_tool::Mesh_format(int(info.format))); }
  catch(const af_tool::File_problem& e) { fail("read_error", std::string("cannot read ") + e.what()); }
  // a file that reads but whose faces are no oriented 2-manifold is an input the fairing refuses, unless
  // --repair asks to make it one (then the mesh is built from the repaired soup)
  bool rebuilt = false;
  try { af_tool::check_oriented_manifold(soup); }
  catch(const af_tool::File_problem& e)
  {
    if(!repair) fail("input_error", std::string("cannot fair ") + e.what() + " (--repair may make it usable)");
    for(const std::string& c : af_tool::repair_soup(soup)) info.notes.push_back("--repair: " + c);
    try { af_tool::check_oriented_manifold(soup); }
    catch(const af_tool::File_problem& again) { fail("input_error", std::string("cannot fair ") + again.what() + ", even after --repair"); }
    rebuilt = true;
    if(info.format != Format::STL)
      info.warnings.push_back("--repair rebuilt the mesh of " + path + " from its positions and faces: its other vertex properties are not kept");
  }
  info.warnings.insert(info.warnings.end(), soup.warnings.begin(), soup.warnings.end());
  if(rebuilt && info.format != Format::STL) add_soup_faces(soup, mesh);
  if(info.format == Format::STL)
  {
    add_soup_faces(soup, mesh);
    info.notes.push_back(std::to_string(soup.merged_points) + " triangle corners of " + path + " merged into the " +
                         std::to_string(soup.points.size()) + " vertices they coincide with");
  }

  bool ok = info.format == Format::STL || rebuilt;
  std::string printed;
  if(!ok)
  {
    Capture_streams capture;
    if(info.format == Format::OFF)
    {
      std::string patched;
      if(stoff_without_colors(path, patched))
      {
        std::istringstream in(patched);
        ok = CGAL::IO::read_OFF(in, mesh);
        // the colour maps made for the "C" put in by stoff_without_colors(): nothing was read into them
        auto vcolor = mesh.property_map<Vertex_index, CGAL::IO::Color>("v:color");
        if(vcolor.second) mesh.remove_property_map(vcolor.first);
        auto fcolor = mesh.property_map<Face_index, CGAL::IO::Color>("f:color");
        if(fcolor.second) mesh.remove_property_map(fcolor.first);
      }
      else
      {
        std::ifstream in(path);
        ok = CGAL::IO::read_OFF(in, mesh);  // Surface_mesh overload: keeps normals, colours, texture coordinates in v:*
      }
    }
    else if(info.format == Format::PLY)
    {
      info.ply_binary = ply_is_binary(path);
      std::ifstream in(path, std::ios::binary);
      ok = CGAL::IO::read_PLY(in, mesh, info.ply_comments, false);  // keeps every property as v:<name>, f:<name>
      if(soup.ply_strips && mesh.number_of_faces() == 0 && mesh.number_of_vertices() == soup.points.size())
      {
        // CGAL reads the vertices and their properties of a file of triangle strips, but not the strips
        add_soup_faces(soup, mesh);
        ok = true;
        info.notes.push_back(std::to_string(soup.faces.size()) + " triangles read from the triangle strips of " + path);
      }
    }
    else
    {
      std::ifstream in(path);
      ok = CGAL::IO::read_OBJ(in, mesh);
    }
    printed = capture.first_line();
  }
  // the checks above are those CGAL's readers make: a difference would be a bug of ours
  if(!ok || mesh.number_of_faces() != soup.faces.size() || mesh.number_of_vertices() != soup.points.size())
  {
    mesh.clear();
    fail("read_error", "cannot read a polygon mesh from " + path + " (CGAL's reader refused a file the checks accepted)" +
                       (printed.empty() ? std::string() : ": " + printed));
  }
  if(repair)
    for(const std::string& c : af_tool::repair_mesh(mesh)) info.notes.push_back("--repair: " + c);
  if(info.format == Format::PLY)
  {
    info.vertex_alpha = fold_alpha<Vertex_index>(mesh, mesh.vertices(), "v:color", "v:alpha");
    fold_alpha<Face_index>(mesh, mesh.faces(), "f:color", "f:alpha");
  }
  if(info.format == Format::OBJ)
  {
    bool normals, textures, colors;
    scan_obj(path, normals, textures, colors);
    if(normals) mesh.add_property_map<Vertex_index, Vector>("v:normal", Vector(0, 0, 0));
    if(textures)
    {
      const Obj_texcoords t = read_obj_texcoords(path, mesh.number_of_vertices());
      if(t.matched)
      {
        Texcoord_map uv = mesh.add_property_map<Vertex_index, Texcoord>("v:texcoord", Texcoord(0, 0)).first;
        for(Vertex_index v : mesh.vertices()) uv[v] = Texcoord(t.uv[std::size_t(v)][0], t.uv[std::size_t(v)][1]);
        if(t.dropped_w) info.warnings.push_back("the third components (w) of the vt of " + path + " are not kept");
      }
      else
      {
        info.uv_problem = "the texture coordinates (vt) of " + path + " are not one per vertex (" + t.problem + ")";
        info.warnings.push_back(info.uv_problem + ": not kept");
      }
    }
    if(colors) info.warnings.push_back("vertex colours on the v lines of " + path + " are not kept (CGAL's OBJ reader drops them)");
  }
  info.has_normals = mesh.property_map<Vertex_index, Vector>("v:normal").second;
  info.normals_read = info.has_normals && info.format != Format::OBJ;
}

// ------------------------------------------------------------------------------------------------
// Attributes: the selected columns, gathered into one vector per vertex and scattered back
// ------------------------------------------------------------------------------------------------

// One scalar component of a vertex property, read and written as a double.
struct Attribute_column
{
  std::string name;
  std::function<double(Vertex_index)> get;
  std::function<void(Vertex_index, double)> set;
};

// The numeric types a PLY property can have (CGAL's reader makes a v:<name> map of that type).
template <typename F>
bool for_numeric_type(F&& f)
{
  return f(boost::int8_t()) || f(boost::uint8_t()) || f(boost::int16_t()) || f(boost::uint16_t()) ||
         f(boost::int32_t()) || f(boost::uint32_t()) || f(boost::int64_t()) || f(boost::uint64_t()) ||
         f(float()) || f(double());
}

template <typename Index>
bool is_numeric_property(const Mesh& mesh, const std::string& property)
{
  return for_numeric_type([&](auto zero) {
    return mesh.property_map<Index, decltype(zero)>(property).second;
  });
}

// A numeric vertex property v:<name>; integers are rounded and clamped when written, floats rounded to float.
bool add_numeric_column(Mesh& mesh, const std::string& name, std::vector<Attribute_column>& columns)
{
  return for_numeric_type([&](auto zero) {
    typedef decltype(zero) T;
    Mesh::Property_map<Vertex_index, T> map;
    bool found = false;
    std::tie(map, found) = mesh.property_map<Vertex_index, T>("v:" + name);
    if(!found) return false;
    columns.push_back({name, [map](Vertex_index v) { return double(get(map, v)); },
                       [map](Vertex_index v, double x) { put(map, v, AF::Vector_attribute_traits<T>::make(get(map, v), &x)); }});
    return true;
  });
}

// Channel c (0 red .. 3 alpha) of v:color; the others are kept.
Attribute_column color_column(Mesh::Property_map<Vertex_index, CGAL::IO::Color> map, const std::string& name, std::size_t c)
{
  return {name, [map, c](Vertex_index v) { return double(get(map, v)[c]); },
          [map, c](Vertex_index v, double x) {
            CGAL::IO::Color color = get(map, v);
            color[c] = !(x > 0) ? (unsigned char)0 : (unsigned char)std::lround((std::min)(x, 255.0));   // NaN -> 0
            put(map, v, color);
          }};
}

Attribute_column texcoord_column(Texcoord_map map, const std::string& name, int c)
{
  return {name, [map, c](Vertex_index v) { return get(map, v)[c]; },
          [map, c](Vertex_index v, double x) {
            const Texcoord p = get(map, v);
            put(map, v, c == 0 ? Texcoord(x, p.y()) : Texcoord(p.x(), x));
          }};
}

// The names --attributes accepts for this mesh.
std::vector<std::string> available_attributes(const Mesh& mesh, const Input_info& info)
{
  std::vector<std::string> names;
  for(const std::string& p : mesh.properties<Vertex_index>())
    if(p.compare(0, 2, "v:") == 0 && is_numeric_property<Vertex_index>(mesh, p)) names.push_back(p.substr(2));
  if(mesh.property_map<Vertex_index, CGAL::IO::Color>("v:color").second)
  {
    for(const char* n : {"red", "green", "blue"}) names.push_back(n);
    if(info.vertex_alpha) names.push_back("alpha");
    names.push_back("color");
  }
  if(mesh.property_map<Vertex_index, Texcoord>("v:texcoord").second) names.push_back("uv");
  return names;
}

// The columns named by --attributes, in their order ("color" is red, green, blue; "uv" is u, v).
// Fails (exit 1, status attribute_error) on a name the input does not have.
std::vector<Attribute_column> resolve_attributes(Mesh& mesh, const Input_info& info, const std::string& input,
                                                 const std::vector<std::string>& names)
{
  std::vector<Attribute_column> columns;
  Mesh::Property_map<Vertex_index, CGAL::IO::Color> color;
  bool has_color = false;
  std::tie(color, has_color) = mesh.property_map<Vertex_index, CGAL::IO::Color>("v:color");
  Texcoord_map uv;
  bool has_uv = false;
  std::tie(uv, has_uv) = mesh.property_map<Vertex_index, Texcoord>("v:texcoord");
  for(const std::string& name : names)
  {
    const std::string what = "--attributes " + name + ": ";
    if(name == "x" || name == "y" || name == "z")
      fail("attribute_error", what + "a vertex coordinate, not an attribute (--mode says whether the geometry is faired)");
    if(name == "nx" || name == "ny" || name == "nz" || name == "normal")
      fail("attribute_error", what + "vertex normals are not faired: the normals of the faired surface are written");
    if(add_numeric_column(mesh, name, columns)) continue;
    if(has_color && (name == "red" || name == "green" || name == "blue" || name == "color" || (name == "alpha" && info.vertex_alpha)))
    {
      if(name == "red" || name == "color") columns.push_back(color_column(color, "red", 0));
      if(name == "green" || name == "color") columns.push_back(color_column(color, "green", 1));
      if(name == "blue" || name == "color") columns.push_back(color_column(color, "blue", 2));
      if(name == "alpha") columns.push_back(color_column(color, "alpha", 3));
      continue;
    }
    if(has_uv && name == "uv")
    {
      columns.push_back(texcoord_column(uv, "u", 0));
      columns.push_back(texcoord_column(uv, "v", 1));
      continue;
    }
    if(name == "uv" && !info.uv_problem.empty()) fail("attribute_error", what + info.uv_problem);
    std::string list;
    for(const std::string& a : available_attributes(mesh, info)) list += (list.empty() ? "" : ", ") + a;
    fail("attribute_error", what + input + " has no such vertex attribute (available: " +
                            (list.empty() ? std::string("none") : list) + ")");
  }
  for(std::size_t i = 0; i < columns.size(); ++i)
    for(std::size_t j = 0; j < i; ++j)
      if(columns[i].name == columns[j].name)
        fail("attribute_error", "--attributes selects " + columns[i].name + " twice (color is red,green,blue)");
  return columns;
}

// All selected columns of a vertex as one vector: the attribute map given to the library.
struct Attribute_vectors
{
  typedef Vertex_index key_type;
  typedef std::vector<double> value_type;
  typedef const value_type& reference;
  typedef boost::read_write_property_map_tag category;
  std::vector<value_type>* values;   // indexed by the vertex index

  friend reference get(const Attribute_vectors& m, Vertex_index v) { return (*m.values)[std::size_t(v)]; }
  friend void put(const Attribute_vectors& m, Vertex_index v, const value_type& x) { (*m.values)[std::size_t(v)] = x; }
};

void gather(const Mesh& mesh, const std::vector<Attribute_column>& columns, std::vector<std::vector<double>>& values)
{
  values.assign(mesh.num_vertices(), std::vector<double>(columns.size()));
  for(Vertex_index v : mesh.vertices())
    for(std::size_t c = 0; c < columns.size(); ++c) values[std::size_t(v)][c] = columns[c].get(v);
}

void scatter(const Mesh& mesh, const std::vector<Attribute_column>& columns, const std::vector<std::vector<double>>& values)
{
  for(Vertex_index v : mesh.vertices())
    for(std::size_t c = 0; c < columns.size(); ++c) columns[c].set(v, values[std::size_t(v)][c]);
}

// ------------------------------------------------------------------------------------------------
// Output
// ------------------------------------------------------------------------------------------------
bool is_internal_property(const std::string& name)
{
  return name == "v:connectivity" || name == "v:point" || name == "v:removed" || name == "f:connectivity" ||
         name == "f:removed" || name == "e:removed" || name == "h:connectivity";
}

// The properties of the mesh that a file of format `f` does not hold (warned about, not an error).
std::vector<std::string> dropped_properties(const Mesh& mesh, Format f)
{
  std::vector<std::string> all = mesh.properties<Vertex_index>();
  for(const std::string& p : mesh.properties<Face_index>()) all.push_back(p);
  for(const std::string& p : mesh.properties<Mesh::Edge_index>()) all.push_back(p);
  for(const std::string& p : mesh.properties<Mesh::Halfedge_index>()) all.push_back(p);
  std::vector<std::string> dropped;
  for(const std::string& p : all)
  {
    if(is_internal_property(p)) continue;
    bool kept = false;
    if(f == Format::PLY)  // CGAL's Surface_mesh PLY writer writes normals, colours and every numeric property
      kept = p == "v:normal" || p == "v:color" || p == "f:color" ||
             (p.compare(0, 2, "v:") == 0 && is_numeric_property<Vertex_index>(mesh, p)) ||
             (p.compare(0, 2, "f:") == 0 && is_numeric_property<Face_index>(mesh, p)) ||
             (p.compare(0, 2, "e:") == 0 && is_numeric_property<Mesh::Edge_index>(mesh, p)) ||
             (p.compare(0, 2, "h:") == 0 && is_numeric_property<Mesh::Halfedge_index>(mesh, p));
    else if(f == Format::OFF) kept = (p == "v:normal" || p == "v:color" || p == "v:texcoord" || p == "f:color");
    else kept = (p == "v:normal" || p == "v:texcoord");
    if(!kept) dropped.push_back(p);
  }
  return dropped;
}

// OBJ with normals or texture coordinates, which CGAL's OBJ writer does not attach to the vertices
// (it writes vn lines but faces without //n references, and no vt). This writes one vn and one vt per
// vertex, in the vertex order, and faces "f a//a", "f a/a" or "f a/a/a".
bool write_obj_with_vertex_data(std::ostream& os, const Mesh& mesh, const Normal_map* normals, const Texcoord_map* uv)
{
  os.precision(17);
  os << "# written by anisotropic_fairing\n";
  os << "# " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces() << " faces\n";
  for(Vertex_index v : mesh.vertices())
  {
    const Point& p = mesh.point(v);
    os << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  if(uv)
    for(Vertex_index v : mesh.vertices())
    {
      const Texcoord& t = (*uv)[v];
      os << "vt " << t.x() << ' ' << t.y() << '\n';
    }
  if(normals)
    for(Vertex_index v : mesh.vertices())
    {
      const Vector& n = (*normals)[v];
      os << "vn " << n.x() << ' ' << n.y() << ' ' << n.z() << '\n';
    }
  for(Face_index f : mesh.faces())
  {
    os << 'f';
    for(Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    {
      const std::size_t i = std::size_t(v) + 1;
      os << ' ' << i;
      if(uv) os << '/' << i;
      if(normals) os << (uv ? "/" : "//") << i;
    }
    os << '\n';
  }
  return bool(os);
}

void write_mesh(const std::string& path, Format f, const Mesh& mesh, const Input_info& info, bool with_normals)
{
  bool ok = false;
  {
    Capture_streams capture;
    if(f == Format::PLY)
    {
      const bool binary = info.format == Format::PLY && info.ply_binary;
      std::ofstream out(path, std::ios::binary);
      if(out)
      {
        CGAL::IO::set_mode(out, binary ? CGAL::IO::BINARY : CGAL::IO::ASCII);
        ok = CGAL::IO::write_PLY(out, mesh, info.ply_comments, CGAL::parameters::stream_precision(17));
        out.close();
        ok = ok && !out.fail();
      }
    }
    else if(f == Format::OFF)
    {
      std::ofstream out(path);
      if(out)
      {
        // the Surface_mesh overload also writes v:normal, v:color, v:texcoord and f:color
        ok = CGAL::IO::write_OFF(out, mesh, CGAL::parameters::stream_precision(17));
        out.close();
        ok = ok && !out.fail();
      }
    }
    else
    {
      std::ofstream out(path);
      if(out)
      {
        const auto normals = mesh.property_map<Vertex_index, Vector>("v:normal");
        const auto uv = mesh.property_map<Vertex_index, Texcoord>("v:texcoord");
        if((with_normals && normals.second) || uv.second)
          ok = write_obj_with_vertex_data(out, mesh, with_normals && normals.second ? &normals.first : nullptr,
                                          uv.second ? &uv.first : nullptr);
        else
          ok = CGAL::IO::write_OBJ(out, mesh, CGAL::parameters::stream_precision(17));
        out.close();
        ok = ok && !out.fail();
      }
    }
  }
  if(!ok) fail("write_error", "cannot write " + path);
}

// Writes `text` to `path` through a temporary file next to it.
bool write_file_atomically(const std::string& path, const std::string& text);

fs::path temporary_next_to(const std::string& path)
{
  const fs::path p(path);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  return dir / ("." + p.filename().string() + ".tmp" + std::to_string(long(::getpid())));
}

bool write_file_atomically(const std::string& path, const std::string& text)
{
  const fs::path tmp = temporary_next_to(path);
  {
    std::ofstream out(tmp, std::ios::binary);
    if(!out) return false;
    out << text;
    out.close();
    if(out.fail()) { std::error_code ec; fs::remove(tmp, ec); return false; }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if(ec) { fs::remove(tmp, ec); return false; }
  return true;
}

// ------------------------------------------------------------------------------------------------
// JSON report
// ------------------------------------------------------------------------------------------------
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

struct Run_record
{
  std::string status = "success";
  std::string message;
  bool mesh_read = false;
  std::size_t vertices = 0, faces = 0;
  bool fairing_ran = false;
  AF::Fairing_report report;
  std::string normals = "none";
  bool curvature = false;   // k1, k2, mean_curvature were added to the output
  bool output_written = false;
};

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
  kv("relative_time_step", ran && scale2 > 0 ? json_number(f.time_step / scale2)
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

// ------------------------------------------------------------------------------------------------
// Fairing: the named parameters differ in type with the time step and fidelity flags given
// ------------------------------------------------------------------------------------------------
template <typename NP, typename Run>
AF::Fairing_report with_fidelity(const NP& np, const Options& o, Run& run)
{
  if(o.has_fidelity) return run(np.fidelity_weight(o.fidelity));
  if(o.has_relative_fidelity) return run(np.relative_fidelity_weight(o.relative_fidelity));
  return run(np);
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
    // with automatic parameters the library also runs the isotropic flow, to keep the better result
    if(!quiet && s.step <= last_step) std::fprintf(stderr, "the isotropic flow, for comparison:\n");
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
    typedef AF::Loop_limit_surface<Mesh> Limit;
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
      if(exact_limit_normals) limit.limit_normals(mesh.property_map<Vertex_index, Vector>("v:normal").first);
      // as in the library's limit output, boundary and isolated vertices keep their (held) positions and attributes
      std::vector<std::pair<Vertex_index, Point>> held;
      std::vector<std::pair<Vertex_index, std::vector<double>>> held_values;
      for(Vertex_index v : mesh.vertices())
        if(mesh.is_border(v) || mesh.is_isolated(v))
        {
          held.emplace_back(v, mesh.point(v));
          if(fair_attributes) held_values.emplace_back(v, attribute_values[std::size_t(v)]);
        }
      limit.limit_positions(mesh.points());
      if(fair_attributes) limit.limit_values(attribute_map, attribute_map);
      for(const auto& h : held) mesh.point(h.first) = h.second;
      for(const auto& h : held_values) attribute_values[std::size_t(h.first)] = h.second;
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

} // namespace

int main(int argc, char** argv)
{
  Options o;
  Run_record r;
  int exit_code = 1;
  try
  {
    parse_arguments(argc, argv, o);
    if(o.help)
    {
      std::fputs(usage_text, stdout);
      return 0;
    }
    return run(o, r);
  }
  catch(const Failure& f)
  {
    r.status = f.status;
    r.message = one_line(f.message);
    exit_code = f.exit_code;
  }
  catch(const std::bad_alloc&)
  {
    r.status = "error";
    r.message = "out of memory";
  }
  catch(const std::exception& e)
  {
    r.status = "error";
    r.message = one_line(e.what());
  }
  int code = exit_code;
  std::string line = "anisotropic_fairing: " + r.message;
  const bool report_failed = r.status == "write_error" && r.message.rfind("cannot write the report ", 0) == 0;
  if(!o.report.empty() && !o.report_refused && !report_failed && !write_file_atomically(o.report, report_json(o, r, elapsed_seconds())))
    line += " (and cannot write the report " + o.report + ")";
  std::fprintf(stderr, "%s\n", line.c_str());
  return code;
}
