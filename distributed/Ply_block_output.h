// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A binary PLY file read by blocks (Ply_blocks.h) written back by blocks: each process writes the records of the
// vertices it is given at their places, and copies its block of faces, in a file of the input's layout, or of the
// input's layout with vertex properties added (with_vertex_properties(): --curvature's k1, k2, mean_curvature).
// In two steps, for records of the output's types (full precision: a float x is written as float):
//   process 0: create_ply_output(input, output, read, written);   // the header, the other elements, the full size
//   all:       MPI_Barrier (the caller's);
//   all:       write_ply_blocks(input, output, read, written, rank, size, vertices, points, values);
// (`read`: the input's header, read_ply_blocks()'s; `written`: the output's, `read` itself or with_vertex_properties'.)

#ifndef AF_DISTRIBUTED_PLY_BLOCK_OUTPUT_H
#define AF_DISTRIBUTED_PLY_BLOCK_OUTPUT_H

#include "Ply_blocks.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace af_distributed {

namespace ply_blocks_detail {

// Bytes [at, at + bytes) of `input` to [to, to + bytes) of `output`, a few MB at a time.
inline void copy_range(std::ifstream& input, std::fstream& output, const std::string& in_path,
                       const std::string& out_path, std::int64_t at, std::int64_t to, std::int64_t bytes)
{
  std::vector<char> buffer(std::size_t(std::min(bytes, chunk_bytes)));
  for(std::int64_t done = 0; done < bytes;)
  {
    const std::int64_t n = std::min(chunk_bytes, bytes - done);
    input.clear();
    input.seekg(std::streamoff(at + done));
    input.read(buffer.data(), std::streamsize(n));
    if(input.gcount() != std::streamsize(n)) throw std::runtime_error(in_path + ": truncated at byte " +
                                                                      std::to_string(at + done + input.gcount()));
    output.seekp(std::streamoff(to + done));
    output.write(buffer.data(), std::streamsize(n));
    if(!output) throw std::runtime_error(out_path + ": cannot be written at byte " + std::to_string(to + done));
    done += n;
  }
}

// The records of `vertices` (global numbers; positions 3 each, the other properties `columns` each), written in
// runs of consecutive numbers, a few MB at a time.
inline void write_vertices(std::fstream& out, const std::string& path, const Ply_header& h,
                           const std::vector<std::int64_t>& vertices, const std::vector<double>& points,
                           const std::vector<double>& values)
{
  const Ply_element& e = h.elements[std::size_t(h.vertex)];
  std::int64_t record = 0;
  const std::vector<std::int64_t> at = property_offsets(e, record);
  const std::size_t columns = h.columns.size();
  std::vector<int> source(e.properties.size());   // a property's value: -1, -2, -3 the position's, k >= 0 column k
  source[std::size_t(h.x)] = -1, source[std::size_t(h.y)] = -2, source[std::size_t(h.z)] = -3;
  for(std::size_t k = 0; k < columns; ++k) source[std::size_t(h.columns[k])] = int(k);
  std::vector<std::size_t> order(vertices.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return vertices[a] < vertices[b]; });
  const bool swap = swapped(h);
  const std::size_t per_chunk = std::size_t(std::max<std::int64_t>(1, chunk_bytes / record));
  std::vector<char> buffer;
  for(std::size_t s = 0, next; s < order.size(); s = next)
  {
    next = s + 1;   // a run: consecutive numbers, at most a chunk
    while(next < order.size() && next - s < per_chunk && vertices[order[next]] == vertices[order[next - 1]] + 1) ++next;
    buffer.assign((next - s) * std::size_t(record), 0);
    for(std::size_t i = s; i < next; ++i)
    {
      const std::size_t j = order[i];
      char* r = buffer.data() + (i - s) * std::size_t(record);
      for(std::size_t k = 0; k < e.properties.size(); ++k)
      {
        const double value = source[k] < 0 ? points[3 * j + std::size_t(-source[k] - 1)]
                                           : values[j * columns + std::size_t(source[k])];
        if(!encode(r + at[k], e.properties[k].type, value, swap))
          throw std::runtime_error(path + ": vertex " + std::to_string(vertices[j]) + "'s " + e.properties[k].name +
                                   " (" + std::to_string(value) + ") is not a " + type_name(e.properties[k].type));
      }
    }
    out.seekp(std::streamoff(e.offset + vertices[order[s]] * record));
    out.write(buffer.data(), std::streamsize(buffer.size()));
    if(!out) throw std::runtime_error(path + ": cannot be written at vertex " + std::to_string(vertices[order[s]]));
  }
}

} // namespace ply_blocks_detail

