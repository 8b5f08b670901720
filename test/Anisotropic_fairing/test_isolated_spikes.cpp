// Impulsive noise (internal/flow/Isolated_spikes.h): isolated spikes are put back at the centroids of their
// rings before the default run estimates the noise, and only when they are a population.
//
// Truth: the unit sphere (an icosphere, every vertex on it) with a tenth of its vertices thrown off it by
// 0.8 h along the radius, either way. Nearly all the vertices moved must be spikes thrown and nearly all
// spikes must be moved, the mesh must come back close to the sphere, and the default run must then write
// a surface whose normals are close to the radial ones. Left exactly as they
// are: the clean sphere, the clean fandisk (creases and corners stand out with their neighbours, not
// alone), and the sphere with one vertex in a hundred thrown off (too few to be noise: tips of a clean
// mesh are that many).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Isolated_spikes.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Indexed_mesh.h>

#include "test_support/check.h"
#include "test_support/mesh_generators.h"

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace AF = CGAL::Anisotropic_fairing;
namespace AFI = CGAL::Anisotropic_fairing::internal;

namespace {

double mean_edge(const Mesh& m)
{
  double s = 0;
  for(auto e : m.edges()) s += std::sqrt(CGAL::squared_distance(m.point(m.source(m.halfedge(e))), m.point(m.target(m.halfedge(e)))));
  return s / double(m.number_of_edges());
}

// every vertex of the mesh is a candidate (a closed mesh, nothing held)
std::size_t spikes_removed(const Mesh& m, AFI::Control_matrix& X)
{
  const AFI::Indexed_mesh<Mesh> im(m, AFI::Borders::GHOSTED, true);
  X = im.read_points(get(CGAL::vertex_point, m));
  return AFI::remove_isolated_spikes(*im.ghost_layer().topology, std::vector<bool>(m.number_of_vertices(), true), X);
}

// a share `rate` of the sphere's vertices moved off it by 0.8 h along the radius, either way
std::vector<bool> throw_spikes(Mesh& m, double rate, unsigned seed)
{
  const double h = mean_edge(m);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<bool> thrown(m.number_of_vertices(), false);
  for(auto v : m.vertices())
    if(unit(rng) < rate)
    {
      const K::Vector_3 r = m.point(v) - CGAL::ORIGIN;
      m.point(v) = m.point(v) + (unit(rng) < 0.5 ? -0.8 : 0.8) * h * r / std::sqrt(r.squared_length());
      thrown[v.idx()] = true;
    }
  return thrown;
}

// mean angle, in degrees, between each face's normal and the radius through its centroid
double radial_normal_error(const Mesh& m)
{
  double sum = 0;
  for(auto f : m.faces())
  {
    const auto h = m.halfedge(f);
    const K::Point_3 &a = m.point(m.source(h)), &b = m.point(m.target(h)), &c = m.point(m.target(m.next(h)));
    const K::Vector_3 n = CGAL::cross_product(b - a, c - a), r = CGAL::centroid(a, b, c) - CGAL::ORIGIN;
    sum += std::acos(std::min(1.0, n * r / std::sqrt(n.squared_length() * r.squared_length()))) * 180 / M_PI;
  }
  return sum / double(m.number_of_faces());
}

} // namespace

