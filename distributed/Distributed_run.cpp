// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "Distributed_run.h"

#include "Collective_failure.h"
#include "Distributed_layout.h"
#include "Distributed_operator.h"
#include "Face_partition.h"
#include "Ghosted_rows.h"
#include "Replicated_setup.h"
#include "Surface_folds.h"
#include "attribute_columns.h"
#include "mesh_io.h"

#include <CGAL/Anisotropic_fairing/internal/run/Caller_maps.h>

#include <petscksp.h>
#include <sys/resource.h>

#include <cstdio>
#include <filesystem>
#include <variant>

namespace af_distributed {

namespace {

struct Input
{
  af_tool::Mesh mesh;
  af_tool::Input_info info;
  std::vector<af_tool::Attribute_column> columns;
  std::vector<std::vector<double>> values;   // per vertex, the attribute columns faired (empty: none)
  AF::Attribute_mode mode = AF::Attribute_mode::GEOMETRY_ONLY;
  bool fair_attributes = false;
};

std::string without_library_prefix(const std::string& what)
{
  const std::string prefix = "Anisotropic_fairing: ";
  return what.compare(0, prefix.size(), prefix) == 0 ? what.substr(prefix.size()) : what;
}

// f() on every process; the program's and the library's failures become every process's Collective_failure
template <typename F>
void collectively(MPI_Comm comm, const std::string& input, const F& f)
{
  std::string message, status = "error";
  try { f(); }
  catch(const Collective_failure&) { throw; }
  catch(const af_tool::Failure& e) { message = e.message; status = e.status; }
  catch(const AF::Input_error& e)
  {
    message = "cannot fair " + input + ": " + without_library_prefix(e.what());
    status = e.kind() == AF::Input_error::INVALID_PARAMETER ? "invalid_parameter" : "input_error";
  }
  catch(const std::exception& e) { message = e.what(); }
  agree(comm, message, status);
}

// the mesh and the attributes faired, as anisotropic_fairing reads them (fairing_run.cpp)
void read(const af_tool::Options& o, Input& in)
{
  af_tool::read_input(o.input, in.mesh, in.info, false);
  in.mode = af_tool::effective_mode(o);
  in.columns = af_tool::resolve_attributes(in.mesh, in.info, o.input, o.attributes);
  in.fair_attributes = !in.columns.empty() && in.mode != AF::Attribute_mode::GEOMETRY_ONLY;
  if(in.fair_attributes) af_tool::gather(in.mesh, in.columns, in.values);
  if(in.info.has_normals)
    af_tool::fail("input_error",
                  o.input + " has vertex normals, which the distributed program does not recompute on the faired "
                            "surface (not supported: remove them, or use anisotropic_fairing)");
}

double peak_memory_mb()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;   // kilobytes on Linux
}

template <typename T>
std::vector<T> gathered(MPI_Comm comm, T mine, MPI_Datatype type)
{
  int size = 1;
  MPI_Comm_size(comm, &size);
  std::vector<T> all(static_cast<std::size_t>(size), T());
  MPI_Allgather(&mine, 1, type, all.data(), 1, type, comm);
  return all;
}

// the step's line, as anisotropic_fairing prints it
void print_step(const AF::Fairing_step& s, unsigned int max_steps)
{
  std::fprintf(
    stderr,
    "anisotropic_fairing_mpi: step %zu/%u  t=%.6g  area=%.6g  int|H|^2=%.6g  max disp=%.6g  %d its  %.3fs+%.3fs\n",
    s.step, max_steps, s.time, s.area, s.H_integral, s.max_displacement, s.solver_iterations, s.assemble_seconds,
    s.solve_seconds);
}

// process 0: the result into the mesh (the library's write-back) and the file, through a temporary file
void write_result(const af_tool::Options& o, Input& in, const Replicated_setup& setup, const Control_matrix& Y)
{
  std::vector<bool> kept;
  const Control_matrix values = setup.written(Y, kept);
  std::vector<std::vector<double>> faired = in.values;
  const af_tool::Attribute_vectors attribute_map{ &faired };
  const AF::Attribute_mode mode = in.fair_attributes ? in.mode : AF::Attribute_mode::GEOMETRY_ONLY;
  AFI::write_back(setup.im, values, mode, kept, in.mesh.points(), attribute_map);
  af_tool::merge_copies(in.mesh,
                        in.info.split); // a split vertex at the mean of its copies, as anisotropic_fairing writes it
  af_tool::merge_copies(faired, in.info.split);
  if(in.fair_attributes) af_tool::scatter(in.mesh, in.columns, faired);
  af_tool::Format format;
  af_tool::format_of(o.output, format);
  const std::filesystem::path tmp = af_tool::temporary_next_to(o.output);
  try
  {
    af_tool::write_mesh(tmp.string(), format, in.mesh, in.info, false, o.text_output);
    af_tool::merge_copies_in_file(tmp.string(), format, in.info.split);
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
  for(const std::string& p : af_tool::dropped_properties(in.mesh, format)) dropped += (dropped.empty() ? "" : ", ") + p;
  if(!dropped.empty())
    std::fprintf(stderr, "anisotropic_fairing_mpi: warning: %s cannot hold the input's %s: not written\n",
                 o.output.c_str(), dropped.c_str());
  for(const std::string& w :
      in.info.warnings) // what reading changed for the run (split vertices, triangulated polygons)
    std::fprintf(stderr, "anisotropic_fairing_mpi: warning: %s\n", af_tool::one_line(w).c_str());
}

// the flow with one tensor type, on this process's part
template <typename Tensor>
AF::Fairing_report fair(MPI_Comm comm, const af_tool::Options& o, const Replicated_setup& setup,
                        const Distributed_layout& d, Ghosted_rows& rows, Distributed_operator& op, const Tensor& tensor,
                        Control_matrix& X, Flow_timing& timing)
{
  const AF::Attribute_mode mode = setup.given.mode;
  AFI::Assembly_context numbering;
  numbering.original_vertex = &setup.ordering.old_of_new_vertex;
  numbering.original_face = &setup.ordering.old_of_new_face;
  numbering.border = &setup.border;
  const Flow_input in{ setup.layer(),
                       setup.components,
                       setup.component_edge,
                       setup.mean_edge,
                       setup.constrained,
                       numbering,
                       mode == AF::Attribute_mode::COUPLED ? int(X.cols()) : 3,
                       AFI::wants_normal_motion(tensor) };
  AFI::Stepper_settings s = setup.given.settings;
  s.limit_written = s.measure_limit_surface = setup.given.output == AF::Output_positions::LIMIT_SURFACE;
  s.verbose = false;   // the program prints its own line per step, on process 0
  if(s.stopping.noise_discrepancy > 0)
    throw std::runtime_error("the noise criterion is not supported by the distributed program");
  const unsigned int max_steps = unsigned(s.maximum_steps);
  const bool print = d.rank == 0 && !o.quiet;
  return run_distributed_flow(comm, d, rows, op, in, s, tensor, X,
                              [&](const AF::Fairing_step& st) { if(print) print_step(st, max_steps); }, timing);
}

} // namespace

// the faces divided, each process's part assembled and stepped, the result gathered and written by process 0
int run_distributed(const af_tool::Options& o, MPI_Comm comm, Run_summary& summary)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  summary.processes = size;
  CGAL::Real_timer clock;
  clock.start();
  Input in;
  collectively(comm, o.input, [&] { read(o, in); });
  summary.read_seconds = clock.time();
  summary.vertices = in.mesh.number_of_vertices();
  summary.faces = in.mesh.number_of_faces();
  clock.reset();
  std::unique_ptr<Replicated_setup> setup;
  AF::Fairing_options options = o.fairing;
  options.attribute_mode = in.fair_attributes ? in.mode : AF::Attribute_mode::GEOMETRY_ONLY;
  const af_tool::Attribute_vectors attribute_map{ &in.values };
  collectively(comm, o.input, [&] {
    setup.reset(new Replicated_setup(in.mesh, options, in.fair_attributes ? &attribute_map : nullptr));
  });
  summary.setup_seconds = clock.time();
  clock.reset();
  const AFI::Ghost_layer& layer = setup->layer();
  Distributed_layout d;
  collectively(comm, o.input, [&] {
    d = make_distributed_layout(layer, *setup->cache, partition_faces(comm, *layer.topology, layer.real_faces), rank,
                                size);
  });
  summary.faces_per_process = gathered<std::size_t>(comm, d.owned_faces.size(), MPI_UNSIGNED_LONG);
  summary.owned_vertices_per_process = gathered<std::size_t>(comm, d.owned_vertices.size(), MPI_UNSIGNED_LONG);
  summary.ghost_vertices_per_process = gathered<std::size_t>(comm, d.ghost_vertices.size(), MPI_UNSIGNED_LONG);
  Ghosted_rows rows(comm, d);
  Control_matrix X = setup->X;
  rows.forget_others(X);
  const AFI::Stepper_settings& s = setup->given.settings;
  Distributed_operator op(comm, *setup->cache, d, rows, setup->constrained, s.solver_tolerance / 100,
                          s.solver_maximum_iterations);
  summary.off_process_columns = gathered<std::size_t>(comm, op.off_process_columns(), MPI_UNSIGNED_LONG);
  summary.partition_seconds = clock.time();
  clock.reset();
  collectively(comm, o.input, [&] {
    summary.report = std::visit([&](const auto& t) { return fair(comm, o, *setup, d, rows, op, t, X, summary.timing); },
                                options.diffusion_tensor_or_default());
  });
  summary.flow_seconds = clock.time();
  summary.prefilter_iterations = op.prefilter_iterations();
  const AF::Fairing_report& r = summary.report;
  if(!r.succeeded())
    agree(comm,
          "fairing " + o.input + " failed (" + AF::to_string(r.status) +
            "): " + (r.message.empty() ? std::string("no detail") : r.message),
          AF::to_string(r.status));
  clock.reset();
  Control_matrix Y;
  if(setup->given.output == AF::Output_positions::LIMIT_SURFACE) distributed_limit_points(layer, d, rows, X, Y);
  else Y = X;
  rows.gather_on_first(Y);
  summary.peak_memory_mb = gathered<double>(comm, peak_memory_mb(), MPI_DOUBLE);
  summary.overlap_doubles_received = gathered<double>(comm, rows.doubles_received(), MPI_DOUBLE);
  summary.overlap_refreshes = rows.refreshes();
  collectively(comm, o.input, [&] { if(rank == 0) write_result(o, in, *setup, Y); });
  summary.write_seconds = clock.time();
  return 0;
}

} // namespace af_distributed
