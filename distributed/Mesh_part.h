// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What one process holds of a mesh no process holds whole: its own faces, the faces within `depth` rings around
// them (the Loop patches of its faces are the first ring; the library's measures read further), their vertices
// with positions and owners, and the halo (which of its vertices' values others hold, which of theirs it holds).
// Made from the contiguous blocks of vertices and faces each process read (Mesh_blocks): the face dual graph is
// built block by block (each edge met at the process of its lower vertex's block) and divided by PETSc's
// partitioner (MatPartitioning), the faces move to their parts, and each part asks the holders of its vertices'
// blocks for the faces around them, one ring at a time (the outermost ring's faces dropped where a vertex's faces
// in the part would make two fans). A vertex belongs to the process of its face with the lowest number (a vertex
// on no face: to the process whose block holds it), the same rule on every process.

#ifndef AF_DISTRIBUTED_MESH_PART_H
#define AF_DISTRIBUTED_MESH_PART_H

#include "Face_partition.h"
#include "Part_exchange.h"

#include <petscmat.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace af_distributed {

/// One process's part of the mesh, in a local numbering: its own faces and vertices first.
struct Mesh_part
{
  int rank = 0, size = 1;
  std::size_t owned_faces = 0, owned_vertices = 0;
  std::vector<std::array<int, 3>> faces;     // by local vertex numbers
  std::vector<std::int64_t> global_face;     // per local face; increasing among the own, then ring by ring
  std::vector<int> face_ring;                // per local face: 0 its own, k > 0 the k-th ring around them
  std::vector<int> face_owner;               // per local face: the process whose own face it is
  std::vector<std::int64_t> global_vertex;   // per local vertex; increasing among the own and among the others
  std::vector<int> vertex_owner;             // per local vertex
  std::vector<double> points;                // 3 per local vertex
  // the halo, grouped by process: the own vertices whose values go to each, the others' that come from each
  std::vector<int> send_count, send_vertices, receive_count, receive_vertices;

  /// The least of every process's values of each vertex at its owner (`columns` per vertex; the other rows as
  /// they were): the halo run backwards.
  void minimum_at_owners(MPI_Comm comm, double* values, int columns) const
  {
    std::vector<double> out;
    out.reserve(receive_vertices.size() * std::size_t(columns));
    for(int v : receive_vertices) out.insert(out.end(), values + std::size_t(v) * columns, values + (v + 1) * columns);
    const std::vector<double> in = exchange_counted(comm, out, receive_count, send_count, columns);
    for(std::size_t k = 0; k < send_vertices.size(); ++k)
      for(int c = 0; c < columns; ++c)
      {
        double& x = values[std::size_t(send_vertices[k]) * columns + std::size_t(c)];
        x = std::min(x, in[k * std::size_t(columns) + std::size_t(c)]);
      }
  }

  /// The other processes' values of the vertices they own, into this process's rows (`columns` per vertex).
  void refresh(MPI_Comm comm, double* values, int columns) const
  {
    std::vector<double> out;
    out.reserve(send_vertices.size() * std::size_t(columns));
    for(int v : send_vertices) out.insert(out.end(), values + std::size_t(v) * columns, values + (v + 1) * columns);
    const std::vector<double> in = exchange_counted(comm, out, send_count, receive_count, columns);
    for(std::size_t k = 0; k < receive_vertices.size(); ++k)
      std::copy(in.begin() + std::ptrdiff_t(k * columns), in.begin() + std::ptrdiff_t((k + 1) * columns),
                values + std::size_t(receive_vertices[k]) * columns);
  }
};

