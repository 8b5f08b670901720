// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// anisotropic_fairing_mpi -- the program anisotropic_fairing's run, distributed over MPI processes with PETSc:
//
//   mpirun -np P anisotropic_fairing_mpi INPUT OUTPUT [options] [PETSc options]
//
// The options are anisotropic_fairing's, with the same meaning (those it does not support are refused by
// name: Run_request.h); single-dash options are PETSc's (-pc_type gamg|hypre, -ksp_rtol, -ksp_monitor,
// -mat_partitioning_type, -log_view; the prefilter's solver with the prefix -prefilter_). Failure contract
// as anisotropic_fairing's: one line on stderr (from process 0), exit 1 (2: usage), no OUTPUT. A process out
// of memory says so, naming itself, and ends every process (MPI_Abort): the others may be waiting for it.

#include "Collective_failure.h"
#include "Distributed_run.h"
#include "Run_request.h"
#include "message_text.h"
#include "mesh_io.h"
#include "options.h"

#include <CGAL/Anisotropic_fairing/internal/run/Memory_estimate.h>

#include <petscsys.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <vector>

namespace {
const std::chrono::steady_clock::time_point program_start = std::chrono::steady_clock::now();
}

double af_tool::elapsed_seconds()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - program_start).count();
}

namespace {

const char* const usage_text =
  "anisotropic_fairing_mpi: anisotropic_fairing's run on MPI processes (PETSc)\n"
  "  mpirun -np P anisotropic_fairing_mpi INPUT OUTPUT [options] [PETSc options]\n"
  "Single-dash options are PETSc's: -pc_type jacobi|gamg|hypre, -ksp_rtol, -ksp_monitor, -mat_partitioning_type,\n"
  "-log_view; the prefilter's solver: -prefilter_ksp_rtol, -prefilter_pc_type. Not supported (refused):\n"
  "--element linear, --solver cholesky, --resample, --snapshot, --memory-limit.\n"
  "anisotropic_fairing's options, with the same meaning:\n\n";

// This process cannot allocate: it says so, naming itself and what it holds, and ends every process (the others
// may be waiting for it in a collective call); nothing has been written then.
[[noreturn]] void out_of_memory(MPI_Comm comm, int rank)
{
  int size = 1;
  MPI_Comm_size(comm, &size);
  namespace AFI = CGAL::Anisotropic_fairing::internal;
  std::fprintf(stderr,
               "anisotropic_fairing_mpi: out of memory on process %d of %d (%s in use); nothing was written: "
               "run on more processes, or on machines with more memory\n",
               rank, size, AFI::megabytes(AFI::available_memory().in_use).c_str());
  std::fflush(stderr);
  MPI_Abort(comm, 1);
  std::abort();
}

// PETSc's errors: out of memory as above, any other ends every process at once with PETSc's message (MPI_Abort),
// so that no process is left waiting for one that stopped; nothing has been written then
PetscErrorCode on_petsc_error(MPI_Comm comm, int line, const char* function, const char* file, PetscErrorCode code,
                              PetscErrorType type, const char* message, void* context)
{
  // (PETSc 3.18 reports a failed allocation from PetscMallocAlign with a code other than PETSC_ERR_MEM)
  if(code == PETSC_ERR_MEM || (function && std::strstr(function, "Malloc")))
  {
    int rank = 0;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    out_of_memory(PETSC_COMM_WORLD, rank);
  }
  return PetscAbortErrorHandler(comm, line, function, file, code, type, message, context);
}

// the run on every process; returns the exit code (the same on every process)
int run_program(const std::vector<std::string>& arguments, MPI_Comm comm, int rank)
{
  std::vector<char*> argv;
  for(const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  af_tool::Options o;
  af_distributed::Run_summary summary;
  std::string status = "error", message;
  int code = 1;
  try
  {
    af_tool::parse_arguments(int(argv.size()), argv.data(), o);   // the same on every process
    if(o.help || o.version)
    {
      if(rank == 0 && o.help) std::fputs(usage_text, stdout);
      if(rank == 0) std::fputs(o.help ? af_tool::help_text().c_str() : af_tool::version_text().c_str(), stdout);
      return 0;
    }
    const std::string refused = af_distributed::unsupported(o);
    if(!refused.empty()) af_tool::usage_error(refused);
    code = af_distributed::run_distributed(o, comm, summary);
    status = "success";
  }
  catch(const af_tool::Failure& f) { status = f.status; message = f.message; code = f.exit_code; }
  catch(const af_distributed::Collective_failure& f) { status = f.status; message = f.what(); code = 1; }
  catch(const std::bad_alloc&) { out_of_memory(comm, rank); }
  if(rank == 0)
  {
    const bool ok = status == "success";
    if(!ok) std::fprintf(stderr, "anisotropic_fairing_mpi: %s\n", af_tool::one_line(message).c_str());
    const std::string refused = ok ? std::string() : af_tool::report_refused_on_failure(o);
    const std::string why = o.report.empty() || !refused.empty() ? std::string()
      : af_tool::write_file_atomically(o.report, af_distributed::summary_json(o, summary, ok, status, message));
    if(!why.empty())
    {
      std::fprintf(stderr, "anisotropic_fairing_mpi: cannot write the report %s: %s\n", o.report.c_str(), why.c_str());
      if(ok) code = 1;
    }
    if(ok && !o.quiet)
      std::fprintf(stderr,
                   "anisotropic_fairing_mpi: wrote %s (%zu vertices, %zu steps, stopped: %s, %d processes, %.3f s)\n",
                   o.output.c_str(), summary.vertices, summary.report.steps.size(),
                   CGAL::Anisotropic_fairing::to_string(summary.report.stop_reason), summary.processes,
                   af_tool::elapsed_seconds());
  }
  MPI_Bcast(&code, 1, MPI_INT, 0, comm);
  return code;
}

} // namespace

int main(int argc, char** argv)
{
  const af_distributed::Split_arguments split = af_distributed::split_arguments(argc, argv);
  std::vector<char*> petsc_argv;
  for(const std::string& a : split.petsc) petsc_argv.push_back(const_cast<char*>(a.c_str()));
  petsc_argv.push_back(nullptr);
  int petsc_argc = int(split.petsc.size());
  char** petsc_args = petsc_argv.data();
  if(PetscInitialize(&petsc_argc, &petsc_args, nullptr, nullptr) != 0)
  {
    std::fprintf(stderr, "anisotropic_fairing_mpi: PETSc could not be initialised\n");
    return 1;
  }
  int rank = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  PetscPushErrorHandler(on_petsc_error, nullptr);
#ifdef CGAL_LINKED_WITH_TBB
  // one thread per process: the processes are the parallelism (one per core)
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
#endif
  const int code = run_program(split.program, PETSC_COMM_WORLD, rank);
  PetscFinalize();
  return code;
}
