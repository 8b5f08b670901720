// The options of anisotropic_fairing. The table `option_table` is the one list of the options: the
// parser reads it, the help text is made from it, and scripts/option_docs.py makes the manual's list
// from the help (the test cli_option_docs checks they agree).
#include "options.h"
#include "json_report.h"
#include "option_values.h"
#include "option_words.h"

#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/version.h>

#include <Eigen/Core>
#include <boost/version.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace af_tool {
namespace fs = std::filesystem;

namespace {

// One option: its name, an alias, the value it takes (nullptr: a flag without value), its help (the
// lines after the first are indented under it) and what it does with its value. A handler may throw
// usage_error(); it runs in the order of the command line, so that a later --report is still read.
struct Option_spec
{
  const char* name;
  const char* alias;
  const char* value;
  const char* help;
  void (*apply)(Options& o, const std::string& flag, const std::string& value);
};

const Option_spec option_table[] = {
  {"--time-step", nullptr, "T", "time step tau in model units (length^2), as in the paper (time_step)",
   [](Options& o, const std::string& flag, const std::string& v) { set_number(o.fairing.time_step, flag, v, false); }},
  {"--relative-time-step", nullptr, "R",
   "time step in units of l^2, l = sqrt(area/4pi) of the input (per connected\n"
   "component; relative_time_step); give at most one of the two. Neither:\n"
   "automatic parameters: the noise is estimated from the mesh, the tensor is\n"
   "the anisotropic one with its threshold and prefilter chosen from the mesh\n"
   "(unless --tensor is given), steps of 0.3 h^2 (h: the edge length) until\n"
   "the surface has moved off the input by the noise",
   [](Options& o, const std::string& flag, const std::string& v) {
     set_number(o.fairing.relative_time_step, flag, v, false);
   }},
  {"--order", nullptr, "2|4",
   "the flow's order: 2 (default: diffusion, as in the paper) or 4\n"
   "(dX/dt = -(M^-1 L)^2 X, which removes noise while rounding the shape less;\n"
   "the time step is then in length^4, --relative-time-step in l^4; automatic:\n"
   "0.1 h^4; flow_order). The automatic\n"
   "default run uses the fourth-order flow itself for its uniform candidate\n"
   "(the report's choices say so)",
   [](Options& o, const std::string& flag, const std::string& v) {
     o.fairing.flow_order = choice(flag, v, order_words);
   }},
  {"--steps", nullptr, "N", "the most time steps to run, all runs of the automatic comparison\n"
   "together (default 10; with automatic parameters 200; number_of_iterations)",
   [](Options& o, const std::string& flag, const std::string& v) { o.fairing.number_of_iterations = parse_unsigned(flag, v); }},
  {"--stop", nullptr, "auto|noise|paper|off",
   "auto (default): noise with automatic parameters, paper otherwise;\n"
   "noise: stop when the surface has moved off the input by the estimated\n"
   "noise (--order 4: or when that displacement levels off short of it);\n"
   "paper: the criteria (27)-(29) and a steady-state test; off: exactly\n"
   "N steps (Stopping_criteria::automatic(), Stopping_criteria(),\n"
   "Stopping_criteria::none()). Whatever the criteria, a step that would fold\n"
   "the surface is retried with a quarter of the time step, and the run ends\n"
   "on the last sound surface (step_rejected, with a warning) if even 1/1024\n"
   "of it fails",
   [](Options& o, const std::string& flag, const std::string& v) {
     o.stop = v;   // set before the check: a usage error's report shows what was asked
     choice_index(flag, v, stop_words);
     o.fairing.stopping_criteria = stopping_rule(v);
   }},
  {"--strength", nullptr, "S",
   "how far the noise stop goes: until the surface has moved off the input\n"
   "by S times the estimated noise (default 1; 2 smooths more, 0.5 less).\n"
   "The rest stays automatic: the flows are compared at the noise level,\n"
   "and the one kept runs again to S times it. Needs the noise stop:\n"
   "automatic parameters, or --stop noise with a time step (strength)",
   [](Options& o, const std::string& flag, const std::string& v) {
     bool given = false;
     set_number(o.fairing.strength, given, flag, v, false);
   }},
  {"--fidelity", nullptr, "W", "fidelity weight omega in model units (1/time), as in the paper (default 0;\n"
   "fidelity_weight)",
   [](Options& o, const std::string& flag, const std::string& v) { set_number(o.fairing.fidelity_weight, flag, v, true); }},
  {"--relative-fidelity", nullptr, "W", "fidelity weight in units of 1/l^2 (relative_fidelity_weight); give at most\n"
   "one of the two",
   [](Options& o, const std::string& flag, const std::string& v) {
     set_number(o.fairing.relative_fidelity_weight, flag, v, true);
   }},
  {"--absolute-maximum-deviation", "--maximum-deviation", "D",
   "no written vertex moves farther than D (model units) off its input\n"
   "position: the vertices nearing it are held by a fidelity weight of\n"
   "their own, and one it cannot hold is written on the bound (default:\n"
   "no bound; 0: none; absolute_maximum_deviation; --maximum-deviation,\n"
   "its former spelling, is deprecated: in the library and Python that\n"
   "name is the relative bound)",
   [](Options& o, const std::string& flag, const std::string& v) {
     if(flag == "--maximum-deviation")
       o.deprecations.push_back("--maximum-deviation is deprecated: write --absolute-maximum-deviation (model units, as here) or "
                                "--relative-maximum-deviation (units of l, as the library's maximum_deviation)");
     set_number(o.fairing.absolute_maximum_deviation, flag, v, true);
   }},
  {"--relative-maximum-deviation", nullptr, "R", "the same in units of l (relative_maximum_deviation); give at most one of the two",
   [](Options& o, const std::string& flag, const std::string& v) { set_number(o.fairing.relative_maximum_deviation, flag, v, true); }},
  {"--attribute-maximum-deviation", nullptr, "D",
   "no vertex's attribute values move farther than D (their units,\n"
   "Euclidean over the components) off the input's (default: no bound;\n"
   "attribute_maximum_deviation)",
   [](Options& o, const std::string& flag, const std::string& v) {
     bool given = false;
     set_number(o.fairing.attribute_maximum_deviation, given, flag, v, true);
   }},
  {"--element", nullptr, "loop|linear", "Loop limit-surface elements (default) or linear (P1) elements\n"
   "(finite_element)",
   [](Options& o, const std::string& flag, const std::string& v) {
     o.fairing.finite_element = choice(flag, v, element_words);
   }},
  {"--output", nullptr, "limit|control",
   "write the points of the faired limit surface (default) or the faired\n"
   "control points (the mesh whose Loop limit surface is the faired surface;\n"
   "output_positions)",
   [](Options& o, const std::string& flag, const std::string& v) {
     o.fairing.output_positions = choice(flag, v, output_words);
   }},
  {"--tensor", nullptr, "isotropic|anisotropic|uniform",
   "the diffusion tensor: isotropic (mean-curvature flow; the\n"
   "default with a time step), anisotropic (curvature-driven, feature-preserving:\n"
   "Anisotropic_diffusion_tensor; the default with automatic parameters, its\n"
   "threshold and prefilter then chosen from the mesh unless given, and the\n"
   "isotropic (or uniform) result kept instead when its estimated error at the\n"
   "noise level is lower: the report's tensor and choices say which) or uniform (the\n"
   "uniform Laplacian's weights, Uniform_diffusion_tensor: for noisy scans with a\n"
   "graded triangulation; it rounds creases like the isotropic tensor);\n"
   "diffusion_tensor",
   [](Options& o, const std::string& flag, const std::string& v) {
     o.tensor = v;   // set before the check: a usage error's report shows what was asked
     choice_index(flag, v, tensor_words);
   }},
  {"--lambda", nullptr, "L",
   "the anisotropic tensor's feature threshold, a curvature in units of 1/l\n"
   "(default 2): principal curvatures above it are diffused less\n"
   "(Anisotropic_diffusion_tensor::set_lambda)",
   [](Options& o, const std::string& flag, const std::string& v) { set_number(o.lambda, o.has_lambda, flag, v, false, true); }},
  {"--epsilon", nullptr, "E",
   "the anisotropic tensor reads curvature on the surface after an isotropic\n"
   "step of E (units of l^2; the paper's prefiltered M_eps); default 1e-3;\n"
   "0: on the current surface (set_epsilon)",
   [](Options& o, const std::string& flag, const std::string& v) { set_number(o.epsilon, o.has_epsilon, flag, v, true, true); }},
  {"--tangential-motion", nullptr, "remove|keep",
   "the anisotropic flow moves control points along the surface's\n"
   "normal only (remove, the default: the tangential part of div(D grad x)\n"
   "folds noisy meshes) or also within it, as the paper does (keep;\n"
   "set_normal_motion_only)",
   [](Options& o, const std::string& flag, const std::string& v) {
     o.normal_motion_only = choice(flag, v, tangential_words);
     o.has_tangential_motion = true;
   }},
  {"--solver", nullptr, "auto|cg|cholesky", "linear solver: automatic (default), conjugate gradients, sparse LDL^T\n"
   "(linear_solver)",
   [](Options& o, const std::string& flag, const std::string& v) {
     o.fairing.linear_solver = choice(flag, v, solver_words);
   }},
  {"--boundary", nullptr, "curve|vertices",
   "on a mesh with borders, hold the limit boundary curve (default: the\n"
   "boundary vertices and the interior vertices that shape the curve) or only\n"
   "the boundary vertices (the paper's choice; the border may slide;\n"
   "boundary_handling). Boundary vertices are written unchanged either way",
   [](Options& o, const std::string& flag, const std::string& v) {
     o.fairing.boundary_handling = choice(flag, v, boundary_words);
   }},
  {"--quadrature-degree", nullptr, "4|6|8", "Gauss rule per face for the Loop element (default 8; quadrature_degree)",
   [](Options& o, const std::string& flag, const std::string& v) {
     o.fairing.quadrature_degree = choice(flag, v, quadrature_words);
   }},
  {"--attributes", nullptr, "NAME,...",
   "the per-vertex attributes to fair, in this order, as one vector per\n"
   "vertex: PLY: any numeric vertex property by name (quality, u, v, s, t,\n"
   "...), red, green, blue, alpha, or color (= red,green,blue); OFF: color\n"
   "(COFF), red, green, blue, uv (texture coordinates); OBJ: uv (the vt, if\n"
   "one per vertex). Not x, y, z, nx, ny, nz. A name the input does not have\n"
   "fails (exit 1) and the message lists the available ones. They are written\n"
   "back into their own properties with their own types (integers rounded\n"
   "and clamped, colours to 0..255)",
   [](Options& o, const std::string&, const std::string& v) { o.attributes = parse_attribute_list(v); }},
  {"--mode", nullptr, "separate|coupled|attributes|geometry",
   "how they are faired: separate (the default with\n"
   "--attributes): with the operator of the geometry's surface; coupled: as one\n"
   "surface with the geometry in R^(3+d); attributes: the geometry is fixed (not\n"
   "written) and only the attributes diffuse on it; geometry (the default\n"
   "without --attributes): the attributes are not faired. coupled and\n"
   "attributes need --attributes (attribute_mode)",
   [](Options& o, const std::string& flag, const std::string& v) {
     o.fairing.attribute_mode = choice(flag, v, mode_words);
   }},
  {"--attribute-weight", nullptr, "W", "coupled: the length that one attribute unit counts for (> 0, default 1;\n"
   "attribute_weight)",
   [](Options& o, const std::string& flag, const std::string& v) {
     set_number(o.fairing.attribute_weight, o.has_attribute_weight, flag, v, false);
   }},
  {"--curvature", nullptr, nullptr,
   "also write the curvature of the faired Loop limit surface at each vertex\n"
   "as the PLY vertex properties k1, k2 (principal curvatures, k1 <= k2) and\n"
   "mean_curvature ((k1 + k2)/2), w.r.t. the oriented normal (negative on a\n"
   "convex surface oriented outward); at vertices of valence other than 6,\n"
   "where the limit surface has no finite curvature, an average over the\n"
   "vertex's faces (Loop_limit_surface::vertex_curvatures). Needs a .ply\n"
   "OUTPUT and the Loop element",
   [](Options& o, const std::string&, const std::string&) { o.curvature = true; }},
  {"--hold", nullptr, "NAME|FILE",
   "hold vertices where they are: those whose numeric vertex property NAME\n"
   "of the input (PLY) is not 0, or those listed in FILE, one vertex index\n"
   "(from 0, in the input's order) per line ('#' starts a comment line);\n"
   "they are written unchanged, attributes included (vertex_is_constrained_map).\n"
   "With --repair, which may drop or split vertices, the indices are those of\n"
   "the repaired mesh",
   [](Options& o, const std::string&, const std::string& v) { o.hold = v; }},
  {"--resample", nullptr, "K",
   "write the faired limit surface at K levels of Loop refinement (4^K\n"
   "faces per input face, K <= 10): the input's vertices first, exactly as\n"
   "without --resample, then new vertices on the limit surface with its\n"
   "normals, curvature (--curvature), the faired attributes' limit values and\n"
   "the Loop limit of every other vertex property; a new face has the\n"
   "properties of the input face it lies in. Needs the Loop element and\n"
   "--output limit",
   [](Options& o, const std::string& flag, const std::string& v) {
     o.resample = parse_unsigned(flag, v);
     o.has_resample = true;
     if(o.resample > 10) usage_error(flag + " must be at most 10");
   }},
  {"--snapshot", nullptr, "FILE.png",
   "also render the input and the result side by side into FILE.png (VTK,\n"
   "no display needed: Debian's python3-vtk9 and xvfb; scripts/figures/\n"
   "render_mesh.py, or the one AF_RENDER_SCRIPT names)",
   [](Options& o, const std::string&, const std::string& v) { o.snapshot = v; }},
  {"--report", nullptr, "FILE.json", "write per-step statistics (also, with status and message, on failure)",
   [](Options& o, const std::string&, const std::string& v) { o.report = v; }},
  {"--repair", nullptr, nullptr,
   "repair the mesh with CGAL's Polygon_mesh_processing and write it as\n"
   "repaired: stitch coinciding borders, remove vertices on no face (the\n"
   "later vertices move up) and keep the copies of split vertices (written\n"
   "after the input's); the vertex properties of the vertices kept are\n"
   "kept; each change is printed",
   [](Options& o, const std::string&, const std::string&) { o.repair = true; }},
  {"--ascii", nullptr, nullptr,
   "write OUTPUT as text: an ASCII STL (STL is otherwise binary, which holds\n"
   "single-precision floats), or an ASCII PLY where INPUT is a binary PLY",
   [](Options& o, const std::string&, const std::string&) { o.text_output = true; }},
  {"--quiet", "-q", nullptr, "no progress line per step on stderr (the callback named parameter)",
   [](Options& o, const std::string&, const std::string&) { o.quiet = true; }},
  {"--progress-interval", nullptr, "SECONDS", "after this many seconds without a line on stderr, say what the\n"
   "program is doing and for how long (reading, set-up, a step retried\n"
   "after rejections, writing; default 2, 0: never)",
   [](Options& o, const std::string& flag, const std::string& v) {
     set_number(o.progress_interval, o.has_progress_interval, flag, v, true);
   }},
  {"--help", "-h", nullptr, "print this help and exit",
   [](Options& o, const std::string&, const std::string&) { o.help = true; }},
  {"--version", nullptr, nullptr, "print the versions of the program, CGAL, Eigen and Boost and exit",
   [](Options& o, const std::string&, const std::string&) { o.version = true; }},
};

const char* const help_before_options =
"usage: anisotropic_fairing INPUT OUTPUT [options]\n"
"\n"
"Fairs the triangle mesh INPUT by geometric diffusion with Loop-subdivision finite elements\n"
"(Bajaj & Xu 2003; isotropic tensor: mean-curvature flow, or the anisotropic, feature-preserving one)\n"
"and writes the result to OUTPUT.\n"
"INPUT and OUTPUT are OFF, OBJ, PLY or STL files (by extension; the formats may differ); in STL\n"
"coincident corners are merged into vertices; INPUT may also be a PLY of triangle strips. Every file is\n"
"checked before it is read: a bad count, index or number is refused with the line or element named.\n"
"Faces that are not triangles are triangulated. Faces that are not an oriented 2-manifold (vertices\n"
"where separate fans of faces meet, edges of three or more faces, flipped faces, faces that use a vertex\n"
"twice) are made one for the run: such a vertex is split into one copy per fan, and written back once,\n"
"at the mean of its copies; flipped faces are turned, faces that use a vertex twice removed;\n"
"a warning and the report's input_changes say what was done. The output keeps the input's vertices in\n"
"their order and number, full double precision and every vertex property of the input that its format\n"
"can hold (PLY: normals, colours, numeric properties; OFF: colours, texture coordinates, face colours;\n"
"OBJ: normals, texture coordinates; STL: positions; a warning names the dropped ones).\n"
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
"steps of 0.3 h^2 (h: the mean edge length) and stops when the surface has moved off the input by\n"
"the noise (a noise-free mesh is left nearly as it is). The isotropic and the uniform tensor's\n"
"fourth-order flow are run too, and the result with the lowest estimated error (Stein's unbiased\n"
"risk estimate) is kept; the report's choices say what was chosen.\n"
"\n"
"options:\n";

const char* const help_after_options =
"Options also accept the form --option=value.\n"
"\n"
"exit status: 0 success; 1 failure (unreadable input, a mesh the library refuses,\n"
"an attribute the input does not have, fairing failure, unwritable output or report); 2 usage error\n"
"(including OUTPUT or --report naming the INPUT or each other).\n"
"On failure one line starting with\n"
"\"anisotropic_fairing: \" is printed on stderr and OUTPUT is not created (an existing one is left as is).\n";

const Option_spec* find_option(const std::string& arg)
{
  for(const Option_spec& s : option_table)
    if(arg == s.name || (s.alias && arg == s.alias)) return &s;
  return nullptr;
}

} // namespace

