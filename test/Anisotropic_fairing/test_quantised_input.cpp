// Inputs whose coordinates lie on a lattice (internal/flow/Coordinate_lattice.h) and control points whose
// limit points are the input (internal/loop/Limit_interpolation.h).
//
// 1. The interpolating control points of a mesh with valences 3 to 9: their limit points, computed by the
//    closed-form masks (vertex_limit_value), are the input to 1e-10.
// 2. The lattice of a sphere rounded to cells (0.01, 0.02, 0.005) from an offset origin is found with
//    exactly those cells; the unrounded sphere, and the rounded one with one vertex moved off the
//    lattice, have none.
// 3. The default run on an 8-bit rounded sphere says so in its choices; given no step, it writes the input
//    back exactly (without the lattice the limit masks would move every vertex inward); with its steps
//    the result is closer to the unit sphere than the rounded input.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Coordinate_lattice.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Limit_interpolation.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Vertex_limit_masks.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Indexed_mesh.h>

#include "test_support/check.h"
#include "test_support/mesh_generators.h"

#include <cmath>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace AF = CGAL::Anisotropic_fairing;
namespace AFI = CGAL::Anisotropic_fairing::internal;

using namespace AF_test;

namespace {

double round_to(double x, double origin, double cell) { return origin + cell * std::round((x - origin) / cell); }

Mesh rounded_sphere(int levels, const double cell[3], const double origin[3])
{
  Triangle_soup soup = icosphere_soup(levels);
  for(auto& p : soup.points)
    for(int a = 0; a < 3; ++a) p[std::size_t(a)] = round_to(p[std::size_t(a)], origin[a], cell[a]);
  Mesh mesh;
  soup_to_mesh(soup, mesh);
  return mesh;
}

double mean_distance_to_unit_sphere(const Mesh& mesh)
{
  double sum = 0;
  for(auto v : vertices(mesh)) sum += std::abs(std::sqrt((mesh.point(v) - CGAL::ORIGIN).squared_length()) - 1);
  return sum / double(num_vertices(mesh));
}

void interpolation_reproduces_the_input()
{
  Mesh mesh;
  soup_to_mesh(mixed_valence_soup(), mesh);
  const AFI::Indexed_mesh<Mesh> im(mesh, AFI::Borders::GHOSTED, true);
  const AFI::Control_matrix Y = im.read_points(get(CGAL::vertex_point, mesh));
  const std::vector<bool> solved(std::size_t(Y.rows()), true);
  AFI::Control_matrix Z;
  AF_CHECK(AFI::interpolating_control_points(im.topology(), Y, solved, Z), "the interpolating control points are found");
  double worst = 0, moved = 0;
  for(Eigen::Index i = 0; i < Y.rows(); ++i)
  {
    double limit[3];
    AFI::vertex_limit_value(im.topology(), Z, int(i), limit);
    for(int a = 0; a < 3; ++a) worst = std::max(worst, std::abs(limit[a] - Y(i, a)));
    moved = std::max(moved, (Z.row(i) - Y.row(i)).norm());
  }
  AF_CHECK(worst < 1e-10, "their limit points are the input (largest difference " + std::to_string(worst) + ")");
  AF_CHECK(moved > 1e-3, "and they are not the input itself (a sphere's limit points lie inside it)");
}

void lattice_found_exactly()
{
  const double cell[3] = { 0.01, 0.02, 0.005 }, origin[3] = { 0.0031, -0.0007, 0.0012 };
  const Mesh mesh = rounded_sphere(4, cell, origin);
  const AFI::Indexed_mesh<Mesh> im(mesh, AFI::Borders::GHOSTED, true);
  AFI::Control_matrix X = im.read_points(get(CGAL::vertex_point, mesh));
  const std::vector<bool> all(std::size_t(X.rows()), true);
  const AFI::Coordinate_lattice lattice = AFI::coordinate_lattice(X, all);
  AF_CHECK(lattice.found, "the rounded sphere's lattice is found");
  for(int a = 0; a < 3; ++a)
    AF_CHECK_REL(lattice.cell[std::size_t(a)], cell[a], 1e-9, "the cell along axis " + std::to_string(a));
  X(7, 1) += 0.3 * cell[1];
  AF_CHECK(!AFI::coordinate_lattice(X, all).found, "one vertex off the lattice: none");
  X(7, 1) -= 0.3 * cell[1];
  AF_CHECK(AFI::coordinate_lattice(X, all).found, "and back on it: found again");

  Mesh smooth;
  soup_to_mesh(icosphere_soup(4), smooth);
  const AFI::Indexed_mesh<Mesh> sm(smooth, AFI::Borders::GHOSTED, true);
  const AFI::Control_matrix S = sm.read_points(get(CGAL::vertex_point, smooth));
  AF_CHECK(!AFI::coordinate_lattice(S, std::vector<bool>(std::size_t(S.rows()), true)).found, "the unrounded sphere has none");
}

void default_run_on_a_quantised_sphere()
{
  const double q = 2.0 / 255;   // 8 bits over the sphere's extent
  const double cell[3] = { q, q, q }, origin[3] = { -1, -1, -1 };
  const Mesh input = rounded_sphere(4, cell, origin);

  Mesh unmoved = input;
  const AF::Fairing_report none = AF::anisotropic_fairing(unmoved, CGAL::parameters::number_of_iterations(0));
  AF_CHECK(none.succeeded(), "no step: " + none.message);
  AF_CHECK(none.choices.find("lattice") != std::string::npos, "the choices name the lattice: " + none.choices);
  double largest = 0;
  for(auto v : vertices(input)) largest = std::max(largest, std::sqrt(CGAL::squared_distance(input.point(v), unmoved.point(v))));
  AF_CHECK(largest < 1e-9, "no step writes the input back (largest move " + std::to_string(largest) + ")");

  Mesh faired = input;
  const AF::Fairing_report r = AF::anisotropic_fairing(faired);
  AF_CHECK(r.succeeded() && !r.steps.empty(), "the default run takes steps: " + r.message);
  const double before = mean_distance_to_unit_sphere(input), after = mean_distance_to_unit_sphere(faired);
  AF_CHECK(after < before, "closer to the sphere than the rounded input: " + std::to_string(after) + " against " + std::to_string(before));
}

} // namespace

int main()
{
  interpolation_reproduces_the_input();
  lattice_found_exactly();
  default_run_on_a_quantised_sphere();
  return report();
}
