// anisotropic_fairing tool: split vertices merged back (vertex_split.h).
#include "vertex_split.h"

#include "element_properties.h"

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <sstream>

namespace af_tool {

void copy_properties_to_copies(Mesh& mesh, const Vertex_split& split)
{
  for(std::size_t i = 0; i < split.copy_of.size(); ++i)
    copy_properties(mesh, Vertex_index(Mesh::size_type(split.copy_of[i])),
                    Vertex_index(Mesh::size_type(split.file_vertices + i)));
}

namespace {

// Sets each split vertex and its copies to the mean of their values, read and written as D coordinates.
template <std::size_t D, typename Get, typename Set>
void average(const Vertex_split& split, Get get, Set set)
{
  std::vector<std::array<double, D> > sum(split.file_vertices);
  std::vector<double> count(split.file_vertices, 0.0);
  for(std::size_t v = 0; v < split.file_vertices + split.copy_of.size(); ++v)
  {
    const std::size_t o = split.original(v);
    const std::array<double, D> x = get(v);
    for(std::size_t c = 0; c < D; ++c) sum[o][c] += x[c];
    count[o] += 1;
  }
  for(std::size_t v = 0; v < split.file_vertices + split.copy_of.size(); ++v)
  {
    const std::size_t o = split.original(v);
    if(v >= split.file_vertices || count[o] > 1)
    {
      std::array<double, D> mean = sum[o];
      for(double& x : mean) x /= count[o];
      set(v, mean);
    }
  }
}

Vertex_index vertex(std::size_t v) { return Vertex_index(Mesh::size_type(v)); }

} // namespace

void merge_copies(Mesh& mesh, const Vertex_split& split)
{
  if(split.empty()) return;
  average<3>(
    split,
    [&](std::size_t v) {
      const Point& p = mesh.point(vertex(v));
      return std::array<double, 3>{ p.x(), p.y(), p.z() };
    },
    [&](std::size_t v, const std::array<double, 3>& x) { mesh.point(vertex(v)) = Point(x[0], x[1], x[2]); });
  for(const std::string& name : mesh.properties<Vertex_index>())
  {
    if(is_internal_property(name)) continue;
    const auto scalar = [&](auto zero) {
      auto map = mesh.property_map<Vertex_index, decltype(zero)>(name);
      if(map.second)
        average<1>(split, [&](std::size_t v) { return std::array<double, 1>{double(map.first[vertex(v)])}; },
                   [&](std::size_t v, const std::array<double, 1>& x) { map.first[vertex(v)] = decltype(zero)(x[0]); });
      return map.second;
    };
    if(scalar(0.0) || scalar(0.f)) continue;
    auto vectors = mesh.property_map<Vertex_index, Vector>(name);
    if(vectors.second)
    {
      const bool unit = name == "v:normal";
      average<3>(
        split,
        [&](std::size_t v) {
          const Vector& n = vectors.first[vertex(v)];
          return std::array<double, 3>{ n.x(), n.y(), n.z() };
        },
        [&](std::size_t v, const std::array<double, 3>& x) {
          const double length = unit ? std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) : 1.0;
          vectors.first[vertex(v)] =
            length > 0 ? Vector(x[0] / length, x[1] / length, x[2] / length) : Vector(x[0], x[1], x[2]);
        });
      continue;
    }
    auto uv = mesh.property_map<Vertex_index, Texcoord>(name);
    if(uv.second)
      average<2>(
        split,
        [&](std::size_t v) {
          const Texcoord& t = uv.first[vertex(v)];
          return std::array<double, 2>{ t.x(), t.y() };
        },
        [&](std::size_t v, const std::array<double, 2>& x) { uv.first[vertex(v)] = Texcoord(x[0], x[1]); });
  }
}

void merge_copies(std::vector<std::vector<double> >& values, const Vertex_split& split)
{
  if(split.empty() || values.empty()) return;
  const std::size_t d = values.front().size();
  for(std::size_t c = 0; c < d; ++c)
    average<1>(split, [&](std::size_t v) { return std::array<double, 1>{values[v][c]}; },
               [&](std::size_t v, const std::array<double, 1>& x) { values[v][c] = x[0]; });
}

