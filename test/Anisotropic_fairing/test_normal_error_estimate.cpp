// The estimate of the face normals' error (internal/run/Normal_error_estimate.h) against known truth.
//
// The loss: on a plane, a linear displacement a.x along the normal turns every face by a: |a|^2 x the area;
// motion within the plane turns no face: 0. The estimate: a unit icosphere (2562 vertices) with noise of
// deviation sigma along its radii, and results whose error to the sphere is known exactly: the input itself
// (relative error 1 in expectation), the projection onto the sphere (error 0) and the input moved halfway onto
// it (0.25 of the input's); the faces' normals and stiffness read on the sphere, then on the input a quarter of
// the way to it (a surface that still follows the noise). Each is estimated with 8 independent probes; their
// mean must be within 4 standard errors of the loss computed with the sphere, give or take 0.02: the data's own
// fluctuation (this draw's slope energy is 1.2% above its expectation, which is exactly what the projection,
// with no divergence, is estimated at).

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

// a 10 x 10 grid of unit squares, each split in two, its vertices jittered within the plane z = 0
void plane_loss()
{
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
  const std::vector<double> ones(121, 1.0);
  const AFI::Normal_error_estimate estimate(topo, faces.size(), X, X, ones, ones);
  // a linear displacement 0.3 x - 0.4 y along the normal turns every face by the same gradient: |a|^2 x area
  AFI::Control_matrix tilted = X, drifted = X;
  for(Eigen::Index i = 0; i < X.rows(); ++i)
  {
    tilted(i, 2) += 0.3 * X(i, 0) - 0.4 * X(i, 1);
    drifted(i, 0) += 0.1 * std::sin(double(i));   // within the plane: no face turns
    drifted(i, 1) += 0.1 * std::cos(double(3 * i));
  }
  const double tilt = estimate.relative_loss(tilted, X) * estimate.input_error();
  const double drift = estimate.relative_loss(drifted, X) * estimate.input_error();
  std::printf("plane: loss of a tilt %.12f (|a|^2 area = %.12f), of a drift within the plane %.2e\n", tilt, 0.25 * 100,
              drift);
  AF_CHECK(std::abs(tilt - 0.25 * 100) < 1e-10, "a linear normal displacement's loss is |a|^2 times the area");
  AF_CHECK(std::abs(drift) < 1e-20, "motion within the faces' planes costs nothing");
}

// `surface`: where the estimate reads its faces' normals and stiffness
void estimate_on_a_sphere(const char* which, double smoothing)
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
  const AFI::Control_matrix surface = toward_sphere(y, smoothing);
  const struct { const char* name; double w; } results[] = { { "the input", 0.0 }, { "halfway", 0.5 },
                                                             { "the projection", 1.0 } };
  for(const auto& result : results)
  {
    const AFI::Control_matrix f = toward_sphere(y, result.w);
    double sum = 0, squares = 0, truth = 0;
    const int probes = 8;
    for(int k = 0; k < probes; ++k)
    {
      std::mt19937 probe_rng(100 + unsigned(k));
      std::normal_distribution<double> unit(0.0, 1.0);
      std::vector<double> b(n);
      for(double& v : b) v = unit(probe_rng);
      const AFI::Normal_error_estimate estimate(*layer.topology, layer.real_faces, y, surface, sigmas, b);
      const double r = estimate.relative(f, toward_sphere(estimate.probed(), result.w));
      truth = estimate.relative_loss(f, x);
      sum += r;
      squares += r * r;
    }
    const double mean = sum / probes, error = std::sqrt((squares / probes - mean * mean) / (probes - 1));
    std::printf("measured on %s: %s: estimate %.4f +- %.4f, truth %.4f\n", which, result.name, mean, error, truth);
    AF_CHECK(std::abs(mean - truth) < 4 * error + 0.02, std::string("the estimate of ") + result.name + " is unbiased");
  }
}

} // namespace

int main()
{
  plane_loss();
  estimate_on_a_sphere("the sphere", 1.0);
  estimate_on_a_sphere("the input a quarter of the way to the sphere", 0.25);
  return AF_test::report();
}
