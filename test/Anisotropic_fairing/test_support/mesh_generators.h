// Deterministic closed triangle-mesh generators for the Anisotropic_fairing tests.
//
// Every generator fills an EMPTY CGAL FaceGraph (tested with CGAL::Surface_mesh and
// CGAL::Polyhedron_3) from an indexed triangle soup through
// CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh, so:
//   * vertex i of the soup is the i-th vertex in vertices(mesh) order,
//   * face j of the soup is the j-th face in faces(mesh) order,
// for both mesh types. With CGAL 5.5 also target(halfedge(f, mesh)) is the soup
// face's first corner for both types, so vertices_around_face(halfedge(f, mesh))
// lists exactly the soup triple (checked by selftest_oracles.cpp; this follows
// from Euler::add_face's implementation and is not documented by CGAL).
// All meshes are closed, 2-manifold and consistently oriented outward.
//
// Randomness uses std::mt19937 with raw rng() outputs only (its output sequence is
// fixed by the C++ standard), so results are identical on every platform.
//
// Independent of include/CGAL/Anisotropic_fairing (test oracle).

#ifndef AF_TEST_SUPPORT_MESH_GENERATORS_H
#define AF_TEST_SUPPORT_MESH_GENERATORS_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace AF_test {

// ---------------------------------------------------------------------------
// Indexed triangle soup
// ---------------------------------------------------------------------------

struct Triangle_soup
{
  std::vector<std::array<double, 3> > points;
  std::vector<std::array<std::size_t, 3> > faces;
};

namespace detail {

inline std::array<double, 3> sub3(const std::array<double, 3>& a, const std::array<double, 3>& b)
{ return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }

inline std::array<double, 3> cross3(const std::array<double, 3>& a, const std::array<double, 3>& b)
{ return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}}; }

inline double dot3(const std::array<double, 3>& a, const std::array<double, 3>& b)
{ return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

inline std::array<double, 3> normalized3(const std::array<double, 3>& a)
{
  const double l = std::sqrt(dot3(a, a));
  return {{a[0] / l, a[1] / l, a[2] / l}};
}

// dot(normal of (a,b,c), centroid): > 0 iff the triangle is seen counter-clockwise
// from outside a star-shaped (w.r.t. the origin) surface.
inline double outward_measure(const Triangle_soup& s, std::size_t a, std::size_t b, std::size_t c)
{
  const auto& pa = s.points[a];
  const auto& pb = s.points[b];
  const auto& pc = s.points[c];
  const std::array<double, 3> n = cross3(sub3(pb, pa), sub3(pc, pa));
  const std::array<double, 3> g = {{pa[0] + pb[0] + pc[0], pa[1] + pb[1] + pc[1], pa[2] + pb[2] + pc[2]}};
  return dot3(n, g);
}

// Orients every face outward, for a convex soup containing the origin.
inline void orient_outward_about_origin(Triangle_soup& s)
{
  for(auto& f : s.faces)
    if(outward_measure(s, f[0], f[1], f[2]) < 0)
      std::swap(f[1], f[2]);
}

// Uniform double in [0, 1) from one raw mt19937 output (platform independent).
inline double unit_double(std::mt19937& rng)
{ return static_cast<double>(rng()) / 4294967296.0; }

} // namespace detail

// Builds the mesh from the soup; `mesh` must be empty.
template <class Mesh>
void soup_to_mesh(const Triangle_soup& soup, Mesh& mesh)
{
  if(num_vertices(mesh) != 0 || num_faces(mesh) != 0)
    throw std::invalid_argument("AF_test::soup_to_mesh: the output mesh must be empty");
  typedef typename boost::property_traits<
      typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point;
  std::vector<Point> pts;
  pts.reserve(soup.points.size());
  for(const auto& p : soup.points)
    pts.push_back(Point(p[0], p[1], p[2]));
  std::vector<std::vector<std::size_t> > polys;
  polys.reserve(soup.faces.size());
  for(const auto& f : soup.faces)
    polys.push_back(std::vector<std::size_t>(f.begin(), f.end()));
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polys))
    throw std::runtime_error("AF_test::soup_to_mesh: soup is not a valid polygon mesh");
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, polys, mesh);
}

// ---------------------------------------------------------------------------
// Soups
// ---------------------------------------------------------------------------

