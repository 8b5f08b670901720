// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A run in which no process holds the whole mesh: each reads its blocks of a binary PLY file (Ply_blocks.h),
// makes its part (its own faces and rings of faces around them: Mesh_part.h) and gives the library the part
// (anisotropic_fairing() on it, with the part's Process_part: Part_process.h), whose measures of the whole mesh
// are made over the processes and whose flow steps on them (Distributed_cache.h with the part's layout). Each
// process then writes its block of vertex records at their places in the output, every vertex property as
// read but the normals (nx, ny, nz: the faired surface's, as the serial program writes them), the faces as they
// were (with --curvature's k1, k2, mean_curvature added: Ply_block_output.h), faired attributes in their types. Any
// other file is read whole by process 0 and scattered (Scattered_mesh.h). What parts cannot run (run_on_parts()
// false) runs with the whole mesh on every process (Distributed_run.cpp).

#include "Part_run.h"

#include "Distributed_flow.h"
#include "Mesh_part.h"
#include "Part_attributes.h"
#include "Part_process.h"
#include "Part_values.h"
#include "Ply_block_output.h"
#include "Ply_blocks.h"
#include "Run_support.h"
#include "Scattered_mesh.h"
#include "attribute_columns.h"
#include "held_vertices.h"
#include "mesh_io.h"
#include "written_normals_and_curvature.h"

#include <CGAL/Anisotropic_fairing/internal/run/Caller_maps.h>
#include <CGAL/Anisotropic_fairing/internal/run/Fairing_driver.h>
#include <CGAL/Anisotropic_fairing/named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <unordered_map>

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

bool fair_attributes(const af_tool::Options& o)
{
  return !o.attributes.empty() && af_tool::effective_mode(o) != AF::Attribute_mode::GEOMETRY_ONLY;
}
bool fairs_geometry(const af_tool::Options& o)
{
  return !fair_attributes(o) || af_tool::effective_mode(o) != AF::Attribute_mode::ATTRIBUTES_ONLY;
}

// Each process's blocks of the file (read by blocks, or read whole by process 0 and scattered with the held vertices
// and the attributes it found: blocks.names, the hold column named as --hold's property), and its part made of them.
void read_parts(const af_tool::Options& o, MPI_Comm comm, bool blocks_read, Ply_blocks& blocks, Mesh_part& part,
                Whole_mesh_file& whole)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  if(!blocks_read) collectively(comm, o.input, [&] { if(rank == 0) read_whole_mesh(o, fair_attributes(o), whole); });
  collectively(comm, o.input, [&] {
    if(blocks_read) blocks = read_ply_blocks(o.input, rank, size);
    else
    {
      blocks.mesh = scattered_blocks(comm, whole);
      std::size_t columns = 0;
      blocks.values = scattered_values(comm, whole, blocks.mesh.vertices, columns);
      if(!o.hold.empty()) blocks.names.push_back(o.hold);
      while(blocks.names.size() < columns) blocks.names.push_back("attribute " + std::to_string(blocks.names.size()));
    }
    for(const std::string& name : blocks.names)   // as check_curvature_properties_free says it
      if(blocks_read && o.curvature && (name == "k1" || name == "k2" || name == "mean_curvature"))
        af_tool::fail("input_error", "--curvature: " + o.input + " already has a vertex property '" + name +
                                       "', which it would overwrite");
    part = make_mesh_part(comm, blocks.mesh, part_depth);
  });
}

// --hold on the part's vertices, as the serial program reads it (held_vertices.cpp): a vertex property of the file
// (held where it is not 0) or a file of vertex indices of the whole mesh. Returns how many of the file's
// `file_vertices` (a split vertex's copies, after them, are held as it is and not counted, as the serial program
// counts them).
std::size_t part_held(MPI_Comm comm, const af_tool::Options& o, const Ply_blocks& blocks, const Mesh_part& part,
                      std::int64_t file_vertices, std::vector<unsigned char>& held)
{
  held.assign(part.global_vertex.size(), 0);
  if(o.hold.empty()) return 0;
  const auto named = std::find(blocks.names.begin(), blocks.names.end(), o.hold);
  if(named != blocks.names.end())
  {
    const std::vector<double> values = part_values(comm, blocks, part);
    const std::size_t k = std::size_t(named - blocks.names.begin()), columns = blocks.names.size();
    for(std::size_t v = 0; v < held.size(); ++v) held[v] = values[v * columns + k] != 0 ? 1 : 0;
  }
  else
  {
    std::unordered_map<std::int64_t, std::size_t> local;
    for(std::size_t v = 0; v < part.global_vertex.size(); ++v) local.emplace(part.global_vertex[v], v);
    const auto mark = [&](std::size_t i) {
      const auto at = local.find(std::int64_t(i));
      if(at != local.end()) held[at->second] = 1;
    };
    if(!af_tool::read_vertex_index_file(o.hold, std::size_t(blocks.mesh.vertices), mark))
      af_tool::fail("input_error", "--hold " + o.hold + ": neither a numeric vertex property of the input nor a "
                                                        "readable file of vertex indices");
  }
  unsigned long own = 0, all = 0;
  for(std::size_t v = 0; v < part.owned_vertices; ++v) own += part.global_vertex[v] < file_vertices ? held[v] : 0;
  MPI_Allreduce(&own, &all, 1, MPI_UNSIGNED_LONG, MPI_SUM, comm);
  return std::size_t(all);
}