namespace mesh_part_detail {

struct Edge_face { std::int64_t a, b, face; };
struct Face_pair { std::int64_t face, neighbour; };
struct Face_record { std::int64_t face; std::int64_t corner[3]; int owner; };
struct Incidence { std::int64_t vertex; Face_record face; };
struct Vertex_record { std::int64_t vertex; int owner; double point[3]; };

// The part of each face of this process's block (the face dual graph divided by PETSc's partitioner).
inline std::vector<int> partition_blocks(MPI_Comm comm, const Mesh_blocks& b, int size)
{
  if(size == 1) return std::vector<int>(b.triangles.size(), 0);
  const int rank = rank_of(comm);
  const std::int64_t first = block_first(b.faces, rank, size);
  std::vector<std::vector<Edge_face>> edges(static_cast<std::size_t>(size));
  for(std::size_t i = 0; i < b.triangles.size(); ++i)
    for(int k = 0; k < 3; ++k)
    {
      const std::int64_t p = b.triangles[i][std::size_t(k)], q = b.triangles[i][std::size_t((k + 1) % 3)];
      const std::int64_t lo = std::min(p, q), hi = std::max(p, q);
      edges[std::size_t(block_of(lo, b.vertices, size))].push_back({ lo, hi, first + std::int64_t(i) });
    }
  std::vector<Edge_face> met = af_distributed::exchange(comm, edges);
  std::sort(met.begin(), met.end(), [](const Edge_face& x, const Edge_face& y) {
    return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.face < y.face;
  });
  std::vector<std::vector<Face_pair>> pairs(static_cast<std::size_t>(size));
  for(std::size_t s = 0, e; s < met.size(); s = e)
  {
    for(e = s + 1; e < met.size() && met[e].a == met[s].a && met[e].b == met[s].b; ++e) {}
    for(std::size_t x = s; x < e; ++x)
      for(std::size_t y = s; y < e; ++y)
        if(met[x].face != met[y].face)
          pairs[std::size_t(block_of(met[x].face, b.faces, size))].push_back({ met[x].face, met[y].face });
  }
  std::vector<Face_pair> mine = af_distributed::exchange(comm, pairs);
  std::sort(mine.begin(), mine.end(), [](const Face_pair& x, const Face_pair& y) {
    return x.face != y.face ? x.face < y.face : x.neighbour < y.neighbour;
  });
  mine.erase(std::unique(mine.begin(), mine.end(), [](const Face_pair& x, const Face_pair& y) {
    return x.face == y.face && x.neighbour == y.neighbour; }), mine.end());
  const PetscInt rows = PetscInt(b.triangles.size());
  PetscInt *ia = nullptr, *ja = nullptr;   // MatCreateMPIAdj takes them: PETSc's allocator
  petsc_check(PetscMalloc1(rows + 1, &ia), "PetscMalloc1");
  petsc_check(PetscMalloc1(mine.size() + 1, &ja), "PetscMalloc1");
  std::size_t at = 0;
  for(PetscInt r = 0; r < rows; ++r)
  {
    ia[r] = PetscInt(at);
    for(; at < mine.size() && mine[at].face == first + r; ++at) ja[at] = PetscInt(mine[at].neighbour);
  }
  ia[rows] = PetscInt(at);
  return apply_partitioner(comm, rows, PetscInt(b.faces), ia, ja);
}

// The face records of `vertices` (global numbers, at most once each) from the holders of their blocks, which hold
// the faces around each vertex of their block (`around`, sorted by vertex).
inline std::vector<Incidence> faces_around(MPI_Comm comm, const std::vector<std::int64_t>& vertices,
                                           const std::vector<Incidence>& around, std::int64_t n, int size)
{
  std::vector<std::vector<std::int64_t>> asked(static_cast<std::size_t>(size));
  for(std::int64_t v : vertices) asked[std::size_t(block_of(v, n, size))].push_back(v);
  std::vector<int> from;
  const std::vector<std::int64_t> questions = af_distributed::exchange(comm, asked, &from);
  std::vector<std::vector<Incidence>> answers(static_cast<std::size_t>(size));
  for(std::size_t k = 0; k < questions.size(); ++k)
  {
    auto it = std::lower_bound(around.begin(), around.end(), questions[k],
                               [](const Incidence& x, std::int64_t v) { return x.vertex < v; });
    for(; it != around.end() && it->vertex == questions[k]; ++it) answers[std::size_t(from[k])].push_back(*it);
  }
  return af_distributed::exchange(comm, answers);
}

// The halo of `part`: each vertex it holds but does not own comes from its owner (whose part holds it: a corner of
// its own face), which learns which of its vertices to send, and in which order.
inline void make_halo(MPI_Comm comm, Mesh_part& part, const std::unordered_map<std::int64_t, int>& local)
{
  const std::size_t size = std::size_t(part.size);
  std::vector<std::vector<std::int64_t>> wanted(size);
  for(std::size_t v = part.owned_vertices; v < part.global_vertex.size(); ++v)
    wanted[std::size_t(part.vertex_owner[v])].push_back(part.global_vertex[v]);
  part.receive_count.assign(size, 0);
  part.receive_vertices.clear();
  for(std::size_t p = 0; p < size; ++p)
  {
    part.receive_count[p] = int(wanted[p].size());
    for(std::int64_t g : wanted[p]) part.receive_vertices.push_back(local.at(g));
  }
  std::vector<int> from;
  const std::vector<std::int64_t> asked = af_distributed::exchange(comm, wanted, &from);
  part.send_count.assign(size, 0);
  part.send_vertices.clear();
  for(std::size_t k = 0; k < asked.size(); ++k)
  {
    part.send_vertices.push_back(local.at(asked[k]));
    ++part.send_count[std::size_t(from[k])];
  }
}

} // namespace mesh_part_detail