inline Triangle_soup tetrahedron_soup()
{
  Triangle_soup s;
  const double c = 1.0 / std::sqrt(3.0);
  s.points = {{{c, c, c}}, {{c, -c, -c}}, {{-c, c, -c}}, {{-c, -c, c}}};
  s.faces = {{{0, 1, 2}}, {{0, 3, 1}}, {{0, 2, 3}}, {{1, 3, 2}}};
  detail::orient_outward_about_origin(s);
  return s;
}

inline Triangle_soup octahedron_soup()
{
  Triangle_soup s;
  // 0:+x 1:-x 2:+y 3:-y 4:+z 5:-z
  s.points = {{{1, 0, 0}}, {{-1, 0, 0}}, {{0, 1, 0}}, {{0, -1, 0}}, {{0, 0, 1}}, {{0, 0, -1}}};
  for(std::size_t z : {4u, 5u})
    for(std::size_t x : {0u, 1u})
      for(std::size_t y : {2u, 3u})
        s.faces.push_back({{x, y, z}});
  detail::orient_outward_about_origin(s);
  return s;
}

inline Triangle_soup icosahedron_soup()
{
  Triangle_soup s;
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  const double raw[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                             {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                             {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for(const auto& p : raw)
    s.points.push_back(detail::normalized3({{p[0], p[1], p[2]}}));
  s.faces = {{{0, 11, 5}}, {{0, 5, 1}},  {{0, 1, 7}},   {{0, 7, 10}}, {{0, 10, 11}},
             {{1, 5, 9}},  {{5, 11, 4}}, {{11, 10, 2}}, {{10, 7, 6}}, {{7, 1, 8}},
             {{3, 9, 4}},  {{3, 4, 2}},  {{3, 2, 6}},   {{3, 6, 8}},  {{3, 8, 9}},
             {{4, 9, 5}},  {{2, 4, 11}}, {{6, 2, 10}},  {{8, 6, 7}},  {{9, 8, 1}}};
  detail::orient_outward_about_origin(s);
  return s;
}

// One 1-to-4 midpoint split of every face, new points projected onto the unit sphere.
// New vertices are numbered in order of first appearance while scanning faces in
// order and each face's edges (v0v1, v1v2, v2v0). Face (a,b,c) becomes
// (a,ab,ca), (b,bc,ab), (c,ca,bc), (ab,bc,ca) in that order.
inline Triangle_soup split_1_to_4_on_sphere(const Triangle_soup& in)
{
  Triangle_soup out;
  out.points = in.points;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> mid;
  auto midpoint = [&](std::size_t a, std::size_t b) {
    const std::pair<std::size_t, std::size_t> key(std::min(a, b), std::max(a, b));
    auto it = mid.find(key);
    if(it != mid.end()) return it->second;
    const auto& pa = in.points[a];
    const auto& pb = in.points[b];
    out.points.push_back(detail::normalized3({{pa[0] + pb[0], pa[1] + pb[1], pa[2] + pb[2]}}));
    const std::size_t id = out.points.size() - 1;
    mid.emplace(key, id);
    return id;
  };
  for(const auto& f : in.faces)
  {
    const std::size_t a = f[0], b = f[1], c = f[2];
    const std::size_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    out.faces.push_back({{a, ab, ca}});
    out.faces.push_back({{b, bc, ab}});
    out.faces.push_back({{c, ca, bc}});
    out.faces.push_back({{ab, bc, ca}});
  }
  return out;
}

inline Triangle_soup icosphere_soup(int levels)
{
  if(levels < 0)
    throw std::invalid_argument("AF_test::icosphere_soup: levels must be >= 0");
  Triangle_soup s = icosahedron_soup();
  for(int l = 0; l < levels; ++l)
    s = split_1_to_4_on_sphere(s);
  return s;
}

// n x m periodic grid; vertex (i,j) has index i*m + j and position
// ((R + r cos v) cos u, (R + r cos v) sin u, r sin v), u = 2 pi i/n, v = 2 pi j/m.
// Quad (i,j),(i+1,j),(i+1,j+1),(i,j+1) is split along the diagonal (i,j)-(i+1,j+1)
// into faces [(i,j),(i+1,j),(i+1,j+1)] then [(i,j),(i+1,j+1),(i,j+1)] (face index
// 2*(i*m+j) and 2*(i*m+j)+1). Every vertex has valence 6; neighbours of (i,j) are
// (i±1,j), (i,j±1), (i+1,j+1), (i-1,j-1). Requires n, m >= 3; use n, m >= 7 so that
// 2-rings of vertices (supports of Loop basis functions) are embedded discs.
inline Triangle_soup regular_torus_soup(std::size_t n, std::size_t m, double R, double r)
{
  if(n < 3 || m < 3)
    throw std::invalid_argument("AF_test::regular_torus_soup: n and m must be >= 3 (>= 7 recommended)");
  Triangle_soup s;
  const double pi = std::acos(-1.0);
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < m; ++j)
    {
      const double u = 2 * pi * double(i) / double(n);
      const double v = 2 * pi * double(j) / double(m);
      s.points.push_back({{(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)}});
    }
  auto id = [n, m](std::size_t i, std::size_t j) { return (i % n) * m + (j % m); };
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < m; ++j)
    {
      s.faces.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
      s.faces.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
    }
  return s;
}

inline void perturb_soup(Triangle_soup& s, double amplitude, unsigned int seed)
{
  std::mt19937 rng(seed);
  for(auto& p : s.points)
    for(int d = 0; d < 3; ++d)
      p[d] += amplitude * (2.0 * detail::unit_double(rng) - 1.0);
}

// Valence of every soup vertex.
inline std::vector<std::size_t> soup_valences(const Triangle_soup& s)
{
  std::vector<std::size_t> val(s.points.size(), 0);
  for(const auto& f : s.faces)
    for(int k = 0; k < 3; ++k)
      ++val[f[k]]; // closed manifold: #incident faces == #incident edges
  return val;
}

// Icosphere(2) (162 vertices, 320 faces) followed by deterministic random edge flips
// (std::mt19937 seed 20240607, raw rng() % k), then a deterministic perturbation of
// amplitude 0.01. A flip of edge (a,b) with opposite vertices c, d is accepted only if
// a and b keep valence >= 3, c and d stay <= 9, edge (c,d) does not exist, and both
// new triangles stay outward oriented with respect to the origin (no fold-over on the
// sphere). Flipping stops as soon as valences 3,4,5,6,7,8,9 all occur, at least one
// face has 3 extraordinary vertices, at least one has exactly 2, and some edge joins
// two extraordinary vertices.
inline Triangle_soup mixed_valence_soup()
{
  Triangle_soup s = icosphere_soup(2);
  std::vector<std::size_t> val = soup_valences(s);
  // directed edge (u,v) -> face that contains it
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> dir;
  for(std::size_t f = 0; f < s.faces.size(); ++f)
    for(int k = 0; k < 3; ++k)
      dir[std::make_pair(s.faces[f][k], s.faces[f][(k + 1) % 3])] = f;

  auto done = [&]() {
    bool has[10] = {false};
    for(std::size_t v : val)
      if(v < 10) has[v] = true;
    for(int n = 3; n <= 9; ++n)
      if(!has[n]) return false;
    bool two = false, three = false, adjacent = false;
    for(const auto& f : s.faces)
    {
      int ev = 0;
      for(int k = 0; k < 3; ++k)
      {
        if(val[f[k]] != 6) ++ev;
        if(val[f[k]] != 6 && val[f[(k + 1) % 3]] != 6) adjacent = true;
      }
      if(ev == 2) two = true;
      if(ev == 3) three = true;
    }
    return two && three && adjacent;
  };

  std::mt19937 rng(20240607u);
  const std::size_t max_attempts = 1000000;
  std::size_t attempts = 0;
  while(!done())
  {
    if(++attempts > max_attempts)
      throw std::runtime_error("AF_test::mixed_valence_soup: flipping did not reach its goal");
    const std::size_t f = rng() % s.faces.size();
    const std::size_t e = rng() % 3;
    const std::size_t a = s.faces[f][e], b = s.faces[f][(e + 1) % 3], c = s.faces[f][(e + 2) % 3];
    const auto itg = dir.find(std::make_pair(b, a));
    if(itg == dir.end())
      throw std::logic_error("AF_test::mixed_valence_soup: soup not closed");
    const std::size_t g = itg->second;
    std::size_t d = s.faces[g][0] + s.faces[g][1] + s.faces[g][2] - a - b;
    if(val[a] <= 3 || val[b] <= 3 || val[c] >= 9 || val[d] >= 9 || c == d)
      continue;
    if(dir.count(std::make_pair(c, d)) || dir.count(std::make_pair(d, c)))
      continue;
    if(detail::outward_measure(s, a, d, c) <= 0 || detail::outward_measure(s, d, b, c) <= 0)
      continue;
    // (a,b,c) + (b,a,d)  ->  (a,d,c) + (d,b,c)
    dir.erase(std::make_pair(a, b)); dir.erase(std::make_pair(b, c)); dir.erase(std::make_pair(c, a));
    dir.erase(std::make_pair(b, a)); dir.erase(std::make_pair(a, d)); dir.erase(std::make_pair(d, b));
    s.faces[f] = {{a, d, c}};
    s.faces[g] = {{d, b, c}};
    dir[std::make_pair(a, d)] = f; dir[std::make_pair(d, c)] = f; dir[std::make_pair(c, a)] = f;
    dir[std::make_pair(d, b)] = g; dir[std::make_pair(b, c)] = g; dir[std::make_pair(c, d)] = g;
    --val[a]; --val[b]; ++val[c]; ++val[d];
  }
  perturb_soup(s, 0.01, 7u);
  return s;
}

// ---------------------------------------------------------------------------
// Mesh-filling functions (mesh must be empty)
// ---------------------------------------------------------------------------

template <class Mesh> void make_tetrahedron(Mesh& mesh) { soup_to_mesh(tetrahedron_soup(), mesh); }
template <class Mesh> void make_octahedron(Mesh& mesh) { soup_to_mesh(octahedron_soup(), mesh); }
template <class Mesh> void make_icosahedron(Mesh& mesh) { soup_to_mesh(icosahedron_soup(), mesh); }

// 12, 42, 162, 642, ... vertices for levels 0, 1, 2, 3, ...
template <class Mesh> void make_icosphere(Mesh& mesh, int levels) { soup_to_mesh(icosphere_soup(levels), mesh); }

template <class Mesh>
void make_regular_torus(Mesh& mesh, std::size_t n, std::size_t m, double R = 2.0, double r = 0.75)
{ soup_to_mesh(regular_torus_soup(n, m, R, r), mesh); }

// 162 vertices, 320 faces, valences 3..9 all present (see mixed_valence_soup()).
template <class Mesh> void make_mixed_valence_mesh(Mesh& mesh) { soup_to_mesh(mixed_valence_soup(), mesh); }

// Adds amplitude * U(-1,1) to every coordinate, vertices in vertices(mesh) order,
// coordinates x,y,z, std::mt19937(seed) raw outputs.
template <class Mesh>
void perturb_vertices(Mesh& mesh, double amplitude, unsigned int seed)
{
  typedef typename boost::property_map<Mesh, CGAL::vertex_point_t>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point;
  VPM vpm = get(CGAL::vertex_point, mesh);
  std::mt19937 rng(seed);
  for(auto v : vertices(mesh))
  {
    const Point p = get(vpm, v);
    double c[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    for(int d = 0; d < 3; ++d)
      c[d] += amplitude * (2.0 * detail::unit_double(rng) - 1.0);
    put(vpm, v, Point(c[0], c[1], c[2]));
  }
}

// ---------------------------------------------------------------------------
// Mesh statistics
// ---------------------------------------------------------------------------

// valence -> number of vertices with that valence
template <class Mesh>
std::map<std::size_t, std::size_t> valence_histogram(const Mesh& mesh)
{
  std::map<std::size_t, std::size_t> h;
  for(auto v : vertices(mesh))
  {
    std::size_t n = 0;
    for(auto hd : CGAL::halfedges_around_target(halfedge(v, mesh), mesh)) { (void)hd; ++n; }
    ++h[n];
  }
  return h;
}

inline std::string histogram_to_string(const std::map<std::size_t, std::size_t>& h)
{
  std::string s;
  for(const auto& kv : h)
    s += (s.empty() ? "" : " ") + std::to_string(kv.first) + ":" + std::to_string(kv.second);
  return s;
}

// result[e] = number of faces with exactly e extraordinary (valence != 6) vertices, e = 0..3
template <class Mesh>
std::array<std::size_t, 4> faces_by_extraordinary_count(const Mesh& mesh)
{
  std::array<std::size_t, 4> r = {{0, 0, 0, 0}};
  for(auto f : faces(mesh))
  {
    int ev = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
    {
      std::size_t n = 0;
      for(auto hd : CGAL::halfedges_around_target(halfedge(v, mesh), mesh)) { (void)hd; ++n; }
      if(n != 6) ++ev;
    }
    ++r[std::min(ev, 3)];
  }
  return r;
}

// V - E + F
template <class Mesh>
long euler_characteristic(const Mesh& mesh)
{
  return long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
}

} // namespace AF_test

#endif // AF_TEST_SUPPORT_MESH_GENERATORS_H