// --mode, or its default: separate with --attributes, geometry without
AF::Attribute_mode effective_mode(const Options& o)
{
  return o.fairing.attribute_mode.value_or(o.attributes.empty() ? AF::Attribute_mode::GEOMETRY_ONLY : AF::Attribute_mode::SEPARATE);
}

const char* mode_name(AF::Attribute_mode m)
{
  for(const auto& w : mode_words)
    if(w.second == m) return w.first;
  return "geometry";
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

// "  --name VALUE" padded to 28 columns (or followed by three blanks), the help's further lines under it
std::string version_text()
{
  return std::string("anisotropic_fairing ") + AF_VERSION + " (Anisotropic_fairing " + AF_VERSION + ")\n" +
         "CGAL " + CGAL_VERSION_STR + ", Eigen " + std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
         std::to_string(EIGEN_MINOR_VERSION) + ", Boost " + std::to_string(BOOST_VERSION / 100000) + "." +
         std::to_string(BOOST_VERSION / 100 % 1000) + "." + std::to_string(BOOST_VERSION % 100) + "\n";
}

std::string help_text()
{
  std::string text = help_before_options;
  for(const Option_spec& s : option_table)
  {
    std::string line = std::string("  ") + s.name + (s.value ? std::string(" ") + s.value : std::string());
    line += line.size() <= 25 ? std::string(28 - line.size(), ' ') : std::string(3, ' ');
    for(const char* c = s.help; *c; ++c)
      line += *c == '\n' ? std::string("\n") + std::string(28, ' ') : std::string(1, *c);
    text += line + "\n";
  }
  // the report's keys, from the report itself, wrapped like the rest
  std::string keys = "JSON report (--report; the manual's page on the program says what each key holds; unknown values are null): " +
                     report_keys() + ".";
  std::string wrapped, line;
  std::size_t start = 0;
  while(start < keys.size())
  {
    std::size_t end = keys.find(' ', start);
    if(end == std::string::npos) end = keys.size();
    const std::string word = keys.substr(start, end - start);
    if(!line.empty() && line.size() + 1 + word.size() > 100) { wrapped += line + "\n"; line.clear(); }
    line += (line.empty() ? "" : " ") + word;
    start = end + 1;
  }
  wrapped += line + "\n\n";
  const std::string after = help_after_options;
  const std::size_t exit_status = after.find("exit status:");
  return text + after.substr(0, exit_status) + wrapped + after.substr(exit_status);
}

std::string report_refused_on_failure(const Options& o)
{
  if(o.report.empty() || o.report_refused) return "refused";
  for(const std::string& p : o.positional)
    if(same_file(o.report, p)) return "it is also the argument " + quoted_excerpt(p, 200) + " of the command line";
  for(const std::string& p : {o.hold, o.snapshot})
    if(!p.empty() && same_file(o.report, p)) return "it is also " + quoted_excerpt(p, 200) + " of the command line";
  std::error_code ec;
  if(!fs::exists(o.report, ec)) return std::string();
  // an existing file is replaced only if it is a report: a JSON object with a "status"
  std::ifstream in(o.report, std::ios::binary);
  std::string head(4096, '\0');
  in.read(&head[0], std::streamsize(head.size()));
  head.resize(std::size_t(in.gcount()));
  const std::size_t first = head.find_first_not_of(" \t\r\n");
  if(!fs::is_regular_file(o.report, ec) || first == std::string::npos || head[first] != '{' || head.find("\"status\"") == std::string::npos)
    return "it exists and is not a report of this program";
  return std::string();
}

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
    try
    {
      const Option_spec* spec = find_option(arg);
      if(!spec) usage_error("unknown option " + arg);
      if(!spec->value && has_inline_value) usage_error(arg + " takes no value");
      if(spec->value && !has_inline_value)
      {
        if(i + 1 >= argc) usage_error(arg + " needs a value");
        value = argv[++i];
      }
      spec->apply(o, arg, value);
    }
    catch(const Failure& f)
    {
      // keep reading, so that a --report given later is still honoured, then report the first problem
      if(!has_error) { first_error = f; has_error = true; }
    }
  }
  o.positional = positional;
  if(o.help || o.version) return;
  if(has_error) throw first_error;
  if(positional.size() < 2) usage_error("INPUT and OUTPUT are required");
  if(positional.size() > 2) usage_error("unexpected argument " + quoted_excerpt(positional[2], 200));
  o.input = positional[0];
  o.output = positional[1];
  const AF::Fairing_options& given = o.fairing;
  if(given.time_step && given.relative_time_step) usage_error("give either --time-step or --relative-time-step, not both");
  if(given.fidelity_weight && given.relative_fidelity_weight) usage_error("give either --fidelity or --relative-fidelity, not both");
  if(given.absolute_maximum_deviation && given.relative_maximum_deviation)
    usage_error("give either --absolute-maximum-deviation or --relative-maximum-deviation, not both");
  const AF::Attribute_mode mode = effective_mode(o);
  if(o.attributes.empty() && (mode == AF::Attribute_mode::COUPLED || mode == AF::Attribute_mode::ATTRIBUTES_ONLY))
    usage_error(std::string("--mode ") + mode_name(mode) + " needs --attributes");
  // --strength scales the noise stop's target: where no run stops at the noise level it would change nothing
  const bool noise_stop = mode != AF::Attribute_mode::ATTRIBUTES_ONLY &&
                          (given.stopping_criteria ? given.stopping_criteria->noise_discrepancy > 0 : given.automatic_parameters());
  if(given.strength != 1 && !noise_stop)
    usage_error(std::string("--strength scales the noise stop, which this run does not use (") +
                (mode == AF::Attribute_mode::ATTRIBUTES_ONLY ? "--mode attributes fairs on a fixed surface"
                 : given.stopping_criteria ? "--stop " + o.stop
                                           : std::string("a time step is given: --stop paper")) +
                "); give --stop noise, or no --strength");
  const bool asked_anisotropic = o.tensor == "anisotropic";   // the tensor's options need it said
  if(o.has_lambda && !asked_anisotropic) usage_error("--lambda needs --tensor anisotropic");
  if(o.has_epsilon && !asked_anisotropic) usage_error("--epsilon needs --tensor anisotropic");
  if(o.has_tangential_motion && !asked_anisotropic) usage_error("--tangential-motion needs --tensor anisotropic");
  o.fairing.diffusion_tensor = package_tensor(o.tensor, given.automatic_parameters(), o.has_lambda || o.has_epsilon || o.has_tangential_motion,
                                              o.lambda, o.epsilon, o.normal_motion_only);
  Format f;
  if(!format_of(o.input, f)) usage_error("INPUT must be an .off, .obj, .ply or .stl file: " + o.input);
  if(!format_of(o.output, f)) usage_error("OUTPUT must be an .off, .obj, .ply or .stl file: " + o.output);
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
  if(!o.report.empty() && !o.hold.empty() && fs::is_regular_file(o.hold) && same_file(o.report, o.hold))
  {
    o.report_refused = true;
    usage_error("the report " + o.report + " is --hold's file: it would be overwritten");
  }
  if(o.curvature && f != Format::PLY)
    usage_error("--curvature needs a .ply OUTPUT (k1, k2 and mean_curvature are written as vertex properties)");
  if(o.has_resample && given.finite_element != AF::Finite_element::LOOP)
    usage_error("--resample needs --element loop (it writes the Loop limit surface)");
  if(o.has_resample && given.output_positions != AF::Output_positions::LIMIT_SURFACE)
    usage_error("--resample writes the limit surface: not with --output control");
  if(!o.snapshot.empty())
  {
    std::string e = fs::path(o.snapshot).extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if(e != ".png") usage_error("--snapshot needs a .png file: " + o.snapshot);
    for(const std::string& other : {o.input, o.output, o.report})
      if(!other.empty() && same_file(o.snapshot, other)) usage_error("--snapshot " + o.snapshot + " is also " + other);
  }
  if(o.curvature && given.finite_element != AF::Finite_element::LOOP)
    usage_error("--curvature needs --element loop (the linear element has no curvature)");
}

} // namespace af_tool
