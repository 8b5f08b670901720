// Bad input is refused with an Input_error naming the problem and the element, before anything is
// computed or written; the user's mesh (including its property list) is left as it was. Borders are
// not an error (Loop_limit_surface closes them with a ghost layer), but a bow-tie border vertex is.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>
#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>

#include "test_support/check.h"
#include "test_support/mesh_generators.h"

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
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
  // a border is accepted: the octahedron without one face; its three border vertices (valence 4,
  // m = 3 triangles left) get the cubic B-spline limit (2/3) v + (1/6)(r0 + r3)
  {
    Mesh m;
    AF_test::make_octahedron(m);
    CGAL::Euler::remove_face(halfedge(*faces(m).begin(), m), m);
    m.collect_garbage();
    try
    {
      Surface s(m);
      AF_CHECK(s.number_of_vertices() == 6 && s.number_of_faces() == 7, "border: the mesh's own counts");
      std::map<Mesh::Vertex_index, Point> limit;
      s.limit_positions(boost::make_assoc_property_map(limit));
      double err = 0;
      int border_vertices = 0;
      for(auto h : halfedges(m))
        if(CGAL::is_border(h, m))   // h: r0 -> v along the hole, next(h): v -> r3
        {
          ++border_vertices;
          const auto v = target(h, m);
          const K::Vector_3 expected = (m.point(v) - CGAL::ORIGIN) * (2.0 / 3) +
                                       ((m.point(source(h, m)) - CGAL::ORIGIN) + (m.point(target(next(h, m), m)) - CGAL::ORIGIN)) / 6;
          err = std::max(err, std::sqrt(CGAL::squared_distance(limit[v], CGAL::ORIGIN + expected)));
        }
      const Eigen::SparseMatrix<double> M = s.mass_matrix();
      std::cout << "border: accepted; area " << s.area() << ", mass matrix sum " << M.sum()
                << ", border vertex limits off the cubic B-spline rule by " << err << "\n";
      AF_CHECK(border_vertices == 3 && err <= 1e-15, "border: limit points of the border vertices by the B-spline rule");
      AF_CHECK(M.rows() == 6 && std::abs(M.sum() - s.area()) <= 1e-14 * s.area(), "border: mass matrix 6 x 6, entries sum to area()");
    }
    catch(const Err& e) { AF_CHECK(false, std::string("border refused: ") + e.what()); }
  }
  // a bow-tie: two triangles sharing only vertex 2 (Surface_mesh holds it when built face by face)
  {
    Mesh m;
    std::vector<Mesh::Vertex_index> v;
    const Point p[5] = { Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(2, 1, 0), Point(1, 2, 0) };
    for(const Point& q : p) v.push_back(m.add_vertex(q));
    AF_CHECK(m.add_face(v[0], v[1], v[2]) != Mesh::null_face() && m.add_face(v[2], v[3], v[4]) != Mesh::null_face(),
             "bow-tie built");
    expect_error([&] { Surface s(m); }, Err::NON_MANIFOLD_VERTEX, 2, "vertex 2 is non-manifold", "bow-tie border vertex");
  }
  // an isolated vertex (a scanner leftover) is accepted: it is its own limit point
  {
    Mesh m;
    AF_test::make_tetrahedron(m);
    const Mesh::Vertex_index lone = m.add_vertex(Point(5, 5, 5));
    try
    {
      Surface s(m);
      std::map<Mesh::Vertex_index, Point> lp;
      s.limit_positions(boost::make_assoc_property_map(lp));
      AF_CHECK(s.number_of_vertices() == 5 && lp[lone] == Point(5, 5, 5), "isolated vertex accepted, its own limit");
    }
    catch(const Err& e) { AF_CHECK(false, std::string("isolated vertex refused: ") + e.what()); }
  }
  // a NaN coordinate, and the mesh's property list unchanged by any of this
  {
    Mesh m;
    AF_test::make_octahedron(m);
    const std::vector<std::string> before = property_names(m);
    m.point(Mesh::Vertex_index(3)) = Point(0, std::numeric_limits<double>::quiet_NaN(), 0);
    expect_error([&] { Surface s(m); }, Err::NON_FINITE_COORDINATE, 3, "vertex 3 has a non-finite coordinate", "NaN coordinate");
    AF_CHECK(property_names(m) == before, "no property added to the user's mesh by a failed construction");
    // coordinates whose fourth powers leave double precision: refused as such, not as a degenerate surface
    m.point(Mesh::Vertex_index(3)) = Point(0, -1e171, 0);
    expect_error([&] { Surface s(m); }, Err::COORDINATE_RANGE, 3, "vertex 3 has a coordinate of -1e+171", "coordinate 1e171");
    expect_error([&] { AF::anisotropic_fairing(m); }, Err::COORDINATE_RANGE, 3, "overflow double precision", "fairing, coordinate 1e171");
    {
      Mesh tiny = m;
      for(Mesh::Vertex_index v : tiny.vertices()) tiny.point(v) = Point(0, 0, 0) + 1e-150 * (m.point(v) - CGAL::ORIGIN);
      tiny.point(Mesh::Vertex_index(3)) = Point(0, -1e-150, 0);
      expect_error([&] { AF::anisotropic_fairing(tiny); }, Err::COORDINATE_RANGE, Err::no_element, "the mesh spans only 2e-150",
                   "fairing, a mesh of 1e-150");
    }
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
  // Polyhedron_3 through the FaceGraph interface: a tetrahedron plus a separate open triangle is
  // accepted; the components do not interact and a lone triangle is its own flat limit surface
  {
    CGAL::Polyhedron_3<K> p, tetrahedron;
    AF_test::make_tetrahedron(p);
    AF_test::make_tetrahedron(tetrahedron);
    p.make_triangle(Point(0, 0, 5), Point(1, 0, 5), Point(0, 1, 5));      // area 1/2
    try
    {
      AF::Loop_limit_surface<CGAL::Polyhedron_3<K>> s(p);
      const double closed = AF::Loop_limit_surface<CGAL::Polyhedron_3<K>>(tetrahedron).area();
      std::cout << "Polyhedron_3 border: accepted; area " << s.area() << " = tetrahedron " << closed << " + 0.5\n";
      AF_CHECK(s.number_of_vertices() == 7 && s.number_of_faces() == 5, "Polyhedron_3 border: the mesh's own counts");
      AF_CHECK(std::abs(s.area() - (closed + 0.5)) <= 1e-15 * s.area(), "Polyhedron_3 border: area = tetrahedron + triangle");
    }
    catch(const Err& e) { AF_CHECK(false, std::string("Polyhedron_3 border refused: ") + e.what()); }
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
