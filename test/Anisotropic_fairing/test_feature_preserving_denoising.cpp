// Feature-preserving denoising on real data (issue 6's acceptance point): on the Fandisk0.3 pair
// (Noisy and Original with the same connectivity), the anisotropic tensor's mean face-normal angle
// error to Original is at most 0.6 times the isotropic one, each at the best point of a small sweep.
// Results are the Loop limit surfaces (LIMIT_SURFACE output); the truth is the noise-free Original.
//
// The sweeps are small cuts of bench_denoising's (where the full ones and their tables live):
// isotropic tau_rel {3e-4, 1e-3, 3e-3} x steps {1, 2, 3} (its best there, 10.16 deg, is 1e-3 x 1);
// anisotropic with the default tensor (lambda_rel 2, prefilter eps_rel 1e-3, normal motion along M_eps's
// normal), tau_rel {3e-4, 1e-3} x steps {5, 10} (its best there within 10 steps, 3.50 deg, is 3e-4 x 10).
// tau = tau_rel l^2 with l^2 = Area(Noisy)/(4 pi). The anisotropic result must also stay below the
// issue's bar of 4.0 deg.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include "test_support/check.h"
#include "test_support/denoising_pair.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace AF = CGAL::Anisotropic_fairing;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

using AF_test::mean_normal_angle;
using AF_test::read_obj_in_order;

template <typename Tensor>
double best_angle(const Mesh& noisy, const Mesh& original, double l2, const std::vector<double>& taus,
                  const std::vector<int>& steps, const Tensor& tensor, const char* name)
{
  double best = 180;
  std::string where;
  for(double tau_rel : taus)
    for(int k : steps)
    {
      Mesh m = noisy;
      const AF::Fairing_report r = AF::anisotropic_fairing(m, AF::parameters::time_step(tau_rel * l2)
                                                                .number_of_iterations(k)
                                                                .stopping_criteria(AF::Stopping_criteria::none())
                                                                .diffusion_tensor(tensor));
      AF_CHECK(r.succeeded() && r.steps.size() == std::size_t(k), "every run of the sweep succeeds");
      const double a = mean_normal_angle(m, original);
      std::printf("  %s tau_rel %g x %d: %.2f deg\n", name, tau_rel, k, a);
      if(a < best)
      {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%g x %d", tau_rel, k);
        best = a; where = buffer;
      }
    }
  std::printf("%s best: %.2f deg (tau_rel %s)\n", name, best, where.c_str());
  return best;
}

int main(int argc, char** argv)
{
  const std::string dir = argc > 1 ? argv[1] : "data";
  Mesh noisy, original;
  if(!AF_CHECK(read_obj_in_order(dir + "/fandisk0.3_noisy.obj", noisy) &&
               read_obj_in_order(dir + "/fandisk0.3_original.obj", original) &&
               num_faces(noisy) == num_faces(original), "read the Fandisk0.3 pair"))
    return AF_test::report();
  const double l2 = PMP::area(noisy) / (4 * 3.14159265358979323846);
  std::printf("Fandisk0.3: %zu vertices, %zu faces; noisy input %.2f deg\n", num_vertices(noisy), num_faces(noisy),
              mean_normal_angle(noisy, original));

  const double isotropic = best_angle(noisy, original, l2, { 3e-4, 1e-3, 3e-3 }, { 1, 2, 3 },
                                      AF::Isotropic_diffusion_tensor(), "isotropic");
  const double anisotropic = best_angle(noisy, original, l2, { 3e-4, 1e-3 }, { 5, 10 },
                                        AF::Anisotropic_diffusion_tensor(), "anisotropic");
  std::printf("ratio anisotropic / isotropic: %.3f\n", anisotropic / isotropic);
  AF_CHECK(anisotropic <= 0.6 * isotropic, "the anisotropic tensor's error is at most 0.6x the isotropic one");
  AF_CHECK(anisotropic <= 4.0, "the anisotropic result reaches the 4.0 deg bar");
  AF_CHECK(isotropic > 9, "isotropic diffusion cannot keep the creases (above 9 deg, as every isotropic method in bench_denoising)");
  return AF_test::report();
}
