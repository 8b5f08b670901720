// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One run of anisotropic_fairing_mpi: every process reads the mesh and makes the library's call of
// anisotropic_fairing() (internal/run/Fairing_driver.h) with the program's Elements (Distributed_cache.h):
// the faces are partitioned (Face_partition.h), and each run of the call -- the default run's candidates and
// comparison included -- assembles and solves on the processes (Distributed_flow.h); process 0 writes the
// result as anisotropic_fairing writes it (full double precision, the input's vertex order, every vertex
// property, the faired surface's normals), then the JSON report. A failure on any process fails the run on
// every process (Collective_failure.h) before anything is written.

#ifndef AF_DISTRIBUTED_DISTRIBUTED_RUN_H
#define AF_DISTRIBUTED_DISTRIBUTED_RUN_H

#include "Distributed_cache.h"
#include "mesh_io.h"
#include "options.h"

#include <CGAL/Anisotropic_fairing/Fairing_report.h>

#include <mpi.h>

#include <string>
#include <vector>

namespace af_distributed {

/// What the JSON report says of a run.
struct Run_summary
{
  int processes = 1;
  std::size_t vertices = 0, faces = 0;
  std::vector<std::size_t> faces_per_process, owned_vertices_per_process, ghost_vertices_per_process;
  std::vector<double> peak_memory_mb;   // per process (getrusage's maximum resident set size)
  double read_seconds = 0, setup_seconds = 0, partition_seconds = 0, flow_seconds = 0, write_seconds = 0;
  Flow_timing timing;                   // of process 0 (the same decisions on every process)
  std::string normals = "none";         // the normals written (anisotropic_fairing's report key)
  std::size_t held_vertices = 0;        // held by --hold
  std::size_t prefilter_iterations = 0;
  std::vector<std::size_t> off_process_columns;   // per process: values received per matrix-vector product and column
  std::vector<double> overlap_doubles_received;   // per process: into rows other processes own, over the run
  std::size_t overlap_refreshes = 0;              // how many refreshes moved them
  std::string ksp_type, pc_type;
  std::string mesh_held = "whole", whole_mesh_why;   // "parts" (Part_run.h), or "whole" and why
  std::string mesh_read, mesh_read_why;   // in parts: "blocks" or "process 0" (and why a binary PLY file was not)
  std::vector<std::size_t> part_vertices;            // per process, the vertices of its part (the parts' run)
  CGAL::Anisotropic_fairing::Fairing_report report;
};

/// Runs `o` on the processes of `comm`; returns 0, or throws Collective_failure (the same on every process)
/// or af_tool::Failure (a usage error, the same on every process).
int run_distributed(const af_tool::Options& o, MPI_Comm comm, Run_summary& summary);

/// Process 0's writing of a mesh it holds whole (`info`: as the program read it: its split vertices merged back,
/// what the output's format cannot hold said), as anisotropic_fairing writes it, through a temporary file.
void write_mesh_file(const af_tool::Options& o, const af_tool::Mesh& mesh, const af_tool::Input_info& info);

/// The JSON text of the report of a run (`ok` false: `status` and `message` say why it failed).
std::string summary_json(const af_tool::Options& o, const Run_summary& s, bool ok, const std::string& status,
                         const std::string& message);

} // namespace af_distributed

#endif // AF_DISTRIBUTED_DISTRIBUTED_RUN_H
