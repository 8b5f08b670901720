// A process's part of a mesh no process holds whole (distributed/Mesh_part.h), made from the blocks each process
// would read of the file, against the whole mesh every process of this test reads as its truth:
// - every face is one process's own and every vertex one process's, the vertex's the process of its face with the
//   lowest number (a vertex on no face: the process whose block holds it);
// - the faces a part holds besides its own are those within `depth` rings, each in its ring, with the corners, in
//   their order, and the positions of the whole mesh: all of them but faces of the outermost ring, and each
//   vertex's faces make one fan (the part is a surface: trim_split_fans);
// - the halo brings every vertex a part holds but does not own its owner's value;
// - the parts are balanced (at most 25% above an even share of the faces).
// Run under mpiexec on 1, 2 and 3 processes (distributed_test.py, case mesh_part), on a closed mesh, a mesh with a
// border and a mesh with a vertex on no face.

#include "Mesh_part.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

#include <petscsys.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double>::Point_3 Point;

namespace {

int failures = 0;

int rank_of_world() { return af_distributed::rank_of(MPI_COMM_WORLD); }

void check(MPI_Comm comm, bool ok, const std::string& what)
{
  int mine = ok ? 1 : 0, all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MIN, comm);
  if(rank_of_world() == 0) std::printf("%s: %s\n", all ? "passed" : "FAILED", what.c_str());
  failures += all ? 0 : 1;
}

// whether the faces around each vertex of the part make one fan (joined by the edges from the vertex)
bool one_fan_each(const af_distributed::Mesh_part& part)
{
  std::vector<std::vector<std::size_t>> around(part.global_vertex.size());
  for(std::size_t f = 0; f < part.faces.size(); ++f)
    for(int v : part.faces[f]) around[std::size_t(v)].push_back(f);
  for(std::size_t v = 0; v < around.size(); ++v)
  {
    std::vector<char> reached(around[v].size(), 0);
    std::vector<std::size_t> stack{ 0 };
    if(around[v].empty()) continue;
    reached[0] = 1;
    while(!stack.empty())
    {
      const std::size_t x = stack.back();
      stack.pop_back();
      for(std::size_t y = 0; y < around[v].size(); ++y)
        for(int p : part.faces[around[v][x]])
          for(int q : part.faces[around[v][y]])
            if(!reached[y] && p == q && std::size_t(p) != v)
            {
              reached[y] = 1;
              stack.push_back(y);
            }
    }
    for(char r : reached)
      if(!r) return false;
  }
  return true;
}

