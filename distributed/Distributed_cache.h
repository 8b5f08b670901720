// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where the library's runs step on the processes: the Loop element's cache the library makes for a call
// (run/Fairing_core.h asks its Elements for it, run/Stepper_call.h), with the faces divided among the
// processes (Face_partition.h, Distributed_layout.h). Its type names the flow operator of every run on it
// (Flow_operator_of in flow/Serial_flow_operator.h): Distributed_flow_operator, so that the whole call --
// the noise estimate, the default run's candidates and their comparison, the stop at the noise level --
// is the library's own code, with M, L(D) and every solve divided among the processes.

#ifndef AF_DISTRIBUTED_DISTRIBUTED_CACHE_H
#define AF_DISTRIBUTED_DISTRIBUTED_CACHE_H

#include "Distributed_layout.h"
#include "Face_partition.h"
#include "Whole_rows.h"

#include <CGAL/Anisotropic_fairing/internal/element/Ghosted_patch_cache.h>
#include <CGAL/Real_timer.h>

#include <mpi.h>

#include <memory>

namespace af_distributed {

namespace AFI = CGAL::Anisotropic_fairing::internal;

/// Per-phase times and counts of a call's runs (the program's JSON report).
struct Flow_timing
{
  double assemble_seconds = 0, solve_seconds = 0, judge_seconds = 0;
  std::size_t iterations = 0, solves = 0;
};

/// What the runs of one call share on this process: the communicator, the faces' layout (made with the
/// cache), and what the report counts.
struct Distributed_state
{
  MPI_Comm comm = MPI_COMM_WORLD;
  int rank = 0, size = 1;
  std::unique_ptr<Distributed_layout> layout;
  double partition_seconds = 0;
  Flow_timing timing;
  std::size_t prefilter_iterations = 0, off_process_columns = 0;
  Communication_volume volume;
};

class Distributed_flow_operator;

/// The Loop patch cache of the whole mesh, its faces divided among the processes of `state`.
class Distributed_patch_cache : public AFI::Ghosted_patch_cache
{
public:
  typedef Distributed_flow_operator Flow_operator;

  /// `part`: the part of the mesh this process holds, when the library's mesh is one (Part_run.cpp)
  Distributed_patch_cache(const AFI::Ghost_layer& layer, const AFI::Quadrature_spec& quadrature,
                          Distributed_state& state, const AFI::Part_view& part)
    : AFI::Ghosted_patch_cache(layer, quadrature), state_(&state)
  {
    CGAL::Real_timer clock;
    clock.start();
    if(part.whole())
      state.layout.reset(new Distributed_layout(make_distributed_layout(
        layer, *this, partition_faces(state.comm, *layer.topology, layer.real_faces), state.rank, state.size)));
    else state.layout.reset(new Distributed_layout(make_part_layout(layer, *this, part, state.comm)));
    state.partition_seconds += clock.time();
  }
  Distributed_state& state() const { return *state_; }

private:
  Distributed_state* state_;
};

/// The library's Elements (run/Stepper_call.h) of the distributed program; `part_of_mesh`: the part of the mesh
/// this process holds, when it gives the library a part (null: every process the whole mesh).
struct Distributed_elements
{
  typedef Distributed_patch_cache Loop_cache;
  Distributed_state* state;
  const AFI::Process_part* part_of_mesh = nullptr;
  Loop_cache loop_cache(const AFI::Ghost_layer& layer, const AFI::Quadrature_spec& quadrature,
                        const AFI::Part_view& part) const
  {
    return Loop_cache(layer, quadrature, *state, part);
  }
  const AFI::Process_part* part() const { return part_of_mesh; }
};

} // namespace af_distributed

#endif // AF_DISTRIBUTED_DISTRIBUTED_CACHE_H