int main(int argc, char** argv)
{
  const std::string data = argc > 1 ? argv[1] : "data";
  Mesh sphere;
  AF_test::soup_to_mesh(AF_test::icosphere_soup(4), sphere);   // 2562 vertices on the unit sphere
  const double h = mean_edge(sphere);
  AFI::Control_matrix X;

  AF_CHECK(spikes_removed(sphere, X) == 0, "the clean sphere has no spike");
  Mesh fandisk;
  AF_CHECK(CGAL::IO::read_polygon_mesh(data + "/fandisk0.3_original.obj", fandisk), "fandisk0.3_original.obj is read");
  const std::size_t fandisk_spikes = spikes_removed(fandisk, X);
  std::printf("clean fandisk: %zu spikes\n", fandisk_spikes);
  AF_CHECK(fandisk_spikes == 0, "the clean fandisk's creases and corners are not spikes");

  Mesh sparse = sphere;
  const std::vector<bool> few = throw_spikes(sparse, 0.01, 3);
  std::size_t thrown_few = 0;
  for(bool t : few) thrown_few += t ? 1 : 0;
  AFI::Control_matrix before;
  {
    const AFI::Indexed_mesh<Mesh> im(sparse, AFI::Borders::GHOSTED, true);
    before = im.read_points(get(CGAL::vertex_point, sparse));
  }
  const std::size_t sparse_removed = spikes_removed(sparse, X);
  std::printf("%zu spikes thrown (1%%): %zu removed\n", thrown_few, sparse_removed);
  AF_CHECK(thrown_few > 0 && sparse_removed == 0 && (X - before).norm() == 0, "one vertex in a hundred is left as it is");

  Mesh noisy = sphere;
  const std::vector<bool> thrown = throw_spikes(noisy, 0.1, 5);
  std::size_t thrown_count = 0, moved_thrown = 0, moved_unthrown = 0;
  double noisy_off = 0, repaired_off = 0;   // mean distance to the sphere
  for(bool t : thrown) thrown_count += t ? 1 : 0;
  const std::size_t removed = spikes_removed(noisy, X);
  // the rows of X are in the mesh's vertex order (Indexed_mesh keeps it)
  for(auto v : noisy.vertices())
  {
    const Eigen::Index i = Eigen::Index(v.idx());
    const K::Point_3& p = noisy.point(v);
    const bool moved = X(i, 0) != p.x() || X(i, 1) != p.y() || X(i, 2) != p.z();
    (thrown[v.idx()] ? moved_thrown : moved_unthrown) += moved ? 1 : 0;
    noisy_off += std::abs(std::sqrt((p - CGAL::ORIGIN).squared_length()) - 1) / double(noisy.number_of_vertices());
    repaired_off += std::abs(X.row(i).norm() - 1) / double(noisy.number_of_vertices());
  }
  std::printf("%zu spikes thrown (10%%): %zu vertices moved, %zu of them thrown; mean distance to the sphere %.3f h, noisy %.3f h\n",
              thrown_count, removed, moved_thrown, repaired_off / h, noisy_off / h);
  // a clean vertex between spikes can be taken for one: most, not all, of the vertices moved are spikes
  AF_CHECK(removed == moved_thrown + moved_unthrown && moved_thrown >= 0.9 * double(removed), "nine in ten of the vertices moved are spikes");
  AF_CHECK(moved_thrown >= 0.85 * double(thrown_count), "and at least 85% of the spikes are moved");
  AF_CHECK(repaired_off < 0.25 * noisy_off, "the mesh is four times closer to the sphere");

  // the default run: the spikes go first, then the flows
  const double noisy_error = radial_normal_error(noisy);
  Mesh faired = noisy;
  const AF::Fairing_report r = AF::anisotropic_fairing(faired);
  const double faired_error = radial_normal_error(faired);
  std::printf("default run: %zu spikes removed, %s; normal error %.2f degrees (noisy %.2f)\n", r.removed_spikes,
              AF::to_string(r.stop_reason), faired_error, noisy_error);
  AF_CHECK(r.succeeded() && r.removed_spikes == removed, "the default run removes the same spikes");
  AF_CHECK(r.choices.find("isolated spikes") != std::string::npos, "and says so in its choices");
  AF_CHECK(faired_error < 0.2 * noisy_error, "its normals are close to the sphere's");

  Mesh clean_run = sphere;
  const AF::Fairing_report rc = AF::anisotropic_fairing(clean_run);
  AF_CHECK(rc.succeeded() && rc.removed_spikes == 0, "the default run on the clean sphere removes nothing");
  return AF_test::report();
}
