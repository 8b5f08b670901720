// Bad input is refused with an Input_error naming the problem and the element, before anything is
// computed or written; the user's mesh (including its property list) is left as it was.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>
#include <CGAL/Anisotropic_fairing/internal/Triangle_topology.h>

#include "test_support/check.h"
#include "test_support/mesh_generators.h"

#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace AF = CGAL::Anisotropic_fairing;
typedef AF::Input_error Err;

// Runs f, expects an Input_error of the given kind and element whose message contains `words`.
void expect_error(const std::function<void()>& f, Err::Kind kind, std::size_t element, const std::string& words,
                  const std::string& what)
{
  try
  {
    f();
    AF_CHECK(false, "no exception for: " + what);
  }
  catch(const Err& e)
  {
    std::cout << what << ": " << e.what() << "\n";
    AF_CHECK(e.kind() == kind, "kind of error for: " + what);
    AF_CHECK(e.element() == element, "offending element for: " + what);
    AF_CHECK(std::string(e.what()).find(words) != std::string::npos, "message names '" + words + "' for: " + what);
  }
}

std::vector<std::string> property_names(const Mesh& m)
{
  std::vector<std::string> n = m.properties<Mesh::Vertex_index>();
  for(const std::string& s : m.properties<Mesh::Face_index>()) n.push_back("f:" + s);
  for(const std::string& s : m.properties<Mesh::Halfedge_index>()) n.push_back("h:" + s);
  for(const std::string& s : m.properties<Mesh::Edge_index>()) n.push_back("e:" + s);
  return n;
}

