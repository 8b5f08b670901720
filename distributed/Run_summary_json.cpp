// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The JSON report of anisotropic_fairing_mpi: the run's steps (as anisotropic_fairing reports them: time,
// area, int |H|^2, CG iterations), the seconds of each phase, and per process its faces, owned and overlap
// vertices and peak memory.

#include "Distributed_run.h"
#include "json_report.h"

#include <nlohmann/json.hpp>

#include <petscsys.h>

namespace af_distributed {

namespace {

std::string petsc_option(const char* name, const char* otherwise)
{
  char value[256] = { 0 };
  PetscBool set = PETSC_FALSE;
  PetscOptionsGetString(nullptr, nullptr, name, value, sizeof value, &set);
  return set ? std::string(value) : std::string(otherwise);
}

nlohmann::json steps_json(const CGAL::Anisotropic_fairing::Fairing_report& r)
{
  nlohmann::json steps = nlohmann::json::array();
  for(const auto& s : r.steps)
    steps.push_back({ { "step", s.step },
                      { "time", s.time },
                      { "time_step", s.time_step },
                      { "area", s.area },
                      { "energy", s.energy },
                      { "H_integral", s.H_integral },
                      { "max_displacement", s.max_displacement },
                      { "cg_iterations", s.solver_iterations },
                      { "assemble_seconds", s.assemble_seconds },
                      { "solve_seconds", s.solve_seconds } });
  return steps;
}

} // namespace

std::string summary_json(const af_tool::Options& o, const Run_summary& s, bool ok, const std::string& status,
                         const std::string& message)
{
  namespace AF = CGAL::Anisotropic_fairing;
  nlohmann::json j;
  j["program"] = "anisotropic_fairing_mpi";
  j["input"] = o.input;
  j["output"] = o.output;
  j["status"] = status;
  if(!ok) j["message"] = message;
  j["output_written"] = ok;
  j["processes"] = s.processes;
  j["vertices"] = s.vertices;
  j["faces"] = s.faces;
  j["ksp_type"] = petsc_option("-ksp_type", "cg");
  j["pc_type"] = petsc_option("-pc_type", "jacobi");
  j["per_process"] = { { "faces", s.faces_per_process }, { "owned_vertices", s.owned_vertices_per_process },
                       { "overlap_vertices", s.ghost_vertices_per_process }, { "peak_memory_mb", s.peak_memory_mb } };
  j["seconds"] = { { "read", s.read_seconds }, { "setup", s.setup_seconds }, { "partition", s.partition_seconds },
                   { "flow", s.flow_seconds }, { "assemble", s.timing.assemble_seconds + s.timing.judge_seconds },
                   { "solve", s.timing.solve_seconds }, { "write", s.write_seconds } };
  j["cg_iterations"] = s.timing.iterations;
  j["solves"] = s.timing.solves;
  j["prefilter_cg_iterations"] = s.prefilter_iterations;
  // what a process receives per matrix-vector product of CG (one per iteration), per column of unknowns
  j["per_process"]["matvec_doubles_received"] = s.off_process_columns;
  // the overlap's control points (and M_eps, the limit points) refreshed from their owners
  j["per_process"]["overlap_doubles_received"] = s.overlap_doubles_received;
  // what a process holds of the mesh: its part, or the whole mesh (and why)
  j["mesh_held"] = s.mesh_held;
  if(s.mesh_held == "parts")
  {
    j["per_process"]["part_vertices"] = s.part_vertices;
    j["mesh_read"] = s.mesh_read;   // by blocks, or whole by process 0 (and why, for a binary PLY file)
    if(!s.mesh_read_why.empty()) j["mesh_read_why"] = s.mesh_read_why;
  }
  else j["whole_mesh_why"] = s.whole_mesh_why;
  j["overlap_refreshes"] = s.overlap_refreshes;
  if(ok)
  {
    j["stop_reason"] = AF::to_string(s.report.stop_reason);
    j["choices"] = s.report.choices;
    j["selected_tensor"] = s.report.selected_tensor;
    j["normals"] = s.normals;
    j["held_vertices"] = s.held_vertices;
    // what the library measured of the whole mesh (as anisotropic_fairing reports it)
    j["boundary_vertices"] = s.report.boundary_vertices;
    j["boundary_held_vertices"] = s.report.boundary_held_vertices;
    j["boundary_loops"] = s.report.boundary_loops;
    j["isolated_vertices"] = s.report.isolated_vertices;
    j["components"] = s.report.components;
    j["mean_edge_length"] = s.report.mean_edge_length;
    j["noise_level"] = s.report.noise_level;
    j["removed_spikes"] = s.report.removed_spikes;
    const AF::Fairing_report& f = s.report;
    if(o.fairing.automatic_parameters())   // as anisotropic_fairing reports the default run's noise model
      j["noise_model"] = { { "tangential_noise_level", f.tangential_noise_level },
                           { "noise_level_spread", f.noise_level_spread },
                           { "tangential_noise_level_spread", f.tangential_noise_level_spread },
                           { "impulse_share", f.impulse_share },
                           { "impulse_deviation", f.impulse_deviation },
                           { "lattice_step", { f.lattice_step[0], f.lattice_step[1], f.lattice_step[2] } } };
    af_tool::Run_record record;   // the deviation bounds, as anisotropic_fairing reports them
    record.fairing_ran = true;
    record.report = s.report;
    const nlohmann::json deviations = nlohmann::json::parse(af_tool::deviations_json(o, record));
    for(const auto& [key, value] : deviations.items()) j[key] = value;
    j["rejected_steps"] = s.report.rejected_steps;
    j["time_step"] = s.report.time_step;
    j["scale"] = s.report.scale;
    j["steps"] = steps_json(s.report);
  }
  return j.dump(2) + "\n";
}

} // namespace af_distributed
