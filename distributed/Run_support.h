// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the program's two runs share (Distributed_run.cpp: every process holds the whole mesh; Part_run.cpp: each
// holds its part): failures made every process's, the step lines as anisotropic_fairing prints them, and the
// per-process figures of the report.

#ifndef AF_DISTRIBUTED_RUN_SUPPORT_H
#define AF_DISTRIBUTED_RUN_SUPPORT_H

#include "Collective_failure.h"
#include "Distributed_run.h"
#include "message_text.h"
#include "tool_common.h"

#include <CGAL/Anisotropic_fairing/Input_error.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Process_part.h>

#include <mpi.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace af_distributed {

namespace AF = CGAL::Anisotropic_fairing;

inline std::string without_library_prefix(const std::string& what)
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
  catch(const CGAL::Anisotropic_fairing::internal::Input_failed_elsewhere&) {}   // that process says why
  catch(const af_tool::Failure& e) { message = e.message; status = e.status; }
  catch(const AF::Input_error& e)
  {
    message = "cannot fair " + input + ": " + without_library_prefix(e.what());
    status = e.kind() == AF::Input_error::INVALID_PARAMETER ? "invalid_parameter" : "input_error";
  }
  catch(const std::bad_alloc&) { throw; }   // main() ends every process, naming this one
  catch(const std::exception& e) { message = e.what(); }
  agree(comm, message, status);
}

inline double peak_memory_mb()
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

// the step's lines, as anisotropic_fairing prints them (the default run's runs named)
inline std::function<bool(const AF::Fairing_step&)> step_lines(const af_tool::Options& o, bool print)
{
  const unsigned int max_steps = o.fairing.maximum_steps();
  auto last_run = std::make_shared<std::size_t>(0);
  auto steps = std::make_shared<std::size_t>(0);
  return [=](const AF::Fairing_step& s) {
    ++*steps;
    if(!print) return true;
    if(s.runs > 1 && s.run != *last_run)
      std::fprintf(stderr, "anisotropic_fairing_mpi: run %zu of at most %zu: the %s\n", s.run, s.runs,
                   s.run_name.c_str());
    *last_run = s.run;
    std::fprintf(stderr,
                 "anisotropic_fairing_mpi: step %zu (%zu/%u in all)  t=%.6g  area=%.6g  int|H|^2=%.6g  max disp=%.6g  "
                 "%d its  %.3fs+%.3fs\n",
                 s.step, *steps, max_steps, s.time, s.area, s.H_integral, s.max_displacement, s.solver_iterations,
                 s.assemble_seconds, s.solve_seconds);
    return true;
  };
}

inline void summarise_parts(MPI_Comm comm, const Distributed_state& state, Run_summary& summary)
{
  const Distributed_layout* d = state.layout.get();
  summary.faces_per_process = gathered<std::size_t>(comm, d ? d->owned_faces.size() : 0, MPI_UNSIGNED_LONG);
  summary.owned_vertices_per_process =
    gathered<std::size_t>(comm, d ? d->owned_vertices.size() : 0, MPI_UNSIGNED_LONG);
  summary.ghost_vertices_per_process =
    gathered<std::size_t>(comm, d ? d->ghost_vertices.size() : 0, MPI_UNSIGNED_LONG);
  summary.off_process_columns = gathered<std::size_t>(comm, state.off_process_columns, MPI_UNSIGNED_LONG);
  summary.overlap_doubles_received = gathered<double>(comm, state.volume.doubles_received, MPI_DOUBLE);
  summary.overlap_refreshes = state.volume.refreshes;
  summary.timing = state.timing;
  summary.prefilter_iterations = state.prefilter_iterations;
  summary.partition_seconds = state.partition_seconds;
}

// After the library's call: the per-process figures and the seconds of its phases (its set-up includes the
// partition, made with its element cache); a run that did not succeed fails on every process.
inline void after_the_call(MPI_Comm comm, const af_tool::Options& o, double call_seconds,
                           const Distributed_state& state, Run_summary& summary)
{
  summarise_parts(comm, state, summary);
  summary.setup_seconds = std::max(0.0, summary.report.setup_seconds - summary.partition_seconds);
  summary.flow_seconds = std::max(0.0, call_seconds - summary.report.setup_seconds);
  const AF::Fairing_report& r = summary.report;
  if(!r.succeeded())
    agree(comm,
          "fairing " + o.input + " failed (" + AF::to_string(r.status) +
            "): " + (r.message.empty() ? std::string("no detail") : r.message),
          AF::to_string(r.status));
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if(rank == 0 && !o.quiet && !r.choices.empty())   // as anisotropic_fairing says what the default run chose
    std::fprintf(stderr, "anisotropic_fairing_mpi: automatic parameters: %s\n", af_tool::one_line(r.choices).c_str());
}

} // namespace af_distributed

#endif // AF_DISTRIBUTED_RUN_SUPPORT_H
