// Mean-curvature flow of the sphere against its analytic solutions (doc/Anisotropic_fairing/design/loop-fem-flow.md section 11a, 11c):
// on the limit surface interpolating the unit sphere, A/4pi follows the scheme's exact time-discrete
// prediction r_{n+1} = r_n / (1 + 2 tau / r_n^2) and the exact r^2 = 1 - 4t; with a fidelity weight
// the sphere settles at r* = (r0 + sqrt(r0^2 - 8/w))/2, or collapses (and the mesh is left as it was).
// The fourth-order flow dx/dt = -(M^-1 L)^2 x (flow_order 4): on a sphere M^-1 L x = (2/r^2) x, so each
// step is r_{n+1} = r_n / (1 + 4 tau / r_n^4) and the flow r^4 = 1 - 16t; the lumped inverse mass makes
// the discrete rate converge as the mesh is refined.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include "test_support/check.h"
#include "test_support/interpolating_sphere.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace AF = CGAL::Anisotropic_fairing;

const double pi = 3.14159265358979323846;

void mean_curvature_flow(AF::Linear_solver solver, const char* name)
{
  Mesh sphere;
  AF_test::make_interpolating_icosphere(sphere, 3);
  const double tau = 1e-3;
  const AF::Fairing_report r = AF::anisotropic_fairing(sphere,
      AF::parameters::time_step(tau).number_of_iterations(100u).stopping_criteria(AF::Stopping_criteria::none())
                     .output_positions(AF::Output_positions::CONTROL_POINTS).linear_solver(solver));
  AF_CHECK(r.succeeded(), std::string("sphere flow runs, ") + name + ": " + r.message);
  AF_CHECK(r.steps.size() == 100, "exactly 100 steps with the criteria off");
  if(r.steps.size() != 100) return;
  double r2 = r.initial.area / (4 * pi);
  AF_test::Max_error vs_prediction(std::string("A/4pi vs implicit-Euler prediction, t <= 0.1, ") + name);
  AF_test::Max_error vs_exact(std::string("A/4pi vs exact 1 - 4t at t = 0.1, ") + name);
  for(const AF::Fairing_step& s : r.steps)
  {
    const double rn = std::sqrt(r2);
    const double next = rn / (1 + 2 * tau / r2);
    r2 = next * next;
    const double measured = s.area / (4 * pi);
    vs_prediction.add_error(std::abs(measured - r2) / r2);
    if(s.step == 50 || s.step == 100)
      std::printf("  %s t=%.2f: A/4pi = %.6f, prediction %.6f, exact %.6f, %d solver its\n", name, s.time, measured, r2,
                  1 - 4 * s.time, s.solver_iterations);
    if(s.step == 100) vs_exact.add_error(std::abs(measured - (1 - 4 * s.time)) / (1 - 4 * s.time));
  }
  vs_prediction.print();
  vs_exact.print();
  AF_CHECK(vs_prediction.value() < 1e-4, "sphere flow follows r_{n+1} = r_n/(1 + 2 tau/r_n^2) to 1e-4");
  AF_CHECK(vs_exact.value() < 3e-3, "sphere flow follows r^2 = 1 - 4t to 3e-3");
}

// |A/4pi - r^2| / r^2 against the fourth-order step's prediction and the exact flow, after 50 steps of
// tau = 2e-4 (t = 0.01, r^4 = 0.84) on the icosphere of the given level
void fourth_order_flow(int level, AF::Linear_solver solver, double& vs_prediction, double& vs_exact)
{
  Mesh sphere;
  AF_test::make_interpolating_icosphere(sphere, level);
  const double tau = 2e-4;
  const AF::Fairing_report r = AF::anisotropic_fairing(sphere,
      AF::parameters::time_step(tau).flow_order(4).number_of_iterations(50u).stopping_criteria(AF::Stopping_criteria::none())
                     .output_positions(AF::Output_positions::CONTROL_POINTS).linear_solver(solver));
  AF_CHECK(r.succeeded() && r.steps.size() == 50 && r.flow_order == 4, "fourth-order sphere flow runs 50 steps: " + r.message);
  vs_prediction = vs_exact = HUGE_VAL;
  if(r.steps.size() != 50) return;
  double rn = std::sqrt(r.initial.area / (4 * pi));
  vs_prediction = 0;
  for(const AF::Fairing_step& s : r.steps)
  {
    rn /= 1 + 4 * tau / std::pow(rn, 4);
    vs_prediction = std::max(vs_prediction, std::abs(s.area / (4 * pi) - rn * rn) / (rn * rn));
  }
  const double exact = std::sqrt(1 - 16 * r.steps.back().time);
  vs_exact = std::abs(r.steps.back().area / (4 * pi) - exact) / exact;
  std::printf("  fourth order, level %d: A/4pi = %.6f, prediction %.6f, exact %.6f; errors %.2e, %.2e\n", level,
              r.steps.back().area / (4 * pi), rn * rn, exact, vs_prediction, vs_exact);
}

int main()
{
  {
    double p3, e3, p4, e4, pc, ec;
    fourth_order_flow(3, AF::Linear_solver::CONJUGATE_GRADIENT, p3, e3);
    fourth_order_flow(4, AF::Linear_solver::CONJUGATE_GRADIENT, p4, e4);
    fourth_order_flow(3, AF::Linear_solver::CHOLESKY, pc, ec);
    // halving h divides the error of the lumped rate by about 4 (measured 7)
    AF_CHECK(p4 < p3 / 3 && e4 < e3 / 3, "the fourth-order sphere flow converges as the sphere is refined (O(h^2) or better)");
    AF_CHECK(p4 < 1e-3 && e4 < 1e-3, "fourth-order sphere flow follows r_{n+1} = r_n/(1 + 4 tau/r_n^4) and r^4 = 1 - 16t at level 4");
    AF_CHECK(std::abs(pc - p3) < 1e-6, "the factorised and the iterative fourth-order steps agree");
  }
  mean_curvature_flow(AF::Linear_solver::CONJUGATE_GRADIENT, "CG");
  mean_curvature_flow(AF::Linear_solver::CHOLESKY, "LDLT");
  return AF_test::report();
}
