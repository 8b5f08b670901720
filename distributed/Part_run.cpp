// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A run in which no process holds the whole mesh: each reads its blocks of a binary PLY file (Ply_blocks.h),
// makes its part (its own faces and rings of faces around them: Mesh_part.h) and gives the library the part
// (anisotropic_fairing() on it, with the part's Process_part: Part_process.h), whose measures of the whole mesh
// are made over the processes and whose flow steps on them (Distributed_cache.h with the part's layout). Each
// process then writes its block of vertex records at their places in the output, every vertex property as
// read, the faces as they were. What a part cannot run yet (part_refusal) is run with the whole mesh on every
// process (Distributed_run.cpp).

#include "Part_run.h"

#include "Distributed_flow.h"
#include "Mesh_part.h"
#include "Part_process.h"
#include "Ply_blocks.h"
#include "Run_support.h"
#include "mesh_io.h"

#include <CGAL/Anisotropic_fairing/internal/run/Caller_maps.h>
#include <CGAL/Anisotropic_fairing/internal/run/Fairing_driver.h>
#include <CGAL/Anisotropic_fairing/named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <filesystem>
#include <limits>

namespace af_distributed {

namespace {

namespace AFI = CGAL::Anisotropic_fairing::internal;

bool ends_with(const std::string& s, const std::string& end)
{
  std::string lower = s;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return lower.size() >= end.size() && lower.compare(lower.size() - end.size(), end.size(), end) == 0;
}

// The part as the library's mesh, its vertices and faces in the part's order; false where the part is not a
// surface (a vertex of two fans, an edge of three faces: the input is not a manifold there).
bool part_mesh(const Mesh_part& part, af_tool::Mesh& mesh)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<af_tool::Point> points;
  for(std::size_t v = 0; v < part.global_vertex.size(); ++v)
    points.emplace_back(part.points[3 * v], part.points[3 * v + 1], part.points[3 * v + 2]);
  std::vector<std::array<std::size_t, 3>> triangles;
  for(const auto& f : part.faces) triangles.push_back({ std::size_t(f[0]), std::size_t(f[1]), std::size_t(f[2]) });
  if(!PMP::is_polygon_soup_a_polygon_mesh(triangles)) return false;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  return mesh.number_of_vertices() == points.size() && mesh.number_of_faces() == triangles.size();
}

// An input error the library found in the part, its element named by its number in the whole mesh (the file's)
AF::Input_error in_the_whole_mesh(const AF::Input_error& e, const Mesh_part& part)
{
  typedef AF::Input_error E;
  const std::size_t local = e.element();
  if(local == E::no_element) return e;
  const bool face = e.kind() == E::NON_TRIANGLE_FACE || e.kind() == E::DEGENERATE_FACE;
  const std::vector<std::int64_t>& global = face ? part.global_face : part.global_vertex;
  if(local >= global.size()) return e;
  const std::string word = face ? "face " : "vertex ", was = word + std::to_string(local);
  std::string message = without_library_prefix(e.what());
  const std::size_t at = message.find(was);
  if(at != std::string::npos) message.replace(at, was.size(), word + std::to_string(global[local]));
  return E(e.kind(), std::size_t(global[local]), message);
}

AF::Fairing_report fair_part(const af_tool::Options& o, af_tool::Mesh& mesh, const Mesh_part& part,
                             const Part_process& process, Distributed_state& state, bool print)
{
  AF::Fairing_options options = o.fairing;
  options.attribute_mode = AF::Attribute_mode::GEOMETRY_ONLY;
  options.memory_limit = std::numeric_limits<double>::infinity();
  const auto np = AF::parameters::fairing_options(options).callback(step_lines(o, print));
  const AFI::No_attributes none;
  const auto hooks = AFI::caller_hooks<af_tool::Mesh>(none, np);
  const Distributed_elements elements{ &state, &process };
  try
  {
    return AFI::fair_with_options(mesh, mesh.points(), none, AFI::read_fairing_options(np), hooks,
                                  options.diffusion_tensor_or_default(), elements);
  }
  catch(const AF::Input_error& e) { throw in_the_whole_mesh(e, part); }
}

// the own vertices' new positions to the holders of their blocks, then each process's block written in place in
// `path`
void write_blocks(const af_tool::Options& o, const std::string& path, MPI_Comm comm, const Ply_blocks& blocks,
                  const Mesh_part& part, const af_tool::Mesh& mesh)
{
  struct Moved { std::int64_t vertex; double point[3]; };
  const int size = part.size;
  std::vector<std::vector<Moved>> out(static_cast<std::size_t>(size));
  for(std::size_t v = 0; v < part.owned_vertices; ++v)
  {
    const af_tool::Point& p = mesh.point(af_tool::Mesh::Vertex_index(af_tool::Mesh::size_type(v)));
    const std::int64_t g = part.global_vertex[v];
    out[std::size_t(block_of(g, blocks.mesh.vertices, size))].push_back({ g, { p.x(), p.y(), p.z() } });
  }
  const std::int64_t first = block_first(blocks.mesh.vertices, part.rank, size);
  std::vector<double> points = blocks.mesh.points;
  for(const Moved& m : af_distributed::exchange(comm, out))
    std::copy(m.point, m.point + 3, points.begin() + std::ptrdiff_t(3 * (m.vertex - first)));
  std::vector<std::int64_t> mine(points.size() / 3);
  for(std::size_t k = 0; k < mine.size(); ++k) mine[k] = first + std::int64_t(k);
  agree_on(comm, [&] { if(part.rank == 0) create_ply_output(o.input, path, blocks.header); }, "write_error");
  write_ply_blocks(o.input, path, blocks.header, part.rank, size, mine, points, blocks.values);
}

// written through a temporary file next to the output, which replaces the output once every process wrote
void write_result(const af_tool::Options& o, MPI_Comm comm, const Ply_blocks& blocks, const Mesh_part& part,
                  const af_tool::Mesh& mesh)
{
  std::string tmp = part.rank == 0 ? af_tool::temporary_next_to(o.output).string() : std::string();
  unsigned long length = tmp.size();
  MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG, 0, comm);
  tmp.resize(length);
  MPI_Bcast(&tmp[0], int(length), MPI_CHAR, 0, comm);
  try
  {
    collectively(comm, o.input, [&] { write_blocks(o, tmp, comm, blocks, part, mesh); });
  }
  catch(...)
  {
    std::error_code ec;
    if(part.rank == 0) std::filesystem::remove(tmp, ec);
    throw;
  }
  agree_on(comm, [&] {
    if(part.rank != 0) return;
    std::error_code ec;
    std::filesystem::rename(tmp, o.output, ec);
    if(ec)
    {
      std::filesystem::remove(tmp, ec);
      throw std::runtime_error("cannot write " + o.output + ": " + ec.message());
    }
  }, "write_error");
}

} // namespace

