// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The run in which each process holds its part of the mesh, not the whole mesh (Part_run.cpp).

#ifndef AF_DISTRIBUTED_PART_RUN_H
#define AF_DISTRIBUTED_PART_RUN_H

#include "Distributed_run.h"

#include <string>

namespace af_distributed {

/// The rings of faces a part holds around its own: the Loop patches of its faces (1), the limit points of their
/// neighbours' corners (2: folds), the places a fold near them marks (3, 4: Fold_sites).
constexpr int part_depth = 4;

/// Runs `o` with each process holding its part of the mesh, as run_distributed() runs it. A binary PLY file whose
/// blocks cannot make the parts (a mesh that is not a manifold surface, an attribute the blocks cannot name as the
/// serial program does) is read whole by process 0 instead (summary.mesh_read_why says why), as any other file.
/// False, having run nothing, where the parts cannot run it (summary.whole_mesh_why says why): then it runs whole.
bool run_on_parts(const af_tool::Options& o, MPI_Comm comm, Run_summary& summary);

} // namespace af_distributed

#endif // AF_DISTRIBUTED_PART_RUN_H