namespace mesh_part_detail {

// This process's faces, increasing, once the partitioner has divided them.
inline std::vector<Face_record> own_faces(MPI_Comm comm, const Mesh_blocks& b, int rank, int size)
{
  const std::int64_t first = block_first(b.faces, rank, size);
  const std::vector<int> owner = partition_blocks(comm, b, size);
  std::vector<std::vector<Face_record>> moving(static_cast<std::size_t>(size));
  for(std::size_t i = 0; i < b.triangles.size(); ++i)
    moving[std::size_t(owner[i])].push_back(
      { first + std::int64_t(i), { b.triangles[i][0], b.triangles[i][1], b.triangles[i][2] }, owner[i] });
  std::vector<Face_record> own = af_distributed::exchange(comm, moving);
  std::sort(own.begin(), own.end(), [](const Face_record& x, const Face_record& y) { return x.face < y.face; });
  return own;
}

// The faces around each vertex of this process's block (told by their owners), sorted by vertex and face.
inline std::vector<Incidence> faces_by_vertex(MPI_Comm comm, const std::vector<Face_record>& own, std::int64_t n,
                                              int size)
{
  std::vector<std::vector<Incidence>> told(static_cast<std::size_t>(size));
  for(const Face_record& f : own)
    for(std::int64_t v : f.corner) told[std::size_t(block_of(v, n, size))].push_back({ v, f });
  std::vector<Incidence> around = af_distributed::exchange(comm, told);
  std::sort(around.begin(), around.end(), [](const Incidence& x, const Incidence& y) {
    return x.vertex != y.vertex ? x.vertex < y.vertex : x.face.face < y.face.face;
  });
  return around;
}

// The own faces, then `depth` rings of faces around them (`ring`: each face's).
inline void grow_rings(MPI_Comm comm, const std::vector<Incidence>& around, std::int64_t n, int size, int depth,
                       std::vector<Face_record>& faces, std::vector<int>& ring)
{
  std::unordered_set<std::int64_t> has_face, has_vertex;
  std::vector<std::int64_t> frontier;
  ring.assign(faces.size(), 0);
  for(const Face_record& f : faces)
  {
    has_face.insert(f.face);
    for(std::int64_t v : f.corner)
      if(has_vertex.insert(v).second) frontier.push_back(v);
  }
  for(int r = 1; r <= depth; ++r)
  {
    std::vector<Incidence> met = faces_around(comm, frontier, around, n, size);
    std::sort(met.begin(), met.end(), [](const Incidence& x, const Incidence& y) { return x.face.face < y.face.face; });
    frontier.clear();
    for(const Incidence& m : met)
    {
      if(!has_face.insert(m.face.face).second) continue;
      faces.push_back(m.face);
      ring.push_back(r);
      for(std::int64_t v : m.face.corner)
        if(has_vertex.insert(v).second) frontier.push_back(v);
    }
  }
}

// The positions and owners of `vertices`, from the holders of their blocks (a vertex on no face: its holder's).
inline std::vector<Vertex_record> vertex_records(MPI_Comm comm, const Mesh_blocks& b,
                                                 const std::vector<Incidence>& around,
                                                 const std::vector<std::int64_t>& vertices, int rank, int size)
{
  const std::int64_t n = b.vertices, first = block_first(n, rank, size);
  std::vector<std::vector<std::int64_t>> asked(static_cast<std::size_t>(size));
  for(std::int64_t v : vertices) asked[std::size_t(block_of(v, n, size))].push_back(v);
  std::vector<int> from;
  const std::vector<std::int64_t> questions = af_distributed::exchange(comm, asked, &from);
  std::vector<std::vector<Vertex_record>> answers(static_cast<std::size_t>(size));
  for(std::size_t k = 0; k < questions.size(); ++k)
  {
    const std::int64_t v = questions[k];
    auto it = std::lower_bound(around.begin(), around.end(), v,
                               [](const Incidence& x, std::int64_t w) { return x.vertex < w; });
    Vertex_record r{ v, it != around.end() && it->vertex == v ? it->face.owner : rank, { 0, 0, 0 } };
    for(int c = 0; c < 3; ++c) r.point[c] = b.points[std::size_t(3 * (v - first) + c)];
    answers[std::size_t(from[k])].push_back(r);
  }
  return af_distributed::exchange(comm, answers);
}

// The outermost ring's faces around a vertex whose faces in the part make more than one fan (a vertex at the edge
// of the part, where the faces beyond are missing): dropped, until every vertex's faces make one fan, so that the
// part is a surface with a border (the library refuses a vertex of two fans). Its own faces and the rings the
// library reads around them are not touched: only a vertex of the outermost ring has faces missing.
inline void trim_split_fans(std::vector<Face_record>& faces, std::vector<int>& ring, int depth)
{
  for(bool again = true; again;)
  {
    again = false;
    std::unordered_map<std::int64_t, std::vector<std::size_t>> around;
    for(std::size_t f = 0; f < faces.size(); ++f)
      for(std::int64_t v : faces[f].corner) around[v].push_back(f);
    std::vector<char> drop(faces.size(), 0);
    for(const auto& a : around)
    {
      // the fans: faces around the vertex joined by an edge from it (a shared second corner)
      const std::vector<std::size_t>& f = a.second;
      std::vector<std::size_t> fan(f.size());
      for(std::size_t k = 0; k < f.size(); ++k) fan[k] = k;
      const auto root = [&](std::size_t k) { while(fan[k] != k) k = fan[k] = fan[fan[k]]; return k; };
      for(std::size_t x = 0; x < f.size(); ++x)
        for(std::size_t y = x + 1; y < f.size(); ++y)
          for(std::int64_t p : faces[f[x]].corner)
            for(std::int64_t q : faces[f[y]].corner)
              if(p == q && p != a.first) fan[root(x)] = root(y);
      std::size_t fans = 0;
      for(std::size_t k = 0; k < f.size(); ++k) fans += root(k) == k ? 1 : 0;
      if(fans > 1)
        for(std::size_t k : f)
          if(ring[k] == depth) drop[k] = again = true;
    }
    std::size_t kept = 0;
    for(std::size_t f = 0; f < faces.size(); ++f)
      if(!drop[f])
      {
        faces[kept] = faces[f];
        ring[kept++] = ring[f];
      }
    faces.resize(kept);
    ring.resize(kept);
  }
}

} // namespace mesh_part_detail

