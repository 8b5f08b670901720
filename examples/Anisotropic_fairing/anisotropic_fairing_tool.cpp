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
// Without input normals the library's LIMIT_SURFACE output is used directly and no normal is written.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/OFF.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/boost/graph/IO/OBJ.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>
#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
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
"(Bajaj & Xu 2003; isotropic tensor: mean-curvature flow) and writes the result to OUTPUT.\n"
"INPUT and OUTPUT are OFF, OBJ or PLY files (by extension; the formats may differ). The output keeps\n"
"the vertex order, full double precision and every vertex property of the input that its format can\n"
"hold (PLY: all of them; OFF: colours, texture coordinates, face colours; a warning names the dropped ones).\n"
"If the input has vertex normals, the normals of the faired surface are written: for the Loop element\n"
"with --output limit the exact normals of the faired limit surface (and the limit points), otherwise\n"
"the vertex normals of the output mesh (CGAL::Polygon_mesh_processing::compute_vertex_normals).\n"
"Borders (holes, scan boundaries) are held fixed, and boundary vertices are written unchanged;\n"
"vertices on no face are left as they are.\n"
"\n"
"options:\n"
"  --time-step T             time step tau in model units (length^2), as in the paper\n"
"  --relative-time-step R    time step in units of l^2, l = sqrt(area/4pi) of the input (default: the\n"
"                            library default, 1e-3); give at most one of the two\n"
"  --steps N                 the most time steps to run (default 10)\n"
"  --stop auto|off           auto (default): the criteria (27)-(29) and a steady-state test may end the\n"
"                            run earlier; off: exactly N steps\n"
"  --fidelity W              fidelity weight omega in model units (1/time), as in the paper (default 0)\n"
"  --relative-fidelity W     fidelity weight in units of 1/l^2; give at most one of the two\n"
"  --element loop|linear     Loop limit-surface elements (default) or linear (P1) elements\n"
"  --output limit|control    write the points of the faired limit surface (default) or the faired\n"
"                            control points (the mesh whose Loop limit surface is the faired surface)\n"
"  --tensor isotropic|anisotropic   the diffusion tensor; only isotropic (default) is available\n"
"  --solver auto|cg|cholesky        linear solver: automatic (default), conjugate gradients, sparse LDL^T\n"
"  --boundary curve|vertices        on a mesh with borders, hold the limit boundary curve (default: the\n"
"                            boundary vertices and the interior vertices that shape the curve) or only\n"
"                            the boundary vertices (the paper's choice; the border may slide)\n"
"  --quadrature-degree 4|6|8        Gauss rule per face for the Loop element (default 8)\n"
"  --report FILE.json        write per-step statistics (also, with status and message, on failure)\n"
"  --quiet                   no progress line per step on stderr\n"
"  --help                    print this help and exit\n"
"Options also accept the form --option=value.\n"
"\n"
"JSON report: status, message, input, output, vertices, faces, element, output_positions, tensor,\n"
"solver, requested_solver, stop, max_steps, quadrature_degree, time_step, relative_time_step, scale,\n"
"fidelity_weight, relative_fidelity_weight, mean_edge_length, normals, boundary_handling,\n"
"boundary_vertices, boundary_held_vertices, boundary_loops, isolated_vertices, constrained_vertices,\n"
"stop_reason, initial {area,\n"
"energy, H_integral}, steps [{step, time, solver_iterations, residual, area, energy, H_integral,\n"
"max_displacement, step_displacement, assemble_seconds, solve_seconds, direct_solve}], setup_seconds,\n"
"total_seconds (the fairing call), wall_seconds (the whole program). Unknown values are null.\n"
"\n"
"exit status: 0 success; 1 failure (unreadable input, a mesh that is not a 2-manifold triangle mesh,\n"
"fairing failure, unwritable output or report); 2 usage error. On failure one line starting with\n"
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
enum class Format { OFF, OBJ, PLY };

