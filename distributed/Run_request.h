// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What anisotropic_fairing_mpi accepts of the program anisotropic_fairing's command line, and the split of
// its arguments between the program (the same flags, the same meaning) and PETSc (single-dash options
// such as -pc_type gamg, -ksp_rtol 1e-12, -mat_partitioning_type ptscotch, -log_view). The default run and
// the paper's flow are supported; what needs a part not distributed yet (the linear element, a
// factorisation, resampling, snapshots) is refused by name, never replaced by something else.

#ifndef AF_DISTRIBUTED_RUN_REQUEST_H
#define AF_DISTRIBUTED_RUN_REQUEST_H

#include "options.h"

#include <string>
#include <vector>

namespace af_distributed {

/// The program's arguments (argv[0] first) and PETSc's (argv[0] first too).
struct Split_arguments
{
  std::vector<std::string> program, petsc;
};

/// A single-dash word longer than a short flag (-q, -h) is PETSc's; its value follows unless the next
/// argument is an option itself (a number is a value).
Split_arguments split_arguments(int argc, char** argv);

/// Empty if `o` asks for a run this program makes; otherwise why not, naming the flag.
std::string unsupported(const af_tool::Options& o);

} // namespace af_distributed

#endif // AF_DISTRIBUTED_RUN_REQUEST_H
