// anisotropic_fairing tool: checked reading of OFF, OBJ and STL files, and the choice of reader
// (mesh_file_check.h says why).

#include "mesh_file_check.h"
#include "text_tokens.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

namespace af_tool {

std::string file_contents(const std::string& path)
{
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if(!in) throw File_problem("cannot open " + path + system_reason(errno));
  std::ostringstream s;
  s << in.rdbuf();
  if(in.bad()) throw File_problem(path + (errno ? system_reason(errno) : ": a read failed"));
  return s.str();
}

void check_count(const std::string& path, const std::string& what, unsigned long long count, const std::string& unit,
                 std::size_t bytes, std::size_t each)
{
  if(each > 0 && count > bytes / each)
    throw File_problem(path + ": " + what + " " + std::to_string(count) + " " + unit + ", more than the " +
                       std::to_string(bytes) + " bytes left in the file can hold (at least " + std::to_string(each) +
                       " each)");
}

void add_face(Polygon_soup& soup, const std::vector<long long>& index, std::size_t vertices, const std::string& place,
              const std::string& path)
{
  if(index.size() < 3)
    throw File_problem(path + " " + place + ": a face of " + std::to_string(index.size()) +
                       " vertices (at least 3 are needed)");
  std::vector<std::size_t> face;
  face.reserve(index.size());
  for(long long i : index)
  {
    if(i < 0 || static_cast<unsigned long long>(i) >= vertices)
      throw File_problem(path + " " + place + ": the face refers to vertex " + std::to_string(i) +
                         ", but the file has " + std::to_string(vertices) + " vertices" +
                         (vertices > 0 ? " (0.." + std::to_string(vertices - 1) + ")" : std::string()));
    face.push_back(std::size_t(i));
  }
  soup.faces.push_back(std::move(face));
  soup.face_place.push_back(place);
}

namespace {

std::uint32_t big_endian_u32(const std::string& text, std::size_t at)
{
  const auto b = [&](std::size_t k) { return std::uint32_t(static_cast<unsigned char>(text[at + k])); };
  return (b(0) << 24) | (b(1) << 16) | (b(2) << 8) | b(3);
}

// Geomview's binary OFF: big-endian 32-bit integers and floats after the "OFF BINARY" line
Polygon_soup read_binary_off(const std::string& path, const std::string& text, std::size_t start, int dim, bool normals,
                             bool colors, bool texcoords)
{
  Polygon_soup soup;
  std::size_t at = start;
  auto need = [&](std::size_t bytes, const std::string& what) {
    if(bytes > text.size() - at)
      throw File_problem(path + ": the file ends inside " + what + " (byte " + std::to_string(at) + ")");
  };
  auto u32 = [&](const std::string& what) {
    need(4, what);
    const std::uint32_t v = big_endian_u32(text, at);
    at += 4;
    return v;
  };
  auto f32 = [&](const std::string& what) {
    const std::uint32_t bits = u32(what);
    float f;
    std::memcpy(&f, &bits, 4);
    return double(f);
  };
  const std::uint32_t nv = u32("the counts"), nf = u32("the counts");
  if(u32("the counts") > 1073741823u)
    throw File_problem(path + ": the edge count is out of range (0..2^30-1)"); // CGAL doubles it in an int
  const std::size_t per_vertex = std::size_t(dim) + (normals ? 3 : 0) + (colors ? 4 : 0) + (texcoords ? 2 : 0);
  check_count(path, "the header declares", nv, "vertices", text.size() - at, 4 * per_vertex);
  check_count(path, "the header declares", nf, "faces", text.size() - at, 8);
  soup.points.resize(nv);
  for(std::uint32_t v = 0; v < nv; ++v)
  {
    const std::string what = "vertex " + std::to_string(v);
    double c[4] = {0, 0, 0, 1};
    for(int k = 0; k < dim; ++k) c[k] = f32(what);
    for(std::size_t k = std::size_t(dim); k < per_vertex; ++k) f32(what);
    for(int k = 0; k < 3; ++k)
    {
      const double x = dim == 4 ? c[k] / c[3] : c[k];
      if(!std::isfinite(x))
        throw File_problem(path + ": vertex " + std::to_string(v) + " has a coordinate that is not a finite number");
      soup.points[v][std::size_t(k)] = x;
    }
  }
  std::vector<long long> index;
  for(std::uint32_t f = 0; f < nf; ++f)
  {
    const std::string what = "face " + std::to_string(f);
    const std::uint32_t k = u32(what);
    need(std::size_t(k) * 4, what);
    index.resize(k);
    for(std::uint32_t i = 0; i < k; ++i) index[i] = static_cast<std::int32_t>(u32(what));
    if(u32(what) != 0)
      throw File_problem(path + ": " + what + " has a colour: binary OFF with colours is not supported");
    add_face(soup, index, nv, what, path);
  }
  return soup;
}

// An OFF colour: one colour-map index, or red, green, blue (and alpha) either as integers 0..255 or, if
// one of them is written with a point or an exponent, as numbers in [0, 1]. CGAL 5.5 casts them to bytes
// unchecked (510 or a negative index is undefined behaviour there), so anything else is refused.
void check_off_color(const Text_lines& lines, const std::vector<std::string_view>& t, std::size_t first,
                     const std::string& what)
{
  const std::size_t n = t.size() - first;
  if(n == 0) return;
  if(n != 1 && n != 3 && n != 4)
    lines.fail(what + " has a colour of " + std::to_string(n) + " numbers (1, 3 or 4 expected)");
  bool fractions = false;
  for(std::size_t k = first; k < t.size(); ++k)
    fractions = fractions || t[k].find_first_of(".eE") != std::string_view::npos;
  for(std::size_t k = first; k < t.size(); ++k)
  {
    if(n > 1 && fractions)
    {
      const double x = lines.real(t[k], "the colour component");
      if(x < 0 || x > 1) lines.fail(what + " has a colour component " + std::string(t[k]) + " outside [0, 1]");
    }
    else
    {
      const long long x = lines.integer(t[k], "the colour component");
      if(x < 0 || x > 255) lines.fail(what + " has a colour component " + std::string(t[k]) + " outside 0..255");
    }
  }
}

// What the header line of an OFF file declares.
struct Off_header
{
  std::string keyword;   // as written, for the messages
  bool texcoords = false, colors = false, normals = false, homogeneous = false, any_dim = false;
  bool binary = false;   // the counts and the rest follow in binary
  int dim = 3;
  long long vertices = 0, faces = 0;