// the library's call on the part, its faired control points to `control` (as the serial program asks for them)
AF::Fairing_report fair_part(const af_tool::Options& o, af_tool::Mesh& mesh, const Mesh_part& part,
                             const Part_process& process, Distributed_state& state, bool print,
                             std::vector<unsigned char>& held, Part_attributes& attributes,
                             std::vector<af_tool::Point>& control)
{
  AF::Fairing_options options = o.fairing;
  options.attribute_mode = attributes.faired() ? af_tool::effective_mode(o) : AF::Attribute_mode::GEOMETRY_ONLY;
  options.memory_limit = std::numeric_limits<double>::infinity();
  control.resize(mesh.number_of_vertices());
  const af_tool::Attribute_vectors attribute_map{ &attributes.values };
  const auto np = AF::parameters::fairing_options(options)
                    .control_point_map(CGAL::make_property_map(control))
                    .attribute_control_map(af_tool::Attribute_vectors{ &attributes.controls })
                    .vertex_is_constrained_map(CGAL::make_property_map(held))
                    .callback(step_lines(o, print));
  const auto hooks = AFI::caller_hooks<af_tool::Mesh>(attribute_map, np);
  const Distributed_elements elements{ &state, &process };
  try
  {
    return AFI::fair_with_options(mesh, mesh.points(), attribute_map, AFI::read_fairing_options(np), hooks,
                                  options.diffusion_tensor_or_default(), elements);
  }
  catch(const AF::Input_error& e) { throw in_the_whole_mesh(e, part); }
}

// the columns of the vertex properties nx, ny, nz among the block's values (empty: the input has no normals)
std::vector<std::size_t> normal_columns(const Ply_blocks& blocks)
{
  std::vector<std::size_t> columns;
  for(const char* name : { "nx", "ny", "nz" })
    for(std::size_t k = 0; k < blocks.names.size(); ++k)
      if(blocks.names[k] == name) columns.push_back(k);
  return columns.size() == 3 ? columns : std::vector<std::size_t>();
}

// The input's normals replaced by the faired surface's at the part's vertices, and --curvature's k1, k2,
// mean_curvature, as the serial program writes them (written_normals_and_curvature.cpp: the limit surface's, from
// the control points); an own vertex's fan and the rings its normal and curvature read are in its part. Returns what
// the report's `normals` says.
std::string limit_quantities(const af_tool::Options& o, bool has_normals, af_tool::Mesh& mesh,
                             const std::vector<af_tool::Point>& control, const AF::Fairing_report& report)
{
  af_tool::Input_info info;
  if(has_normals)
  {
    mesh.add_property_map<af_tool::Vertex_index, af_tool::Vector>("v:normal", af_tool::Vector(0, 0, 0));
    info.has_normals = info.normals_read = true;
  }
  af_tool::Run_record record;
  record.report = report;
  af_tool::write_normals_and_curvature(o, info, fairs_geometry(o), control, mesh, record);
  return record.normals;
}