/// The header `read` with the vertex properties `names` (double) added after the vertex's last property: the
/// header's text, the vertex records and the offsets of what follows them, and the file's size.
inline Ply_header with_vertex_properties(const Ply_header& read, const std::vector<std::string>& names,
                                         const std::string& path)
{
  Ply_header h = read;
  if(names.empty()) return h;
  // the text: after the last property line of the vertex element, with the header's own line ends
  std::size_t at = h.text.find("element vertex");
  const std::string end = h.text.find("\r\n") != std::string::npos ? "\r\n" : "\n";
  for(at = h.text.find('\n', at) + 1; h.text.compare(at, 9, "property ") == 0;) at = h.text.find('\n', at) + 1;
  std::string added;
  for(const std::string& name : names) added += "property double " + name + end;
  h.text.insert(at, added);
  Ply_element& vertex = h.elements[std::size_t(h.vertex)];
  for(const std::string& name : names)
  {
    h.columns.push_back(int(vertex.properties.size()));
    vertex.properties.push_back(Ply_property{ name, Ply_type::float64, false, Ply_type::uint8 });
  }
  h.file_size = read.file_size + std::int64_t(added.size()) + vertex.count * std::int64_t(8 * names.size());
  const std::string why = ply_blocks_detail::layout(h, path);
  if(!why.empty()) throw std::logic_error("with_vertex_properties: " + why);
  return h;
}

/// Process 0's step of writing back the file `input` read by blocks (`read`: read_ply_blocks()'s header) as
/// `output` of header `written`: creates it at its full size with the header and the bytes of every element other
/// than the vertices and faces. The caller then makes every process wait (MPI_Barrier) before write_ply_blocks().
inline void create_ply_output(const std::string& input, const std::string& output, const Ply_header& read,
                              const Ply_header& written)
{
  namespace d = ply_blocks_detail;
  if(!read.refusal.empty()) throw std::logic_error("create_ply_output: " + read.refusal);
  std::error_code error;
  if(std::filesystem::equivalent(input, output, error))   // the input is read again by write_ply_blocks()
    throw std::runtime_error(output + ": the output cannot be the input");
  {
    std::ofstream out(output, std::ios::binary | std::ios::trunc);
    out.write(written.text.data(), std::streamsize(written.text.size()));
    if(!out) throw std::runtime_error(output + ": cannot be written");
  }
  std::filesystem::resize_file(output, std::uintmax_t(written.file_size), error);
  if(error) throw std::runtime_error(output + ": cannot be made " + std::to_string(written.file_size) + " bytes long");
  std::ifstream in = d::open_input(input);
  std::fstream out(output, std::ios::in | std::ios::out | std::ios::binary);
  if(!out) throw std::runtime_error(output + ": cannot be opened for writing");
  for(std::size_t i = 0; i < read.elements.size(); ++i)
    if(int(i) != read.vertex && int(i) != read.face)
    {
      const Ply_element& e = read.elements[i];
      d::copy_range(in, out, input, output, e.offset, written.elements[i].offset, e.count * e.record);
    }
}

inline void create_ply_output(const std::string& input, const std::string& output, const Ply_header& header)
{
  create_ply_output(input, output, header, header);
}

/// Every process's step of writing back (after process 0's create_ply_output() and the caller's MPI_Barrier):
/// the records of `vertices` (global numbers, each given by exactly one process, in any order) with their
/// `points` (3 each) and other properties `values` (written.columns.size() each, in their order), in the output's
/// types, at their places in `output`; and the bytes of this process's block of faces, copied from `input`.
inline void write_ply_blocks(const std::string& input, const std::string& output, const Ply_header& read,
                             const Ply_header& written, int rank, int size, const std::vector<std::int64_t>& vertices,
                             const std::vector<double>& points, const std::vector<double>& values)
{
  namespace d = ply_blocks_detail;
  if(!read.refusal.empty()) throw std::logic_error("write_ply_blocks: " + read.refusal);
  const std::int64_t n = written.elements[std::size_t(written.vertex)].count;
  if(points.size() != 3 * vertices.size() || values.size() != written.columns.size() * vertices.size())
    throw std::logic_error("write_ply_blocks: " + std::to_string(vertices.size()) + " vertices, " +
                           std::to_string(points.size()) + " coordinates, " + std::to_string(values.size()) +
                           " property values");
  std::vector<std::int64_t> sorted(vertices);
  std::sort(sorted.begin(), sorted.end());
  for(std::size_t k = 0; k < sorted.size(); ++k)
    if(sorted[k] < 0 || sorted[k] >= n || (k > 0 && sorted[k] == sorted[k - 1]))
      throw std::logic_error("write_ply_blocks: vertex " + std::to_string(sorted[k]) + " is not in [0, " +
                             std::to_string(n) + ") or given twice");
  std::fstream out(output, std::ios::in | std::ios::out | std::ios::binary);
  if(!out) throw std::runtime_error(output + ": cannot be opened for writing (created by process 0 first?)");
  d::write_vertices(out, output, written, vertices, points, values);
  const Ply_element& f = read.elements[std::size_t(read.face)];
  const std::int64_t first = block_first(f.count, rank, size), last = block_first(f.count, rank + 1, size);
  std::ifstream in = d::open_input(input);
  d::copy_range(in, out, input, output, f.offset + first * f.record,
                written.elements[std::size_t(read.face)].offset + first * f.record, (last - first) * f.record);
  out.flush();
  if(!out) throw std::runtime_error(output + ": cannot be written");
}

inline void write_ply_blocks(const std::string& input, const std::string& output, const Ply_header& header, int rank,
                             int size, const std::vector<std::int64_t>& vertices, const std::vector<double>& points,
                             const std::vector<double>& values)
{
  write_ply_blocks(input, output, header, header, rank, size, vertices, points, values);
}

} // namespace af_distributed

#endif // AF_DISTRIBUTED_PLY_BLOCK_OUTPUT_H