struct Options
{
  std::string input, output, report;
  bool has_time_step = false, has_relative_time_step = false;
  double time_step = 0, relative_time_step = 0;
  unsigned int steps = 10;
  bool stop_auto = true;
  bool has_fidelity = false, has_relative_fidelity = false;
  double fidelity = 0, relative_fidelity = 0;
  AF::Finite_element element = AF::Finite_element::LOOP;
  AF::Output_positions output_positions = AF::Output_positions::LIMIT_SURFACE;
  AF::Linear_solver solver = AF::Linear_solver::AUTOMATIC;
  AF::Boundary_handling boundary = AF::Boundary_handling::HOLD_BOUNDARY_CURVE;
  int quadrature_degree = 8;
  bool quiet = false;
  bool help = false;
};

double parse_double(const std::string& flag, const std::string& text)
{
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if(text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v))
    usage_error(flag + " expects a finite number, not '" + text + "'");
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
  else return false;
  return true;
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
      else if(arg == "--steps") o.steps = parse_unsigned(arg, next());
      else if(arg == "--stop")
      {
        const std::string v = next();
        if(v == "auto") o.stop_auto = true;
        else if(v == "off") o.stop_auto = false;
        else usage_error("--stop expects auto or off, not '" + v + "'");
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
        if(v == "anisotropic")  // a usage error (exit 2), with the exact message of the public interface
          throw Failure{2, "not_available", "--tensor anisotropic is not available yet (isotropic only in this version)"};
        if(v != "isotropic") usage_error("--tensor expects isotropic or anisotropic, not '" + v + "'");
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
      else if(arg == "--quadrature-degree")
      {
        const std::string v = next();
        if(v == "4" || v == "6" || v == "8") o.quadrature_degree = std::atoi(v.c_str());
        else usage_error("--quadrature-degree expects 4, 6 or 8, not '" + v + "'");
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
  Format f;
  if(!format_of(o.input, f)) usage_error("INPUT must be an .off, .obj or .ply file: " + o.input);
  if(!format_of(o.output, f)) usage_error("OUTPUT must be an .off, .obj or .ply file: " + o.output);
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
  std::vector<std::string> warnings;
};

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
// alpha back into the colour (same for faces).
template <typename Index, typename Range>
void fold_alpha(Mesh& mesh, const Range& range, const std::string& color_name, const std::string& alpha_name)
{
  Mesh::Property_map<Index, CGAL::IO::Color> color;
  Mesh::Property_map<Index, boost::uint8_t> alpha;
  bool has_color = false, has_alpha = false;
  std::tie(color, has_color) = mesh.property_map<Index, CGAL::IO::Color>(color_name);
  std::tie(alpha, has_alpha) = mesh.property_map<Index, boost::uint8_t>(alpha_name);
  if(!has_color || !has_alpha) return;
  for(Index i : range)
  {
    const CGAL::IO::Color c = color[i];
    color[i] = CGAL::IO::Color(c.red(), c.green(), c.blue(), alpha[i]);
  }
  mesh.remove_property_map(alpha);
}

void read_input(const std::string& path, Mesh& mesh, Input_info& info)
{
  if(!format_of(path, info.format)) usage_error("INPUT must be an .off, .obj or .ply file: " + path);
  std::error_code ec;
  if(!fs::is_regular_file(path, ec)) fail("read_error", "cannot open " + path + ": no such file");
  std::ifstream probe(path);
  if(!probe) fail("read_error", "cannot open " + path + ": " + std::strerror(errno));
  probe.close();

  bool ok = false;
  std::string printed;
  {
    Capture_streams capture;
    if(info.format == Format::OFF)
    {
      std::ifstream in(path);
      ok = CGAL::IO::read_OFF(in, mesh);  // Surface_mesh overload: keeps normals, colours, texture coordinates in v:*
    }
    else if(info.format == Format::PLY)
    {
      info.ply_binary = ply_is_binary(path);
      std::ifstream in(path, std::ios::binary);
      ok = CGAL::IO::read_PLY(in, mesh, info.ply_comments, false);  // keeps every property as v:<name>, f:<name>
    }
    else
    {
      std::ifstream in(path);
      ok = CGAL::IO::read_OBJ(in, mesh);
    }
    printed = capture.first_line();
  }
  if(!ok || mesh.number_of_faces() == 0)
  {
    mesh.clear();
    fail("read_error", "cannot read a polygon mesh from " + path +
                       " (unreadable file, or faces that do not form an oriented 2-manifold)" +
                       (printed.empty() ? std::string() : ": " + printed));
  }
  if(info.format == Format::PLY)
  {
    fold_alpha<Vertex_index>(mesh, mesh.vertices(), "v:color", "v:alpha");
    fold_alpha<Face_index>(mesh, mesh.faces(), "f:color", "f:alpha");
  }
  if(info.format == Format::OBJ)
  {
    bool normals, textures, colors;
    scan_obj(path, normals, textures, colors);
    if(normals) mesh.add_property_map<Vertex_index, Vector>("v:normal", Vector(0, 0, 0));
    if(textures) info.warnings.push_back("texture coordinates (vt) of " + path + " are not kept (CGAL's OBJ reader drops them)");
    if(colors) info.warnings.push_back("vertex colours on the v lines of " + path + " are not kept (CGAL's OBJ reader drops them)");
  }
  info.has_normals = mesh.property_map<Vertex_index, Vector>("v:normal").second;
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
    if(f == Format::PLY) kept = true;  // CGAL's Surface_mesh PLY writer writes every simple-typed property
    else if(f == Format::OFF) kept = (p == "v:normal" || p == "v:color" || p == "v:texcoord" || p == "f:color");
    else kept = (p == "v:normal");
    if(!kept) dropped.push_back(p);
  }
  return dropped;
}

