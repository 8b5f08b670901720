// The options of anisotropic_fairing. Those of the library's parameters come from its parameter table
// (CGAL/Anisotropic_fairing/internal/parameter_table.h), the program's own from `program_options`; the
// parser reads both, the help text is made from them, and scripts/option_docs.py makes the manual's list
// from the help (the test cli_option_docs checks they agree).
#include "options.h"
#include "json_report.h"
#include "option_kinds.h"
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

// The options of the library's parameters, in the table's order (a row without option has no name)
#define AF_PARAMETER(name, type, default_value, named, setting, check, flag, value, program, python, help) \
  {flag, nullptr, value, help, [](Options& o, const std::string& f, const std::string& v) {                \
     const auto set = program;                                                                              \
     set(o, o.fairing.name, f, v);                                                                          \
   }},
#define AF_TENSOR_SETTING(name, flag, value, program, python, help)                         \
  {flag, nullptr, value, help, [](Options& o, const std::string& f, const std::string& v) { \
     const auto set = program;                                                              \
     set(o, f, v);                                                                          \
   }},
const Option_spec parameter_options[] = {
#include <CGAL/Anisotropic_fairing/internal/parameter_table.h>
};
#undef AF_PARAMETER
#undef AF_TENSOR_SETTING

// Spellings kept working, each with the option it now names and the warning it gives.
struct Deprecated_flag
{
  const char* flag;
  const char* now;
  const char* warning;
};
const Deprecated_flag deprecated_flags[] = {
  {"--maximum-deviation", "--absolute-maximum-deviation",
   "--maximum-deviation is deprecated: write --absolute-maximum-deviation (model units, as here) or "
   "--relative-maximum-deviation (units of l, as the library's maximum_deviation)"},
};

// The program's own options, after the parameters' in the help.
const Option_spec program_options[] = {
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

// every option: the parameters' that have one, then the program's own
const std::vector<Option_spec>& option_table()
{
  static const std::vector<Option_spec> table = [] {
    std::vector<Option_spec> t;
    for(const Option_spec& s : parameter_options)
      if(s.name) t.push_back(s);
    t.insert(t.end(), std::begin(program_options), std::end(program_options));
    return t;
  }();
  return table;
}

// the option that `arg` names; a deprecated spelling names the option it now is, and gives its `warning`
const Option_spec* find_option(const std::string& arg, const char*& warning)
{
  std::string name = arg;
  warning = nullptr;
  for(const Deprecated_flag& d : deprecated_flags)
    if(arg == d.flag)
    {
      warning = d.warning;
      name = d.now;
    }
  for(const Option_spec& s : option_table())
    if(name == s.name || (s.alias && name == s.alias)) return &s;
  return nullptr;
}

} // namespace

// --mode, or its default: separate with --attributes, geometry without
AF::Attribute_mode effective_mode(const Options& o)
{
  return o.fairing.attribute_mode.value_or(o.attributes.empty() ? AF::Attribute_mode::GEOMETRY_ONLY
                                                                : AF::Attribute_mode::SEPARATE);
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
         "CGAL " + CGAL_VERSION_STR + ", Eigen " + std::to_string(EIGEN_WORLD_VERSION) + "." +
         std::to_string(EIGEN_MAJOR_VERSION) + "." +
         std::to_string(EIGEN_MINOR_VERSION) + ", Boost " + std::to_string(BOOST_VERSION / 100000) + "." +
         std::to_string(BOOST_VERSION / 100 % 1000) + "." + std::to_string(BOOST_VERSION % 100) + "\n";
}

std::string help_text()
{
  std::string text = help_before_options;
  for(const Option_spec& s : option_table())
  {
    std::string line = std::string("  ") + s.name + (s.value ? std::string(" ") + s.value : std::string());
    line += line.size() <= 25 ? std::string(28 - line.size(), ' ') : std::string(3, ' ');
    for(const char* c = s.help; *c; ++c)
      line += *c == '\n' ? std::string("\n") + std::string(28, ' ') : std::string(1, *c);
    text += line + "\n";
  }
  // the report's keys, from the report itself, wrapped like the rest
  std::string keys =
    "JSON report (--report; the manual's page on the program says what each key holds; unknown values are null): " +
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
  if(!fs::is_regular_file(o.report, ec) || first == std::string::npos || head[first] != '{' ||
     head.find("\"status\"") == std::string::npos)
    return "it exists and is not a report of this program";
  return std::string();
}

