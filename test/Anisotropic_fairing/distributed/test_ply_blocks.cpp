// A binary PLY file read and written by blocks (distributed/Ply_blocks.h, Ply_block_output.h), without MPI: the processes are
// simulated, process p of P (P = 1, 2, 3, 5) calling the reader and the writer as it would. Files written here, by
// this test's own PLY writer, from the mesh bumpy.off (little and big endian; float and double positions; other
// vertex properties of several types; a face property; elements before the vertices, between the vertices and the
// faces, after the faces):
// - the union of the blocks is the whole mesh: positions and the other properties bit for bit, the faces;
// - refused (by_blocks() false, the same on every process): polygons, ascii, a list in another element, no face
//   element; errors naming the file and the record: a truncated file, a face of 4 corners, a corner out of range,
//   a missing x, a bad header line;
// - written back in parts (vertex v by process v % P, moved, with changed properties; each process copying its
//   block of faces), the file is byte for byte the one this test's writer makes of the same values, and reads back;
//   so too with vertex properties added (--curvature's k1, k2, mean_curvature), the elements after them moved.
// Arguments: the test data directory; the directory to write in (default: the current one).

#include "Ply_block_output.h"
#include "Ply_blocks.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double>::Point_3 Point;
namespace af = af_distributed;

namespace {

int passed = 0, failed = 0;

void check(bool ok, const std::string& what)
{
  std::printf("%s: %s\n", ok ? "passed" : "FAILED", what.c_str());
  ok ? ++passed : ++failed;
}

// This test's own PLY files: each property's values per record (a list's: its items).
struct Prop { std::string name, type, count_type; };   // count_type empty: a scalar
struct Element
{
  std::string name;
  std::vector<Prop> props;
  std::vector<std::vector<std::vector<double>>> records;
};
struct Ply_file
{
  std::string format = "binary_little_endian";
  std::vector<Element> elements;
};

bool host_big_endian()
{
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 0;
}

template <typename T>
void put_as(std::string& out, double v, bool big)
{
  const T x = T(v);
  char b[sizeof(T)];
  std::memcpy(b, &x, sizeof(T));
  if(big != host_big_endian()) std::reverse(b, b + sizeof(T));
  out.append(b, sizeof(T));
}

// `v` as the type named (its bytes onto `out` when given): the value the file holds.
double as_type(const std::string& t, double v, std::string* out = nullptr, bool big = false)
{
  std::string ignored;
  std::string& o = out ? *out : ignored;
  if(t == "char" || t == "int8") return put_as<std::int8_t>(o, v, big), double(std::int8_t(v));
  if(t == "uchar" || t == "uint8") return put_as<std::uint8_t>(o, v, big), double(std::uint8_t(v));
  if(t == "short" || t == "int16") return put_as<std::int16_t>(o, v, big), double(std::int16_t(v));
  if(t == "ushort" || t == "uint16") return put_as<std::uint16_t>(o, v, big), double(std::uint16_t(v));
  if(t == "int" || t == "int32") return put_as<std::int32_t>(o, v, big), double(std::int32_t(v));
  if(t == "uint" || t == "uint32") return put_as<std::uint32_t>(o, v, big), double(std::uint32_t(v));
  if(t == "float" || t == "float32") return put_as<float>(o, v, big), double(float(v));
  return put_as<double>(o, v, big), v;
}

std::string bytes_of(const Ply_file& f)
{
  std::string out = "ply\nformat " + f.format + " 1.0\ncomment made by test_ply_blocks\n";
  for(const Element& e : f.elements)
  {
    out += "element " + e.name + " " + std::to_string(e.records.size()) + "\n";
    for(const Prop& p : e.props)
      out += p.count_type.empty() ? "property " + p.type + " " + p.name + "\n"
                                  : "property list " + p.count_type + " " + p.type + " " + p.name + "\n";
  }
  out += "end_header\n";
  const bool ascii = f.format == "ascii", big = f.format == "binary_big_endian";
  for(const Element& e : f.elements)
    for(const auto& r : e.records)
    {
      for(std::size_t k = 0; k < e.props.size(); ++k)
      {
        std::vector<double> items = r[k];
        if(!e.props[k].count_type.empty()) items.insert(items.begin(), double(r[k].size()));
        for(std::size_t i = 0; i < items.size(); ++i)
          if(ascii) out += std::to_string(items[i]) + " ";
          else as_type(i == 0 && !e.props[k].count_type.empty() ? e.props[k].count_type : e.props[k].type, items[i],
                       &out, big);
      }
      if(ascii) out += "\n";
    }
  return out;
}

void write_file(const std::string& path, const std::string& bytes)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

std::string read_file(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The value of property `name` of record `r` (moved or changed when `moved`), before it takes its type.
double value_of(const std::string& name, std::size_t r, const std::vector<Point>& points, bool moved)
{
  const double shift = moved ? 1e-3 * double(r % 7) + 1.0 / 3.0 : 0;
  if(name == "x" || name == "y" || name == "z") return points[r][name[0] - 'x'] + (name == "y" ? -shift : shift);
  if(name == "quality") return 0.1 * double(r) + 1.0 / 7.0 + (moved ? 0.5 : 0);
  if(name == "red") return double((r * 7 + (moved ? 1 : 0)) % 256);
  if(name == "alpha") return double((r * 37) % 65536);
  if(name == "label") return double(int(r % 200) - 100);
  return double(r) * 0.25 + 1;   // anything else: a face's flags, a camera's fields, a marker's
}

Element vertices(const std::vector<Prop>& props, const std::vector<Point>& points, bool moved = false)
{
  Element e{ "vertex", props, {} };
  for(std::size_t v = 0; v < points.size(); ++v)
  {
    std::vector<std::vector<double>> r;
    for(const Prop& p : props) r.push_back({ as_type(p.type, value_of(p.name, v, points, moved)) });
    e.records.push_back(r);
  }
  return e;
}

// The faces, with `props` (the list among them, named vertex_indices or vertex_index).
Element faces(const std::vector<Prop>& props, const std::vector<std::vector<std::size_t>>& polygons)
{
  Element e{ "face", props, {} };
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    std::vector<std::vector<double>> r;
    for(const Prop& p : props)
      r.push_back(p.count_type.empty() ? std::vector<double>{ as_type(p.type, value_of(p.name, f, {}, false)) }
                                       : std::vector<double>(polygons[f].begin(), polygons[f].end()));
    e.records.push_back(r);
  }
  return e;
}

Element fixed(const std::string& name, const std::vector<Prop>& props, std::size_t count)
{
  Element e{ name, props, {} };
  for(std::size_t r = 0; r < count; ++r)
  {
    std::vector<std::vector<double>> rec;
    for(const Prop& p : props) rec.push_back({ as_type(p.type, value_of(p.name, r, {}, false)) });
    e.records.push_back(rec);
  }
  return e;
}

// The three files read by blocks (their vertex element made by `vertices`, moved or not).
std::vector<std::pair<std::string, Ply_file>> files(const std::vector<Point>& points,
                                                    const std::vector<std::vector<std::size_t>>& polygons, bool moved)
{
  Ply_file a, b, c;
  a.elements = { fixed("camera", { { "view_px", "float", "" }, { "view_py", "float", "" }, { "viewportx", "int", "" },
                                   { "flag", "uchar", "" } }, 1),
                 vertices({ { "x", "float", "" }, { "y", "float", "" }, { "z", "float", "" },
                            { "quality", "double", "" }, { "red", "uchar", "" } }, points, moved),
                 faces({ { "vertex_indices", "int", "uchar" } }, polygons) };
  b.format = "binary_big_endian";
  b.elements = { vertices({ { "red", "uchar", "" }, { "x", "double", "" }, { "quality", "float", "" },
                            { "y", "double", "" }, { "z", "double", "" }, { "alpha", "ushort", "" } }, points, moved),
                 faces({ { "flags", "ushort", "" }, { "vertex_index", "uint", "uint" }, { "weight", "float", "" } },
                       polygons),
                 fixed("material", { { "r", "uchar", "" }, { "shininess", "float", "" } }, 2) };
  c.elements = { vertices({ { "x", "float64", "" }, { "y", "float64", "" }, { "z", "float64", "" },
                            { "label", "int16", "" } }, points, moved),
                 fixed("marker", { { "id", "int32", "" }, { "w", "float64", "" } }, 3),
                 faces({ { "vertex_indices", "int32", "uint8" } }, polygons) };
  return { { "le_float", a }, { "be_double", b }, { "le_double", c } };
}

const Element& element(const Ply_file& f, const std::string& name)
{
  for(const Element& e : f.elements)
    if(e.name == name) return e;
  throw std::logic_error("no element " + name);
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

// The blocks of processes 0 .. P-1 of `path`, against `f`'s vertices and faces.
void check_blocks(const std::string& path, const Ply_file& f, int P, const std::string& what)
{
  const Element& v = element(f, "vertex");
  const Element& t = element(f, "face");
  const std::size_t n = v.records.size(), m = t.records.size();
  std::vector<std::string> names;
  for(const Prop& p : v.props)
    if(p.name != "x" && p.name != "y" && p.name != "z") names.push_back(p.name);
  bool sizes = true, positions = true, values = true, triangles = true, named = true;
  std::size_t next_vertex = 0, next_face = 0;
  for(int p = 0; p < P; ++p)
  {
    const af::Ply_blocks b = af::read_ply_blocks(path, p, P);
    sizes = sizes && b.by_blocks() && b.mesh.vertices == std::int64_t(n) && b.mesh.faces == std::int64_t(m) &&
            b.mesh.points.size() == 3 * std::size_t(af::block_first(n, p + 1, P) - af::block_first(n, p, P)) &&
            b.values.size() == names.size() * (b.mesh.points.size() / 3) &&
            b.mesh.triangles.size() == std::size_t(af::block_first(m, p + 1, P) - af::block_first(m, p, P));
    named = named && b.names == names;
    if(!sizes) break;
    for(std::size_t i = 0; i < b.mesh.points.size() / 3; ++i, ++next_vertex)
      for(std::size_t k = 0, column = 0; k < v.props.size(); ++k)
      {
        const double expected = v.records[next_vertex][k][0];
        const char name = v.props[k].name.size() == 1 ? v.props[k].name[0] : 0;
        if(name >= 'x' && name <= 'z')
          positions = positions && same_bits(b.mesh.points[3 * i + std::size_t(name - 'x')], expected);
        else values = values && same_bits(b.values[i * names.size() + column++], expected);
      }
    for(std::size_t i = 0; i < b.mesh.triangles.size(); ++i, ++next_face)
      for(std::size_t k = 0; k < t.props.size(); ++k)
        if(!t.props[k].count_type.empty())
          for(std::size_t c = 0; c < 3; ++c)
            triangles = triangles && double(b.mesh.triangles[i][c]) == t.records[next_face][k][c];
  }
  const std::string on = what + " on " + std::to_string(P) + " processes: ";
  check(sizes && next_vertex == n && next_face == m, on + "the blocks' counts");
  check(named, on + "the other vertex properties' names, in order");
  check(positions, on + "the positions, bit for bit");
  check(values, on + "the other vertex properties, bit for bit");
  check(triangles, on + "the faces");
}

// The message of what process p of P throws reading `path` (empty: nothing).
std::string error_of(const std::string& path, int p, int P)
{
  try { af::read_ply_blocks(path, p, P); }
  catch(const std::runtime_error& e) { return e.what(); }
  return std::string();
}

// Each process holding face `face` throws `message`; the others nothing.
void check_face_error(const std::string& path, std::size_t faces, std::size_t face, const std::string& message)
{
  bool ok = true;
  for(int P : { 1, 2, 3, 5 })
    for(int p = 0; p < P; ++p)
    {
      const bool holds = af::block_first(faces, p, P) <= std::int64_t(face) && std::int64_t(face) <
                         af::block_first(faces, p + 1, P);
      const std::string e = error_of(path, p, P);
      ok = ok && e == (holds ? message : std::string());
      if(!ok) { std::printf("  process %d of %d: \"%s\"\n", p, P, e.c_str()); return check(false, message); }
    }
  check(ok, "the process of the face says: " + message);
}

// Every process throws `message`.
void check_error(const std::string& path, const std::string& message)
{
  bool ok = true;
  for(int P : { 1, 3 })
    for(int p = 0; p < P; ++p) ok = ok && error_of(path, p, P) == message;
  if(!ok) std::printf("  got \"%s\"\n", error_of(path, 0, 1).c_str());
  check(ok, "every process says: " + message);
}

// Every process refuses, saying `words`, and reads nothing.
void check_refusal(const std::string& path, const std::string& words)
{
  bool ok = true;
  for(int P : { 1, 2, 3 })
    for(int p = 0; p < P; ++p)
    {
      const af::Ply_blocks b = af::read_ply_blocks(path, p, P);
      ok = ok && !b.by_blocks() && b.header.refusal.find(path + ": ") == 0 &&
           b.header.refusal.find(words) != std::string::npos && b.mesh.points.empty() && b.mesh.triangles.empty();
    }
  check(ok, "refused: " + path + ": ..." + words + "...");
}

void refusals_and_errors(const std::string& dir, const std::vector<Point>& points,
                         const std::vector<std::vector<std::size_t>>& polygons)
{
  const std::vector<Prop> xyz = { { "x", "float", "" }, { "y", "float", "" }, { "z", "float", "" } };
  const Prop corners{ "vertex_indices", "int", "uchar" };
  Ply_file f;
  std::vector<std::vector<std::size_t>> quads(polygons);
  quads[10].push_back(quads[11][0]);   // a quad among the triangles
  f.elements = { vertices(xyz, points), faces({ corners }, quads) };
  write_file(dir + "/quad.ply", bytes_of(f));
  check_refusal(dir + "/quad.ply", "the faces are not all triangles");
  f.format = "ascii";
  f.elements = { vertices(xyz, points), faces({ corners }, polygons) };
  write_file(dir + "/ascii.ply", bytes_of(f));
  check_refusal(dir + "/ascii.ply", "an ascii PLY file cannot be read by blocks");
  f.format = "binary_little_endian";
  f.elements.push_back(Element{ "range", { { "ids", "int", "uchar" } }, { { { 1, 2 } } } });
  write_file(dir + "/after_list.ply", bytes_of(f));
  check_refusal(dir + "/after_list.ply", "the range element has a list property (ids)");
  f.elements = { vertices(xyz, points), faces({ corners }, polygons) };
  f.elements[1].name = "tristrips";
  write_file(dir + "/strips.ply", bytes_of(f));
  check_refusal(dir + "/strips.ply", "no face element");

  f.elements = { vertices(xyz, points), faces({ corners }, polygons) };
  const std::string whole = bytes_of(f);
  const std::size_t header = whole.find("end_header\n") + 11, n = points.size(), m = polygons.size();
  const std::size_t cut = header + 12 * n + 13 * 2000 + 5;   // records of 12 and 13 bytes
  write_file(dir + "/cut_faces.ply", whole.substr(0, cut));
  check_error(dir + "/cut_faces.ply", dir + "/cut_faces.ply: truncated in face 2000 (the file has " +
              std::to_string(cut) + " bytes, " + std::to_string(whole.size()) + " expected)");
  write_file(dir + "/cut_vertices.ply", whole.substr(0, header + 12 * 600 + 7));
  check_error(dir + "/cut_vertices.ply", dir + "/cut_vertices.ply: truncated in vertex 600 (the file has " +
              std::to_string(header + 12 * 600 + 7) + " bytes, " + std::to_string(whole.size()) + " expected)");
  write_file(dir + "/cut_header.ply", whole.substr(0, header - 5));
  check_error(dir + "/cut_header.ply", dir + "/cut_header.ply: the PLY header has no end_header line");

  std::vector<std::vector<std::size_t>> odd(polygons);
  odd[1234][1] = n;   // a corner out of range
  f.elements = { vertices(xyz, points), faces({ corners }, odd) };
  write_file(dir + "/out_of_range.ply", bytes_of(f));
  check_face_error(dir + "/out_of_range.ply", m, 1234, dir + "/out_of_range.ply: face 1234's corner 1 is vertex " +
                   std::to_string(n) + ", not in [0, " + std::to_string(n) + ")");
  odd = polygons;
  odd[m - 2].push_back(odd[m - 1][0]);   // 4 corners, then 2: the size of two triangles
  odd[m - 1].pop_back();
  f.elements = { vertices(xyz, points), faces({ corners }, odd) };
  write_file(dir + "/four.ply", bytes_of(f));
  check_face_error(dir + "/four.ply", m, m - 2, dir + "/four.ply: face " + std::to_string(m - 2) +
                   " has 4 corners (a file read by blocks must have only triangles)");

  f.elements = { vertices({ { "y", "float", "" }, { "z", "float", "" } }, points), faces({ corners }, polygons) };
  write_file(dir + "/no_x.ply", bytes_of(f));
  check_error(dir + "/no_x.ply", dir + "/no_x.ply: the vertex element has no property x");
  std::string bad = whole;
  bad.replace(bad.find("property float x"), 16, "property flaot x");
  write_file(dir + "/bad_line.ply", bad);
  check_error(dir + "/bad_line.ply", dir + "/bad_line.ply: PLY header line 5 is not understood: \"property flaot x\"");
}

// The file `name` written back in parts by P processes with the moved values (`moved`: as its types hold them), and
// with `added` vertex properties after the vertex's others (doubles: 0.25 i, -i, i / 3 at vertex i).
void write_back(const std::string& dir, const std::string& name, const std::vector<Point>& original,
                const Ply_file& moved, int P, const std::vector<std::string>& added = {})
{
  const std::string input = dir + "/" + name + ".ply", output = dir + "/" + name + "_out.ply";
  const std::string on = name + " written back by " + std::to_string(P) + " processes" +
                         (added.empty() ? "" : " with properties added") + ": ";
  const af::Ply_header header = af::read_ply_header(input);
  const af::Ply_header written = af::with_vertex_properties(header, added, output);
  af::create_ply_output(input, output, header, written);   // process 0; then the barrier
  const Element& v = element(moved, "vertex");
  const auto added_value = [](std::size_t k, std::size_t i) { return k == 0 ? 0.25 * double(i) : k == 1 ? -double(i) : double(i) / 3; };
  for(int p = P - 1; p >= 0; --p)   // any order: each writes its own bytes
  {
    std::vector<std::int64_t> mine;
    std::vector<double> points, values;
    for(std::size_t i = std::size_t(p); i < v.records.size(); i += std::size_t(P))
    {
      mine.push_back(std::int64_t(i));
      double xyz[3] = { 0, 0, 0 };
      for(std::size_t k = 0; k < v.props.size(); ++k)
      {
        const double value = value_of(v.props[k].name, i, original, true);   // the writer gives it its type
        const char c = v.props[k].name.size() == 1 ? v.props[k].name[0] : 0;
        if(c >= 'x' && c <= 'z') xyz[c - 'x'] = value;
        else values.push_back(value);
      }
      for(std::size_t k = 0; k < added.size(); ++k) values.push_back(added_value(k, i));
      points.insert(points.end(), xyz, xyz + 3);
    }
    af::write_ply_blocks(input, output, header, written, p, P, mine, points, values);
  }
  Ply_file expected = moved;
  for(Element& e : expected.elements)
    if(e.name == "vertex")
      for(std::size_t k = 0; k < added.size(); ++k)
      {
        e.props.push_back({ added[k], "double", "" });
        for(std::size_t i = 0; i < e.records.size(); ++i) e.records[i].push_back({ added_value(k, i) });
      }
  const std::string in = read_file(input), out = read_file(output);
  const af::Ply_element& faces = header.elements[std::size_t(header.face)];
  const std::size_t at = std::size_t(faces.offset), bytes = std::size_t(faces.count * faces.record);
  const std::size_t to = std::size_t(written.elements[std::size_t(header.face)].offset);
  check(out.size() >= to + bytes && out.compare(to, bytes, in, at, bytes) == 0, on + "the faces' bytes are the input's");
  check(out == bytes_of(expected), on + "the file is byte for byte the one of the moved values");
  check_blocks(output, expected, P, name + " written back, read");
}

void writer_refuses(const std::string& dir)
{
  const std::string input = dir + "/le_float.ply", output = dir + "/refused_out.ply";
  const af::Ply_header header = af::read_ply_header(input);
  af::create_ply_output(input, output, header);
  std::string message;
  try { af::write_ply_blocks(input, output, header, 0, 1, { 5 }, { 0, 0, 0 }, { 0.5, 300 }); }
  catch(const std::runtime_error& e) { message = e.what(); }
  check(message == output + ": vertex 5's red (300.000000) is not a uchar", "a value its type cannot hold: " + message);
  message.clear();
  try { af::create_ply_output(input, input, header); }
  catch(const std::runtime_error& e) { message = e.what(); }
  check(message == input + ": the output cannot be the input", "the output is not the input: " + message);
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::fprintf(stderr, "usage: %s DATA_DIR [WORK_DIR]\n", argv[0]);
    return 2;
  }
  const std::string data = argv[1], dir = argc > 2 ? argv[2] : ".";
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if(!CGAL::IO::read_polygon_soup(data + "/bumpy.off", points, polygons) || polygons.size() < 2000)
  {
    std::fprintf(stderr, "cannot read %s/bumpy.off\n", data.c_str());
    return 2;
  }
  try
  {
    const auto originals = files(points, polygons, false), moved = files(points, polygons, true);
    for(std::size_t k = 0; k < originals.size(); ++k)
    {
      write_file(dir + "/" + originals[k].first + ".ply", bytes_of(originals[k].second));
      for(int P : { 1, 2, 3, 5 }) check_blocks(dir + "/" + originals[k].first + ".ply", originals[k].second, P,
                                               originals[k].first);
      for(int P : { 1, 2, 3, 5 }) write_back(dir, originals[k].first, points, moved[k].second, P);
      for(int P : { 1, 3 }) write_back(dir, originals[k].first, points, moved[k].second, P, { "k1", "k2", "mean_curvature" });
    }
    refusals_and_errors(dir, points, polygons);
    writer_refuses(dir);
  }
  catch(const std::exception& e)
  {
    std::printf("FAILED: unexpected exception: %s\n", e.what());
    ++failed;
  }
  std::printf("%d passed, %d failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
