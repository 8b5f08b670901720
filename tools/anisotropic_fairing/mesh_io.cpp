// Reading and writing the meshes of anisotropic_fairing (see mesh_io.h).
#include "mesh_io.h"

#include "mesh_file_check.h"
#include "mesh_repair.h"
#include "obj_vertex_data.h"
#include "options.h"

#include <CGAL/Surface_mesh/IO/OFF.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/boost/graph/IO/OBJ.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace af_tool {
namespace fs = std::filesystem;

namespace {

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

bool ply_is_binary(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for(int i = 0; i < 4 && std::getline(in, line); ++i)
    if(line.compare(0, 6, "format") == 0) return line.find("binary") != std::string::npos;
  return false;
}

// The comments of a PLY header as CGAL's reader keeps them: the rest of each "comment" line after the
// third, a line each
std::string ply_header_comments(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line, keyword, comments;
  for(int number = 1; std::getline(in, line); ++number)
  {
    std::istringstream words(line);
    if(!(words >> keyword) || number <= 2) continue;
    if(keyword == "end_header") break;
    if(keyword == "comment" && line.size() > 8) comments += line.substr(8) + "\n";
  }
  return comments;
}

// An ASCII PLY file whose properties hold NaN or infinity (never its coordinates: the check refuses
// those): CGAL's ASCII reader cannot read them, so it reads the text with 0 in their place, and the
// values are then put back into their properties, to be written as they were.
bool read_ply_with_nonfinite_values(const std::string& path, const Polygon_soup& soup, Mesh& mesh, std::string& comments)
{
  std::ifstream file(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  for(const Polygon_soup::Nonfinite_value& x : soup.nonfinite) text.replace(x.offset, x.length, std::string(x.length, ' ')).at(x.offset) = '0';
  std::istringstream in(text);
  if(!CGAL::IO::read_PLY(in, mesh, comments, false)) return false;
  for(const Polygon_soup::Nonfinite_value& x : soup.nonfinite)
  {
    const std::string name = (x.vertex ? "v:" : "f:") + x.property;
    const auto put_back_as = [&](auto index, auto zero) {
      typedef decltype(index) Index;
      auto map = mesh.property_map<Index, decltype(zero)>(name);
      const std::size_t count = x.vertex ? mesh.number_of_vertices() : mesh.number_of_faces();
      if(!map.second || x.index >= count) return false;
      map.first[Index(Mesh::size_type(x.index))] = decltype(zero)(x.value);
      return true;
    };
    const bool put_back = x.vertex ? put_back_as(Vertex_index(), 0.f) || put_back_as(Vertex_index(), 0.0)
                                   : put_back_as(Face_index(), 0.f) || put_back_as(Face_index(), 0.0);
    if(!put_back) return false;
  }
  return true;
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

// The reverse for writing: CGAL's PLY writer writes a colour with an alpha. When the input had none, the
// colour goes out as the three uchar properties red, green, blue (prefix "v:" or "f:") instead, so that
// the output's properties are the input's. Returns whether it did.
template <typename Index, typename Range>
bool unfold_rgb(Mesh& mesh, const Range& range, const std::string& prefix)
{
  Mesh::Property_map<Index, CGAL::IO::Color> color;
  bool has_color = false;
  std::tie(color, has_color) = mesh.property_map<Index, CGAL::IO::Color>(prefix + "color");
  if(!has_color) return false;
  auto red = mesh.add_property_map<Index, boost::uint8_t>(prefix + "red", 0).first;
  auto green = mesh.add_property_map<Index, boost::uint8_t>(prefix + "green", 0).first;
  auto blue = mesh.add_property_map<Index, boost::uint8_t>(prefix + "blue", 0).first;
  for(Index i : range)
  {
    red[i] = color[i].red();
    green[i] = color[i].green();
    blue[i] = color[i].blue();
  }
  mesh.remove_property_map(color);
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
  {
    mesh.reserve(Mesh::size_type(soup.points.size()), Mesh::size_type(2 * soup.faces.size()), Mesh::size_type(soup.faces.size()));
    for(const auto& p : soup.points) mesh.add_vertex(Point(p[0], p[1], p[2]));
  }
  std::vector<Vertex_index> face;
  for(const auto& f : soup.faces)
  {
    face.clear();
    for(std::size_t v : f) face.push_back(Vertex_index(static_cast<Mesh::size_type>(v)));
    if(mesh.add_face(face) == Mesh::null_face()) fail("read_error", "cannot build the mesh of " + soup.path);
  }
}

} // namespace

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
      if(soup.positions_and_faces_only)
      {
        // nothing but what the check read: the mesh from it, without parsing the file again
        add_soup_faces(soup, mesh);
        info.ply_comments = ply_header_comments(path);
        ok = true;
      }
      else if(soup.nonfinite.empty())
      {
        std::ifstream in(path, std::ios::binary);
        ok = CGAL::IO::read_PLY(in, mesh, info.ply_comments, false);  // keeps every property as v:<name>, f:<name>
      }
      else
        ok = read_ply_with_nonfinite_values(path, soup, mesh, info.ply_comments);
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
    info.face_alpha = fold_alpha<Face_index>(mesh, mesh.faces(), "f:color", "f:alpha");
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
// Output
// ------------------------------------------------------------------------------------------------
namespace {

bool is_internal_property(const std::string& name)
{
  return name == "v:connectivity" || name == "v:point" || name == "v:removed" || name == "f:connectivity" ||
         name == "f:removed" || name == "e:removed" || name == "h:connectivity";
}

} // namespace

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

namespace {

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

} // namespace

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
        // colours without the alpha the input did not have (a copy: the mesh is the caller's)
        const bool vertex_rgb = !info.vertex_alpha && mesh.property_map<Vertex_index, CGAL::IO::Color>("v:color").second;
        const bool face_rgb = !info.face_alpha && mesh.property_map<Face_index, CGAL::IO::Color>("f:color").second;
        if(vertex_rgb || face_rgb)
        {
          Mesh rgb = mesh;
          if(vertex_rgb) unfold_rgb<Vertex_index>(rgb, rgb.vertices(), "v:");
          if(face_rgb) unfold_rgb<Face_index>(rgb, rgb.faces(), "f:");
          ok = CGAL::IO::write_PLY(out, rgb, info.ply_comments, CGAL::parameters::stream_precision(17));
        }
        else ok = CGAL::IO::write_PLY(out, mesh, info.ply_comments, CGAL::parameters::stream_precision(17));
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

fs::path temporary_next_to(const std::string& path)
{
  const fs::path p(path);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  // the extension kept last, so that a reader (--snapshot's renderer) knows the format
  return dir / ("." + p.stem().string() + ".tmp" + std::to_string(long(::getpid())) + p.extension().string());
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

} // namespace af_tool