namespace {

// One option with its value: `arg` as given, its value inline (--option=value) or the next argument.
void read_option(std::string arg, int argc, char** argv, int& i, Options& o)
{
  std::string value;
  bool has_inline_value = false;
  const std::size_t eq = arg.find('=');
  if(arg.compare(0, 2, "--") == 0 && eq != std::string::npos)
  {
    value = arg.substr(eq + 1);
    arg = arg.substr(0, eq);
    has_inline_value = true;
  }
  const char* warning = nullptr;
  const Option_spec* spec = find_option(arg, warning);
  if(!spec) usage_error("unknown option " + arg);
  if(!spec->value && has_inline_value) usage_error(arg + " takes no value");
  if(spec->value && !has_inline_value)
  {
    if(i + 1 >= argc) usage_error(arg + " needs a value");
    value = argv[++i];
  }
  if(warning) o.deprecations.push_back(warning);
  spec->apply(o, arg, value);
}

// Reads every argument into `o`, the options in the order given, and returns the first usage error, if any.
std::optional<Failure> read_arguments(int argc, char** argv, Options& o)
{
  std::optional<Failure> first_error;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(arg.size() < 2 || arg[0] != '-') { o.positional.push_back(arg); continue; }
    if(arg == "--") { for(++i; i < argc; ++i) o.positional.push_back(argv[i]); break; }
    try
    {
      read_option(arg, argc, argv, i, o);
    }
    catch(const Failure& f)
    {
      // keep reading, so that a --report given later is still honoured, then report the first problem
      if(!first_error) first_error = f;
    }
  }
  return first_error;
}

// The checks between the parameters' options, then the tensor they make.
void check_parameters(Options& o)
{
  const AF::Fairing_options& given = o.fairing;
  if(given.time_step && given.relative_time_step)
    usage_error("give either --time-step or --relative-time-step, not both");
  if(given.fidelity_weight && given.relative_fidelity_weight)
    usage_error("give either --fidelity or --relative-fidelity, not both");
  if(given.absolute_maximum_deviation && given.relative_maximum_deviation)
    usage_error("give either --absolute-maximum-deviation or --relative-maximum-deviation, not both");
  const AF::Attribute_mode mode = effective_mode(o);
  if(o.attributes.empty() && (mode == AF::Attribute_mode::COUPLED || mode == AF::Attribute_mode::ATTRIBUTES_ONLY))
    usage_error(std::string("--mode ") + mode_name(mode) + " needs --attributes");
  // --strength scales the noise stop's target: where no run stops at the noise level it would change nothing
  const bool noise_stop =
    mode != AF::Attribute_mode::ATTRIBUTES_ONLY &&
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
  const bool settings = o.has_lambda || o.has_epsilon || o.has_tangential_motion;
  o.fairing.diffusion_tensor =
    package_tensor(o.tensor, given.automatic_parameters(), settings, o.lambda, o.epsilon, o.normal_motion_only);
}

// The report may overwrite no other file of the command line.
void check_report_path(Options& o)
{
  if(o.report.empty()) return;
  const auto hold_file = [&o] { return !o.hold.empty() && fs::is_regular_file(o.hold) && same_file(o.report, o.hold); };
  const char* clash = same_file(o.report, o.input)    ? " is the INPUT: it would be overwritten"
                      : same_file(o.report, o.output) ? " is the OUTPUT: one would overwrite the other"
                      : hold_file()                   ? " is --hold's file: it would be overwritten"
                                                      : nullptr;
  if(!clash) return;
  o.report_refused = true;
  usage_error("the report " + o.report + clash);
}

// The files: their formats, and nothing written over the input or another file written.
void check_files(Options& o)
{
  Format f;
  if(!format_of(o.input, f)) usage_error("INPUT must be an .off, .obj, .ply or .stl file: " + o.input);
  if(!format_of(o.output, f)) usage_error("OUTPUT must be an .off, .obj, .ply or .stl file: " + o.output);
  // nothing written may overwrite the input or another file written (the report is not written either)
  if(same_file(o.output, o.input)) usage_error("OUTPUT " + o.output + " is the INPUT: it would be overwritten");
  check_report_path(o);
  if(o.curvature && f != Format::PLY)
    usage_error("--curvature needs a .ply OUTPUT (k1, k2 and mean_curvature are written as vertex properties)");
  const AF::Fairing_options& given = o.fairing;
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

} // namespace

void parse_arguments(int argc, char** argv, Options& o)
{
  o.positional.clear();
  const std::optional<Failure> first_error = read_arguments(argc, argv, o);
  if(o.help || o.version) return;
  if(first_error) throw *first_error;
  if(o.positional.size() < 2) usage_error("INPUT and OUTPUT are required");
  if(o.positional.size() > 2) usage_error("unexpected argument " + quoted_excerpt(o.positional[2], 200));
  o.input = o.positional[0];
  o.output = o.positional[1];
  check_parameters(o);
  check_files(o);
}

} // namespace af_tool
