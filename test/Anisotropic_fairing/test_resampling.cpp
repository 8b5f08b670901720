// Resampling: the k-times refined mesh written by Loop_limit_surface::resample has CGAL's Loop
// connectivity, its vertices are the exact limit points (CGAL Loop^k + limit mask), its normals are
// the exact limit normals (tangent masks on the level-k mesh), and attributes follow the same basis;
// its faces come 4^k per control face, in the control mesh's face order.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/Color.h>

#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>

#include "test_support/cgal_loop_reference.h"
#include "test_support/check.h"
#include "test_support/mesh_generators.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <set>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
namespace AF = CGAL::Anisotropic_fairing;

// nearest resampled vertex of each reference point
std::vector<std::size_t> match_points(const std::vector<Point>& out, const std::vector<Point>& ref,
                                      AF_test::Max_error& dist)
{
  typedef CGAL::Search_traits_3<K> Base_traits;
  typedef boost::tuple<Point, std::size_t> Indexed_point;
  typedef CGAL::Search_traits_adapter<Indexed_point, CGAL::Nth_of_tuple_property_map<0, Indexed_point>, Base_traits> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  std::vector<Indexed_point> pts;
  for(std::size_t i = 0; i < out.size(); ++i) pts.emplace_back(out[i], i);
  typename Search::Tree tree(pts.begin(), pts.end());
  std::vector<std::size_t> m;
  for(const Point& p : ref)
  {
    Search search(tree, p, 1);
    const auto& nn = *search.begin();
    dist.add_error(std::sqrt(nn.second));
    m.push_back(boost::get<1>(nn.first));
  }
  return m;
}

template <class Rotatable>
Rotatable min_rotation(Rotatable t)
{
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

template <class Control, class Out>
void test_against_cgal(const Control& control, int levels, const std::string& name)
{
  AF::Loop_limit_surface<Control> surface(control);
  Out out;
  auto normals = get(CGAL::dynamic_vertex_property_t<Vector>(), out);
  surface.resample(levels, out, AF::parameters::vertex_normal_map(normals));
  const AF_test::Loop_reference<Control> ref = AF_test::cgal_loop_reference(control, levels);
  AF_CHECK(num_vertices(out) == num_vertices(ref.refined), "same number of vertices as CGAL's Loop^k, " + name);
  AF_CHECK(num_faces(out) == num_faces(ref.refined), "same number of faces as CGAL's Loop^k, " + name);

  std::vector<Point> out_points;
  std::vector<typename boost::graph_traits<Out>::vertex_descriptor> out_vertices;
  for(auto v : vertices(out)) { out_points.push_back(get(CGAL::vertex_point, out, v)); out_vertices.push_back(v); }
  std::vector<Point> ref_points;
  for(const auto& l : ref.limits) ref_points.emplace_back(l[0], l[1], l[2]);
  AF_test::Max_error dist("resampled vertices vs CGAL Loop^" + std::to_string(levels) + " + limit mask, " + name);
  const std::vector<std::size_t> m = match_points(out_points, ref_points, dist);
  dist.print();
  AF_CHECK(dist.value() <= 1e-12, "resampled vertices are the exact limit points, " + name);
  AF_CHECK(std::set<std::size_t>(m.begin(), m.end()).size() == m.size(), "the matching is one-to-one, " + name);

  // normals: tangent masks on the level-k control mesh are the exact limit normals
  const auto ref_normals = AF_test::tangent_mask_normals(ref.refined);
  AF_test::Max_error nerr("resampled normals vs level-k tangent masks, " + name);
  for(std::size_t r = 0; r < m.size(); ++r)
  {
    const Vector n = get(normals, out_vertices[m[r]]);
    nerr.add_error(std::max({ std::abs(n.x() - ref_normals[r][0]), std::abs(n.y() - ref_normals[r][1]),
                              std::abs(n.z() - ref_normals[r][2]) }));
  }
  nerr.print();
  AF_CHECK(nerr.value() <= 1e-12, "resampled normals are the exact limit normals, " + name);

  // connectivity: every CGAL face, mapped through the matching, is a face of the output (same orientation)
  std::set<std::array<std::size_t, 3>> out_faces;
  std::map<typename boost::graph_traits<Out>::vertex_descriptor, std::size_t> out_index;
  for(std::size_t i = 0; i < out_vertices.size(); ++i) out_index[out_vertices[i]] = i;
  for(auto f : faces(out))
  {
    std::array<std::size_t, 3> t;
    int k = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, out), out)) t[k++] = out_index[v];
    out_faces.insert(min_rotation(t));
  }
  std::map<typename boost::graph_traits<Control>::vertex_descriptor, std::size_t> ref_index;
  for(std::size_t i = 0; i < ref.refined_vertices.size(); ++i) ref_index[ref.refined_vertices[i]] = i;
  std::size_t missing = 0;
  for(auto f : faces(ref.refined))
  {
    std::array<std::size_t, 3> t;
    int k = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, ref.refined), ref.refined)) t[k++] = m[ref_index[v]];
    if(!out_faces.count(min_rotation(t))) ++missing;
  }
  AF_CHECK(missing == 0, "the output has CGAL's Loop connectivity and orientation, " + name);
  AF_CHECK(CGAL::is_valid_polygon_mesh(out) && CGAL::is_closed(out), "the output is a valid closed mesh, " + name);
}

