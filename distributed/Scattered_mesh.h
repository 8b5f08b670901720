// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A mesh not read by blocks (OFF, OBJ, STL, an ASCII PLY file, or any input whose output is not a binary PLY
// file): process 0 reads it whole, as anisotropic_fairing reads it (mesh_io.h: checked, non-manifold vertices
// split, polygons triangulated), and sends each process its blocks of vertices and faces, as if each had read
// them from a binary PLY file (Part_exchange.h's Mesh_blocks). After the run each process sends process 0 its
// own vertices' positions and control points, and process 0 writes the file as the program writes a mesh held
// whole (Distributed_run.cpp). Process 0 holds the whole mesh meanwhile; the other processes, their parts.
// Held vertices (--hold, a property or a file) and attributes are found by process 0 as the program finds them
// (held_vertices.h, attribute_columns.h: a split vertex's copies held as it is, uv and colours included), sent with
// the blocks as columns of values, and the faired attributes gathered back and written as the program writes them.

#ifndef AF_DISTRIBUTED_SCATTERED_MESH_H
#define AF_DISTRIBUTED_SCATTERED_MESH_H

#include "Mesh_part.h"
#include "Part_exchange.h"
#include "attribute_columns.h"
#include "held_vertices.h"
#include "mesh_io.h"
#include "written_normals_and_curvature.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace af_distributed {

/// The mesh process 0 read whole, and what reading it found (empty on the other processes).
struct Whole_mesh_file
{
  af_tool::Mesh mesh;
  af_tool::Input_info info;
  bool held = false;                                  // the first column of `values`: --hold's (every process's)
  std::vector<af_tool::Attribute_column> attributes;  // the others: the attributes faired
  std::vector<double> values;                         // per vertex, the columns
};

/// Process 0's reading of the mesh, its held vertices and its attributes, as anisotropic_fairing reads them
/// (fairing_run.cpp: read_mesh, plan_attributes, plan_held_vertices); `fair_attributes`: whether they are faired.
inline void read_whole_mesh(const af_tool::Options& o, bool fair_attributes, Whole_mesh_file& whole)
{
  af_tool::read_input(o.input, whole.mesh, whole.info, o.repair);
  af_tool::check_curvature_properties_free(o, whole.mesh);
  const std::size_t n = whole.mesh.number_of_vertices();
  std::vector<unsigned char> held(n, 0);
  whole.held = !o.hold.empty();
  if(whole.held) af_tool::read_held_vertices(whole.mesh, o.hold, held);
  for(std::size_t i = 0; i < whole.info.split.copy_of.size(); ++i)   // a split vertex's copies are held as it is
    held[whole.info.split.file_vertices + i] = held[whole.info.split.copy_of[i]];
  std::vector<std::vector<double>> attributes;
  if(fair_attributes)
  {
    whole.attributes = af_tool::resolve_attributes(whole.mesh, whole.info, o.input, o.attributes);
    af_tool::gather(whole.mesh, whole.attributes, attributes);
  }
  for(std::size_t v = 0; v < n; ++v)
  {
    if(whole.held) whole.values.push_back(held[v]);
    if(fair_attributes) whole.values.insert(whole.values.end(), attributes[v].begin(), attributes[v].end());
  }
}

/// Each process's blocks of the mesh process 0 holds in `whole` (collective).
inline Mesh_blocks scattered_blocks(MPI_Comm comm, const Whole_mesh_file& whole)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const af_tool::Mesh& m = whole.mesh;
  std::int64_t counts[2] = { std::int64_t(m.number_of_vertices()), std::int64_t(m.number_of_faces()) };
  MPI_Bcast(counts, 2, MPI_INT64_T, 0, comm);
  Mesh_blocks b;
  b.vertices = counts[0];
  b.faces = counts[1];
  if(3 * std::max(b.vertices, b.faces) > std::numeric_limits<int>::max())
    throw std::runtime_error("a mesh of more than 715 million vertices or faces is read by blocks: give a binary PLY "
                             "file as input and output");
  const std::size_t processes = static_cast<std::size_t>(size);
  std::vector<int> point_count(processes), point_at(processes), corner_count(processes), corner_at(processes);
  for(int p = 0; p < size; ++p)
  {
    const std::size_t q = std::size_t(p);
    point_at[q] = int(3 * block_first(b.vertices, p, size));
    point_count[q] = int(3 * block_first(b.vertices, p + 1, size)) - point_at[q];
    corner_at[q] = int(3 * block_first(b.faces, p, size));
    corner_count[q] = int(3 * block_first(b.faces, p + 1, size)) - corner_at[q];
  }
  std::vector<double> points;
  std::vector<std::int64_t> corners;
  if(rank == 0)
  {
    points.reserve(std::size_t(3 * b.vertices));
    for(af_tool::Vertex_index v : m.vertices())
      points.insert(points.end(), { m.point(v).x(), m.point(v).y(), m.point(v).z() });
    corners.reserve(std::size_t(3 * b.faces));
    for(af_tool::Face_index f : m.faces())
      for(af_tool::Vertex_index v : CGAL::vertices_around_face(m.halfedge(f), m)) corners.push_back(std::int64_t(v));
  }
  const std::size_t me = std::size_t(rank);
  b.points.resize(std::size_t(point_count[me]));
  MPI_Scatterv(points.data(), point_count.data(), point_at.data(), MPI_DOUBLE, b.points.data(), point_count[me],
               MPI_DOUBLE, 0, comm);
  std::vector<std::int64_t> mine(std::size_t(corner_count[me]));
  MPI_Scatterv(corners.data(), corner_count.data(), corner_at.data(), MPI_INT64_T, mine.data(), corner_count[me],
               MPI_INT64_T, 0, comm);
  for(std::size_t k = 0; k + 2 < mine.size(); k += 3) b.triangles.push_back({ mine[k], mine[k + 1], mine[k + 2] });
  return b;
}

