// anisotropic_fairing tool: checked reading of PLY files (ASCII and binary), faces and triangle strips
// (mesh_file_check.h says why).

#include "mesh_file_check.h"
#include "text_tokens.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace af_tool {

namespace {

enum class Ply_encoding { ASCII, LITTLE, BIG };

struct Ply_property
{
  std::string name;
  int size = 0;             // bytes of the value (of each item for a list)
  bool is_float = false, is_signed = false;
  int count_size = 0;       // a list: bytes of its count; 0: a scalar
  bool count_signed = false;
};

struct Ply_element
{
  std::string name;
  unsigned long long count = 0;
  std::vector<Ply_property> properties;
};

bool scalar_type(std::string_view t, int& size, bool& is_float, bool& is_signed)
{
  struct Type { const char* a; const char* b; int size; bool is_float, is_signed; };
  static const Type types[] = { {"char", "int8", 1, false, true}, {"uchar", "uint8", 1, false, false},
                                {"short", "int16", 2, false, true}, {"ushort", "uint16", 2, false, false},
                                {"int", "int32", 4, false, true}, {"uint", "uint32", 4, false, false},
                                {"float", "float32", 4, true, true}, {"double", "float64", 8, true, true} };
  for(const Type& x : types)
    if(t == x.a || t == x.b) { size = x.size; is_float = x.is_float; is_signed = x.is_signed; return true; }
  return false;
}

// The values of the body, in order, from text or bytes, each read within the file's bounds.
class Ply_values
{
public:
  Ply_values(const std::string& path, const std::string& text, std::size_t start, Ply_encoding encoding)
    : path_(path), text_(text), at_(start), encoding_(encoding),
      lines_(std::string_view(text).substr(start), path, false)
  {}

  // `finite`: a float must be finite (the coordinates); the other properties are carried through as
  // they are, NaN included, and checked only where they are faired (attribute_columns.cpp)
  double value(int size, bool is_float, bool is_signed, const std::string& where, bool finite = true)
  {
    if(encoding_ == Ply_encoding::ASCII)
    {
      if(used_ >= tokens_.size())
      {
        if(!lines_.next(tokens_)) fail("the file ends inside " + where);
        used_ = 0;
      }
      const std::string_view t = tokens_[used_++];
      last_token_ = t;
      if(is_float) return lines_.real(t, where.c_str(), finite);
      const long long v = lines_.integer(t, where.c_str());
      const long long low = is_signed ? -(1LL << (8 * size - 1)) : 0,
                      high = is_signed ? (1LL << (8 * size - 1)) - 1 : (1LL << (8 * size)) - 1;
      if(v < low || v > high)
        fail(where + ": " + quoted_excerpt(t) + " is outside the range of its " + std::to_string(8 * size) + "-bit " +
             (is_signed ? "signed" : "unsigned") + " type");
      return double(v);
    }
    if(std::size_t(size) > text_.size() - at_) fail("the file ends inside " + where);
    unsigned char b[8];
    std::memcpy(b, text_.data() + at_, std::size_t(size));
    at_ += std::size_t(size);
    if(encoding_ == Ply_encoding::BIG) std::reverse(b, b + size);   // the machines we build for are little-endian
    if(is_float)
    {
      double v;
      if(size == 4) { float f; std::memcpy(&f, b, 4); v = f; }
      else std::memcpy(&v, b, 8);
      if(finite && !std::isfinite(v)) fail(where + " has a coordinate that is not a finite number");
      return v;
    }
    unsigned long long u = 0;
    for(int k = size - 1; k >= 0; --k) u = (u << 8) | b[k];
    if(is_signed && size < 8 && (u >> (8 * size - 1)) != 0)
      return double(static_cast<long long>(u) - (1LL << (8 * size)));
    return double(u);
  }

  // bytes (binary) or tokens (ASCII, 2 bytes each at least) left
  std::size_t left() const
  {
    return encoding_ == Ply_encoding::ASCII ? (text_.size() - at_) / 2 + 1 : text_.size() - at_;
  }

  // ASCII: whether tokens are left; binary: how many bytes
  std::size_t rest()
  {
    if(encoding_ != Ply_encoding::ASCII) return text_.size() - at_;
    return used_ < tokens_.size() || lines_.next(tokens_) ? 1 : 0;
  }

  [[noreturn]] void fail(const std::string& what) const { throw File_problem(path_ + ": " + what); }

