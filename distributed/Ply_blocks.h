// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A binary PLY file read and written by blocks (Mesh_blocks, block_first()): each process reads only the bytes of
// its block of vertices and of its block of faces, so that no process reads, or holds, the whole file; and writes
// back only the records of the vertices it is given, at their places in a file of the input's layout.
// Possible because a binary vertex record has a fixed size, and a face record too when every face is a triangle:
// the file's size says whether they are (the header's counts, with triangles for faces, must add up to it). When
// they are not (polygons, ascii, list properties in other elements, no face element: triangle strips), the reader
// says so (Ply_header::refusal), from the header and the file's size alone, so the same on every process, and the
// caller reads the file once and scatters it. Plain file IO: one process's reads and writes touch byte ranges no
// other process's writes touch (on a file system without write coherence between hosts, such as NFS, records
// written by processes on different hosts may share a cached page: write to a parallel or a local file system).
// Writing back: Ply_block_output.h.

#ifndef AF_DISTRIBUTED_PLY_BLOCKS_H
#define AF_DISTRIBUTED_PLY_BLOCKS_H

#include "Part_exchange.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace af_distributed {

/// A PLY scalar type (char, uchar, short, ushort, int, uint, float, double and their sized names).
enum class Ply_type { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

struct Ply_property
{
  std::string name;
  Ply_type type = Ply_type::float32;       // a list's: the type of its items
  bool list = false;
  Ply_type count_type = Ply_type::uint8;   // a list's
};

struct Ply_element
{
  std::string name;
  std::int64_t count = 0;
  std::vector<Ply_property> properties;
  std::int64_t offset = 0;   // of its first record in the file, and the bytes of a record (a face's: a triangle's);
  std::int64_t record = 0;   // both known only when the file can be read by blocks
};

/// What a PLY header says, and where its elements lie in the file.
struct Ply_header
{
  std::string text;                     // the header's bytes, "ply" to end_header's line end: written back as is
  bool binary = true, big_endian = false;
  std::vector<Ply_element> elements;
  int vertex = -1, face = -1;           // the vertex and face elements (-1: none)
  int x = -1, y = -1, z = -1;           // the vertex's properties x, y, z
  std::vector<int> columns;             // the vertex's other properties, in the file's order
  int corners = -1;                     // the face's property vertex_indices or vertex_index
  std::int64_t file_size = 0;
  std::string refusal;                  // why the file cannot be read by blocks (empty: it can)
};

/// What process `rank` of `size` read of a PLY file: its blocks, when the file can be read by blocks.
struct Ply_blocks
{
  Ply_header header;
  Mesh_blocks mesh;                     // the whole mesh's counts, this process's blocks
  std::vector<std::string> names;       // the vertex's other properties (header.columns), in the file's order
  std::vector<double> values;           // names.size() per vertex of the block, vertex by vertex