// the own vertices' new positions (and normals, when the file has them, and faired attributes) to the holders of
// their blocks, then each process's block written in place in `path`
void write_blocks(const af_tool::Options& o, const std::string& path, MPI_Comm comm, const Ply_blocks& blocks,
                  const Mesh_part& part, const af_tool::Mesh& mesh, const Part_attributes& attributes)
{
  const int size = part.size;
  const std::vector<std::size_t> normal = normal_columns(blocks);
  const auto normals = mesh.property_map<af_tool::Vertex_index, af_tool::Vector>("v:normal");
  std::vector<af_tool::Mesh::Property_map<af_tool::Vertex_index, double>> curvature;
  for(const char* name : af_tool::curvature_properties)
    if(o.curvature) curvature.push_back(mesh.property_map<af_tool::Vertex_index, double>(name).first);
  // a record: the vertex's number, its point, its normal, its attributes, its curvature
  const std::size_t width = 7 + attributes.columns.size() + curvature.size();
  std::vector<std::vector<double>> out(static_cast<std::size_t>(size));
  for(std::size_t v = 0; v < part.owned_vertices; ++v)
  {
    const af_tool::Vertex_index i(static_cast<af_tool::Mesh::size_type>(v));
    const af_tool::Point& p = mesh.point(i);
    const af_tool::Vector n = normals.second ? normals.first[i] : af_tool::Vector(0, 0, 0);
    const std::int64_t g = part.global_vertex[v];
    std::vector<double>& to = out[std::size_t(block_of(g, blocks.mesh.vertices, size))];
    to.insert(to.end(), { double(g), p.x(), p.y(), p.z(), n.x(), n.y(), n.z() });
    if(attributes.faired()) to.insert(to.end(), attributes.values[v].begin(), attributes.values[v].end());
    for(const auto& k : curvature) to.push_back(k[i]);
  }
  const std::int64_t first = block_first(blocks.mesh.vertices, part.rank, size);
  std::vector<double> points = blocks.mesh.points, values;
  const Ply_header written = with_vertex_properties(
    blocks.header, o.curvature ? std::vector<std::string>{ "k1", "k2", "mean_curvature" } : std::vector<std::string>(),
    path);
  const std::size_t read_columns = blocks.names.size(), columns = written.columns.size();
  for(std::size_t row = 0; row < points.size() / 3; ++row)   // the properties read, then room for those added
  {
    values.insert(values.end(), blocks.values.begin() + std::ptrdiff_t(row * read_columns),
                  blocks.values.begin() + std::ptrdiff_t((row + 1) * read_columns));
    values.resize(values.size() + columns - read_columns);
  }
  const Ply_element& vertex = blocks.header.elements[std::size_t(blocks.header.vertex)];
  const std::vector<double> received = af_distributed::exchange(comm, out);
  for(std::size_t at = 0; at + width <= received.size(); at += width)
  {
    const double* m = received.data() + at;
    const std::size_t row = std::size_t(std::int64_t(m[0]) - first);
    std::copy(m + 1, m + 4, points.begin() + std::ptrdiff_t(3 * row));
    for(std::size_t a = 0; a < normal.size() && normals.second; ++a) values[row * columns + normal[a]] = m[4 + a];
    for(std::size_t c = 0; c < attributes.columns.size(); ++c)
    {
      const std::size_t k = attributes.columns[c];
      const Ply_type type = vertex.properties[std::size_t(blocks.header.columns[k])].type;
      values[row * columns + k] = in_property_type(type, m[7 + c]);
    }
    for(std::size_t c = 0; c < curvature.size(); ++c) values[row * columns + read_columns + c] = m[width - 3 + c];
  }
  std::vector<std::int64_t> mine(points.size() / 3);
  for(std::size_t k = 0; k < mine.size(); ++k) mine[k] = first + std::int64_t(k);
  agree_on(comm, [&] { if(part.rank == 0) create_ply_output(o.input, path, blocks.header, written); }, "write_error");
  write_ply_blocks(o.input, path, blocks.header, written, part.rank, size, mine, points, values);
}