  // ASCII: where the last value read stands in the file
  std::size_t last_offset() const { return std::size_t(last_token_.data() - text_.data()); }
  std::size_t last_length() const { return last_token_.size(); }

private:
  const std::string& path_;
  const std::string& text_;
  std::size_t at_;
  Ply_encoding encoding_;
  Text_lines lines_;
  std::vector<std::string_view> tokens_;
  std::string_view last_token_;
  std::size_t used_ = 0;
};

// The properties CGAL 5.5's Surface_mesh reader interprets, it reads with fixed types, unchecked (a
// uint8 x is a null pointer there): x, y, z both float or both double, and nx, ny, nz as they; red,
// green, blue as uchar; face indices as int or uint. It also takes edge and halfedge elements as vertex
// indices, unchecked: those are refused.
void check_types_cgal_reads(const std::string& path, const std::vector<Ply_element>& elements)
{
  const auto fail = [&](const std::string& what) { throw File_problem(path + ": " + what); };
  for(const Ply_element& e : elements)
  {
    if(e.name == "edge" || e.name == "halfedge")
      fail("element '" + e.name + "' is not supported (only vertex, face and tristrips)");
    const auto find = [&](const char* name) -> const Ply_property* {
      for(const Ply_property& p : e.properties)
        if(p.name == name) return &p;
      return nullptr;
    };
    const auto same_type = [&](const char* const* names, const Ply_property* like, const char* rule) {
      for(int k = 0; k < 3; ++k)
      {
        const Ply_property* p = find(names[k]);
        if(!p) return;
        if(p->count_size || p->size != like->size || p->is_float != like->is_float)
          fail("property '" + std::string(names[k]) + "' of element '" + e.name + "' has another type than " + rule);
      }
    };
    static const char* const coordinates[3] = {"x", "y", "z"};
    static const char* const normal[3] = {"nx", "ny", "nz"};
    static const char* const color[3] = {"red", "green", "blue"};
    static const Ply_property uchar_type = [] { Ply_property p; p.size = 1; return p; }();
    if(e.name == "vertex")
    {
      const Ply_property* x = find("x");
      if(x && (!x->is_float || x->count_size)) fail("the vertex coordinate x is not float or double");
      if(x) same_type(coordinates, x, "x (float or double for all three)");
      if(x && find("nx") && find("ny") && find("nz")) same_type(normal, x, "the coordinates");
    }
    if((e.name == "vertex" || e.name == "face") && find("red") && find("green") && find("blue"))
      same_type(color, &uchar_type, "uchar (colours are bytes)");
    if(e.name == "face")
      for(const char* name : {"vertex_indices", "vertex_index"})
        if(const Ply_property* p = find(name))
          if(!p->count_size || p->is_float || p->size != 4)
            fail("the face property '" + std::string(name) + "' is not a list of int or uint");
  }
}

// Whether the file holds positions and faces and nothing else CGAL's reader would keep, with positions that
// read here to the values CGAL reads (binary, or text of doubles: CGAL reads a float in text as a float)
bool positions_and_faces_only(const std::vector<Ply_element>& elements, Ply_encoding encoding)
{
  if(elements.size() != 2 || elements[0].name != "vertex" || elements[1].name != "face") return false;
  const std::vector<Ply_property>& v = elements[0].properties;
  const std::vector<Ply_property>& f = elements[1].properties;
  if(v.size() != 3 || f.size() != 1 || !f[0].count_size ||
     (f[0].name != "vertex_indices" && f[0].name != "vertex_index"))
    return false;
  for(int c = 0; c < 3; ++c)
    if(v[std::size_t(c)].count_size || v[std::size_t(c)].name != std::string(1, char('x' + c)) ||
       !v[std::size_t(c)].is_float || (encoding == Ply_encoding::ASCII && v[std::size_t(c)].size != 8))
      return false;
  return true;
}

// What the header declares: the encoding of the body, where it starts, and its elements in order.
struct Ply_header
{
  Ply_encoding encoding = Ply_encoding::ASCII;
  std::vector<Ply_element> elements;
  std::size_t body = 0;   // the offset of the body in the file
};

// "format <encoding> 1.0", once: CGAL 5.5 and this check must agree on the encoding
void read_format_line(const Text_lines& header, const std::vector<std::string_view>& t, bool& format_seen,
                      Ply_encoding& encoding)
{
  if(format_seen) header.fail("a second 'format' line");
  if(t.size() != 3 || t[2] != "1.0") header.fail("the format line is not 'format <encoding> 1.0'");
  if(t[1] == "ascii") encoding = Ply_encoding::ASCII;
  else if(t[1] == "binary_little_endian") encoding = Ply_encoding::LITTLE;
  else if(t[1] == "binary_big_endian") encoding = Ply_encoding::BIG;
  else header.fail("unknown encoding " + quoted_excerpt(t[1]));
  format_seen = true;
}

void read_element_line(const Text_lines& header, const std::vector<std::string_view>& t,
                       std::vector<Ply_element>& elements)
{
  if(t.size() != 3) header.fail("'element' needs a name and a count");
  const long long n = header.integer(t[2], "the element count");
  if(n < 0) header.fail("a negative element count");
  for(const Ply_element& e : elements)   // CGAL 5.5 mixes the properties of two elements of one name
    if(e.name == t[1]) header.fail("element '" + e.name + "' is declared twice");
  elements.push_back({std::string(t[1]), static_cast<unsigned long long>(n), {}});
}

void read_property_line(const Text_lines& header, const std::vector<std::string_view>& t,
                        std::vector<Ply_element>& elements)
{
  if(elements.empty()) header.fail("a property before any element");
  Ply_property p;
  if(t.size() == 5 && t[1] == "list")
  {
    bool count_float = false;
    if(!scalar_type(t[2], p.count_size, count_float, p.count_signed) || count_float)
      header.fail("the count type " + quoted_excerpt(t[2]) + " of a list is not an integer type");
    if(!scalar_type(t[3], p.size, p.is_float, p.is_signed)) header.fail("unknown type " + quoted_excerpt(t[3]));
    p.name = std::string(t[4]);
  }
  else if(t.size() == 3)
  {
    if(!scalar_type(t[1], p.size, p.is_float, p.is_signed)) header.fail("unknown type " + quoted_excerpt(t[1]));
    p.name = std::string(t[2]);
  }
  else header.fail("a property needs a type and a name");
  elements.back().properties.push_back(p);
}

// the header: "ply", "format ...", elements and their properties, "end_header"
Ply_header read_ply_header(const std::string& path, const std::string& text)
{
  Text_lines header(text, path, false);
  std::vector<std::string_view> t;
  if(!header.next(t) || t[0] != "ply") throw File_problem(path + ": not a PLY file (it does not start with 'ply')");
  Ply_header h;
  bool format_seen = false;
  for(;;)
  {
    if(!header.next(t)) throw File_problem(path + ": the header has no 'end_header'");
    if(t[0] == "end_header") break;
    if(t[0] == "comment" || t[0] == "obj_info") continue;
    if(t[0] == "format") read_format_line(header, t, format_seen, h.encoding);
    else if(t[0] == "element") read_element_line(header, t, h.elements);
    else if(t[0] == "property") read_property_line(header, t, h.elements);
    else header.fail(quoted_excerpt(t[0]) + " is not a PLY header keyword");
  }
  if(!format_seen) throw File_problem(path + ": the header has no 'format' line");
  h.body = header.offset();
  return h;
}

// Where an element keeps what the soup takes: the properties x, y, z of a vertex and the index list of a
// face or a strip (-1: none).
struct Element_layout
{
  bool is_vertex = false, is_face = false, is_strip = false;
  int coordinate[3] = {-1, -1, -1};
  int list = -1;

