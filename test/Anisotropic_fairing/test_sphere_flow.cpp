// Mean-curvature flow of the sphere against its analytic solutions (doc/Anisotropic_fairing/design/loop-fem.md section 11a, 11c):
// on the limit surface interpolating the unit sphere, A/4pi follows the scheme's exact time-discrete
// prediction r_{n+1} = r_n / (1 + 2 tau / r_n^2) and the exact r^2 = 1 - 4t; with a fidelity weight
// the sphere settles at r* = (r0 + sqrt(r0^2 - 8/w))/2, or collapses (and the mesh is left as it was).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include "test_support/check.h"
#include "test_support/interpolating_sphere.h"

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

int main()
{
  mean_curvature_flow(AF::Linear_solver::CONJUGATE_GRADIENT, "CG");
  mean_curvature_flow(AF::Linear_solver::CHOLESKY, "LDLT");
  return AF_test::report();
}
