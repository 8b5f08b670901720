// Fairs noisy texture coordinates on a fixed surface (Bajaj & Xu's case c; cf. their Fig. 14): a
// patch of a torus carries its (u, v) parameters as a CGAL::Point_2 per vertex, with noise added to
// the interior ones (the border, the texture's seam, is exact and held). The geometry is not
// touched; the matrices are assembled and factorised once and each step is one solve.
//
// usage: texture_coordinates_fairing [OUTPUT.off]
// Prints the RMS error of the texture coordinates before and after; exits 1 if it did not halve.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include <cmath>
#include <iostream>
#include <random>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace AF = CGAL::Anisotropic_fairing;

int main(int argc, char** argv)
{
  // three quarters of a torus (R = 2, r = 0.7) in both directions: an open patch, 61 x 41 vertices
  const int nu = 61, nv = 41;
  const double R = 2, r = 0.7, two_pi = 6.283185307179586;
  Mesh mesh;
  auto uv = mesh.add_property_map<Vertex, K::Point_2>("v:uv").first;
  std::vector<Vertex> grid;
  std::vector<K::Point_2> exact;
  for(int i = 0; i < nv; ++i)
    for(int j = 0; j < nu; ++j)
    {
      const double u = 0.75 * j / (nu - 1), v = 0.75 * i / (nv - 1);
      const double a = two_pi * u, b = two_pi * v;
      const Vertex x = mesh.add_vertex(K::Point_3((R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a), r * std::sin(b)));
      grid.push_back(x);
      exact.emplace_back(u, v);
    }
  for(int i = 0; i + 1 < nv; ++i)
    for(int j = 0; j + 1 < nu; ++j)
    {
      const int a = i * nu + j, b = a + 1, c = a + nu, d = c + 1;
      mesh.add_face(grid[a], grid[b], grid[d]);
      mesh.add_face(grid[a], grid[d], grid[c]);
    }
  std::mt19937 rng(14);
  std::normal_distribution<double> noise(0, 0.004);   // about a third of the parameter spacing
  for(Vertex x : mesh.vertices())
  {
    const K::Point_2& e = exact[std::size_t(x)];
    uv[x] = mesh.is_border(x) ? e : K::Point_2(e.x() + noise(rng), e.y() + noise(rng));
  }
  auto rms_error = [&] {
    double s = 0;
    for(Vertex x : mesh.vertices()) s += CGAL::squared_distance(uv[x], exact[std::size_t(x)]);
    return std::sqrt(s / double(mesh.number_of_vertices()));
  };
  const double before = rms_error();

  const AF::Fairing_report report = AF::anisotropic_fairing(mesh, mesh.points(), uv,
      AF::parameters::attribute_mode(AF::Attribute_mode::ATTRIBUTES_ONLY)
                     .relative_time_step(1e-3)
                     .number_of_iterations(4)
                     .output_positions(AF::Output_positions::CONTROL_POINTS));
  if(!report.succeeded())
  {
    std::cerr << "fairing failed: " << report.message << "\n";
    return 1;
  }
  const double after = rms_error();
  std::cout << "texture coordinates on a torus patch (" << mesh.number_of_vertices() << " vertices, "
            << report.boundary_vertices << " on the seam, held): RMS error " << before << " -> " << after << " after "
            << report.steps.size() << " steps (" << (report.used_cholesky ? "one factorisation" : "conjugate gradients")
            << ", " << report.total_seconds << " s)\n";
  if(argc > 1)
  {
    // the faired texture domain as a flat mesh (u, v, 0), to look at
    Mesh flat = mesh;
    for(Vertex x : flat.vertices()) flat.point(x) = K::Point_3(uv[x].x(), uv[x].y(), 0);
    CGAL::IO::write_polygon_mesh(argv[1], flat, CGAL::parameters::stream_precision(17));
  }
  return after * 2 <= before ? 0 : 1;
}