/// Each process's block of process 0's `whole.values` (collective): `columns` per vertex, their count sent to all.
inline std::vector<double> scattered_values(MPI_Comm comm, const Whole_mesh_file& whole, std::int64_t vertices,
                                            std::size_t& columns)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  unsigned long counts[2] = { whole.held ? 1ul : 0ul, (unsigned long)whole.attributes.size() };
  MPI_Bcast(counts, 2, MPI_UNSIGNED_LONG, 0, comm);
  columns = std::size_t(counts[0] + counts[1]);
  std::vector<int> count(static_cast<std::size_t>(size)), at(static_cast<std::size_t>(size));
  for(int p = 0; p < size; ++p)
  {
    at[std::size_t(p)] = int(columns * std::size_t(block_first(vertices, p, size)));
    count[std::size_t(p)] = int(columns * std::size_t(block_first(vertices, p + 1, size))) - at[std::size_t(p)];
  }
  std::vector<double> mine(std::size_t(count[std::size_t(rank)]));
  MPI_Scatterv(whole.values.data(), count.data(), at.data(), MPI_DOUBLE, mine.data(), count[std::size_t(rank)],
               MPI_DOUBLE, 0, comm);
  return mine;
}

/// The faired positions and control points of every process's own vertices, into process 0's `whole` and
/// `control` (collective; the other processes' arguments are not read).
inline void gather_faired(MPI_Comm comm, const Mesh_part& part, const af_tool::Mesh& faired,
                          const std::vector<af_tool::Point>& part_control, Whole_mesh_file& whole,
                          std::vector<af_tool::Point>& control)
{
  struct Faired { std::int64_t vertex; double point[3], control[3]; };
  std::vector<std::vector<Faired>> out(static_cast<std::size_t>(part.size));
  for(std::size_t v = 0; v < part.owned_vertices; ++v)
  {
    const af_tool::Point& p = faired.point(af_tool::Vertex_index(static_cast<af_tool::Mesh::size_type>(v)));
    const af_tool::Point& c = part_control[v];
    out[0].push_back({ part.global_vertex[v], { p.x(), p.y(), p.z() }, { c.x(), c.y(), c.z() } });
  }
  const std::vector<Faired> all = af_distributed::exchange(comm, out);
  if(part.rank != 0) return;
  control.assign(whole.mesh.number_of_vertices(), af_tool::Point(0, 0, 0));
  for(const Faired& f : all)
  {
    whole.mesh.point(af_tool::Vertex_index(static_cast<af_tool::Mesh::size_type>(f.vertex))) =
      af_tool::Point(f.point[0], f.point[1], f.point[2]);
    control[std::size_t(f.vertex)] = af_tool::Point(f.control[0], f.control[1], f.control[2]);
  }
}

/// The faired attributes of every process's own vertices (`part_values`, per vertex of the part), into process 0's
/// `values` per vertex of the whole mesh (collective).
inline void gather_attributes(MPI_Comm comm, const Mesh_part& part, const std::vector<std::vector<double>>& part_values,
                              std::size_t vertices, std::vector<std::vector<double>>& values)
{
  const std::size_t width = part_values.empty() ? 0 : part_values[0].size();
  std::vector<std::vector<double>> out(static_cast<std::size_t>(part.size));
  for(std::size_t v = 0; v < part.owned_vertices && width > 0; ++v)
  {
    out[0].push_back(double(part.global_vertex[v]));
    out[0].insert(out[0].end(), part_values[v].begin(), part_values[v].end());
  }
  const std::vector<double> all = af_distributed::exchange(comm, out);
  if(part.rank != 0) return;
  values.assign(vertices, std::vector<double>(width));
  for(std::size_t at = 0; at + width + 1 <= all.size(); at += width + 1)
    std::copy(all.begin() + std::ptrdiff_t(at + 1), all.begin() + std::ptrdiff_t(at + 1 + width),
              values[std::size_t(all[at])].begin());
}

} // namespace af_distributed

#endif // AF_DISTRIBUTED_SCATTERED_MESH_H