int main()
{
  typedef AF::Loop_limit_surface<Mesh> Surface;

  // a quad face: a cube made of 6 quads, one of them split into triangles
  {
    Mesh m;
    std::vector<Mesh::Vertex_index> v;
    for(int i = 0; i < 8; ++i) v.push_back(m.add_vertex(Point(i & 1, (i >> 1) & 1, (i >> 2) & 1)));
    m.add_face(v[0], v[2], v[3]); m.add_face(v[0], v[3], v[1]);      // bottom, two triangles
    m.add_face(v[4], v[5], v[7], v[6]);                             // top (face 2)
    m.add_face(v[0], v[1], v[5], v[4]);
    m.add_face(v[1], v[3], v[7], v[5]);
    m.add_face(v[3], v[2], v[6], v[7]);
    m.add_face(v[2], v[0], v[4], v[6]);
    AF_CHECK(CGAL::is_closed(m), "the cube is closed");
    expect_error([&] { Surface s(m); }, Err::NON_TRIANGLE_FACE, 2, "face 2 has 4 vertices", "quad face");
  }
  // a border: the octahedron without one face
  {
    Mesh m;
    AF_test::make_octahedron(m);
    CGAL::Euler::remove_face(halfedge(*faces(m).begin(), m), m);
    m.collect_garbage();
    try { Surface s(m); AF_CHECK(false, "no exception for a border"); }
    catch(const Err& e)
    {
      std::cout << "border: " << e.what() << "\n";
      AF_CHECK(e.kind() == Err::BORDER_EDGE, "border edge reported");
      AF_CHECK(std::string(e.what()).find("border edge") != std::string::npos, "message says border edge");
    }
  }
  // an isolated vertex
  {
    Mesh m;
    AF_test::make_tetrahedron(m);
    m.add_vertex(Point(5, 5, 5));
    expect_error([&] { Surface s(m); }, Err::ISOLATED_VERTEX, 4, "vertex 4 has no incident face", "isolated vertex");
  }
  // a NaN coordinate, and the mesh's property list unchanged by any of this
  {
    Mesh m;
    AF_test::make_octahedron(m);
    const std::vector<std::string> before = property_names(m);
    m.point(Mesh::Vertex_index(3)) = Point(0, std::numeric_limits<double>::quiet_NaN(), 0);
    expect_error([&] { Surface s(m); }, Err::NON_FINITE_COORDINATE, 3, "vertex 3 has a non-finite coordinate", "NaN coordinate");
    AF_CHECK(property_names(m) == before, "no property added to the user's mesh by a failed construction");
    m.point(Mesh::Vertex_index(3)) = Point(0, -1, 0);
    {
      Surface s(m);
      Mesh out;
      s.resample(1, out);
      AF_CHECK(property_names(m) == before, "no property added to the user's mesh by a successful use");
    }
  }
  // valence 2: two triangles glued along their three edges
  {
    Mesh m;
    auto a = m.add_vertex(Point(0, 0, 0)), b = m.add_vertex(Point(1, 0, 0)), c = m.add_vertex(Point(0, 1, 0));
    m.add_face(a, b, c);
    m.add_face(a, c, b);
    expect_error([&] { Surface s(m); }, Err::LOW_VALENCE_VERTEX, 0, "vertex 0 has valence 2", "pillow (valence 2)");
  }
  // an empty mesh
  {
    Mesh m;
    expect_error([&] { Surface s(m); }, Err::EMPTY_MESH, Err::no_element, "no face", "empty mesh");
  }
  // non-manifold configurations, at the level where they are detected (index triangles)
  {
    typedef AF::internal::Triangle_topology Topology;
    // two tetrahedra sharing vertex 0
    std::vector<Topology::Face> t = { {0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3},
                                      {0, 5, 4}, {0, 4, 6}, {0, 6, 5}, {4, 5, 6} };
    expect_error([&] { Topology topo(7, t); }, Err::NON_MANIFOLD_VERTEX, 0, "vertex 0 is non-manifold", "bow-tie vertex");
    // three triangles on one edge
    std::vector<Topology::Face> fin = { {0, 1, 2}, {1, 0, 3}, {0, 1, 4} };
    expect_error([&] { Topology topo(5, fin); }, Err::NON_MANIFOLD_EDGE, 0, "between vertices 0 and 1", "edge with three faces");
    std::vector<Topology::Face> deg = { {0, 1, 1} };
    expect_error([&] { Topology topo(2, deg); }, Err::DEGENERATE_FACE, 0, "face 0 uses vertex 1 twice", "degenerate face");
  }
  // Polyhedron_3: the same checks through the FaceGraph interface
  {
    CGAL::Polyhedron_3<K> p;
    AF_test::make_tetrahedron(p);
    p.make_triangle(Point(0, 0, 5), Point(1, 0, 5), Point(0, 1, 5));      // a separate open triangle
    try { AF::Loop_limit_surface<CGAL::Polyhedron_3<K>> s(p); AF_CHECK(false, "no exception (Polyhedron_3 border)"); }
    catch(const Err& e) { std::cout << "Polyhedron_3 border: " << e.what() << "\n"; AF_CHECK(e.kind() == Err::BORDER_EDGE, "Polyhedron_3 border"); }
  }
  // attribute dimension, parameters, evaluation and resampling arguments
  {
    Mesh m;
    AF_test::make_icosahedron(m);
    auto dyn = m.add_property_map<Mesh::Vertex_index, std::vector<double>>("v:dyn", std::vector<double>(2, 0.0)).first;
    dyn[Mesh::Vertex_index(7)] = std::vector<double>(3, 0.0);
    Surface s(m);
    Mesh out;
    auto out_dyn = out.add_property_map<Mesh::Vertex_index, std::vector<double>>("v:dyn").first;
    expect_error([&] { s.resample(1, out, dyn, out_dyn); }, Err::ATTRIBUTE_DIMENSION, 7,
                 "vertex 7 has dimension 3", "attribute of the wrong size");
    AF_CHECK(num_vertices(out) == 0, "nothing written to the output on error");
    expect_error([&] { Surface t(m, AF::parameters::quadrature_degree(5)); }, Err::INVALID_PARAMETER, Err::no_element,
                 "quadrature degree 5", "quadrature degree 5");
    expect_error([&] { Surface t(m, AF::parameters::quadrature_tiling_depth(13)); }, Err::INVALID_PARAMETER,
                 Err::no_element, "tiling depth", "tiling depth 13");
    expect_error([&] { s.evaluate(*faces(m).begin(), { 0.5, 0.6, -0.1 }); }, Err::INVALID_PARAMETER, 0,
                 "barycentric", "negative barycentric coordinate");
    Mesh full;
    AF_test::make_tetrahedron(full);
    expect_error([&] { s.resample(1, full); }, Err::INVALID_PARAMETER, Err::no_element, "must be empty", "non-empty output");
    expect_error([&] { s.resample(11, out); }, Err::INVALID_PARAMETER, Err::no_element, "must not exceed 10", "11 levels");
  }
  return AF_test::report();
}
