// Mass matrix and area on the limit surface: sum of M = area (partition of unity), symmetry,
// positive definiteness, 37 non-zeros per row on an all-regular torus, the area of the limit
// surface interpolating the unit sphere, and convergence of the adaptive (tiled) quadrature.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>

#include "test_support/cgal_loop_reference.h"
#include "test_support/check.h"
#include "test_support/mesh_generators.h"
#include "test_support/interpolating_sphere.h"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include <cmath>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
namespace AF = CGAL::Anisotropic_fairing;

template <class M>
void check_mass_matrix(const M& mesh, const std::string& name, int degree, int tiling, bool dense_spd)
{
  AF::Loop_limit_surface<M> s(mesh, AF::parameters::quadrature_degree(degree).quadrature_tiling_depth(tiling));
  const Eigen::SparseMatrix<double> Mm = s.mass_matrix();
  const std::string label = name + ", degree " + std::to_string(degree) + ", tiling " + std::to_string(tiling);
  std::printf("%s: area %.15g, sum M %.15g, nnz/row %.2f\n", label.c_str(), s.area(), Mm.sum(),
              double(Mm.nonZeros()) / double(Mm.rows()));
  AF_CHECK_REL(Mm.sum(), s.area(), 1e-13, "sum of M = limit-surface area, " + label);
  const Eigen::SparseMatrix<double> T = Mm.transpose();
  AF_CHECK((Mm - T).norm() == 0.0, "M is exactly symmetric, " + label);
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt(Mm);
  AF_CHECK(llt.info() == Eigen::Success, "M has a Cholesky factorisation (positive definite), " + label);
  if(dense_spd)
  {
    const Eigen::MatrixXd dense = Eigen::MatrixXd(Mm);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(dense);
    const double lmin = es.eigenvalues().minCoeff(), lmax = es.eigenvalues().maxCoeff();
    std::printf("  eigenvalues of M in [%.3g, %.3g], cond %.1f\n", lmin, lmax, lmax / lmin);
    AF_CHECK(lmin > 0, "smallest eigenvalue of M is positive, " + label);
  }
}