// OBJ with normals: CGAL's OBJ writer writes vn lines but faces without //n references, so the
// normals would not be attached to the vertices. This writes "f a//a b//b c//c" instead.
bool write_obj_with_normals(std::ostream& os, const Mesh& mesh, const Normal_map& normals)
{
  os.precision(17);
  os << "# written by anisotropic_fairing\n";
  os << "# " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces() << " faces\n";
  for(Vertex_index v : mesh.vertices())
  {
    const Point& p = mesh.point(v);
    os << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  for(Vertex_index v : mesh.vertices())
  {
    const Vector& n = normals[v];
    os << "vn " << n.x() << ' ' << n.y() << ' ' << n.z() << '\n';
  }
  for(Face_index f : mesh.faces())
  {
    os << 'f';
    for(Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      os << ' ' << std::size_t(v) + 1 << "//" << std::size_t(v) + 1;
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
        if(with_normals)
          ok = write_obj_with_normals(out, mesh, mesh.property_map<Vertex_index, Vector>("v:normal").first);
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
  kv("tensor", json_string("isotropic"));
  kv("solver", ran ? json_string(f.used_cholesky ? "cholesky" : "cg") : "null");
  kv("requested_solver", json_string(solver_name(o.solver)));
  kv("stop", json_string(o.stop_auto ? "auto" : "off"));
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
  kv("boundary_handling", json_string(o.boundary == AF::Boundary_handling::HOLD_BOUNDARY_CURVE ? "curve" : "vertices"));
  kv("boundary_vertices", ran ? json_count(f.boundary_vertices) : "null");
  kv("boundary_held_vertices", ran ? json_count(f.boundary_held_vertices) : "null");
  kv("boundary_loops", ran ? json_count(f.boundary_loops) : "null");
  kv("isolated_vertices", ran ? json_count(f.isolated_vertices) : "null");
  kv("constrained_vertices", ran ? json_count(f.constrained_vertices) : "null");
  kv("stop_reason", ran ? json_string(AF::to_string(f.stop_reason)) : "null");
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
          << ", \"direct_solve\": " << (s.direct_solve ? "true" : "false") << "}";
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

  // fail early on an output that cannot be created (the final write checks again)
  {
    const fs::path out(o.output);
    const fs::path dir = out.has_parent_path() ? out.parent_path() : fs::path(".");
    std::error_code ec;
    if(!fs::is_directory(dir, ec)) fail("write_error", "cannot write " + o.output + ": no directory " + dir.string());
    if(::access(dir.c_str(), W_OK) != 0) fail("write_error", "cannot write " + o.output + ": directory " + dir.string() + " is not writable");
    if(fs::is_directory(out, ec)) fail("write_error", "cannot write " + o.output + ": it is a directory");
  }

  Mesh mesh;
  Input_info info;
  read_input(o.input, mesh, info);
  r.mesh_read = true;
  r.vertices = mesh.number_of_vertices();
  r.faces = mesh.number_of_faces();

  // Exact limit normals need the control points: see the comment at the top of this file.
  const bool limit_output = o.element == AF::Finite_element::LOOP && o.output_positions == AF::Output_positions::LIMIT_SURFACE;
  const bool exact_limit_normals = info.has_normals && limit_output;
  const AF::Output_positions library_output = exact_limit_normals ? AF::Output_positions::CONTROL_POINTS : o.output_positions;

  const unsigned int max_steps = o.steps;
  const bool quiet = o.quiet;
  auto progress = [max_steps, quiet](const AF::Fairing_step& s) {
    if(!quiet)
      std::fprintf(stderr, "step %zu/%u  t=%.6g  area=%.6g  int|H|^2=%.6g  max disp=%.6g  %d %s  %.3fs+%.3fs\n",
                   s.step, max_steps, s.time, s.area, s.H_integral, s.max_displacement, s.solver_iterations,
                   s.direct_solve ? "factorisation" : "its",
                   s.assemble_seconds, s.solve_seconds);
    return true;
  };
  auto fair = [&mesh](const auto& np) { return AF::anisotropic_fairing(mesh, np); };

  const auto base = AF::parameters::number_of_iterations(max_steps)
                      .stopping_criteria(o.stop_auto ? AF::Stopping_criteria() : AF::Stopping_criteria::none())
                      .finite_element(o.element)
                      .output_positions(library_output)
                      .linear_solver(o.solver)
                      .boundary_handling(o.boundary)
                      .quadrature_degree(o.quadrature_degree)
                      .callback(progress);
  try
  {
    r.report = with_time_step(base, o, fair);
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

  if(info.has_normals)
  {
    Normal_map normals = mesh.property_map<Vertex_index, Vector>("v:normal").first;
    if(exact_limit_normals)
    {
      // the mesh holds the faired control points; the quadrature is not used here (degree 4 is the cheapest set-up)
      AF::Loop_limit_surface<Mesh> limit(mesh, AF::parameters::quadrature_degree(4));
      limit.limit_normals(normals);
      // as in the library's limit output, boundary and isolated vertices keep their (held) positions
      std::vector<std::pair<Vertex_index, Point>> held;
      for(Vertex_index v : mesh.vertices())
        if(mesh.is_border(v) || mesh.is_isolated(v)) held.emplace_back(v, mesh.point(v));
      limit.limit_positions(mesh.points());
      for(const auto& h : held) mesh.point(h.first) = h.second;
      r.normals = "limit_surface";
    }
    else
    {
      CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);
      r.normals = "vertex_normals";
    }
  }

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
  if(!o.report.empty() && !write_file_atomically(o.report, report_json(o, r, elapsed_seconds())))
    line += " (and cannot write the report " + o.report + ")";
  std::fprintf(stderr, "%s\n", line.c_str());
  return code;
}