// written through a temporary file next to the output, which replaces the output once every process wrote
void write_result(const af_tool::Options& o, MPI_Comm comm, const Ply_blocks& blocks, const Mesh_part& part,
                  const af_tool::Mesh& mesh, const Part_attributes& attributes)
{
  std::string tmp = part.rank == 0 ? af_tool::temporary_next_to(o.output).string() : std::string();
  unsigned long length = tmp.size();
  MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG, 0, comm);
  tmp.resize(length);
  MPI_Bcast(&tmp[0], int(length), MPI_CHAR, 0, comm);
  try
  {
    collectively(comm, o.input, [&] { write_blocks(o, tmp, comm, blocks, part, mesh, attributes); });
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

// binary PLY files of triangles in and out: each process reads and writes its blocks (else process 0 reads the mesh
// whole and scatters it: Scattered_mesh.h)
bool by_blocks(const af_tool::Options& o)
{
  if(o.repair || !ends_with(o.input, ".ply") || !ends_with(o.output, ".ply")) return false;   // --repair: whole
  try { return read_ply_header(o.input).refusal.empty(); }
  catch(const std::exception&) { return false; }
}

// process 0's writing of the mesh it read whole, with every process's faired vertices, as the program writes a mesh
// held whole (the normals from the control points, split vertices merged back)
void write_whole(const af_tool::Options& o, MPI_Comm comm, const Mesh_part& part, const af_tool::Mesh& mesh,
                 const std::vector<af_tool::Point>& control, const Part_attributes& attributes, Whole_mesh_file& whole,
                 Run_summary& summary)
{
  std::vector<af_tool::Point> all_control;
  gather_faired(comm, part, mesh, control, whole, all_control);
  std::vector<std::vector<double>> values;
  if(attributes.faired()) gather_attributes(comm, part, attributes.values, whole.mesh.number_of_vertices(), values);
  collectively(comm, o.input, [&] {
    if(part.rank != 0) return;
    af_tool::Run_record record;
    record.report = summary.report;
    af_tool::write_normals_and_curvature(o, whole.info, fairs_geometry(o), all_control, whole.mesh, record);
    af_tool::merge_copies(whole.mesh, whole.info.split);
    af_tool::merge_copies(values, whole.info.split);
    if(attributes.faired()) af_tool::scatter(whole.mesh, whole.attributes, values);
    write_mesh_file(o, whole.mesh, whole.info);
    summary.normals = record.normals;
  });
}

} // namespace

namespace {

// run_on_parts(), the file read by blocks or by process 0
bool run_parts(const af_tool::Options& o, MPI_Comm comm, Run_summary& summary, bool blocks_read)
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
  Whole_mesh_file whole;
  summary.mesh_read = blocks_read ? "blocks" : "process 0";
  read_parts(o, comm, blocks_read, blocks, part, whole);
  summary.read_seconds = clock.time();
  std::int64_t file_vertices = whole.info.split.empty() ? blocks.mesh.vertices : whole.info.split.file_vertices;
  MPI_Bcast(&file_vertices, 1, MPI_INT64_T, 0, comm);   // process 0's: it read the file
  summary.vertices = std::size_t(file_vertices);
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
  std::vector<unsigned char> held;
  collectively(comm, o.input, [&] { summary.held_vertices = part_held(comm, o, blocks, part, file_vertices, held); });
  Part_attributes attributes;
  if(fair_attributes(o))
  {
    if(!blocks_read)   // the columns process 0 sent after --hold's
      for(std::size_t k = o.hold.empty() ? 0 : 1; k < blocks.names.size(); ++k) attributes.columns.push_back(k);
    else if(!resolve_part_attributes(o, blocks, attributes.columns))
    {
      summary = Run_summary();
      summary.whole_mesh_why = "an attribute named is not a numeric vertex property or a colour of bytes of the file "
                               "(uv, or a name it lacks): the mesh is read whole, as anisotropic_fairing reads it";
      return false;
    }
    collectively(comm, o.input, [&] { gather_part_attributes(comm, blocks, part, attributes); });
  }
  std::vector<af_tool::Point> control;
  collectively(comm, o.input, [&] {
    summary.report = fair_part(o, mesh, part, process, state, print, held, attributes, control);
  });
  const double call_seconds = clock.time();
  after_the_call(comm, o, call_seconds, state, summary);
  const bool has_normals = !normal_columns(blocks).empty();
  if(blocks_read && (has_normals || o.curvature))
    collectively(comm, o.input,
                 [&] { summary.normals = limit_quantities(o, has_normals, mesh, control, summary.report); });
  summary.part_vertices = gathered<std::size_t>(comm, part.global_vertex.size(), MPI_UNSIGNED_LONG);
  clock.reset();
  summary.peak_memory_mb = gathered<double>(comm, peak_memory_mb(), MPI_DOUBLE);
  if(blocks_read) write_result(o, comm, blocks, part, mesh, attributes);
  else write_whole(o, comm, part, mesh, control, attributes, whole, summary);
  summary.write_seconds = clock.time();
  return true;
}

} // namespace

bool run_on_parts(const af_tool::Options& o, MPI_Comm comm, Run_summary& summary)
{
  if(run_parts(o, comm, summary, by_blocks(o))) return true;
  if(!by_blocks(o)) return false;
  // a binary PLY file whose blocks cannot make the parts: read whole by process 0, as any other file
  const std::string why = summary.whole_mesh_why;
  if(!run_parts(o, comm, summary, false)) return false;
  summary.mesh_read_why = why;
  return true;
}

} // namespace af_distributed