std::string part_refusal(const af_tool::Options& o)
{
  if(!ends_with(o.input, ".ply") || !ends_with(o.output, ".ply")) return "the input and the output are not PLY files";
  Ply_header h;
  try { h = read_ply_header(o.input); }
  catch(const std::exception&) { return "the input's header is read with the whole mesh"; }
  if(!h.refusal.empty()) return h.refusal;
  const Ply_element& vertex = h.elements[std::size_t(h.vertex)];
  for(const Ply_property& p : vertex.properties)
    if(p.name == "nx" || p.name == "ny" || p.name == "nz") return "the input has vertex normals";
  const AF::Fairing_options& f = o.fairing;
  if(o.fairing.attribute_mode && *o.fairing.attribute_mode != AF::Attribute_mode::GEOMETRY_ONLY)
    return "attributes are faired";
  if(f.relative_maximum_deviation || f.absolute_maximum_deviation || f.attribute_maximum_deviation > 0)
    return "a deviation bound is given";
  if(!o.hold.empty() || o.curvature || o.repair) return "--hold, --curvature or --repair is given";
  if(f.finite_element != AF::Finite_element::LOOP) return "the linear element is asked for";
  return std::string();
}

bool run_on_parts(const af_tool::Options& o, MPI_Comm comm, Run_summary& summary)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  summary.processes = size;
  summary.mesh_held = "parts";
  CGAL::Real_timer clock;
  clock.start();
  Ply_blocks blocks;
  Mesh_part part;
  collectively(comm, o.input, [&] {
    blocks = read_ply_blocks(o.input, rank, size);
    part = make_mesh_part(comm, blocks.mesh, part_depth);
  });
  summary.read_seconds = clock.time();
  summary.vertices = std::size_t(blocks.mesh.vertices);
  summary.faces = std::size_t(blocks.mesh.faces);
  af_tool::Mesh mesh;
  int surface = 0, everywhere = 0;
  collectively(comm, o.input, [&] { surface = part_mesh(part, mesh) ? 1 : 0; });
  MPI_Allreduce(&surface, &everywhere, 1, MPI_INT, MPI_MIN, comm);
  if(!everywhere)
  {
    summary = Run_summary();
    summary.whole_mesh_why = "the mesh is not a manifold surface everywhere (a vertex of two fans or an edge of three "
                             "faces): it is read whole, and split there, as anisotropic_fairing reads it";
    return false;
  }
  clock.reset();
  Distributed_state state;
  state.comm = comm;
  state.rank = rank;
  state.size = size;
  const Part_process process(comm, part);
  const bool print = rank == 0 && !o.quiet;
  collectively(comm, o.input, [&] { summary.report = fair_part(o, mesh, part, process, state, print); });
  const double call_seconds = clock.time();
  after_the_call(comm, o, call_seconds, state, summary);
  summary.part_vertices = gathered<std::size_t>(comm, part.global_vertex.size(), MPI_UNSIGNED_LONG);
  clock.reset();
  summary.peak_memory_mb = gathered<double>(comm, peak_memory_mb(), MPI_DOUBLE);
  write_result(o, comm, blocks, part, mesh);
  summary.write_seconds = clock.time();
  return true;
}

} // namespace af_distributed
