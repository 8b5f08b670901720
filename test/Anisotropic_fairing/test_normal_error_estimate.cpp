// The estimate of the face normals' error (internal/run/Normal_error_estimate.h) against known truth.
//
// The stiffness matrix: constant functions have no energy, and a linear function a.x on a plane has
// e^T K e = |a|^2 x area. The estimate: a unit icosphere (2562 vertices) with noise of deviation sigma along
// its radii, and results whose error to the sphere is known exactly: the input itself (relative error 1 in
// expectation), the projection onto the sphere (error 0) and the input moved halfway onto it (error
// 0.25 of the input's). Each is estimated with 8 independent probes; their mean must be within 4 standard
// errors of the truth, e_n^T K e_n / tr(K S^2) with e the exact error along the normals, give or take 0.02:
// the data's own fluctuation (this draw's slope energy is 1.2% above its expectation, which is exactly what
// the projection, with no divergence, is estimated at).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Anisotropic_fairing/internal/mesh/Indexed_mesh.h>
#include <CGAL/Anisotropic_fairing/internal/run/Normal_error_estimate.h>

#include "test_support/check.h"
#include "test_support/mesh_generators.h"
#include "test_support/unit_sphere.h"

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace AFI = CGAL::Anisotropic_fairing::internal;

namespace {

using AF_test::toward_sphere;

void stiffness_of_a_plane()
{
  // a 10 x 10 grid of unit squares, each split in two, its vertices jittered within the plane z = 0
  AFI::Control_matrix X(121, 3);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for(int i = 0; i <= 10; ++i)
    for(int j = 0; j <= 10; ++j)
      X.row(11 * i + j) << i + (i % 10 ? jitter(rng) : 0.0), j + (j % 10 ? jitter(rng) : 0.0), 0.0;
  std::vector<std::array<int, 3>> faces;
  for(int i = 0; i < 10; ++i)
    for(int j = 0; j < 10; ++j)
    {
      const int a = 11 * i + j;
      faces.push_back({ a, a + 11, a + 12 });
      faces.push_back({ a, a + 12, a + 1 });
    }
  const AFI::Triangle_topology topo(121, faces, 0);   // every vertex may lie on the border
  const Eigen::SparseMatrix<double> S = AFI::stiffness_matrix(topo, faces.size(), X);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(121), e = X.col(0) * 0.3 - X.col(1) * 0.4;
  const double energy = e.dot(S * e);
  std::printf("plane: |K 1| = %.2e, e^T K e = %.12f (|a|^2 area = %.12f)\n", (S * ones).norm(), energy, 0.25 * 100);
  AF_CHECK((S * ones).norm() < 1e-12, "constants have no energy");
  AF_CHECK(std::abs(energy - 0.25 * 100) < 1e-10, "a linear function's energy is |a|^2 times the area");
}

void estimate_on_a_sphere()
{
  Mesh mesh;
  AF_test::soup_to_mesh(AF_test::icosphere_soup(4), mesh);
  const AFI::Indexed_mesh<Mesh> im(mesh, AFI::Borders::GHOSTED, true);
  const AFI::Ghost_layer& layer = im.ghost_layer();
  const AFI::Control_matrix x = im.read_points(get(CGAL::vertex_point, mesh));
  const std::size_t n = std::size_t(x.rows());
  const double sigma = 0.004;
  AFI::Control_matrix y = x;
  std::mt19937 rng(11);
  std::normal_distribution<double> gauss(0.0, sigma);
  for(Eigen::Index i = 0; i < y.rows(); ++i) y.row(i) *= 1 + gauss(rng);
  const std::vector<double> sigmas(n, sigma);
  const AFI::Control_matrix N = AFI::vertex_normals(*layer.topology, layer.real_faces, x);
  const Eigen::SparseMatrix<double> Ks = AFI::stiffness_matrix(*layer.topology, layer.real_faces, x);
  const struct { const char* name; double w; } results[] = { { "the input", 0.0 }, { "halfway", 0.5 },
                                                             { "the projection", 1.0 } };
  for(const auto& result : results)
  {
    const AFI::Control_matrix f = toward_sphere(y, result.w);
    Eigen::VectorXd e(x.rows());
    for(Eigen::Index i = 0; i < x.rows(); ++i) e[i] = N.row(i).dot(f.row(i) - x.row(i));
    double sum = 0, squares = 0, truth = 0;
    const int probes = 8;
    for(int k = 0; k < probes; ++k)
    {
      std::mt19937 probe_rng(100 + unsigned(k));
      std::normal_distribution<double> unit(0.0, 1.0);
      std::vector<double> b(n);
      for(double& v : b) v = unit(probe_rng);
      const AFI::Normal_error_estimate estimate(y, N, Ks, sigmas, b);
      const AFI::Control_matrix f_probed = toward_sphere(AFI::probed_input(y, N, sigmas, b), result.w);
      const double r = estimate.relative(estimate.terms(f, f_probed));
      truth = e.dot(Ks * e) / estimate.input_error();
      sum += r;
      squares += r * r;
    }
    const double mean = sum / probes, error = std::sqrt((squares / probes - mean * mean) / (probes - 1));
    std::printf("%s: estimate %.4f +- %.4f, truth %.4f\n", result.name, mean, error, truth);
    AF_CHECK(std::abs(mean - truth) < 4 * error + 0.02, std::string("the estimate of ") + result.name + " is unbiased");
  }
}

} // namespace

int main()
{
  stiffness_of_a_plane();
  estimate_on_a_sphere();
  return AF_test::report();
}