// ------------------------------------------------------------------------------------------------
// The written file without the copies
// ------------------------------------------------------------------------------------------------
namespace {

[[noreturn]] void cannot(const std::string& path, const std::string& why)
{
  fail("write_error", "cannot write " + path + " with its split vertices merged: " + why);
}

// the lines of a text, each with its end of line
std::vector<std::string> lines_of(const std::string& text)
{
  std::vector<std::string> lines;
  for(std::size_t at = 0; at < text.size();)
  {
    const std::size_t end = text.find('\n', at);
    const std::size_t next = end == std::string::npos ? text.size() : end + 1;
    lines.push_back(text.substr(at, next - at));
    at = next;
  }
  return lines;
}

std::vector<std::string> words_of(const std::string& line)
{
  std::istringstream in(line);
  return std::vector<std::string>(std::istream_iterator<std::string>(in), std::istream_iterator<std::string>());
}

std::string original_index(const std::string& word, const Vertex_split& split, std::size_t base)
{
  const std::size_t v = std::stoull(word) - base;
  return std::to_string(split.original(v) + base);
}

// OFF as CGAL writes it: the keyword line, "nv nf ne", nv vertex lines, nf lines "k i1 .. ik [colour]"
std::string merged_off(const std::string& text, const Vertex_split& split, const std::string& path)
{
  const std::vector<std::string> lines = lines_of(text);
  std::string out;
  std::size_t i = 0, kept = 0, vertices = 0;
  const auto content = [](const std::string& l) { const auto w = words_of(l); return !w.empty() && w[0][0] != '#'; };
  for(; i < lines.size() && !content(lines[i]); ++i) out += lines[i];
  if(i == lines.size()) cannot(path, "no OFF header");
  out += lines[i++];
  for(; i < lines.size() && !content(lines[i]); ++i) out += lines[i];
  if(i == lines.size()) cannot(path, "no counts");
  std::vector<std::string> counts = words_of(lines[i++]);
  vertices = std::stoull(counts.at(0));
  if(vertices != split.file_vertices + split.copy_of.size()) cannot(path, "it has " + counts[0] + " vertices");
  counts[0] = std::to_string(split.file_vertices);
  for(std::size_t k = 0; k < counts.size(); ++k) out += (k ? " " : "") + counts[k];
  out += "\n";
  for(; i < lines.size(); ++i)
  {
    if(!content(lines[i])) { out += lines[i]; continue; }
    if(kept < vertices)
    {
      if(kept++ < split.file_vertices) out += lines[i];
      continue;
    }
    std::vector<std::string> w = words_of(lines[i]);
    const std::size_t k = std::stoull(w.at(0));
    for(std::size_t c = 1; c <= k; ++c) w.at(c) = original_index(w[c], split, 0);
    for(std::size_t c = 0; c < w.size(); ++c) out += (c ? " " : "") + w[c];
    out += "\n";
  }
  return out;
}

// OBJ as write_mesh() writes it: one v (and vt, vn) per vertex, faces "f a", "f a/a", "f a//a", "f a/a/a"
std::string merged_obj(const std::string& text, const Vertex_split& split)
{
  std::string out;
  std::size_t v = 0, vt = 0, vn = 0;
  for(const std::string& line : lines_of(text))
  {
    const std::string key = line.substr(0, line.find(' '));
    std::size_t* count = key == "v" ? &v : key == "vt" ? &vt : key == "vn" ? &vn : nullptr;
    if(count)
    {
      if((*count)++ < split.file_vertices) out += line;
      continue;
    }
    if(key != "f") { out += line; continue; }
    out += "f";
    const std::vector<std::string> w = words_of(line);
    for(std::size_t c = 1; c < w.size(); ++c)
    {
      out += ' ';
      std::size_t at = 0;
      for(;;)
      {
        const std::size_t slash = w[c].find('/', at);
        const std::string part = w[c].substr(at, slash == std::string::npos ? std::string::npos : slash - at);
        out += part.empty() ? part : original_index(part, split, 1);
        if(slash == std::string::npos) break;
        out += '/';
        at = slash + 1;
      }
    }
    out += "\n";
  }
  return out;
}

// PLY as CGAL writes it (ASCII: a line per element; binary: little endian)
struct Ply_property
{
  std::string name, type, count_type;   // count_type: a list's
};
struct Ply_element
{
  std::string name;
  std::size_t count = 0;
  std::vector<Ply_property> properties;
};

std::size_t size_of(const std::string& type, const std::string& path)
{
  if(type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if(type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if(type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32")
    return 4;
  if(type == "double" || type == "float64") return 8;
  cannot(path, "unknown PLY type " + type);
}

std::uint64_t read_unsigned(const std::string& text, std::size_t at, std::size_t size)
{
  std::uint64_t x = 0;
  for(std::size_t b = 0; b < size; ++b) x |= std::uint64_t(static_cast<unsigned char>(text[at + b])) << (8 * b);
  return x;
}

void write_unsigned(std::string& text, std::size_t at, std::size_t size, std::uint64_t x)
{
  for(std::size_t b = 0; b < size; ++b) text[at + b] = char((x >> (8 * b)) & 0xff);
}

std::string merged_ply(const std::string& text, const Vertex_split& split, const std::string& path)
{
  const std::size_t end = text.find("end_header\n");
  if(end == std::string::npos) cannot(path, "no PLY header");
  std::string header;
  std::vector<Ply_element> elements;
  bool binary = false;
  for(const std::string& line : lines_of(text.substr(0, end)))
  {
    const std::vector<std::string> w = words_of(line);
    std::string written = line;
    if(!w.empty() && w[0] == "format") binary = w.at(1) != "ascii";
    if(!w.empty() && w[0] == "format" && w[1] == "binary_big_endian") cannot(path, "big-endian PLY");
    if(!w.empty() && w[0] == "element")
    {
      elements.push_back({w.at(1), std::stoull(w.at(2)), {}});
      if(w[1] == "vertex") written = "element vertex " + std::to_string(split.file_vertices) + "\n";
    }
    if(!w.empty() && w[0] == "property" && !elements.empty())
      elements.back().properties.push_back(w.at(1) == "list" ? Ply_property{ w.at(4), w.at(3), w.at(2) }
                                                             : Ply_property{ w.at(2), w.at(1), "" });
    header += written;
  }
  header += "end_header\n";
  const auto is_indices = [](const Ply_element& e, const Ply_property& p) {
    return e.name == "face" && !p.count_type.empty() && (p.name == "vertex_indices" || p.name == "vertex_index");
  };
  std::string body;
  std::size_t at = end + std::string("end_header\n").size();
  if(!binary)
  {
    const std::vector<std::string> lines = lines_of(text.substr(at));
    std::size_t l = 0;
    for(const Ply_element& e : elements)
      for(std::size_t r = 0; r < e.count; ++r, ++l)
      {
        if(l >= lines.size()) cannot(path, "the file is shorter than its header says");
        if(e.name == "vertex") { if(r < split.file_vertices) body += lines[l]; continue; }
        if(e.name != "face") { body += lines[l]; continue; }
        std::vector<std::string> w = words_of(lines[l]);
        std::size_t c = 0;
        for(const Ply_property& p : e.properties)
        {
          if(p.count_type.empty()) { ++c; continue; }
          const std::size_t k = std::stoull(w.at(c++));
          for(std::size_t j = 0; j < k; ++j, ++c)
            if(is_indices(e, p)) w.at(c) = original_index(w.at(c), split, 0);
        }
        for(std::size_t j = 0; j < w.size(); ++j) body += (j ? " " : "") + w[j];
        body += "\n";
      }
    for(; l < lines.size(); ++l) body += lines[l];
    return header + body;
  }
  std::string data = text.substr(at);
  std::size_t p = 0;
  for(const Ply_element& e : elements)
    for(std::size_t r = 0; r < e.count; ++r)
    {
      const std::size_t record = p;
      for(const Ply_property& q : e.properties)
      {
        if(q.count_type.empty()) { p += size_of(q.type, path); continue; }
        const std::size_t count_size = size_of(q.count_type, path), item = size_of(q.type, path);
        if(p + count_size > data.size()) cannot(path, "the file is shorter than its header says");
        const std::uint64_t k = read_unsigned(data, p, count_size);
        p += count_size;
        if(p + k * item > data.size()) cannot(path, "the file is shorter than its header says");
        for(std::uint64_t j = 0; j < k; ++j, p += item)
          if(is_indices(e, q)) write_unsigned(data, p, item, split.original(std::size_t(read_unsigned(data, p, item))));
      }
      if(p > data.size()) cannot(path, "the file is shorter than its header says");
      if(e.name != "vertex" || r < split.file_vertices) body.append(data, record, p - record);
    }
  body.append(data, p, std::string::npos);
  return header + body;
}

} // namespace

void merge_copies_in_file(const std::string& path, Format format, const Vertex_split& split)
{
  if(split.empty() || format == Format::STL)
    return; // STL has no vertices: the merged positions are written as they are
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if(!in.good() && !in.eof()) cannot(path, "it cannot be read back");
  std::string merged;
  try
  {
    merged = format == Format::OFF   ? merged_off(text, split, path)
             : format == Format::OBJ ? merged_obj(text, split)
                                     : merged_ply(text, split, path);
  }
  catch(const std::logic_error& e)   // stoull, at(): a file write_mesh() would not write
  {
    cannot(path, std::string("unexpected content (") + e.what() + ")");
  }
  errno = 0;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << merged;
  out.close();
  if(out.fail()) fail("write_error", "cannot write " + path + system_reason(errno));
}

} // namespace af_tool
