// The Loop limit surface of a control mesh, as a mesh of the same connectivity whose vertices are the
// limit positions (what a LIMIT_SURFACE output writes); shared by the denoising benchmarks.

#ifndef AF_BENCH_LOOP_LIMIT_H
#define AF_BENCH_LOOP_LIMIT_H

#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>

#include "bench_cases.h"

inline Mesh limit_mesh(const Mesh& control)
{
  Mesh e = control;
  CGAL::Anisotropic_fairing::Loop_limit_surface<Mesh>(control).limit_positions(e.points());
  return e;
}

#endif // AF_BENCH_LOOP_LIMIT_H
