// Reading the meshes of anisotropic_fairing (see mesh_io.h; writing: mesh_write.cpp).
#include "mesh_io.h"

#include "captured_streams.h"
#include "element_properties.h"
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
bool read_ply_with_nonfinite_values(const std::string& path, const Polygon_soup& soup, Mesh& mesh,
                                    std::string& comments)
{
  std::ifstream file(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  for(const Polygon_soup::Nonfinite_value& x : soup.nonfinite)
    text.replace(x.offset, x.length, std::string(x.length, ' ')).at(x.offset) = '0';
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
    mesh.reserve(Mesh::size_type(soup.points.size()), Mesh::size_type(2 * soup.faces.size()),
                 Mesh::size_type(soup.faces.size()));
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

// Whether the faces of an ASCII OFF file carry colours: CGAL's reader makes "f:color" for every file with
// "C" in its keyword, black where a face line has none.
bool off_face_colours(const std::string& text)
{
  std::istringstream in(text);
  std::string line;
  std::size_t content = 0, vertices = 0, faces = 0;
  while(std::getline(in, line))
  {
    std::istringstream words(line.substr(0, line.find('#')));
    std::vector<std::string> w{std::istream_iterator<std::string>(words), std::istream_iterator<std::string>()};
    if(w.empty()) continue;
    if(content == 0 && w.size() >= 4)
    {
      vertices = std::strtoull(w[1].c_str(), nullptr, 10);
      faces = std::strtoull(w[2].c_str(), nullptr, 10);
      content = 2;
      continue;
    }
    if(content == 1)
    {
      vertices = std::strtoull(w[0].c_str(), nullptr, 10);
      faces = std::strtoull(w[1].c_str(), nullptr, 10);
    }
    ++content;
    if(content <= 2 + vertices) continue;
    if(content > 2 + vertices + faces) break;
    if(w.size() > 1 + std::strtoull(w[0].c_str(), nullptr, 10)) return true;
  }
  return false;
}

// The text of an OFF or PLY file whose header declares no face (nor triangle strip): CGAL's reader then
// reads the vertices and their properties alone. False for a file it cannot say so of (binary OFF).
bool without_faces(std::string& text, Format format)
{
  if(format == Format::PLY)
  {
    const std::size_t end = text.find("end_header");
    if(end == std::string::npos) return false;
    for(const char* element : {"element face ", "element tristrips "})
      for(std::size_t at = text.find(element); at != std::string::npos && at < end; at = text.find(element, at + 1))
      {
        const std::size_t count = at + std::strlen(element), eol = text.find_first_of("\r\n", count);
        text.replace(count, eol - count, "0");
      }
    return true;
  }
  // OFF: the keyword ([ST][C][N]OFF), then "vertices faces edges", on its line or the next
  std::size_t at = 0;
  std::vector<std::pair<std::size_t, std::size_t> > words;   // offset, length
  while(words.size() < 3)
  {
    at = text.find_first_not_of(" \t\r\n", at);
    if(at == std::string::npos) return false;
    if(text[at] == '#') { at = text.find('\n', at); continue; }
    const std::size_t end = std::min(text.find_first_of(" \t\r\n#", at), text.size());
    words.emplace_back(at, end - at);
    if(words.size() == 1)
    {
      const std::string keyword = text.substr(at, end - at);
      if(keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0 ||
         keyword.find_first_of("4n") != std::string::npos)
        return false;
      const std::size_t eol = text.find('\n', end);
      if(text.substr(end, eol == std::string::npos ? std::string::npos : eol - end).find("BINARY") != std::string::npos)
        return false;
    }
    at = end;
  }
  text.replace(words[2].first, words[2].second, "0");
  return true;
}

// The mesh of a repaired soup with the vertex properties of the file's vertices: CGAL's reader reads
// the vertices alone (without_faces), the copies of split vertices and the faces come from the soup.
// Where that cannot be done, the positions alone, as said in a warning.
void read_vertices_then_soup_faces(const std::string& path, const Polygon_soup& soup, std::size_t file_vertices,
                                   Mesh& mesh, Input_info& info)
{
  std::ifstream file(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  std::string patched;
  const bool stoff = info.format == Format::OFF && stoff_without_colors(path, patched);
  if(stoff) text = patched;
  const bool face_colours = info.format == Format::OFF && off_face_colours(text);
  bool read = false;
  if(without_faces(text, info.format))
  {
    Capture_streams capture;
    std::istringstream in(text);
    if(info.format == Format::PLY)
    {
      info.ply_binary = ply_is_binary(path);
      read = CGAL::IO::read_PLY(in, mesh, info.ply_comments, false);
    }
    else
    {
      read = CGAL::IO::read_OFF(in, mesh);
      if(stoff)   // the colour map made for the "C" stoff_without_colors() put in
      {
        auto vcolor = mesh.property_map<Vertex_index, CGAL::IO::Color>("v:color");
        if(vcolor.second) mesh.remove_property_map(vcolor.first);
      }
    }
    read = read && mesh.number_of_vertices() == file_vertices;
  }
  if(!read)
  {
    mesh.clear();
    info.warnings.push_back("the mesh of " + path +
                            " was rebuilt from its positions and faces: its other vertex properties are not kept");
  }
  std::string face_properties;   // made by the reader for faces it did not read
  for(const std::string& p : mesh.properties<Face_index>())
    if(!is_internal_property(p)) face_properties += (face_properties.empty() ? "" : ", ") + p.substr(2);
  for(const std::string& p : mesh.properties<Face_index>())
    if(!is_internal_property(p))
      with_property_map<Face_index>(mesh, p, [&](auto& map) { mesh.remove_property_map(map); });
  if(!face_properties.empty() && (info.format == Format::PLY || face_colours))
    info.warnings.push_back("the face properties of " + path + " (" + face_properties +
                            ") are not kept: its faces were rebuilt");
  if(read)
    for(std::size_t v = file_vertices; v < soup.points.size(); ++v)
      mesh.add_vertex(Point(soup.points[v][0], soup.points[v][1], soup.points[v][2]));
  add_soup_faces(soup, mesh);
}

// INPUT exists and can be opened, and its extension names a format.
void check_openable(const std::string& path, Input_info& info)
{
  if(!format_of(path, info.format)) usage_error("INPUT must be an .off, .obj, .ply or .stl file: " + path);
  std::error_code ec;
  if(fs::is_directory(path, ec)) fail("read_error", "cannot open " + path + ": it is a directory");
  if(!fs::exists(path, ec)) fail("read_error", "cannot open " + path + ": no such file");
  if(!fs::is_regular_file(path, ec)) fail("read_error", "cannot open " + path + ": not a regular file");
  std::ifstream probe(path);
  if(!probe) fail("read_error", "cannot open " + path + system_reason(errno ? errno : EIO));
}

// The file read and checked before CGAL's readers see it (mesh_file_check.h).
af_tool::Polygon_soup checked_soup(const std::string& path, const Input_info& info)
{
  try { return af_tool::read_checked_soup(path, af_tool::Mesh_format(int(info.format))); }
  catch(const af_tool::File_problem& e) { fail("read_error", std::string("cannot read ") + e.what()); }
}

// Faces that are no oriented 2-manifold (non-manifold vertices and edges of raw scans, flipped faces, faces
// repeating a vertex) are made one for the run (vertex_split.h); returns whether the soup was changed, the
// mesh then being built from it, with the vertex properties the file's vertices have.
bool make_oriented_manifold(af_tool::Polygon_soup& soup, Input_info& info, bool repair)
{
  const std::size_t file_vertices = soup.points.size();
  try { af_tool::check_oriented_manifold(soup); return false; }
  catch(const af_tool::File_problem& e)
  {
    const af_tool::Soup_repair fixed = af_tool::repair_soup(soup);
    try { af_tool::check_oriented_manifold(soup); }
    catch(const af_tool::File_problem& again)
    {
      fail("input_error", std::string("cannot fair ") + again.what() +
                          (repair ? ", even after --repair" : ", even after splitting its non-manifold vertices"));
    }
    info.split.file_vertices = file_vertices;
    info.split.copy_of = fixed.copy_of;
    info.split.split_vertices = fixed.split_vertices;
    for(const std::string& c : fixed.changes) info.input_changes.push_back(repair ? "--repair: " + c : c);
    if(repair && !fixed.copy_of.empty())
      info.input_changes.push_back("--repair: the copies of split vertices are written after the input's " +
                                   std::to_string(file_vertices) + " vertices");
    if(!repair)
    {
      std::string changes;
      for(const std::string& c : fixed.changes) changes += (changes.empty() ? "" : "; ") + c;
      info.warnings.push_back(std::string(e.what()) + ": for the run, " + changes +
                              (fixed.copy_of.empty() ? std::string()
                                                     : "; each split vertex is written once, at the mean of its "
                                                       "copies, with the input's vertex numbers"));
    }
    return true;
  }
}

// The mesh of a repaired soup, or of an STL file (whose corners the check merged), without CGAL's readers.
void build_from_soup(const std::string& path, const af_tool::Polygon_soup& soup, std::size_t file_vertices,
                     bool rebuilt, Mesh& mesh, Input_info& info)
{
  if(rebuilt && info.format != Format::STL && info.format != Format::OBJ)
    read_vertices_then_soup_faces(path, soup, file_vertices, mesh, info);
  else if(rebuilt && info.format == Format::OBJ)
    add_soup_faces(soup, mesh);   // CGAL's OBJ reader keeps no vertex property: what the program keeps is read below
  if(info.format == Format::STL)
  {
    add_soup_faces(soup, mesh);
    info.notes.push_back(std::to_string(soup.merged_points) + " triangle corners of " + path + " merged into the " +
                         std::to_string(file_vertices) + " vertices they coincide with");
  }
}

bool read_off_with_cgal(const std::string& path, Mesh& mesh)
{
  std::string patched;
  if(stoff_without_colors(path, patched))
  {
    std::istringstream in(patched);
    const bool ok = CGAL::IO::read_OFF(in, mesh);
    // the colour maps made for the "C" put in by stoff_without_colors(): nothing was read into them
    auto vcolor = mesh.property_map<Vertex_index, CGAL::IO::Color>("v:color");
    if(vcolor.second) mesh.remove_property_map(vcolor.first);
    auto fcolor = mesh.property_map<Face_index, CGAL::IO::Color>("f:color");
    if(fcolor.second) mesh.remove_property_map(fcolor.first);
    return ok;
  }
  std::ifstream in(path);
  const bool ok =
    CGAL::IO::read_OFF(in, mesh); // Surface_mesh overload: keeps normals, colours, texture coordinates in v:*
  // no face colours where the file has none (CGAL's reader makes them black for a COFF file)
  auto fcolor = mesh.property_map<Face_index, CGAL::IO::Color>("f:color");
  std::ifstream again(path, std::ios::binary);
  if(ok && fcolor.second &&
     !off_face_colours(std::string(std::istreambuf_iterator<char>(again), std::istreambuf_iterator<char>())))
    mesh.remove_property_map(fcolor.first);
  return ok;
}

bool read_ply_with_cgal(const std::string& path, const af_tool::Polygon_soup& soup, Mesh& mesh, Input_info& info)
{
  bool ok;
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
  return ok;
}

// CGAL's readers, which keep the vertex and face properties; `printed`: the first line they printed.
bool read_with_cgal(const std::string& path, const af_tool::Polygon_soup& soup, Mesh& mesh, Input_info& info,
                    std::string& printed)
{
  bool ok;
  Capture_streams capture;
  if(info.format == Format::OFF)
    ok = read_off_with_cgal(path, mesh);
  else if(info.format == Format::PLY)
    ok = read_ply_with_cgal(path, soup, mesh, info);
  else
  {
    std::ifstream in(path);
    ok = CGAL::IO::read_OBJ(in, mesh);
  }
  printed = capture.first_line();
  return ok;
}

// What the program keeps of an OBJ file that CGAL's reader drops: vn (recomputed), vt one per vertex.
void keep_obj_vertex_data(const std::string& path, std::size_t file_vertices, Mesh& mesh, Input_info& info)
{
  bool normals, textures, colors;
  scan_obj(path, normals, textures, colors);
  if(normals) mesh.add_property_map<Vertex_index, Vector>("v:normal", Vector(0, 0, 0));
  if(textures)
  {
    const Obj_texcoords t = read_obj_texcoords(path, file_vertices);
    if(t.matched)
    {
      Texcoord_map uv = mesh.add_property_map<Vertex_index, Texcoord>("v:texcoord", Texcoord(0, 0)).first;
      for(std::size_t v = 0; v < file_vertices; ++v)
        uv[Vertex_index(Mesh::size_type(v))] = Texcoord(t.uv[v][0], t.uv[v][1]);
      if(t.dropped_w) info.warnings.push_back("the third components (w) of the vt of " + path + " are not kept");
    }
    else
    {
      info.uv_problem = "the texture coordinates (vt) of " + path + " are not one per vertex (" + t.problem + ")";
      info.warnings.push_back(info.uv_problem + ": not kept");
    }
  }
  if(colors)
    info.warnings.push_back("vertex colours on the v lines of " + path +
                            " are not kept (CGAL's OBJ reader drops them)");
}

// The mesh made ready for the run: properties on the split copies, --repair, triangles only.
void prepare_for_run(const std::string& path, Mesh& mesh, Input_info& info, bool repair)
{
  copy_properties_to_copies(mesh, info.split);
  if(repair)
  {
    for(const std::string& c : af_tool::repair_mesh(mesh)) info.input_changes.push_back("--repair: " + c);
    info.split = Vertex_split();   // --repair writes the repaired mesh, copies included
  }
  info.triangulated_faces = af_tool::triangulate_polygons(mesh);
  if(info.triangulated_faces)
  {
    info.input_changes.push_back("triangulated " + std::to_string(info.triangulated_faces) +
                                 " faces that are not triangles");
    info.warnings.push_back(std::to_string(info.triangulated_faces) + " faces of " + path +
                            " are not triangles: triangulated (CGAL's triangulate_faces), and written as triangles");
  }
  for(const std::string& c : info.input_changes)
    if(c.compare(0, 9, "--repair:") == 0) info.notes.push_back(c);
  info.has_normals = mesh.property_map<Vertex_index, Vector>("v:normal").second;
  info.normals_read = info.has_normals && info.format != Format::OBJ;
}

} // namespace

void read_input(const std::string& path, Mesh& mesh, Input_info& info, bool repair)
{
  check_openable(path, info);
  af_tool::Polygon_soup soup = checked_soup(path, info);
  const std::size_t file_vertices = soup.points.size();
  const bool rebuilt = make_oriented_manifold(soup, info, repair);
  info.warnings.insert(info.warnings.end(), soup.warnings.begin(), soup.warnings.end());
  build_from_soup(path, soup, file_vertices, rebuilt, mesh, info);

  std::string printed;
  const bool ok = info.format == Format::STL || rebuilt || read_with_cgal(path, soup, mesh, info, printed);
  // the checks above are those CGAL's readers make: a difference would be a bug of ours
  if(!ok || mesh.number_of_faces() != soup.faces.size() || mesh.number_of_vertices() != soup.points.size())
  {
    mesh.clear();
    fail("read_error", "cannot read a polygon mesh from " + path +
                         " (CGAL's reader refused a file the checks accepted)" +
                         (printed.empty() ? std::string() : ": " + printed));
  }
  if(info.format == Format::PLY)
  {
    info.vertex_alpha = fold_alpha<Vertex_index>(mesh, mesh.vertices(), "v:color", "v:alpha");
    info.face_alpha = fold_alpha<Face_index>(mesh, mesh.faces(), "f:color", "f:alpha");
  }
  if(info.format == Format::OBJ) keep_obj_vertex_data(path, file_vertices, mesh, info);
  prepare_for_run(path, mesh, info, repair);
}

} // namespace af_tool