/// This process's part of the mesh read in `blocks`, with `depth` >= 1 rings of faces around its own (the
/// outermost ring where its faces make a surface: trim_split_fans).
inline Mesh_part make_mesh_part(MPI_Comm comm, const Mesh_blocks& blocks, int depth)
{
  namespace d = mesh_part_detail;
  Mesh_part part;
  MPI_Comm_rank(comm, &part.rank);
  MPI_Comm_size(comm, &part.size);
  const int rank = part.rank, size = part.size;
  const std::int64_t n = blocks.vertices;
  std::vector<d::Face_record> faces = d::own_faces(comm, blocks, rank, size);
  part.owned_faces = faces.size();
  const std::vector<d::Incidence> around = d::faces_by_vertex(comm, faces, n, size);
  d::grow_rings(comm, around, n, size, depth, faces, part.face_ring);
  d::trim_split_fans(faces, part.face_ring, depth);
  std::unordered_set<std::int64_t> kept;   // the vertices of the faces left
  for(const d::Face_record& f : faces) kept.insert(f.corner, f.corner + 3);
  std::vector<std::int64_t> vertices(kept.begin(), kept.end());
  // the vertices of this process's block on no face
  std::size_t a = 0;
  for(std::int64_t v = block_first(n, rank, size); v < block_first(n, rank + 1, size); ++v)
  {
    for(; a < around.size() && around[a].vertex < v; ++a) {}
    if(a == around.size() || around[a].vertex != v) vertices.push_back(v);
  }
  std::vector<d::Vertex_record> records = d::vertex_records(comm, blocks, around, vertices, rank, size);
  std::sort(records.begin(), records.end(), [&](const d::Vertex_record& x, const d::Vertex_record& y) {
    const bool xo = x.owner == rank, yo = y.owner == rank;
    return xo != yo ? xo : x.vertex < y.vertex;
  });
  std::unordered_map<std::int64_t, int> local;
  for(const d::Vertex_record& r : records)
  {
    local.emplace(r.vertex, int(part.global_vertex.size()));
    part.global_vertex.push_back(r.vertex);
    part.vertex_owner.push_back(r.owner);
    part.points.insert(part.points.end(), r.point, r.point + 3);
    part.owned_vertices += r.owner == rank ? 1 : 0;
  }
  for(const d::Face_record& f : faces)
  {
    part.global_face.push_back(f.face);
    part.face_owner.push_back(f.owner);
    part.faces.push_back({ local.at(f.corner[0]), local.at(f.corner[1]), local.at(f.corner[2]) });
  }
  d::make_halo(comm, part, local);
  return part;
}

} // namespace af_distributed

#endif // AF_DISTRIBUTED_MESH_PART_H