  bool is_coordinate(std::size_t k) const
  {
    return int(k) == coordinate[0] || int(k) == coordinate[1] || int(k) == coordinate[2];
  }
};

// The layout of `e`, whose count is checked first against what is left of the file.
Element_layout element_layout(const std::string& path, const Ply_element& e, Ply_encoding encoding,
                              const Ply_values& values)
{
  std::size_t least = 0;   // the fewest bytes (or tokens) one element can take
  for(const Ply_property& p : e.properties)
    least += std::size_t(encoding == Ply_encoding::ASCII ? 1 : (p.count_size ? p.count_size : p.size));
  if(least == 0 && e.count > 0)
    throw File_problem(path + ": element '" + e.name + "' has " + std::to_string(e.count) + " items and no property");
  check_count(path, "element '" + e.name + "' declares", e.count, "items", values.left(), least);
  Element_layout l;
  l.is_vertex = e.name == "vertex";
  l.is_face = e.name == "face";
  l.is_strip = e.name == "tristrips";
  for(std::size_t k = 0; k < e.properties.size(); ++k)
  {
    const Ply_property& p = e.properties[k];
    if(l.is_vertex && !p.count_size && p.name.size() == 1 && p.name[0] >= 'x' && p.name[0] <= 'z')
      l.coordinate[p.name[0] - 'x'] = int(k);
    if((l.is_face || l.is_strip) && p.count_size && (p.name == "vertex_indices" || p.name == "vertex_index"))
      l.list = int(k);
  }
  if(l.is_vertex && (l.coordinate[0] < 0 || l.coordinate[1] < 0 || l.coordinate[2] < 0))
    throw File_problem(path + ": the vertex element has no x, y and z");
  return l;
}

// A list property of item `where`; its values go to `index` if it is the element's index list.
void read_list(const std::string& path, const Ply_property& p, Ply_encoding encoding, const std::string& where,
               bool is_index_list, Ply_values& values, std::vector<long long>& index)
{
  const double n = values.value(p.count_size, false, p.count_signed, where);
  if(n < 0) values.fail(where + ": a list of " + std::to_string(static_cast<long long>(n)) + " items");
  const std::size_t each = std::size_t(encoding == Ply_encoding::ASCII ? 1 : p.size);
  if(static_cast<unsigned long long>(n) > values.left() / each)   // (the message made only then)
    check_count(path, where + ": property '" + p.name + "' lists", static_cast<unsigned long long>(n), "values",
                values.left(), each);
  if(is_index_list) index.clear();
  for(std::size_t j = 0; j < std::size_t(n); ++j)
  {
    const double v = values.value(p.size, p.is_float, p.is_signed, where);
    if(is_index_list) index.push_back(static_cast<long long>(v));
  }
}

// A strip a b c d ... is the triangles (a b c), (c b d), ...; -1 starts a new strip; a triangle that
// repeats a vertex only turns the strip around.
void add_strip_triangles(const std::string& path, std::vector<long long>& index, std::size_t vertices,
                         std::size_t& strip_number, Polygon_soup& soup)
{
  std::vector<long long> strip;
  index.push_back(-1);
  for(long long v : index)
  {
    if(v != -1) { strip.push_back(v); continue; }
    for(std::size_t j = 2; j < strip.size(); ++j)
    {
      std::vector<long long> tri = (j % 2 == 0) ? std::vector<long long>{strip[j - 2], strip[j - 1], strip[j]}
                                                : std::vector<long long>{strip[j - 1], strip[j - 2], strip[j]};
      if(tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
      add_face(soup, tri, vertices, "triangle " + std::to_string(j - 2) + " of strip " + std::to_string(strip_number),
               path);
    }
    strip.clear();
    ++strip_number;
  }
  soup.ply_strips = true;
}

// The items of element `e` into the soup: positions, faces, strips; the other values read and checked.
void read_element(const std::string& path, const Ply_element& e, Ply_encoding encoding, std::size_t vertices,
                  Ply_values& values, std::size_t& strip_number, Polygon_soup& soup)
{
  const Element_layout l = element_layout(path, e, encoding, values);
  if(l.is_vertex) soup.points.resize(std::size_t(e.count));
  if(l.is_face) { soup.faces.reserve(std::size_t(e.count)); soup.face_place.reserve(std::size_t(e.count)); }
  std::vector<long long> index;
  for(unsigned long long i = 0; i < e.count; ++i)
  {
    const std::string where = e.name + " " + std::to_string(i);
    for(std::size_t k = 0; k < e.properties.size(); ++k)
    {
      const Ply_property& p = e.properties[k];
      if(p.count_size)
      {
        read_list(path, p, encoding, where, int(k) == l.list, values, index);
        continue;
      }
      const double v = values.value(p.size, p.is_float, p.is_signed, where, l.is_coordinate(k));
      if(!std::isfinite(v) && encoding == Ply_encoding::ASCII && (l.is_vertex || l.is_face))
        soup.nonfinite.push_back({values.last_offset(), values.last_length(), l.is_vertex, std::size_t(i), p.name, v});
      for(int c = 0; c < 3; ++c)
        if(int(k) == l.coordinate[c]) soup.points[std::size_t(i)][std::size_t(c)] = v;
    }
    if(l.is_face && l.list >= 0) add_face(soup, index, vertices, where, path);
    if(l.is_strip && l.list >= 0) add_strip_triangles(path, index, vertices, strip_number, soup);
  }
}

} // namespace

Polygon_soup read_checked_ply(const std::string& path, const std::string& text)
{
  const Ply_header h = read_ply_header(path, text);
  check_types_cgal_reads(path, h.elements);

  Polygon_soup soup;
  soup.positions_and_faces_only = positions_and_faces_only(h.elements, h.encoding);
  std::size_t vertices = 0;
  for(const Ply_element& e : h.elements)
    if(e.name == "vertex") vertices = std::size_t(e.count);
  Ply_values values(path, text, h.body, h.encoding);
  std::size_t strip_number = 0;
  for(const Ply_element& e : h.elements) read_element(path, e, h.encoding, vertices, values, strip_number, soup);
  if(const std::size_t rest = values.rest())
  {
    if(h.encoding == Ply_encoding::ASCII)
      throw File_problem(path + ": data after the last element the header declares (is a count wrong?)");
    soup.warnings.push_back(std::to_string(rest) + " bytes after the last element of " + path + " are ignored");
  }
  return soup;
}

} // namespace af_tool