int main()
{
  Mesh mixed, ico;
  AF_test::make_mixed_valence_mesh(mixed);
  AF_test::make_icosahedron(ico);
  test_against_cgal<Mesh, Mesh>(mixed, 3, "valences 3-9, Surface_mesh");
  test_against_cgal<Mesh, Mesh>(ico, 4, "icosahedron, Surface_mesh");
  {
    Polyhedron poly;
    AF_test::make_mixed_valence_mesh(poly);
    test_against_cgal<Polyhedron, Polyhedron>(poly, 2, "valences 3-9, Polyhedron_3");
  }

  // the first vertices are the control vertices' limit points, in order; level 0 keeps the connectivity
  {
    AF::Loop_limit_surface<Mesh> s(mixed);
    Mesh out0, out2;
    s.resample(0, out0);
    s.resample(2, out2);
    auto lim = mixed.add_property_map<Mesh::Vertex_index, Point>("v:limit").first;
    s.limit_positions(lim);
    AF_test::Max_error first("first output vertices vs limit_positions()");
    for(auto v : vertices(mixed))
    {
      first.add_error(std::sqrt(CGAL::squared_distance(out0.point(v), lim[v])));
      first.add_error(std::sqrt(CGAL::squared_distance(out2.point(v), lim[v])));
    }
    first.print();
    AF_CHECK(first.value() == 0.0, "control vertices come first, in order, at their limit points");
    AF_CHECK(num_faces(out0) == num_faces(mixed) && num_faces(out2) == 16 * num_faces(mixed), "face counts 4^k F");
    bool same = true;
    for(auto f : faces(mixed))
    {
      auto a = CGAL::vertices_around_face(halfedge(f, mixed), mixed);
      auto b = CGAL::vertices_around_face(halfedge(f, out0), out0);
      std::array<std::size_t, 3> ta, tb;
      int k = 0;
      for(auto v : a) ta[k++] = std::size_t(v);
      k = 0;
      for(auto v : b) tb[k++] = std::size_t(v);
      same = same && min_rotation(ta) == min_rotation(tb);
    }
    AF_CHECK(same, "level 0 keeps the control connectivity");
    // the faces of the output come 4^k per control face, in the order of faces(): the 16 faces of face f
    // at level 2 have f's three corners and no other control vertex
    bool grouped = true;
    std::vector<Mesh::Face_index> fine(out2.faces().begin(), out2.faces().end());
    std::size_t index = 0;
    for(auto f : faces(mixed))
    {
      std::set<std::size_t> corners, seen;
      for(auto v : CGAL::vertices_around_face(halfedge(f, mixed), mixed)) corners.insert(std::size_t(v));
      for(std::size_t k = 0; k < 16; ++k, ++index)
        for(auto v : CGAL::vertices_around_face(halfedge(fine[index], out2), out2))
          if(std::size_t(v) < num_vertices(mixed)) seen.insert(std::size_t(v));
      grouped = grouped && seen == corners;
    }
    AF_CHECK(grouped, "the output faces come 4^k per control face, in the order of faces()");
  }

  // attributes: the same basis functions
  {
    AF::Loop_limit_surface<Mesh> s(mixed);
    auto vec = mixed.add_property_map<Mesh::Vertex_index, Vector>("v:vec").first;
    auto affine = mixed.add_property_map<Mesh::Vertex_index, double>("v:affine").first;
    auto color = mixed.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
    auto arr = mixed.add_property_map<Mesh::Vertex_index, std::array<float, 2>>("v:arr").first;
    std::mt19937 rng(5);
    unsigned char lo = 255, hi = 0;
    for(auto v : vertices(mixed))
    {
      const Point& p = mixed.point(v);
      vec[v] = p - CGAL::ORIGIN;
      affine[v] = 2 * p.x() - p.y() + 3 * p.z() + 1;
      const unsigned char r = (unsigned char)(rng() % 256);
      lo = std::min(lo, r); hi = std::max(hi, r);
      color[v] = CGAL::IO::Color(r, 255 - r, 7, 200);
      arr[v] = { float(p.x()), 1.0f };
    }
    Mesh o1, o2, o3, o4;
    auto vec_out = o1.add_property_map<Mesh::Vertex_index, Vector>("v:vec").first;
    auto aff_out = o2.add_property_map<Mesh::Vertex_index, double>("v:affine").first;
    auto col_out = o3.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
    auto arr_out = o4.add_property_map<Mesh::Vertex_index, std::array<float, 2>>("v:arr").first;
    s.resample(2, o1, vec, vec_out);
    s.resample(2, o2, affine, aff_out);
    s.resample(2, o3, color, col_out);
    s.resample(2, o4, arr, arr_out);
    AF_test::Max_error e_vec("attribute = positions vs resampled positions"),
        e_aff("affine attribute vs the same affine function of the resampled positions"),
        e_arr("std::array<float,2> attribute (x, 1)");
    bool colors_ok = true;
    for(auto v : vertices(o1))
    {
      const Point p = o1.point(v);
      e_vec.add_error((vec_out[v] - (p - CGAL::ORIGIN)).squared_length() == 0 ? 0.0 : std::sqrt((vec_out[v] - (p - CGAL::ORIGIN)).squared_length()));
      e_aff.add_error(std::abs(aff_out[v] - (2 * p.x() - p.y() + 3 * p.z() + 1)));
      e_arr.add_error(std::abs(double(arr_out[v][0]) - p.x()) + std::abs(double(arr_out[v][1]) - 1.0));
      const CGAL::IO::Color c = col_out[v];
      // Loop basis functions are non-negative: limit values stay within the input range
      colors_ok = colors_ok && c.red() >= lo && c.red() <= hi && int(c.red()) + int(c.green()) >= 254 &&
                  int(c.red()) + int(c.green()) <= 256 && c.blue() == 7 && c.alpha() == 200;
    }
    e_vec.print(); e_aff.print(); e_arr.print();
    AF_CHECK(e_vec.value() <= 1e-15, "a Vector_3 attribute equal to the positions resamples to the positions");
    AF_CHECK(e_aff.value() <= 1e-13, "affine attributes stay affine (partition of unity)");
    AF_CHECK(e_arr.value() <= 1e-6, "std::array<float,2> attributes (float precision)");
    AF_CHECK(colors_ok, "colours stay within the input range, alpha kept");

    // evaluate_attribute at the centre of every face vs evaluate()
    AF_test::Max_error e_eval("evaluate_attribute vs evaluate at face centres");
    for(auto f : faces(mixed))
    {
      const auto p = s.evaluate(f, { 1. / 3, 1. / 3, 1. / 3 });
      const Vector a = s.evaluate_attribute(f, { 1. / 3, 1. / 3, 1. / 3 }, vec);
      e_eval.add_error(std::sqrt((a - (p.position - CGAL::ORIGIN)).squared_length()));
    }
    e_eval.print();
    AF_CHECK(e_eval.value() <= 1e-15, "evaluate_attribute uses the same basis as evaluate");
  }
  return AF_test::report();
}