  bool by_blocks() const { return header.refusal.empty(); }
};

namespace ply_blocks_detail {

const std::int64_t chunk_bytes = std::int64_t(4) << 20;   // a read or write of a big block: a few MB at a time

inline std::size_t type_size(Ply_type t)
{
  static const std::size_t sizes[] = { 1, 1, 2, 2, 4, 4, 4, 8 };
  return sizes[int(t)];
}

inline bool is_integer(Ply_type t) { return t != Ply_type::float32 && t != Ply_type::float64; }

inline bool type_of(const std::string& word, Ply_type& t)
{
  static const char* const names[][2] = { { "char", "int8" }, { "uchar", "uint8" }, { "short", "int16" },
    { "ushort", "uint16" }, { "int", "int32" }, { "uint", "uint32" }, { "float", "float32" }, { "double", "float64" } };
  for(int k = 0; k < 8; ++k)
    if(word == names[k][0] || word == names[k][1])
    {
      t = Ply_type(k);
      return true;
    }
  return false;
}

inline const char* type_name(Ply_type t)
{
  static const char* const names[] = { "char", "uchar", "short", "ushort", "int", "uint", "float", "double" };
  return names[int(t)];
}

// Whether the file's bytes are in the other order than this machine's.
inline bool swapped(const Ply_header& h)
{
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return h.big_endian == (first == 1);
}

template <typename T>
double load(const char* p, bool swap)
{
  char bytes[sizeof(T)];
  std::memcpy(bytes, p, sizeof(T));
  if(swap) std::reverse(bytes, bytes + sizeof(T));
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return double(value);   // exact: no PLY type is wider than a double's mantissa
}

inline double decode(const char* p, Ply_type t, bool swap)
{
  switch(t)
  {
    case Ply_type::int8: return load<std::int8_t>(p, swap);
    case Ply_type::uint8: return load<std::uint8_t>(p, swap);
    case Ply_type::int16: return load<std::int16_t>(p, swap);
    case Ply_type::uint16: return load<std::uint16_t>(p, swap);
    case Ply_type::int32: return load<std::int32_t>(p, swap);
    case Ply_type::uint32: return load<std::uint32_t>(p, swap);
    case Ply_type::float32: return load<float>(p, swap);
    default: return load<double>(p, swap);
  }
}

// False when `value` is not one of T's (an integer type's: a fraction, or out of its range).
template <typename T>
bool store(char* p, double value, bool swap)
{
  if(std::is_integral<T>::value && !(value >= double(std::numeric_limits<T>::min()) &&
                                     value <= double(std::numeric_limits<T>::max()) && value == std::floor(value)))
    return false;
  const T v = T(value);
  char bytes[sizeof(T)];
  std::memcpy(bytes, &v, sizeof(T));
  if(swap) std::reverse(bytes, bytes + sizeof(T));
  std::memcpy(p, bytes, sizeof(T));
  return true;
}

inline bool encode(char* p, Ply_type t, double value, bool swap)
{
  switch(t)
  {
    case Ply_type::int8: return store<std::int8_t>(p, value, swap);
    case Ply_type::uint8: return store<std::uint8_t>(p, value, swap);
    case Ply_type::int16: return store<std::int16_t>(p, value, swap);
    case Ply_type::uint16: return store<std::uint16_t>(p, value, swap);
    case Ply_type::int32: return store<std::int32_t>(p, value, swap);
    case Ply_type::uint32: return store<std::uint32_t>(p, value, swap);
    case Ply_type::float32: return store<float>(p, value, swap);
    default: return store<double>(p, value, swap);
  }
}

// The offset of each property in a record (a list: as a triangle's), and the record's bytes.
inline std::vector<std::int64_t> property_offsets(const Ply_element& e, std::int64_t& record)
{
  std::vector<std::int64_t> at;
  record = 0;
  for(const Ply_property& p : e.properties)
  {
    at.push_back(record);
    record += std::int64_t(p.list ? type_size(p.count_type) + 3 * type_size(p.type) : type_size(p.type));
  }
  return at;
}

// The header's text: up to the line end after end_header (a header is a few lines: at most 16 MB read).
inline std::string header_text(std::ifstream& in, const std::string& path)
{
  std::string text;
  std::vector<char> buffer(std::size_t(64) << 10);
  while(text.size() < (std::size_t(16) << 20))
  {
    in.read(buffer.data(), std::streamsize(buffer.size()));
    text.append(buffer.data(), std::size_t(in.gcount()));
    for(std::size_t at = text.find("end_header"); at != std::string::npos; at = text.find("end_header", at + 1))
    {
      if(at > 0 && text[at - 1] != '\n') continue;
      std::size_t end = at + 10;
      if(end < text.size() && text[end] == '\r') ++end;
      if(end < text.size() && text[end] == '\n') return text.substr(0, end + 1);
    }
    if(!in) break;
  }
  if(text.compare(0, 3, "ply") != 0) throw std::runtime_error(path + ": not a PLY file (no \"ply\" first line)");
  throw std::runtime_error(path + ": the PLY header has no end_header line");
}

// One line of the header into `h` (false: not a line of a PLY header).
inline bool parse_line(const std::vector<std::string>& w, Ply_header& h)
{
  Ply_type t = Ply_type::uint8, c = Ply_type::uint8;
  if(w.empty() || w[0] == "comment" || w[0] == "obj_info") return true;
  if(w[0] == "format" && w.size() == 3 && w[2] == "1.0")
  {
    h.binary = w[1] != "ascii";
    h.big_endian = w[1] == "binary_big_endian";
    return w[1] == "ascii" || w[1] == "binary_little_endian" || w[1] == "binary_big_endian";
  }
  if(w[0] == "element" && w.size() == 3)
  {
    Ply_element e;
    e.name = w[1];
    std::size_t used = 0;
    try { e.count = std::stoll(w[2], &used); } catch(const std::exception&) { return false; }
    h.elements.push_back(e);
    return used == w[2].size() && e.count >= 0;
  }
  if(w[0] != "property" || h.elements.empty()) return false;
  Ply_property p;
  if(w.size() == 3 && type_of(w[1], t)) p = Ply_property{ w[2], t, false, Ply_type::uint8 };
  else if(w.size() == 5 && w[1] == "list" && type_of(w[2], c) && type_of(w[3], t) && is_integer(c))
    p = Ply_property{ w[4], t, true, c };
  else return false;
  h.elements.back().properties.push_back(p);
  return true;
}

inline int property_named(const Ply_element& e, const std::string& name)
{
  for(std::size_t k = 0; k < e.properties.size(); ++k)
    if(e.properties[k].name == name) return int(k);
  return -1;
}

// The vertex element's x, y, z and other properties, the face element's corners; an error if missing.
inline void find_mesh(Ply_header& h, const std::string& path)
{
  for(std::size_t i = 0; i < h.elements.size(); ++i)
  {
    if(h.elements[i].name == "vertex" && h.vertex < 0) h.vertex = int(i);
    if(h.elements[i].name == "face" && h.face < 0) h.face = int(i);
  }
  if(h.vertex < 0) throw std::runtime_error(path + ": the PLY header has no vertex element");
  const Ply_element& v = h.elements[std::size_t(h.vertex)];
  int* xyz[] = { &h.x, &h.y, &h.z };
  for(int c = 0; c < 3; ++c)
  {
    const std::string name(1, char('x' + c));
    *xyz[c] = property_named(v, name);
    if(*xyz[c] < 0 || v.properties[std::size_t(*xyz[c])].list)
      throw std::runtime_error(path + ": the vertex element has no property " + name);
  }
  for(int k = 0; k < int(v.properties.size()); ++k)
    if(k != h.x && k != h.y && k != h.z) h.columns.push_back(k);
  if(h.face < 0) return;   // refused by layout(): the caller's reader knows other elements (triangle strips)
  const Ply_element& f = h.elements[std::size_t(h.face)];
  h.corners = property_named(f, "vertex_indices");
  if(h.corners < 0) h.corners = property_named(f, "vertex_index");
  if(h.corners < 0 || !f.properties[std::size_t(h.corners)].list ||
     !is_integer(f.properties[std::size_t(h.corners)].type))
    throw std::runtime_error(path + ": the face element has no list property vertex_indices or vertex_index of "
                             "integers");
}

// Where each element lies, when every record has a fixed size (the faces: triangles); else why not. An error when
// the file is shorter than that layout: it is truncated (named by the record it ends in).
inline std::string layout(Ply_header& h, const std::string& path)
{
  if(!h.binary) return path + ": an ascii PLY file cannot be read by blocks";
  if(h.face < 0) return path + ": the PLY file has no face element: it cannot be read by blocks";
  std::int64_t at = std::int64_t(h.text.size());
  for(std::size_t i = 0; i < h.elements.size(); ++i)
  {
    Ply_element& e = h.elements[i];
    for(std::size_t k = 0; k < e.properties.size(); ++k)
      if(e.properties[k].list && !(int(i) == h.face && int(k) == h.corners))
        return path + ": the " + e.name + " element has a list property (" + e.properties[k].name +
               "): the size of its records cannot be known, the file cannot be read by blocks";
    e.offset = at;
    property_offsets(e, e.record);
    if(e.record > 0 && e.count > (std::numeric_limits<std::int64_t>::max() - at) / e.record)
      throw std::runtime_error(path + ": the " + e.name + " element's count is too large");
    at += e.count * e.record;
  }
  if(h.file_size > at)
    return path + ": the faces are not all triangles (the file has " + std::to_string(h.file_size) +
           " bytes, its triangles would fill " + std::to_string(at) + "): it cannot be read by blocks";
  if(h.file_size == at) return std::string();
  for(const Ply_element& e : h.elements)
    if(e.record > 0 && h.file_size < e.offset + e.count * e.record)
      throw std::runtime_error(path + ": truncated in " + e.name + " " +
                               std::to_string(std::max<std::int64_t>(0, h.file_size - e.offset) / e.record) +
                               " (the file has " + std::to_string(h.file_size) + " bytes, " + std::to_string(at) +
                               " expected)");
  throw std::runtime_error(path + ": truncated");
}

// Records [first, last) of element `e`, read a few MB at a time, each given to `f` with its number.
template <typename F>
void for_records(std::ifstream& in, const std::string& path, const Ply_element& e, std::int64_t first,
                 std::int64_t last, const F& f)
{
  if(first >= last || e.record == 0) return;
  const std::int64_t per_chunk = std::max<std::int64_t>(1, chunk_bytes / e.record);
  std::vector<char> buffer(std::size_t(std::min(per_chunk, last - first) * e.record));
  for(std::int64_t r = first; r < last; r += per_chunk)
  {
    const std::int64_t records = std::min(per_chunk, last - r);
    in.clear();
    in.seekg(std::streamoff(e.offset + r * e.record));
    in.read(buffer.data(), std::streamsize(records * e.record));
    if(in.gcount() != std::streamsize(records * e.record))
      throw std::runtime_error(path + ": truncated in " + e.name + " " +
                               std::to_string(r + std::int64_t(in.gcount()) / e.record));
    for(std::int64_t k = 0; k < records; ++k) f(buffer.data() + k * e.record, r + k);
  }
}

inline void read_vertices(std::ifstream& in, const std::string& path, Ply_blocks& b, std::int64_t first,
                          std::int64_t last)
{
  const Ply_header& h = b.header;
  const Ply_element& e = h.elements[std::size_t(h.vertex)];
  std::int64_t record = 0;
  const std::vector<std::int64_t> at = property_offsets(e, record);
  const bool swap = swapped(h);
  b.mesh.points.reserve(std::size_t(3 * (last - first)));
  b.values.reserve(std::size_t(last - first) * h.columns.size());
  for_records(in, path, e, first, last, [&](const char* r, std::int64_t) {
    for(int k : { h.x, h.y, h.z })
      b.mesh.points.push_back(decode(r + at[std::size_t(k)], e.properties[std::size_t(k)].type, swap));
    for(int k : h.columns) b.values.push_back(decode(r + at[std::size_t(k)], e.properties[std::size_t(k)].type, swap));
  });
}

inline void read_faces(std::ifstream& in, const std::string& path, Ply_blocks& b, std::int64_t first,
                       std::int64_t last)
{
  const Ply_header& h = b.header;
  const Ply_element& e = h.elements[std::size_t(h.face)];
  const Ply_property& p = e.properties[std::size_t(h.corners)];
  std::int64_t record = 0;
  const std::int64_t list_at = property_offsets(e, record)[std::size_t(h.corners)];
  const std::int64_t item = std::int64_t(type_size(p.type)), items_at = list_at + std::int64_t(type_size(p.count_type));
  const bool swap = swapped(h);
  const std::int64_t n = b.mesh.vertices;
  b.mesh.triangles.reserve(std::size_t(last - first));
  for_records(in, path, e, first, last, [&](const char* r, std::int64_t number) {
    const double count = decode(r + list_at, p.count_type, swap);
    if(count != 3)
      throw std::runtime_error(path + ": face " + std::to_string(number) + " has " + std::to_string(std::int64_t(count))
                               + " corners (a file read by blocks must have only triangles)");
    std::array<std::int64_t, 3> t;
    for(int c = 0; c < 3; ++c)
    {
      const double v = decode(r + items_at + c * item, p.type, swap);
      if(!(v >= 0 && v < double(n)))
        throw std::runtime_error(path + ": face " + std::to_string(number) + "'s corner " + std::to_string(c) +
                                 " is vertex " + std::to_string(std::int64_t(v)) + ", not in [0, " +
                                 std::to_string(n) + ")");
      t[std::size_t(c)] = std::int64_t(v);
    }
    b.mesh.triangles.push_back(t);
  });
}

inline std::ifstream open_input(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if(!in) throw std::runtime_error(path + ": cannot be opened");
  return in;
}

} // namespace ply_blocks_detail

/// The header of the PLY file `path` and where its elements lie (header.refusal: why it cannot be read by blocks).
/// Throws std::runtime_error naming the file on a bad header, a missing x, y, z or face list, a truncated file.
inline Ply_header read_ply_header(const std::string& path)
{
  namespace d = ply_blocks_detail;
  std::ifstream in = d::open_input(path);
  Ply_header h;
  h.text = d::header_text(in, path);
  in.clear();
  in.seekg(0, std::ios::end);
  h.file_size = std::int64_t(in.tellg());
  std::istringstream lines(h.text);
  std::string line;
  int formats = 0;
  for(int number = 1; std::getline(lines, line); ++number)
  {
    if(!line.empty() && line.back() == '\r') line.pop_back();
    if(number == 1 ? line == "ply" : line == "end_header") continue;
    std::istringstream words(line);
    std::vector<std::string> w;
    for(std::string word; words >> word;) w.push_back(word);
    formats += !w.empty() && w[0] == "format" ? 1 : 0;
    if(number == 1 || !d::parse_line(w, h))
      throw std::runtime_error(path + ": PLY header line " + std::to_string(number) + " is not understood: \"" + line +
                               "\"");
  }
  if(formats != 1) throw std::runtime_error(path + ": the PLY header has " + std::to_string(formats) + " format lines");
  d::find_mesh(h, path);
  h.refusal = d::layout(h, path);
  return h;
}

/// What process `rank` of `size` holds of the binary PLY file `path`: the whole mesh's counts, vertices
/// [block_first(n, rank, size), block_first(n, rank + 1, size)) (positions and the other properties, as doubles)
/// and faces likewise (checked: triangles, corners in [0, n)), read from their byte ranges only. When the file cannot
/// be read by blocks (by_blocks() false: header.refusal says why, the same on every process), only the header is
/// read and the caller reads the whole file once. Throws std::runtime_error naming the file and the element or record.
inline Ply_blocks read_ply_blocks(const std::string& path, int rank, int size)
{
  namespace d = ply_blocks_detail;
  Ply_blocks b;
  b.header = read_ply_header(path);
  const Ply_header& h = b.header;
  const Ply_element& v = h.elements[std::size_t(h.vertex)];
  for(int k : h.columns) b.names.push_back(v.properties[std::size_t(k)].name);
  if(!b.by_blocks()) return b;
  b.mesh.vertices = v.count;
  b.mesh.faces = h.elements[std::size_t(h.face)].count;
  std::ifstream in = d::open_input(path);
  d::read_vertices(in, path, b, block_first(b.mesh.vertices, rank, size), block_first(b.mesh.vertices, rank + 1, size));
  d::read_faces(in, path, b, block_first(b.mesh.faces, rank, size), block_first(b.mesh.faces, rank + 1, size));
  return b;
}

} // namespace af_distributed

#endif // AF_DISTRIBUTED_PLY_BLOCKS_H