  // the numbers of a vertex line that are not colours
  std::size_t texcoord_numbers() const { return texcoords ? (homogeneous ? 3 : 2) : 0; }
};

// CGAL 5.5 reads a '#' on the header line neither as a comment nor as an error (it may then take binary
// counts from the text): the header line holds the keyword and the counts or BINARY only.
void check_header_line_has_no_comment(const Text_lines& lines, const std::string& text)
{
  std::size_t begin = 0;
  for(std::size_t k = 1; k < lines.line(); ++k) begin = text.find('\n', begin) + 1;
  const std::size_t end = text.find('\n', begin);
  if(text.substr(begin, end == std::string::npos ? std::string::npos : end - begin).find('#') != std::string::npos)
    lines.fail("a '#' on the header line (write comments on lines of their own)");
}

// [ST][C][N][4][n]OFF: texture coordinates, colours, normals, homogeneous coordinates, dimension
void read_off_keyword(const Text_lines& lines, const std::vector<std::string_view>& t, Off_header& h)
{
  h.keyword = std::string(t[0]);
  std::string_view key = t[0];
  const auto flag = [&](std::string_view prefix) {
    if(key.substr(0, prefix.size()) != prefix) return false;
    key.remove_prefix(prefix.size());
    return true;
  };
  h.texcoords = flag("ST");
  h.colors = flag("C");
  h.normals = flag("N");
  h.homogeneous = flag("4");
  h.any_dim = flag("n");
  if(key != "OFF") lines.fail("the header " + quoted_excerpt(t[0]) + " is not an OFF keyword ([ST][C][N][4][n]OFF)");
  h.dim = h.homogeneous ? 4 : 3;
  h.binary = t.size() > 1 && t[1] == "BINARY";
}

// The dimension (nOFF) and the counts, on the header line or the lines after it.
void read_off_counts(Text_lines& lines, std::vector<std::string_view>& t, const std::string& path,
                     const std::string& text, Off_header& h)
{
  std::size_t used = 1;
  const auto next_number = [&](const char* what) {
    if(used >= t.size())
    {
      if(!lines.next(t)) lines.fail(std::string("the file ends before ") + what);
      used = 0;
    }
    return lines.integer(t[used++], what);
  };
  if(h.any_dim)
  {
    const long long n = next_number("the dimension");
    if(n != 3) lines.fail("an nOFF file of dimension " + std::to_string(n) + " (only 3 is a surface in space)");
  }
  h.vertices = next_number("the vertex count");
  h.faces = next_number("the face count");
  // the edge count means nothing to a reader, but CGAL 5.5 reads it wherever it is (on the next line if
  // need be, taking a coordinate for it) and doubles it in an int
  const long long ne = next_number("the edge count");
  if(ne < 0 || ne > 1073741823) lines.fail("the edge count " + std::to_string(ne) + " is out of range (0..2^30-1)");
  if(used < t.size()) lines.fail("unexpected " + quoted_excerpt(t[used]) + " after the counts");
  if(h.vertices < 0 || h.faces < 0) lines.fail("negative counts");
  check_count(path, "the header declares", static_cast<unsigned long long>(h.vertices), "vertices", text.size(),
              2 * std::size_t(h.dim));
  check_count(path, "the header declares", static_cast<unsigned long long>(h.faces), "faces", text.size(), 8);
}

// The colour of vertex `v`, between its normal and its texture coordinates; returns its count of numbers.
std::size_t check_vertex_color(const Text_lines& lines, const std::vector<std::string_view>& t, const Off_header& h,
                               long long v, std::size_t color_begin, std::size_t color_end)
{
  if(color_end < color_begin)
    lines.fail("vertex " + std::to_string(v) + " has too few numbers for its header's keyword");
  // CGAL 5.5 reads three colour numbers of a COFF vertex that has none (beyond its line)
  if(color_end == color_begin)
    lines.fail("vertex " + std::to_string(v) + " has no colour, though the header's " + h.keyword +
               " says every vertex has one");
  const std::vector<std::string_view> color(t.begin() + std::ptrdiff_t(color_begin),
                                            t.begin() + std::ptrdiff_t(color_end));
  check_off_color(lines, color, 0, "vertex " + std::to_string(v));
  return color_end - color_begin;
}

void read_off_vertices(Text_lines& lines, std::vector<std::string_view>& t, const std::string& path,
                       const Off_header& h, Polygon_soup& soup)
{
  const long long nv = h.vertices;
  soup.points.resize(std::size_t(nv));
  const std::size_t fixed = std::size_t(h.dim) * (h.normals ? 2 : 1) + h.texcoord_numbers();
  bool alpha = false;
  for(long long v = 0; v < nv; ++v)
  {
    if(!lines.next(t))
      lines.fail("the file ends after " + std::to_string(v) + " of the " + std::to_string(nv) +
                 " vertices it declares");
    if(t.size() < fixed)
      lines.fail("vertex " + std::to_string(v) + " has " + std::to_string(t.size()) + " numbers, fewer than the " +
                 std::to_string(fixed) + " its header's keyword needs");
    double c[4] = {0, 0, 0, 1};
    const std::size_t color_end = t.size() - h.texcoord_numbers();
    const std::size_t color_begin = std::size_t(h.dim) + (h.normals ? std::size_t(h.dim) : 0);
    for(std::size_t k = 0; k < t.size(); ++k)
      if(!h.colors || k < color_begin || k >= color_end)
      {
        const double x = lines.real(t[k], "the number");
        if(k < std::size_t(h.dim)) c[k] = x;
      }
    const std::size_t color_numbers = h.colors ? check_vertex_color(lines, t, h, v, color_begin, color_end) : 0;
    for(int k = 0; k < 3; ++k)
    {
      const double x = h.homogeneous ? c[k] / c[3] : c[k];
      if(!std::isfinite(x)) lines.fail("vertex " + std::to_string(v) + " has a coordinate that is not a finite number");
      soup.points[std::size_t(v)][std::size_t(k)] = x;
    }
    alpha = alpha || (h.colors && color_numbers == 4);
  }
  if(alpha)
    soup.warnings.push_back("the alpha of the vertex colours of " + path +
                            " is not kept (CGAL's OFF reader reads red, green and blue)");
}

void read_off_faces(Text_lines& lines, std::vector<std::string_view>& t, const std::string& path, const Off_header& h,
                    Polygon_soup& soup)
{
  std::vector<long long> index;
  long long first_colored_face = -1;
  for(long long f = 0; f < h.faces; ++f)
  {
    if(!lines.next(t))
      lines.fail("the file ends after " + std::to_string(f) + " of the " + std::to_string(h.faces) +
                 " faces it declares");
    const long long k = lines.integer(t[0], "the face's vertex count");
    if(k < 0 || static_cast<unsigned long long>(k) + 1 > t.size())
      lines.fail("face " + std::to_string(f) + " declares " + std::to_string(k) + " vertices but the line holds " +
                 std::to_string(t.size() - 1) + " numbers after it");
    index.resize(std::size_t(k));
    for(long long i = 0; i < k; ++i) index[std::size_t(i)] = lines.integer(t[std::size_t(i) + 1], "the vertex index");
    if(h.colors)
    {
      check_off_color(lines, t, std::size_t(k) + 1, "face " + std::to_string(f));
      // once a face has a colour, CGAL 5.5 reads one for every later face, beyond the line if it has none
      if(t.size() > std::size_t(k) + 1 && first_colored_face < 0) first_colored_face = f;
      if(t.size() == std::size_t(k) + 1 && first_colored_face >= 0)
        lines.fail("face " + std::to_string(f) + " has no colour, though face " + std::to_string(first_colored_face) +
                   " has one");
    }
    else
      for(std::size_t i = std::size_t(k) + 1; i < t.size(); ++i) lines.real(t[i], "the number");
    add_face(soup, index, std::size_t(h.vertices), "line " + std::to_string(lines.line()), path);
  }
}

} // namespace

Polygon_soup read_checked_off(const std::string& path, const std::string& text)
{
  Text_lines lines(text, path);
  std::vector<std::string_view> t;
  if(!lines.next(t)) throw File_problem(path + ": the file is empty");
  check_header_line_has_no_comment(lines, text);
  Off_header h;
  read_off_keyword(lines, t, h);
  if(h.binary)
  {
    // CGAL 5.5 casts binary colours to bytes unchecked and its count of their floats is not Geomview's
    if(h.any_dim || h.colors) lines.fail("binary " + h.keyword + " is not supported (only binary OFF without colours)");
    const std::size_t start = text.find('\n') + 1;
    return read_binary_off(path, text, start, h.dim, h.normals, h.colors, h.texcoords);
  }
  read_off_counts(lines, t, path, text, h);
  Polygon_soup soup;
  read_off_vertices(lines, t, path, h, soup);
  read_off_faces(lines, t, path, h, soup);
  if(lines.next(t))
    lines.fail("more lines after the " + std::to_string(h.faces) +
               " faces the header declares (is its face count wrong?)");
  return soup;
}

Polygon_soup read_checked_obj(const std::string& path, const std::string& text)
{
  Polygon_soup soup;
  std::vector<std::vector<long long> > faces;   // 0-based, as CGAL's reader will compute them
  std::vector<std::size_t> face_line;
  std::vector<std::string_view> t;
  std::istringstream in(text);
  std::string raw;
  std::size_t line = 0;
  const auto fail = [&](const std::string& what) {
    throw File_problem(path + " line " + std::to_string(line) + ": " + what);
  };
  while(std::getline(in, raw))
  {
    ++line;
    std::istringstream words(raw);
    std::string key;
    if(!(words >> key)) continue;
    if(key == "v")
    {
      const std::string_view content = std::string_view(raw).substr(0, raw.find('#'));
      t.clear();
      Text_lines::split(content, t);
      if(t.size() < 4) fail("a vertex with " + std::to_string(t.size() - 1) + " coordinates");
      Text_lines numbers(content, path);
      std::array<double, 3> p;
      for(std::size_t k = 0; k < 3; ++k)
        try { p[k] = numbers.real(t[k + 1], "the coordinate"); }
        catch(const File_problem&) { fail("the coordinate " + quoted_excerpt(t[k + 1]) + " is not a finite number"); }
      soup.points.push_back(p);
    }
    else if(key == "f")
    {
      // the indices exactly as CGAL 5.5's reader takes them: an integer, then everything up to the next
      // space skipped ("1/2/3", but also "1#comment"); below 1: relative to the vertices read so far
      std::vector<long long> index;
      int i;
      while(words >> i)
      {
        if(i == 0) fail("vertex index 0 (OBJ counts from 1; a relative index is negative)");
        const long long v = i < 0 ? static_cast<long long>(soup.points.size()) + i : i - 1LL;
        if(v < 0) fail("the relative index " + std::to_string(i) + " reaches before the first vertex");
        index.push_back(v);
        words.ignore(256, ' ');
      }
      faces.push_back(index);
      face_line.push_back(line);
    }
  }
  for(std::size_t f = 0; f < faces.size(); ++f)
    add_face(soup, faces[f], soup.points.size(), "line " + std::to_string(face_line[f]), path);
  return soup;
}

Polygon_soup read_checked_stl(const std::string& path, const std::string& text)
{
  std::vector<std::array<double, 3> > corners;
  std::vector<std::string> places;
  std::uint32_t count = 0;
  if(text.size() >= 84) std::memcpy(&count, text.data() + 80, 4);   // little-endian on the machines we build for
  if(text.size() >= 84 && text.size() == 84 + 50 * std::size_t(count))
  {
    corners.reserve(3 * std::size_t(count));
    for(std::uint32_t f = 0; f < count; ++f)
    {
      const char* base = text.data() + 84 + 50 * std::size_t(f) + 12;   // after the facet's normal
      for(int c = 0; c < 3; ++c)
      {
        float x[3];
        std::memcpy(x, base + 12 * c, 12);
        if(!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
          throw File_problem(path + ": triangle " + std::to_string(f) +
                             " has a coordinate that is not a finite number");
        corners.push_back({double(x[0]), double(x[1]), double(x[2])});
      }
      places.push_back("triangle " + std::to_string(f));
    }
  }
  else
  {
    Text_lines lines(text, path, false);
    std::vector<std::string_view> t;
    if(!lines.next(t) || t[0] != "solid")
      throw File_problem(path +
                         ": neither an ASCII STL file (starting with 'solid') nor a binary one (84 + 50 n bytes)");
    std::size_t in_facet = 0;
    while(lines.next(t))
    {
      if(t[0] == "vertex")
      {
        if(t.size() != 4) lines.fail("a vertex line needs 3 coordinates");
        if(++in_facet > 3) lines.fail("a facet with more than 3 vertices");
        corners.push_back({ lines.real(t[1], "the coordinate"), lines.real(t[2], "the coordinate"),
                            lines.real(t[3], "the coordinate") });
      }
      else if(t[0] == "endfacet")
      {
        if(in_facet != 3) lines.fail("a facet with " + std::to_string(in_facet) + " vertices");
        places.push_back("line " + std::to_string(lines.line()));
        in_facet = 0;
      }
      else if(t[0] != "facet" && t[0] != "outer" && t[0] != "endloop" && t[0] != "endsolid" && t[0] != "solid")
        lines.fail(quoted_excerpt(t[0]) + " is not an STL keyword");
    }
    if(in_facet != 0) throw File_problem(path + ": the file ends inside a facet");
  }
  // STL repeats each corner in every triangle: merge corners with equal coordinates into one vertex
  Polygon_soup soup;
  std::map<std::array<double, 3>, std::size_t> vertex_of;
  std::vector<long long> index(3);
  for(std::size_t f = 0; f < places.size(); ++f)
  {
    for(std::size_t c = 0; c < 3; ++c)
    {
      const auto inserted = vertex_of.emplace(corners[3 * f + c], soup.points.size());
      if(inserted.second) soup.points.push_back(corners[3 * f + c]);
      index[c] = static_cast<long long>(inserted.first->second);
    }
    add_face(soup, index, soup.points.size(), places[f], path);
  }
  soup.merged_points = corners.size() - soup.points.size();
  return soup;
}

Polygon_soup read_checked_soup(const std::string& path, Mesh_format format)
{
  const std::string text = file_contents(path);
  Polygon_soup soup;
  switch(format)
  {
    case Mesh_format::OFF: soup = read_checked_off(path, text); break;
    case Mesh_format::OBJ: soup = read_checked_obj(path, text); break;
    case Mesh_format::PLY: soup = read_checked_ply(path, text); break;
    case Mesh_format::STL: soup = read_checked_stl(path, text); break;
  }
  soup.path = path;
  if(soup.faces.empty())
    throw File_problem(path + ": " + std::to_string(soup.points.size()) + " vertices and no face: not a surface");
  return soup;
}

} // namespace af_tool