int main(int argc, char** argv)
{
  const std::string data = argc > 1 ? argv[1] : "data";
  Mesh tet, oct, ico, mixed, bunny;
  AF_test::make_tetrahedron(tet);
  AF_test::make_octahedron(oct);
  AF_test::make_icosahedron(ico);
  AF_test::make_mixed_valence_mesh(mixed);
  AF_CHECK(CGAL::IO::read_polygon_mesh(data + "/bunny.off", bunny), "read bunny.off");

  check_mass_matrix(tet, "tetrahedron", 8, 0, true);
  check_mass_matrix(oct, "octahedron", 8, 0, true);
  check_mass_matrix(ico, "icosahedron", 8, 0, true);
  check_mass_matrix(ico, "icosahedron", 6, 3, true);
  check_mass_matrix(mixed, "valences 3-9", 8, 0, true);
  check_mass_matrix(mixed, "valences 3-9", 4, 2, false);
  check_mass_matrix(bunny, "bunny", 8, 0, false);
  {
    Polyhedron p;
    AF_test::make_mixed_valence_mesh(p);
    AF::Loop_limit_surface<Polyhedron> sp(p);
    AF::Loop_limit_surface<Mesh> sm(mixed);
    AF_CHECK((sp.mass_matrix() - sm.mass_matrix()).norm() == 0.0, "Polyhedron_3 and Surface_mesh give the same M");
  }

  // all-regular torus: the 3-ring of every vertex has 1 + 6 + 12 + 18 = 37 vertices
  {
    Mesh torus;
    AF_test::make_regular_torus(torus, 12, 10, 2.0, 0.7);
    AF::Loop_limit_surface<Mesh> s(torus);
    const Eigen::SparseMatrix<double> Mm = s.mass_matrix();
    int wrong = 0;
    for(int j = 0; j < Mm.outerSize(); ++j)
      if(Mm.outerIndexPtr()[j + 1] - Mm.outerIndexPtr()[j] != 37) ++wrong;
    std::printf("regular torus: %d of %d rows without exactly 37 non-zeros, %zu patch categories\n",
                wrong, int(Mm.outerSize()), s.number_of_patch_categories());
    AF_CHECK(wrong == 0, "exactly 37 non-zeros per row on the all-regular torus");
    AF_CHECK(s.number_of_patch_categories() == 1, "one patch category on the all-regular torus");
    AF_CHECK_REL(Mm.sum(), s.area(), 1e-13, "sum of M = area on the torus");
  }

  // limit surface interpolating the unit sphere at 642 vertices (doc/Anisotropic_fairing/design/loop-fem-flow.md section 11). With the
  // prototype's rule (point, degree 6) the area is 4 pi to 1e-5, as loop-fem-flow.md reports (1.000000).
  // The converged area is 1.7e-5 smaller: the surface interpolates the sphere at the vertices only
  // (radius 0.99943..1.00040 in between), and the degree-6 point rule's error happens to cancel that.
  // A closed surface enclosing the ball of radius r_min has area at least 4 pi r_min^2.
  {
    Mesh sphere;
    AF_test::make_interpolating_icosphere(sphere, 3);
    AF::Loop_limit_surface<Mesh> s(sphere, AF::parameters::quadrature_degree(6));
    const double ratio = s.area() / (4 * CGAL_PI);
    std::printf("interpolating icosphere, %zu vertices, point degree 6: area / 4 pi = %.9f\n",
                std::size_t(num_vertices(sphere)), ratio);
    AF_CHECK_CLOSE(ratio, 1.0, 1e-5, "area of the interpolating icosphere = 4 pi (point degree 6)");

    const double converged = AF::Loop_limit_surface<Mesh>(sphere, AF::parameters::quadrature_degree(8).quadrature_tiling_depth(6)).area() / (4 * CGAL_PI);
    const double tiled4 = AF::Loop_limit_surface<Mesh>(sphere, AF::parameters::quadrature_degree(6).quadrature_tiling_depth(4)).area() / (4 * CGAL_PI);
    Mesh fine;
    s.resample(4, fine);
    double rmin = 1e300, rmax = 0;
    for(auto v : vertices(fine))
    {
      const double r = std::sqrt((fine.point(v) - CGAL::ORIGIN).squared_length());
      rmin = (std::min)(rmin, r);
      rmax = (std::max)(rmax, r);
    }
    std::printf("  converged (tiled K=6, degree 8) area / 4 pi = %.9f (tiled K=4 degree 6: %.9f); "
                "radius in [%.6f, %.6f]\n", converged, tiled4, rmin, rmax);
    AF_CHECK_CLOSE(converged, tiled4, 1e-7, "tiled quadrature has converged");
    AF_CHECK(converged >= rmin * rmin, "area >= 4 pi r_min^2");
    AF_CHECK_CLOSE(converged, 1.0, 2e-5, "area of the interpolating icosphere = 4 pi to 2e-5 (converged)");

    AF_test::Max_error on_sphere("limit points at the control vertices on the unit sphere");
    Mesh::Property_map<Mesh::Vertex_index, K::Point_3> lim =
        sphere.add_property_map<Mesh::Vertex_index, K::Point_3>("v:limit").first;
    s.limit_positions(lim);
    for(auto v : vertices(sphere)) on_sphere.add_error(std::abs(std::sqrt((lim[v] - CGAL::ORIGIN).squared_length()) - 1));
    on_sphere.print();
    AF_CHECK(on_sphere.value() < 1e-14, "limit_positions() interpolates the sphere vertices");
  }

  // the adaptive (tiled) quadrature converges near extraordinary vertices (loop-fem.md section 5)
  {
    auto area = [&](int degree, int tiling) {
      return AF::Loop_limit_surface<Mesh>(ico, AF::parameters::quadrature_degree(degree).quadrature_tiling_depth(tiling)).area();
    };
    const double ref = area(8, 7), point8 = area(8, 0), point6 = area(6, 0), tiled4 = area(6, 4), tiled6 = area(8, 6);
    std::printf("icosahedron area relative errors vs tiled K=7 deg 8: point deg6 %.2e, point deg8 %.2e, "
                "tiled K=4 deg6 %.2e, tiled K=6 deg8 %.2e\n", std::abs(point6 / ref - 1), std::abs(point8 / ref - 1),
                std::abs(tiled4 / ref - 1), std::abs(tiled6 / ref - 1));
    AF_CHECK(std::abs(point8 / ref - 1) < 3e-3, "point mode within its known near-EV error (1.3e-3)");
    AF_CHECK(std::abs(tiled4 / ref - 1) < 1e-5, "tiled K=4 is 1000 times closer (2.1e-6 expected)");
    AF_CHECK(std::abs(tiled6 / ref - 1) < 3e-7, "tiled K=6 closer still (1.0e-7 expected)");
  }
  return AF_test::report();
}