void part_of(const std::string& name, const std::vector<Point>& points,
             const std::vector<std::vector<std::size_t>>& polygons, int depth)
{
  MPI_Comm comm = MPI_COMM_WORLD;
  const int rank = af_distributed::rank_of(comm);
  int size = 1;
  MPI_Comm_size(comm, &size);
  const std::int64_t n = std::int64_t(points.size()), m = std::int64_t(polygons.size());
  af_distributed::Mesh_blocks blocks;
  blocks.vertices = n;
  blocks.faces = m;
  for(std::int64_t v = af_distributed::block_first(n, rank, size); v < af_distributed::block_first(n, rank + 1, size); ++v)
    for(int c = 0; c < 3; ++c) blocks.points.push_back(points[std::size_t(v)][c]);
  for(std::int64_t f = af_distributed::block_first(m, rank, size); f < af_distributed::block_first(m, rank + 1, size); ++f)
  {
    const auto& p = polygons[std::size_t(f)];
    blocks.triangles.push_back({ std::int64_t(p[0]), std::int64_t(p[1]), std::int64_t(p[2]) });
  }
  const af_distributed::Mesh_part part = af_distributed::make_mesh_part(comm, blocks, depth);
  const std::string on = name + " on " + std::to_string(size) + " processes: ";

  // each face and vertex owned once; the owner rule
  std::vector<int> face_owner(std::size_t(m), -1), vertex_count(std::size_t(n), 0);
  std::vector<int> all_owner(static_cast<std::size_t>(m));
  for(std::size_t f = 0; f < part.owned_faces; ++f) face_owner[std::size_t(part.global_face[f])] = rank;
  for(std::size_t v = 0; v < part.owned_vertices; ++v) vertex_count[std::size_t(part.global_vertex[v])] += 1;
  MPI_Allreduce(face_owner.data(), all_owner.data(), int(m), MPI_INT, MPI_MAX, comm);
  MPI_Allreduce(MPI_IN_PLACE, vertex_count.data(), int(n), MPI_INT, MPI_SUM, comm);
  int owned_faces_total = int(part.owned_faces);
  MPI_Allreduce(MPI_IN_PLACE, &owned_faces_total, 1, MPI_INT, MPI_SUM, comm);
  bool once = owned_faces_total == int(m);
  for(int c : vertex_count) once = once && c == 1;
  check(comm, once, on + "every face and every vertex is one process's own");
  std::vector<std::int64_t> lowest_face(std::size_t(n), m);
  for(std::int64_t f = m - 1; f >= 0; --f)
    for(std::size_t v : polygons[std::size_t(f)]) lowest_face[v] = f;
  bool rule = true;
  for(std::size_t v = 0; v < part.global_vertex.size(); ++v)
  {
    const std::int64_t g = part.global_vertex[v], f = lowest_face[std::size_t(g)];
    const int expected = f < m ? all_owner[std::size_t(f)] : af_distributed::block_of(g, n, size);
    rule = rule && part.vertex_owner[v] == expected && (v < part.owned_vertices) == (expected == rank);
  }
  check(comm, rule, on + "a vertex is the process's of its lowest face (on no face: its block's)");

  // the rings, the corners and the positions
  std::vector<std::vector<std::int64_t>> around(static_cast<std::size_t>(n));
  for(std::int64_t f = 0; f < m; ++f)
    for(std::size_t v : polygons[std::size_t(f)]) around[v].push_back(f);
  std::vector<int> ring(std::size_t(m), -1);
  std::set<std::int64_t> frontier;
  for(std::size_t f = 0; f < part.owned_faces; ++f)
  {
    ring[std::size_t(part.global_face[f])] = 0;
    for(std::size_t v : polygons[std::size_t(part.global_face[f])]) frontier.insert(std::int64_t(v));
  }
  std::set<std::int64_t> seen = frontier;
  for(int r = 1; r <= depth; ++r)
  {
    std::set<std::int64_t> next;
    for(std::int64_t v : frontier)
      for(std::int64_t f : around[std::size_t(v)])
        if(ring[std::size_t(f)] < 0)
        {
          ring[std::size_t(f)] = r;
          for(std::size_t w : polygons[std::size_t(f)])
            if(seen.insert(std::int64_t(w)).second) next.insert(std::int64_t(w));
        }
    frontier = next;
  }
  std::size_t inner_faces = 0, held_inner = 0;   // within depth - 1 rings: all held
  for(int r : ring) inner_faces += r >= 0 && r < depth ? 1 : 0;
  bool rings = true, corners = true, positions = true;
  for(std::size_t f = 0; f < part.global_face.size(); ++f)
  {
    const std::size_t g = std::size_t(part.global_face[f]);
    rings = rings && ring[g] >= 0 && ring[g] == part.face_ring[f] && (f < part.owned_faces) == (ring[g] == 0) &&
            part.face_owner[f] == all_owner[g];
    held_inner += ring[g] < depth ? 1 : 0;
    for(int k = 0; k < 3; ++k)
      corners = corners && part.global_vertex[std::size_t(part.faces[f][std::size_t(k)])] ==
                             std::int64_t(polygons[g][std::size_t(k)]);
  }
  for(std::size_t v = 0; v < part.global_vertex.size(); ++v)
    for(int c = 0; c < 3; ++c)
      positions = positions && part.points[3 * v + std::size_t(c)] == points[std::size_t(part.global_vertex[v])][c];
  check(comm, rings && held_inner == inner_faces, on + "the part holds the faces within " + std::to_string(depth) +
                                                   " rings (all but the outermost's), each in its ring, with its owner");
  check(comm, one_fan_each(part), on + "each vertex's faces in the part make one fan");
  check(comm, corners && positions, on + "with the whole mesh's corners, in their order, and positions");

  // the halo
  std::vector<double> values(2 * part.global_vertex.size(), std::nan(""));
  for(std::size_t v = 0; v < part.owned_vertices; ++v)
  {
    values[2 * v] = double(part.global_vertex[v]);
    values[2 * v + 1] = std::sin(double(part.global_vertex[v]));
  }
  part.refresh(comm, values.data(), 2);
  bool halo = true;
  for(std::size_t v = 0; v < part.global_vertex.size(); ++v)
    halo = halo && values[2 * v] == double(part.global_vertex[v]) &&
           values[2 * v + 1] == std::sin(double(part.global_vertex[v]));
  check(comm, halo, on + "the halo brings each vertex held its owner's value");

  int largest = int(part.owned_faces);
  MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_INT, MPI_MAX, comm);
  if(rank == 0) std::printf("%s%lld faces, the largest part %d\n", on.c_str(), (long long)m, largest);
  check(comm, largest <= 1.25 * double(m) / size + 1, on + "the parts are balanced");
}

} // namespace

int main(int argc, char** argv)
{
  PetscInitialize(&argc, &argv, nullptr, nullptr);
  const std::string data = argc > 1 ? argv[1] : "data";
  for(const char* file : { "bumpy.off", "hemisphere.off" })
  {
    std::vector<Point> points;
    std::vector<std::vector<std::size_t>> polygons;
    if(!CGAL::IO::read_polygon_soup(data + "/" + file, points, polygons))
    {
      std::printf("cannot read %s/%s\n", data.c_str(), file);
      ++failures;
      continue;
    }
    part_of(file, points, polygons, 2);
    part_of(std::string(file) + " (depth 1)", points, polygons, 1);
    if(std::string(file) == "bumpy.off")
    {
      const std::size_t at = points.size() / 2;
      points.insert(points.begin() + std::ptrdiff_t(at), Point(9, 9, 9));   // a vertex on no face
      for(auto& p : polygons)
        for(std::size_t& v : p) v += v >= at ? 1 : 0;
      part_of("bumpy.off with a vertex on no face", points, polygons, 2);
    }
  }
  PetscFinalize();
  return failures == 0 ? 0 : 1;
}
