// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The memory a call will still need once its input is read, predicted from the mesh's size and the
// parameters, and the check against what the process may take (Available_memory.h), so that a run that
// cannot fit is refused before its set-up instead of failing with "out of memory" partway.
//
// Everything a run allocates grows with its vertices: the rows of every vector, and the sparse rows of M, L
// and the systems made of them, whose entries per row are the vertices of a 3-ring (37 on a regular mesh).
// So the prediction is bytes per vertex, one figure per kind of run, plus a part per faired column (the
// conjugate gradients' vectors, the results a comparison carries). The figures are the peaks measured above
// the memory in use at the check (bench/memory_estimate.py, 64-bit glibc): Loop-refined fertility of 36,000
// to 2,304,000 triangles with noise, where they fall by 5-10% from the smallest to the largest, and scans
// (face, igea, armadillo, bunny), which take up to 20% more (the face scan's isotropic flow). A clean input,
// which the noise stop leaves before a first step, takes the element's set-up and one assembly. A
// factorisation (Linear_solver::CHOLESKY, or the fixed surface's constant system) adds its factor; an
// automatic run of at most 50,000 vertices may factorise a hard step too, where that factor fits beside the
// run (Stepper_settings::factor_budget): the prediction is of the run without it.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_MEMORY_ESTIMATE_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_MEMORY_ESTIMATE_H

#include <CGAL/Anisotropic_fairing/internal/run/Available_memory.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Solver_choice.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// What decides a run's memory.
struct Memory_plan
{
  enum Flow { UNIFORM, ISOTROPIC, ANISOTROPIC };
  std::size_t vertices = 0;
  int columns = 3;            // faired columns: 3 coordinates, plus the attributes (coupled) or these alone
  bool comparison = false;    // the default run: the anisotropic, isotropic and uniform fourth-order flows
  Flow flow = ANISOTROPIC;    // otherwise the one flow run
  int order = 2;
  bool loop = true;           // the Loop element (else the linear one)
  bool factorised = false;    // every step factorised (Linear_solver::CHOLESKY)
  bool constant_factorised = false;   // a fixed surface's constant system, factorised by AUTOMATIC where it fits
  bool at_noise_level = false;  // the noise stop ends every flow before its first step (a clean input)
};

/// The bytes a run of `p` needs above what the process holds when it is checked (without the factor that
/// AUTOMATIC makes only where it fits: expected_memory()).
inline double predicted_memory(const Memory_plan& p)
{
  // bytes per vertex for three columns, and per further column (measured: see the top of this file)
  double per_vertex = 1680, per_column = 64;   // one second-order flow, isotropic or uniform
  if(!p.loop) per_vertex = 510;
  else if(p.at_noise_level) per_vertex = 1300;   // the element's set-up and one assembly, no step
  else if(p.comparison) { per_vertex = 2450; per_column = 300; }
  else if(p.order == 4) per_vertex = 1460;
  else if(p.flow == Memory_plan::ANISOTROPIC) per_vertex = 1880;
  const double n = double(p.vertices);
  double bytes = n * (per_vertex + per_column * double(p.columns - 3));
  if(p.factorised) bytes += Solver_choice::factor_memory(p.vertices);
  return bytes;
}

/// The bytes a run of `p` is expected to take with `available` bytes: its need, and the constant system's factor
/// where AUTOMATIC makes it, that is where it fits beside the run (Solver_choice.h).
inline double expected_memory(const Memory_plan& p, double available)
{
  const double need = predicted_memory(p), factor = Solver_choice::factor_memory(p.vertices);
  return need + (p.constant_factorised && factor <= available - need ? factor : 0.0);
}

/// "1,234 MB"
inline std::string megabytes(double bytes)
{
  char text[64];
  const double mb = std::round(bytes / (1024.0 * 1024.0));
  if(mb >= 1000) std::snprintf(text, sizeof text, "%.0f,%03.0f MB", std::floor(mb / 1000), std::fmod(mb, 1000));
  else std::snprintf(text, sizeof text, "%.0f MB", mb);
  return text;
}

/// What the process may take: `limit` (the named parameter memory_limit) if given, else what it may still take.
inline Available_memory available_memory(const std::optional<double>& limit)
{
  Available_memory a = available_memory();
  if(limit) a = Available_memory{ *limit, "the memory_limit given", a.in_use };
  return a;
}

/// Why a run of `need` bytes cannot start with `a` available; empty when it fits (or nothing is known).
inline std::string memory_refusal(double need, const Available_memory& a)
{
  if(!(need > a.bytes)) return std::string();
  return "the run needs about " + megabytes(need) + " of memory and " + megabytes(a.bytes) + " are available (" +
         a.source + "); nothing was done: the named parameter memory_limit (the program's --memory-limit) sets "
         "what the run may take, and infinity (off) runs it without this check";
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_MEMORY_ESTIMATE_H
