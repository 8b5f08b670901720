// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "Distributed_run.h"
#include "Part_run.h"
#include "Run_support.h"

#include "Collective_failure.h"
#include "Distributed_cache.h"
#include "Distributed_flow.h"
#include "attribute_columns.h"
#include "held_vertices.h"
#include "mesh_io.h"
#include "written_normals_and_curvature.h"

#include <CGAL/Anisotropic_fairing/internal/run/Caller_maps.h>
#include <CGAL/Anisotropic_fairing/internal/run/Fairing_driver.h>
#include <CGAL/Anisotropic_fairing/named_function_parameters.h>

#include <petscksp.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <limits>

namespace af_distributed {

namespace {

namespace AF = CGAL::Anisotropic_fairing;

typedef std::vector<std::vector<double>> Vertex_vectors;

// the mesh and what the run reads and writes besides, as anisotropic_fairing has them (fairing_run.cpp)
struct Input
{
  af_tool::Mesh mesh;
  af_tool::Input_info info;
  std::vector<af_tool::Attribute_column> columns;
  Vertex_vectors values, controls;   // per vertex, the attribute columns faired and their control values
  std::vector<af_tool::Point> control_points;
  std::vector<unsigned char> held;   // --hold
  std::size_t held_vertices = 0;
  AF::Attribute_mode mode = AF::Attribute_mode::GEOMETRY_ONLY;
  bool fair_attributes = false;
};

// as anisotropic_fairing reads them (fairing_run.cpp: read_mesh, plan_attributes, plan_held_vertices)
void read(const af_tool::Options& o, Input& in)
{
  af_tool::read_input(o.input, in.mesh, in.info, o.repair);
  af_tool::check_curvature_properties_free(o, in.mesh);
  in.mode = af_tool::effective_mode(o);
  in.columns = af_tool::resolve_attributes(in.mesh, in.info, o.input, o.attributes);
  in.fair_attributes = !in.columns.empty() && in.mode != AF::Attribute_mode::GEOMETRY_ONLY;
  if(in.fair_attributes) af_tool::gather(in.mesh, in.columns, in.values);
  in.controls = in.values;
  in.control_points.resize(in.mesh.number_of_vertices());
  in.held.assign(in.mesh.number_of_vertices(), 0);
  if(!o.hold.empty()) in.held_vertices = af_tool::read_held_vertices(in.mesh, o.hold, in.held);
  for(std::size_t i = 0; i < in.info.split.copy_of.size(); ++i)   // a split vertex's copies are held as it is
    in.held[in.info.split.file_vertices + i] = in.held[in.info.split.copy_of[i]];
}

// The library's call of anisotropic_fairing() (internal/run/Fairing_driver.h) with the distributed program's
// Elements: every process runs it alike, its runs stepping on the processes (Distributed_cache.h). The memory
// check is the processes' own sum's, not one process's: not made (--memory-limit is refused).
AF::Fairing_report fair(const af_tool::Options& o, Input& in, Distributed_state& state, bool print)
{
  AF::Fairing_options options = o.fairing;
  options.attribute_mode = in.fair_attributes ? in.mode : AF::Attribute_mode::GEOMETRY_ONLY;
  options.memory_limit = std::numeric_limits<double>::infinity();
  const af_tool::Attribute_vectors attribute_map{ &in.values };
  const auto np = AF::parameters::fairing_options(options)
                    .control_point_map(CGAL::make_property_map(in.control_points))
                    .attribute_control_map(af_tool::Attribute_vectors{ &in.controls })
                    .vertex_is_constrained_map(CGAL::make_property_map(in.held))
                    .callback(step_lines(o, print));
  const auto hooks = AFI::caller_hooks<af_tool::Mesh>(attribute_map, np);
  const Distributed_elements elements{ &state };
  return AFI::fair_with_options(in.mesh, in.mesh.points(), attribute_map, AFI::read_fairing_options(np), hooks,
                                options.diffusion_tensor_or_default(), elements);
}

// process 0: the normals, the curvature and the attributes as anisotropic_fairing writes them
// (fairing_run.cpp: write_back), then the file, through a temporary file
void write_result(const af_tool::Options& o, Input& in, af_tool::Run_record& record)
{
  const bool fair_geometry = in.mode != AF::Attribute_mode::ATTRIBUTES_ONLY;
  af_tool::write_normals_and_curvature(o, in.info, fair_geometry, in.control_points, in.mesh, record);
  af_tool::merge_copies(in.mesh, in.info.split);   // a split vertex at the mean of its copies
  af_tool::merge_copies(in.values, in.info.split);
  if(in.fair_attributes) af_tool::scatter(in.mesh, in.columns, in.values);
  write_mesh_file(o, in.mesh, in.info);
}

} // namespace

void write_mesh_file(const af_tool::Options& o, const af_tool::Mesh& mesh, const af_tool::Input_info& info)
{
  af_tool::Format format;
  af_tool::format_of(o.output, format);
  const std::filesystem::path tmp = af_tool::temporary_next_to(o.output);
  try
  {
    af_tool::write_mesh(tmp.string(), format, mesh, info, false, o.text_output);
    af_tool::merge_copies_in_file(tmp.string(), format, info.split);
  }
  catch(const af_tool::Failure& f)
  {
    af_tool::fail_writing(f, tmp, o.output);
  }
  std::error_code ec;
  std::filesystem::rename(tmp, o.output, ec);
  if(ec)
  {
    std::filesystem::remove(tmp, ec);
    af_tool::fail("write_error", "cannot write " + o.output + ": " + ec.message());
  }
  // as anisotropic_fairing warns: what the output's format cannot hold
  std::string dropped;
  for(const std::string& p : af_tool::dropped_properties(mesh, format)) dropped += (dropped.empty() ? "" : ", ") + p;
  if(!dropped.empty())
    std::fprintf(stderr, "anisotropic_fairing_mpi: warning: %s cannot hold the input's %s: not written\n",
                 o.output.c_str(), dropped.c_str());
  for(const std::string& w :
      info.warnings) // what reading changed for the run (split vertices, triangulated polygons)
    std::fprintf(stderr, "anisotropic_fairing_mpi: warning: %s\n", af_tool::one_line(w).c_str());
}

// the library's call on every process, its runs divided among them; the result written by process 0
int run_distributed(const af_tool::Options& o, MPI_Comm comm, Run_summary& summary)
{
  if(run_on_parts(o, comm, summary)) return 0;
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  summary.processes = size;
  CGAL::Real_timer clock;
  clock.start();
  Input in;
  collectively(comm, o.input, [&] { read(o, in); });
  summary.read_seconds = clock.time();
  summary.held_vertices = in.held_vertices;
  summary.vertices = in.info.split.empty() ? in.mesh.number_of_vertices() : in.info.split.file_vertices;
  summary.faces = in.mesh.number_of_faces();
  clock.reset();
  Distributed_state state;
  state.comm = comm;
  state.rank = rank;
  state.size = size;
  collectively(comm, o.input, [&] { summary.report = fair(o, in, state, rank == 0 && !o.quiet); });
  const double call_seconds = clock.time();
  after_the_call(comm, o, call_seconds, state, summary);
  const AF::Fairing_report& r = summary.report;
  clock.reset();
  summary.peak_memory_mb = gathered<double>(comm, peak_memory_mb(), MPI_DOUBLE);
  collectively(comm, o.input, [&] {
    if(rank != 0) return;
    af_tool::Run_record record;
    record.report = r;
    write_result(o, in, record);
    summary.normals = record.normals;
  });
  summary.write_seconds = clock.time();
  return 0;
}

} // namespace af_distributed
