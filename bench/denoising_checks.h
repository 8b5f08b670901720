// Checks of bench_denoising's method: does the incremental sweep (one step per call, CONTROL_POINTS
// output, Loop limit evaluated here) give what one call with k steps and LIMIT_SURFACE output gives?
// To round-off with CHOLESKY; to the CG tolerance with CG, which the single call warm-starts from the
// previous step's displacement, and the one-step calls from zero. The anisotropic sweep passes its
// threshold in absolute units (lambda_rel / l0, l0 of the Loop limit of Noisy), which is what one
// multi-step call with the relative tensor uses (it measures l once on its input).

#ifndef AF_BENCH_DENOISING_CHECKS_H
#define AF_BENCH_DENOISING_CHECKS_H

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include "bench_cases.h"
#include "denoising_sweeps.h"   // aniso_tensor
#include "loop_limit.h"

#include <algorithm>
#include <cmath>

// k incremental one-step calls (CONTROL_POINTS) of Loop with `tensor` and `solver`; returns the control points.
template <typename Tensor>
Mesh run_incremental(const Mesh& noisy, double tau, int k, const Tensor& tensor,
                     AF::Linear_solver solver = AF::Linear_solver::AUTOMATIC)
{
  Mesh m = noisy;
  for(int i = 0; i < k; ++i)
    AF::anisotropic_fairing(m, AF::parameters::time_step(tau).number_of_iterations(1)
                                   .stopping_criteria(AF::Stopping_criteria::none())
                                   .linear_solver(solver)
                                   .diffusion_tensor(tensor)
                                   .output_positions(AF::Output_positions::CONTROL_POINTS));
  return m;
}

// The largest distance between corresponding vertices of the limit surface of `control` and of `direct`,
// over `diagonal`.
double limit_difference(const Mesh& control, const Mesh& direct, double diagonal)
{
  const Mesh e = limit_mesh(control);
  double d = 0;
  for(Mesh::Vertex_index v : e.vertices()) d = std::max(d, std::sqrt(CGAL::squared_distance(e.point(v), direct.point(v))));
  return d / diagonal;
}

// The isotropic Loop sweep's incremental form vs one k-step LIMIT_SURFACE call with `solver`.
double equivalence(const Mesh& noisy, double tau, int k, AF::Linear_solver solver, double diagonal, bool* factorised = nullptr)
{
  Mesh direct = noisy;
  const AF::Fairing_report r = AF::anisotropic_fairing(direct, AF::parameters::time_step(tau).number_of_iterations(k)
                                      .stopping_criteria(AF::Stopping_criteria::none())
                                      .linear_solver(solver)
                                      .output_positions(AF::Output_positions::LIMIT_SURFACE));
  if(factorised) *factorised = r.used_cholesky;
  return limit_difference(run_incremental(noisy, tau, k, AF::Isotropic_diffusion_tensor(), solver), direct, diagonal);
}

// The anisotropic sweep's incremental form (absolute threshold lambda_rel / l0, prefilter eps_rel l0^2) vs
// one k-step LIMIT_SURFACE call with the relative tensor.
double equivalence_aniso(const Mesh& noisy, double tau, int k, double lambda_rel, double epsilon_rel, double l0, double diagonal)
{
  Mesh direct = noisy;
  AF::anisotropic_fairing(direct, AF::parameters::time_step(tau).number_of_iterations(k)
                                      .stopping_criteria(AF::Stopping_criteria::none())
                                      .diffusion_tensor(aniso_tensor(lambda_rel, epsilon_rel, true))
                                      .output_positions(AF::Output_positions::LIMIT_SURFACE));
  return limit_difference(run_incremental(noisy, tau, k, aniso_tensor(lambda_rel / l0, epsilon_rel * l0 * l0)), direct, diagonal);
}

#endif // AF_BENCH_DENOISING_CHECKS_H
