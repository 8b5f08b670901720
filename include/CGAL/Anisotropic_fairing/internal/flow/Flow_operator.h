// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the flow loop (Flow_loop.h) asks of the machine it runs on: one process (Serial_flow_operator.h) or
// several (the distributed program's Distributed_flow_operator). An operator assembles M and L(D) on a
// surface, solves a step, moves the free rows and measures a surface; its measures are of the whole mesh
// (reduced over the processes), so every process takes the loop's decisions alike. Its members:
//
//   const Flow_mesh& mesh()                           the mesh, its components and edge lengths
//   std::string unsupported(settings, fixed)          what of the settings it cannot run (empty: all)
//   std::size_t vertex_count(), free_count()          the vertices of the whole mesh, and its free ones
//   largest(x), total(x), everywhere(b)               the largest of the processes' x, their sum, whether b holds
//                                                     on each
//   free_rows()                                       the free rows this process owns (a bound judges them)
//   units:     assemble_isotropic(X, columns, kept), discard_isotropic(), set_prefilter(eps, settings),
//              set_units(units, statistics, component_scale), units(), where_face(statistics)
//   operator:  assemble(X, columns, tensor, with_matrices), error(), save(), restore(X, columns, tensor),
//              prefiltered(), dirichlet_energy(Z)
//   step:      start_solver(settings, columns, fixed, fidelity, anchor, Z0), solve(factor, Z, Z0, weights),
//              displacement(), solution_finite(statistics), solve_seconds()
//   motion:    move(Zc, dZ, Z0, columns, row_unit), add(X, dZ), normal_part(surface, columns, dZ), moves_normally()
//   measures:  measured_positions(X, Y), limit_points(X, Y), count_folds(X, soundness),
//              input_folds(X, soundness), all_finite(X)

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_FLOW_OPERATOR_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_FLOW_OPERATOR_H

#include <CGAL/Anisotropic_fairing/internal/assembly/Fem_assembly.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_safety.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Mesh_components.h>

#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The mesh a flow runs on, the same on every process.
struct Flow_mesh
{
  const Ghost_layer& layer;
  const Mesh_components& components;
  const std::vector<double>& component_edge;   // the mean edge length of each component
  double mean_edge;                            // of the whole mesh
};

/// What the assembler of a flow is told besides the caller's `numbering`: the components, the curvature
/// each component's edges can show (|H| up to 2 / h, a sphere of diameter h: `curvature_bound`, kept by the
/// caller) and the turns that count as folded and bent.
inline Assembly_context flow_context(const Assembly_context& numbering, const Flow_mesh& mesh,
                                     std::vector<double>& curvature_bound)
{
  curvature_bound.clear();
  for(double h : mesh.component_edge) curvature_bound.push_back(2 / h);
  Assembly_context context = numbering;
  context.face_component = &mesh.components.of_face;
  context.components = mesh.components.count;
  context.curvature_bound = &curvature_bound;
  context.folded_turn = turn_120;
  context.bent_turn = turn_110;
  return context;
}

/// How far a step moved the surface: its largest motion, and the largest total one off the input; in model
/// units and in each row's unit (the stopping criteria's).
struct Step_motion
{
  double step = 0, total = 0, step_relative = 0, total_relative = 0;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_FLOW_OPERATOR_H
