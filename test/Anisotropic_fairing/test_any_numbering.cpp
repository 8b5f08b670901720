// The same result whatever the numbering of the input (the manual's Validation page, "Reproducibility"): the
// default run on a mesh, and on the same mesh with its vertices and faces shuffled and each face's corners
// rotated, moves every vertex to the same place to 1e-9 of the diagonal, with the same steps and the same flow
// kept. The numbering the run works in is made from the mesh's geometry (Locality_ordering.h) and the numbers it
// draws per vertex come from the vertex's input position (Vertex_keys.h), so nothing of the caller's numbering
// is left but the order of sums.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include "test_support/check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace AF = CGAL::Anisotropic_fairing;

namespace {

// `m` with vertex v at position new_of_old[v], the faces in a shuffled order and each face's corners rotated
Mesh shuffled(const Mesh& m, std::vector<std::size_t>& new_of_old, unsigned seed)
{
  std::mt19937 random(seed);
  const std::size_t n = num_vertices(m);
  std::vector<std::size_t> old_of_new(n);
  for(std::size_t i = 0; i < n; ++i) old_of_new[i] = i;
  std::shuffle(old_of_new.begin(), old_of_new.end(), random);
  new_of_old.assign(n, 0);
  for(std::size_t i = 0; i < n; ++i) new_of_old[old_of_new[i]] = i;
  Mesh out;
  for(std::size_t i = 0; i < n; ++i) out.add_vertex(m.point(Vertex(Mesh::size_type(old_of_new[i]))));
  std::vector<std::vector<Vertex>> faces;
  for(auto f : m.faces())
  {
    std::vector<Vertex> corners;
    for(Vertex v : vertices_around_face(m.halfedge(f), m)) corners.push_back(Vertex(Mesh::size_type(new_of_old[v])));
    std::rotate(corners.begin(), corners.begin() + std::ptrdiff_t(random() % corners.size()), corners.end());
    faces.push_back(corners);
  }
  std::shuffle(faces.begin(), faces.end(), random);
  for(const auto& c : faces) out.add_face(c);
  return out;
}

// `m` with Gaussian noise of `relative` mean edge lengths on each coordinate
Mesh noisy(Mesh m, double relative, unsigned seed)
{
  double edge = 0;
  for(auto e : edges(m)) edge += CGAL::Polygon_mesh_processing::edge_length(halfedge(e, m), m);
  edge /= double(num_edges(m));
  std::mt19937 random(seed);
  std::normal_distribution<double> gauss(0.0, relative * edge);
  for(Vertex v : m.vertices())
  {
    const K::Point_3 p = m.point(v);
    m.point(v) = K::Point_3(p.x() + gauss(random), p.y() + gauss(random), p.z() + gauss(random));
  }
  return m;
}

void same_on_any_numbering(const char* what, const Mesh& input)
{
  Mesh a = input;
  const AF::Fairing_report ra = AF::anisotropic_fairing(a);
  AF_CHECK(ra.succeeded() && !ra.steps.empty(), (std::string(what) + ": the run succeeded and stepped").c_str());
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(input);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  for(unsigned seed : { 1u, 2u })
  {
    std::vector<std::size_t> new_of_old;
    Mesh b = shuffled(input, new_of_old, seed);
    const AF::Fairing_report rb = AF::anisotropic_fairing(b);
    double largest = 0;
    for(Vertex v : a.vertices())
    {
      const K::Point_3 p = a.point(v), q = b.point(Vertex(Mesh::size_type(new_of_old[v])));
      largest = std::max(largest, std::sqrt(CGAL::squared_distance(p, q)));
    }
    std::printf("%s, shuffled (seed %u): %zu and %zu steps, %s and %s kept; largest difference %.3g of the diagonal\n",
                what, seed, ra.steps.size(), rb.steps.size(), ra.selected_tensor.c_str(), rb.selected_tensor.c_str(),
                largest / diagonal);
    AF_CHECK(rb.succeeded() && rb.steps.size() == ra.steps.size() && rb.selected_tensor == ra.selected_tensor,
             (std::string(what) + ": the shuffled input takes the same steps and keeps the same flow").c_str());
    AF_CHECK(largest <= 1e-9 * diagonal,
             (std::string(what) + ": the shuffled input's vertices end where the input's do").c_str());
  }
}

} // namespace

int main(int argc, char** argv)
{
  const std::string data = argc > 1 ? argv[1] : "data";
  Mesh fandisk, camelhead;
  AF_CHECK(CGAL::IO::read_polygon_mesh(data + "/fandisk0.3_noisy.obj", fandisk), "read fandisk0.3_noisy.obj");
  AF_CHECK(CGAL::IO::read_polygon_mesh(data + "/camelhead.off", camelhead), "read camelhead.off");
  same_on_any_numbering("the default run (Fandisk0.3)", fandisk);
  same_on_any_numbering("the default run (camel head with noise of 0.2 h, a border)", noisy(camelhead, 0.2, 55));
  return AF_test::report();
}
