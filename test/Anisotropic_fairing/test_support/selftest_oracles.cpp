// Self-test of the test oracles in test_support/ (not part of the CTest suite).
//
// Build by hand from the repository root, e.g.
//   g++ -std=c++17 -O2 -I/usr/include/eigen3 -I test/Anisotropic_fairing
//       test/Anisotropic_fairing/test_support/selftest_oracles.cpp -o /tmp/selftest -lgmp -lmpfr
//
// Runs every check with CGAL::Surface_mesh and CGAL::Polyhedron_3 and compares the two.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/helpers.h>

#include "test_support/cgal_loop_reference.h"
#include "test_support/check.h"
#include "test_support/mesh_generators.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef CGAL::Polyhedron_3<K> Poly;

using AF_test::Max_error;

namespace {

typedef std::array<double, 3> V3;

double norm(const V3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
double dist(const V3& a, const V3& b) { return norm({{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}); }

template <class Mesh>
std::vector<V3> positions(const Mesh& m)
{
  std::vector<V3> r;
  for(auto v : vertices(m)) r.push_back(AF_test::detail::point_as_array(m, v));
  return r;
}

template <class Mesh>
std::vector<std::array<std::size_t, 3> > face_indices(const Mesh& m)
{
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, std::size_t> id;
  for(auto v : vertices(m)) id.emplace(v, id.size());
  std::vector<std::array<std::size_t, 3> > r;
  for(auto f : faces(m))
  {
    std::array<std::size_t, 3> t;
    int c = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) t[c++] = id.at(v);
    r.push_back(t);
  }
  return r;
}

// same cyclic triangle?
bool same_cycle(const std::array<std::size_t, 3>& a, const std::array<std::size_t, 3>& b)
{
  for(int s = 0; s < 3; ++s)
    if(a[0] == b[s] && a[1] == b[(s + 1) % 3] && a[2] == b[(s + 2) % 3]) return true;
  return false;
}

// ---------------------------------------------------------------------------
// 1. generators
// ---------------------------------------------------------------------------

template <class Mesh>
void check_generated(const std::string& name, const Mesh& m, const AF_test::Triangle_soup& soup,
                     std::size_t nv, std::size_t nf, long euler, bool star_shaped)
{
  AF_CHECK(num_vertices(m) == nv, name + ": vertex count " + std::to_string(num_vertices(m)));
  AF_CHECK(num_faces(m) == nf, name + ": face count " + std::to_string(num_faces(m)));
  AF_CHECK(CGAL::is_valid_polygon_mesh(m), name + ": valid");
  AF_CHECK(CGAL::is_closed(m), name + ": closed");
  AF_CHECK(CGAL::is_triangle_mesh(m), name + ": triangle mesh");
  AF_CHECK(AF_test::euler_characteristic(m) == euler,
           name + ": Euler characteristic " + std::to_string(AF_test::euler_characteristic(m)));
  // vertex and face order == soup order
  const auto pos = positions(m);
  bool same_pos = pos.size() == soup.points.size();
  for(std::size_t i = 0; same_pos && i < pos.size(); ++i) same_pos = (pos[i] == soup.points[i]);
  AF_CHECK(same_pos, name + ": vertices(mesh) order == soup order");
  const auto fi = face_indices(m);
  bool same_faces = fi.size() == soup.faces.size();
  for(std::size_t i = 0; same_faces && i < fi.size(); ++i) same_faces = same_cycle(fi[i], soup.faces[i]);
  AF_CHECK(same_faces, name + ": faces(mesh) order and orientation == soup");
  bool same_start = fi.size() == soup.faces.size();
  for(std::size_t i = 0; same_start && i < fi.size(); ++i) same_start = (fi[i] == soup.faces[i]);
  AF_CHECK(same_start, name + ": vertices_around_face(halfedge(f)) starts at the soup's first corner");
  if(star_shaped)
  {
    std::size_t bad = 0;
    for(const auto& f : soup.faces)
      if(AF_test::detail::outward_measure(soup, f[0], f[1], f[2]) <= 0) ++bad;
    AF_CHECK(bad == 0, name + ": all faces oriented outward (" + std::to_string(bad) + " not)");
  }
}

template <class Mesh>
void test_generators(const char* type)
{
  const std::string T = std::string(" [") + type + "]";
  { Mesh m; AF_test::make_tetrahedron(m);
    check_generated("tetrahedron" + T, m, AF_test::tetrahedron_soup(), 4, 4, 2, true);
    const auto h = AF_test::valence_histogram(m);
    AF_CHECK(h.size() == 1 && h.count(3), "tetrahedron valences " + AF_test::histogram_to_string(h)); }
  { Mesh m; AF_test::make_octahedron(m);
    check_generated("octahedron" + T, m, AF_test::octahedron_soup(), 6, 8, 2, true);
    const auto h = AF_test::valence_histogram(m);
    AF_CHECK(h.size() == 1 && h.count(4), "octahedron valences " + AF_test::histogram_to_string(h)); }
  { Mesh m; AF_test::make_icosahedron(m);
    check_generated("icosahedron" + T, m, AF_test::icosahedron_soup(), 12, 20, 2, true);
    const auto h = AF_test::valence_histogram(m);
    AF_CHECK(h.size() == 1 && h.count(5), "icosahedron valences " + AF_test::histogram_to_string(h)); }
  const std::size_t ico_v[4] = {12, 42, 162, 642}, ico_f[4] = {20, 80, 320, 1280};
  for(int l = 0; l <= 3; ++l)
  {
    Mesh m; AF_test::make_icosphere(m, l);
    const std::string nm = "icosphere(" + std::to_string(l) + ")" + T;
    check_generated(nm, m, AF_test::icosphere_soup(l), ico_v[l], ico_f[l], 2, true);
    const auto h = AF_test::valence_histogram(m);
    AF_CHECK(h.at(5) == 12 && h.size() == (l == 0 ? 1u : 2u) && (l == 0 || h.at(6) == ico_v[l] - 12),
             nm + " valences " + AF_test::histogram_to_string(h));
    Max_error r(nm + " max |radius - 1|");
    for(const auto& p : positions(m)) r.add(norm(p), 1.0);
    AF_CHECK(r.value() < 1e-15, nm + ": on the unit sphere");
  }
  {
    Mesh m; AF_test::make_regular_torus(m, 8, 9, 2.0, 0.75);
    check_generated("torus(8,9)" + T, m, AF_test::regular_torus_soup(8, 9, 2.0, 0.75), 72, 144, 0, false);
    const auto h = AF_test::valence_histogram(m);
    AF_CHECK(h.size() == 1 && h.count(6), "torus valences all 6: " + AF_test::histogram_to_string(h));
    // outward: face normal . (centroid - nearest point on the core circle) > 0
    std::size_t bad = 0;
    const auto soup = AF_test::regular_torus_soup(8, 9, 2.0, 0.75);
    for(const auto& f : soup.faces)
    {
      const auto &a = soup.points[f[0]], &b = soup.points[f[1]], &c = soup.points[f[2]];
      const V3 n = AF_test::detail::cross3(AF_test::detail::sub3(b, a), AF_test::detail::sub3(c, a));
      const V3 g = {{(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3}};
      const double rho = std::hypot(g[0], g[1]);
      const V3 core = {{2.0 * g[0] / rho, 2.0 * g[1] / rho, 0.0}};
      if(AF_test::detail::dot3(n, AF_test::detail::sub3(g, core)) <= 0) ++bad;
    }
    AF_CHECK(bad == 0, "torus faces oriented outward");
  }
  {
    Mesh m; AF_test::make_mixed_valence_mesh(m);
    const auto soup = AF_test::mixed_valence_soup();
    check_generated("mixed" + T, m, soup, 162, 320, 2, true);
    const auto h = AF_test::valence_histogram(m);
    bool all = true;
    for(std::size_t n = 3; n <= 9; ++n) all = all && h.count(n);
    AF_CHECK(all && h.begin()->first == 3 && h.rbegin()->first == 9,
             "mixed valences 3..9: " + AF_test::histogram_to_string(h));
    const auto ev = AF_test::faces_by_extraordinary_count(m);
    AF_CHECK(ev[2] > 0 && ev[3] > 0, "mixed has faces with 2 and 3 EVs");
    // min angle, for information
    double min_angle = 180;
    const double pi = std::acos(-1.0);
    for(const auto& f : soup.faces)
      for(int k = 0; k < 3; ++k)
      {
        const auto& p = soup.points[f[k]];
        const V3 u = AF_test::detail::sub3(soup.points[f[(k + 1) % 3]], p);
        const V3 w = AF_test::detail::sub3(soup.points[f[(k + 2) % 3]], p);
        min_angle = std::min(min_angle, std::acos(AF_test::detail::dot3(u, w) / (norm(u) * norm(w))) * 180 / pi);
      }
    std::printf("mixed%s: valences %s; faces with 0/1/2/3 EVs: %zu/%zu/%zu/%zu; min angle %.1f deg\n",
                T.c_str(), AF_test::histogram_to_string(h).c_str(), ev[0], ev[1], ev[2], ev[3], min_angle);
  }
  {
    Mesh a, b; AF_test::make_icosphere(a, 1); AF_test::make_icosphere(b, 1);
    AF_test::perturb_vertices(a, 0.05, 3u); AF_test::perturb_vertices(b, 0.05, 3u);
    AF_CHECK(positions(a) == positions(b), "perturb_vertices deterministic" + T);
    const auto p0 = AF_test::icosphere_soup(1).points;
    const auto p1 = positions(a);
    double mx = 0, mn = 1;
    for(std::size_t i = 0; i < p0.size(); ++i)
      for(int d = 0; d < 3; ++d) { mx = std::max(mx, std::fabs(p1[i][d] - p0[i][d])); mn = std::min(mn, std::fabs(p1[i][d] - p0[i][d])); }
    AF_CHECK(mx <= 0.05 && mx > 0.04 && mn > 0, "perturb_vertices amplitude" + T);
  }
}

// ---------------------------------------------------------------------------
// 2. the Loop reference
// ---------------------------------------------------------------------------

// sparse parameter of a sample, rebuilt from (face, xi1, xi2)
template <class Mesh>
AF_test::Sparse_param param_of_sample(const AF_test::Loop_reference<Mesh>& ref, const AF_test::Limit_sample& s)
{
  const auto& t = ref.control_faces[s.face];
  std::vector<std::pair<std::size_t, double> > e;
  const double w[3] = {1.0 - s.xi1 - s.xi2, s.xi1, s.xi2};
  for(int i = 0; i < 3; ++i)
    if(w[i] != 0) e.emplace_back(t[i], w[i]);
  std::sort(e.begin(), e.end());
  AF_test::Sparse_param p;
  for(const auto& x : e) { p.vertex[p.size] = x.first; p.weight[p.size] = x.second; ++p.size; }
  return p;
}

// Generic structural checks of a reference on a closed mesh.
template <class Mesh>
void check_reference_structure(const std::string& name, const Mesh& control, const AF_test::Loop_reference<Mesh>& ref)
{
  const int k = ref.level;
  const std::size_t F = num_faces(control);
  const std::size_t Fk = F << (2 * k);
  const long chi = AF_test::euler_characteristic(control);
  AF_CHECK(num_faces(ref.refined) == Fk, name + ": refined face count");
  AF_CHECK(long(ref.refined_vertices.size()) == chi + long(Fk / 2), name + ": refined vertex count");
  AF_CHECK(ref.params.size() == ref.refined_vertices.size() && ref.limits.size() == ref.refined_vertices.size(),
           name + ": per-vertex arrays");
  const std::size_t per_face = ((std::size_t(1) << k) + 1) * ((std::size_t(1) << k) + 2) / 2;
  AF_CHECK(ref.samples.size() == F * per_face, name + ": " + std::to_string(ref.samples.size()) +
           " samples, expected F*(2^k+1)(2^k+2)/2 = " + std::to_string(F * per_face));

  // per face: every dyadic point exactly once
  const double scale = double(1 << k);
  std::vector<std::set<std::pair<long, long> > > seen(F);
  std::size_t bad_dyadic = 0, dup = 0, bad_param = 0, bad_limit = 0;
  std::vector<std::size_t> count_per_vertex(ref.refined_vertices.size(), 0);
  const auto ctrl_pos = positions(control);
  Max_error pl("  " + name + ": same refined vertex, PL location spread");
  std::vector<V3> pl_of_vertex(ref.refined_vertices.size());
  for(const auto& s : ref.samples)
  {
    const double a = s.xi1 * scale, b = s.xi2 * scale;
    if(a != std::floor(a) || b != std::floor(b) || a < 0 || b < 0 || a + b > scale) { ++bad_dyadic; continue; }
    if(!seen[s.face].insert(std::make_pair(long(a), long(b))).second) ++dup;
    if(param_of_sample(ref, s) != ref.params[s.refined_vertex]) ++bad_param;
    if(s.limit != ref.limits[s.refined_vertex]) ++bad_limit;
    // location on the control polyhedron
    const auto& t = ref.control_faces[s.face];
    const double w[3] = {1.0 - s.xi1 - s.xi2, s.xi1, s.xi2};
    V3 x = {{0, 0, 0}};
    for(int i = 0; i < 3; ++i)
      for(int d = 0; d < 3; ++d) x[d] += w[i] * ctrl_pos[t[i]][d];
    if(count_per_vertex[s.refined_vertex]++ == 0) pl_of_vertex[s.refined_vertex] = x;
    else pl.add_error(dist(x, pl_of_vertex[s.refined_vertex]));
  }
  AF_CHECK(bad_dyadic == 0, name + ": samples at dyadic points of level k inside the triangle");
  AF_CHECK(dup == 0, name + ": no duplicate (face, xi) samples");
  AF_CHECK(bad_param == 0, name + ": (face, xi1, xi2) of every sample maps to the vertex's control parameter");
  AF_CHECK(bad_limit == 0, name + ": samples of one refined vertex carry the same limit point");
  AF_CHECK(pl.value() < 1e-15, name + ": samples of one refined vertex map to the same control-polyhedron point");
  pl.print();

  // number of samples per refined vertex = 1 (interior), 2 (original edge), valence (original vertex)
  std::size_t bad_count = 0;
  std::vector<std::size_t> val(ref.num_control_vertices, 0);
  for(const auto& t : ref.control_faces) for(int i = 0; i < 3; ++i) ++val[t[i]];
  for(std::size_t r = 0; r < ref.refined_vertices.size(); ++r)
  {
    const auto& p = ref.params[r];
    const std::size_t expect = p.size == 3 ? 1 : p.size == 2 ? 2 : val[p.vertex[0]];
    if(count_per_vertex[r] != expect) ++bad_count;
  }
  AF_CHECK(bad_count == 0, name + ": samples per refined vertex = faces whose closure contains it");

  // corners equal the level-0 limit mask
  const auto lm = AF_test::limit_mask_positions(control);
  Max_error corner("  " + name + ": corner samples vs limit_mask_positions(control)");
  for(const auto& s : ref.samples)
  {
    const auto& t = ref.control_faces[s.face];
    int c = -1;
    if(s.xi1 == 0 && s.xi2 == 0) c = 0;
    else if(s.xi1 == 1 && s.xi2 == 0) c = 1;
    else if(s.xi1 == 0 && s.xi2 == 1) c = 2;
    if(c >= 0) corner.add_error(dist(s.limit, lm[t[c]]));
  }
  AF_CHECK(corner.count() == long(3 * F), name + ": three corner samples per face");
  AF_CHECK(corner.value() <= 1e-14, name + ": corner samples == limit mask of the control mesh");
  corner.print();
}

// Limit at level k1 < k2 must agree at the common dyadic points.
template <class Mesh>
double level_consistency(const std::string& name, const Mesh& control, int k1, int k2)
{
  const auto r1 = AF_test::cgal_loop_reference(control, k1);
  const auto r2 = AF_test::cgal_loop_reference(control, k2);
  std::map<std::tuple<std::size_t, double, double>, V3> fine;
  for(const auto& s : r2.samples) fine[std::make_tuple(s.face, s.xi1, s.xi2)] = s.limit;
  Max_error e("  " + name + ": level " + std::to_string(k1) + " vs level " + std::to_string(k2) + " limits");
  std::size_t missing = 0;
  for(const auto& s : r1.samples)
  {
    auto it = fine.find(std::make_tuple(s.face, s.xi1, s.xi2));
    if(it == fine.end()) { ++missing; continue; }
    e.add_error(dist(s.limit, it->second));
  }
  AF_CHECK(missing == 0, name + ": coarse dyadic points present at the finer level");
  AF_CHECK(e.value() <= 2e-15, name + ": limit invariant under extra subdivision levels");
  e.print();
  return e.value();
}

// ---- quartic box splines of design doc §2 (independent of the package) ----
void box_spline(double x0, double x1, double x2, double N[12])
{
  const double a = x0, b = x1, c = x2;
  const double a2 = a * a, a3 = a2 * a, a4 = a3 * a, b2 = b * b, b3 = b2 * b, b4 = b3 * b, c2 = c * c, c3 = c2 * c, c4 = c3 * c;
  N[0] = a4 + 2 * a3 * b;
  N[1] = a4 + 2 * a3 * c;
  N[2] = a4 + 6 * a3 * b + 2 * a3 * c + 12 * a2 * b2 + 6 * a2 * b * c + 6 * a * b3 + 6 * a * b2 * c + b4 + 2 * b3 * c;
  N[3] = 6 * a4 + 24 * a3 * b + 24 * a3 * c + 24 * a2 * b2 + 60 * a2 * b * c + 24 * a2 * c2 + 8 * a * b3 + 36 * a * b2 * c
         + 36 * a * b * c2 + 8 * a * c3 + b4 + 6 * b3 * c + 12 * b2 * c2 + 6 * b * c3 + c4;
  N[4] = a4 + 2 * a3 * b + 6 * a3 * c + 6 * a2 * b * c + 12 * a2 * c2 + 6 * a * b * c2 + 6 * a * c3 + 2 * b * c3 + c4;
  N[5] = 2 * a * b3 + b4;
  N[6] = a4 + 8 * a3 * b + 6 * a3 * c + 24 * a2 * b2 + 36 * a2 * b * c + 12 * a2 * c2 + 24 * a * b3 + 60 * a * b2 * c
         + 36 * a * b * c2 + 6 * a * c3 + 6 * b4 + 24 * b3 * c + 24 * b2 * c2 + 8 * b * c3 + c4;
  N[7] = a4 + 6 * a3 * b + 8 * a3 * c + 12 * a2 * b2 + 36 * a2 * b * c + 24 * a2 * c2 + 6 * a * b3 + 36 * a * b2 * c
         + 60 * a * b * c2 + 24 * a * c3 + b4 + 8 * b3 * c + 24 * b2 * c2 + 24 * b * c3 + 6 * c4;
  N[8] = 2 * a * c3 + c4;
  N[9] = b4 + 2 * b3 * c;
  N[10] = 2 * a * b3 + 6 * a * b2 * c + 6 * a * b * c2 + 2 * a * c3 + b4 + 6 * b3 * c + 12 * b2 * c2 + 6 * b * c3 + c4;
  N[11] = 2 * b * c3 + c4;
  for(int i = 0; i < 12; ++i) N[i] /= 12.0;
}

// Regular torus (all valence 6): the reference equals the box-spline patch at every sample.
template <class Mesh>
void test_box_spline_torus(const char* type, std::size_t n, std::size_t m, int k)
{
  Mesh control;
  AF_test::make_regular_torus(control, n, m, 2.0, 0.75);
  AF_test::perturb_vertices(control, 0.1, 11u); // generic geometry, topology unchanged
  const auto ref = AF_test::cgal_loop_reference(control, k);
  check_reference_structure(std::string("torus k=") + std::to_string(k) + " [" + type + "]", control, ref);
  const auto pos = positions(control);
  // doc lattice coordinates of labels 1..12; patch (4,7,8) = (v0,v1,v2)
  const long P[12][2] = {{-1, 2}, {0, 2}, {-1, 1}, {0, 1}, {1, 1}, {-1, 0}, {0, 0}, {1, 0}, {2, 0}, {0, -1}, {1, -1}, {2, -1}};
  auto wrap = [](long d, long period) { d %= period; if(d > period / 2) d -= period; if(d < -period / 2) d += period; return d; };
  Max_error e(std::string("  torus k=") + std::to_string(k) + " [" + type + "]: |CGAL Loop limit - box spline|");
  for(const auto& s : ref.samples)
  {
    const auto& t = ref.control_faces[s.face];
    const long i0 = long(t[0] / m), j0 = long(t[0] % m);
    const long d1[2] = {wrap(long(t[1] / m) - i0, long(n)), wrap(long(t[1] % m) - j0, long(m))};
    const long d2[2] = {wrap(long(t[2] / m) - i0, long(n)), wrap(long(t[2] % m) - j0, long(m))};
    double N[12];
    box_spline(1.0 - s.xi1 - s.xi2, s.xi1, s.xi2, N);
    V3 x = {{0, 0, 0}};
    for(int L = 0; L < 12; ++L)
    {
      const long pp = P[L][0], qq = P[L][1] - 1;    // relative to label 4 = v0
      const long al = -pp - qq, be = pp;           // T^{-1} (pp, qq), T = [(0,-1) (1,-1)]
      const long ii = ((i0 + al * d1[0] + be * d2[0]) % long(n) + long(n)) % long(n);
      const long jj = ((j0 + al * d1[1] + be * d2[1]) % long(m) + long(m)) % long(m);
      const auto& xp = pos[std::size_t(ii) * m + std::size_t(jj)];
      for(int d = 0; d < 3; ++d) x[d] += N[L] * xp[d];
    }
    e.add_error(dist(x, s.limit), "face " + std::to_string(s.face));
  }
  AF_CHECK(e.value() <= 1e-14, std::string("torus [") + type + "]: reference == quartic box spline");
  e.print();
}

// Linear precision: data = affine image of unwrapped lattice coordinates on a periodic
// lattice; away from the seam the limit equals the affine image of the parameter.
template <class Mesh>
void test_linear_precision(const char* type)
{
  const std::size_t n = 14, m = 14;
  Mesh control;
  AF_test::make_regular_torus(control, n, m, 3.0, 1.0);
  auto affine = [](double i, double j) -> V3 {
    return {{0.3 + 1.1 * i - 0.4 * j, -2.0 + 0.25 * i + 0.9 * j, 0.5 - 0.7 * i + 0.2 * j}};
  };
  std::vector<V3> values;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < m; ++j) values.push_back(affine(double(i), double(j)));
  const auto ref = AF_test::cgal_loop_reference(control, 3, values);
  Max_error e(std::string("  linear precision [") + type + "]: |limit - affine(param)|");
  for(const auto& s : ref.samples)
  {
    const auto& t = ref.control_faces[s.face];
    bool inside = true;
    for(int c = 0; c < 3; ++c)
      inside = inside && t[c] / m >= 3 && t[c] / m <= n - 4 && t[c] % m >= 3 && t[c] % m <= m - 4;
    if(!inside) continue;
    const double w[3] = {1.0 - s.xi1 - s.xi2, s.xi1, s.xi2};
    double I = 0, J = 0;
    for(int c = 0; c < 3; ++c) { I += w[c] * double(t[c] / m); J += w[c] * double(t[c] % m); }
    e.add_error(dist(s.limit, affine(I, J)));
  }
  AF_CHECK(e.count() > 1000, "linear precision: enough interior samples");
  AF_CHECK(e.value() <= 1e-13, std::string("linear precision [") + type + "]");
  e.print();
}

template <class Mesh>
void test_reference(const char* type)
{
  const std::string T = std::string(" [") + type + "]";
  // icosahedron k = 3
  {
    Mesh ico; AF_test::make_icosahedron(ico);
    const auto ref = AF_test::cgal_loop_reference(ico, 3);
    check_reference_structure("icosahedron k=3" + T, ico, ref);
    double rmin = 1e300, rmax = 0;
    for(const auto& x : ref.limits) { rmin = std::min(rmin, norm(x)); rmax = std::max(rmax, norm(x)); }
    std::printf("  icosahedron k=3%s: limit radii in [%.6f, %.6f]\n", T.c_str(), rmin, rmax);
    // limit of a control vertex: (1 - 5 chi) + 5 chi / sqrt(5) = 0.70781 (the maximum radius)
    AF_CHECK_CLOSE(rmax, (1 - 5 * AF_test::loop_limit_weight(5)) + 5 * AF_test::loop_limit_weight(5) / std::sqrt(5.0), 1e-14,
                   "icosahedron: largest limit radius is at the control vertices");
    AF_CHECK(rmin > 0.69 && (rmax - rmin) < 0.02 * rmax, "icosahedron limit radii in a narrow band");
    // mask normals: outward and, by symmetry, radial at the control vertices
    const auto nrm = AF_test::tangent_mask_normals(ico);
    const auto lm = AF_test::limit_mask_positions(ico);
    Max_error rad("  icosahedron" + T + ": |mask normal - radial direction|");
    bool outward = true;
    for(std::size_t i = 0; i < nrm.size(); ++i)
    {
      const double r = norm(lm[i]);
      outward = outward && AF_test::detail::dot3(nrm[i], lm[i]) > 0;
      rad.add_error(dist(nrm[i], {{lm[i][0] / r, lm[i][1] / r, lm[i][2] / r}}));
    }
    AF_CHECK(outward, "icosahedron mask normals point outward" + T);
    AF_CHECK(rad.value() < 1e-14, "icosahedron mask normals radial" + T);
    rad.print();
  }
  // tetrahedron / octahedron: tiny meshes (ring not a disk)
  { Mesh m; AF_test::make_tetrahedron(m); check_reference_structure("tetrahedron k=3" + T, m, AF_test::cgal_loop_reference(m, 3)); }
  { Mesh m; AF_test::make_octahedron(m); check_reference_structure("octahedron k=2" + T, m, AF_test::cgal_loop_reference(m, 2)); }
  // mixed valences
  {
    Mesh mixed; AF_test::make_mixed_valence_mesh(mixed);
    check_reference_structure("mixed k=2" + T, mixed, AF_test::cgal_loop_reference(mixed, 2));
    level_consistency("mixed" + T, mixed, 1, 3);
    level_consistency("mixed" + T, mixed, 2, 3);
    Mesh ico1; AF_test::make_icosphere(ico1, 1);
    level_consistency("icosphere(1)" + T, ico1, 1, 4);

    // mask normals vs the normal of the fine limit ring around each control vertex
    const auto nrm = AF_test::tangent_mask_normals(mixed);
    for(int k : {3, 5})
    {
      const auto ref = AF_test::cgal_loop_reference(mixed, k);
      std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, std::size_t> rid;
      for(std::size_t r = 0; r < ref.refined_vertices.size(); ++r) rid.emplace(ref.refined_vertices[r], r);
      Max_error e("  mixed" + T + ": angle(mask normal, level-" + std::to_string(k) + " limit-ring normal) [rad]");
      for(std::size_t r = 0; r < ref.refined_vertices.size(); ++r)
      {
        if(ref.params[r].size != 1) continue;
        const std::size_t c = ref.params[r].vertex[0];
        const auto nb = AF_test::ccw_neighbours(ref.refined, ref.refined_vertices[r]);
        const V3& x = ref.limits[r];
        V3 acc = {{0, 0, 0}};
        for(std::size_t j = 0; j < nb.size(); ++j)
        {
          const V3& y0 = ref.limits[rid.at(nb[j])];
          const V3& y1 = ref.limits[rid.at(nb[(j + 1) % nb.size()])];
          const V3 cr = AF_test::detail::cross3(AF_test::detail::sub3(y0, x), AF_test::detail::sub3(y1, x));
          for(int d = 0; d < 3; ++d) acc[d] += cr[d];
        }
        const double cosang = AF_test::detail::dot3(acc, nrm[c]) / norm(acc);
        e.add_error(std::acos(std::min(1.0, std::max(-1.0, cosang))), "valence " + std::to_string(nb.size()));
      }
      AF_CHECK(e.value() < (k == 3 ? 0.02 : 0.005), "mixed: mask normal close to the fine limit-ring normal");
      e.print();
    }
  }
  test_box_spline_torus<Mesh>(type, 8, 9, 3);
  test_linear_precision<Mesh>(type);

  // runtime k = 4 on the mixed mesh
  {
    Mesh mixed; AF_test::make_mixed_valence_mesh(mixed);
    const auto t0 = std::chrono::steady_clock::now();
    const auto ref = AF_test::cgal_loop_reference(mixed, 4);
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("  mixed k=4%s: %zu refined vertices, %zu samples, %.3f s\n", T.c_str(),
                ref.refined_vertices.size(), ref.samples.size(), sec);
    AF_CHECK(sec < 10.0, "mixed k=4 runs in a few seconds");
  }
}

// Same samples, keyed by the type-independent control parameter, for SM and Polyhedron.
template <class Mesh>
std::map<std::vector<std::pair<std::size_t, double> >, V3> keyed_limits(int k)
{
  Mesh m; AF_test::make_mixed_valence_mesh(m);
  const auto ref = AF_test::cgal_loop_reference(m, k);
  std::map<std::vector<std::pair<std::size_t, double> >, V3> r;
  for(std::size_t i = 0; i < ref.params.size(); ++i)
  {
    std::vector<std::pair<std::size_t, double> > key;
    for(int j = 0; j < ref.params[i].size; ++j) key.emplace_back(ref.params[i].vertex[j], ref.params[i].weight[j]);
    r[key] = ref.limits[i];
  }
  return r;
}

} // namespace

int main()
{
  std::printf("Loop weights: a(6) = %.17g, chi(6) = %.17g, chi(3) = %.17g\n",
              AF_test::loop_vertex_weight(6), AF_test::loop_limit_weight(6), AF_test::loop_limit_weight(3));
  AF_CHECK_CLOSE(AF_test::loop_vertex_weight(6), 1.0 / 16, 1e-17, "a(6)");
  AF_CHECK_CLOSE(AF_test::loop_limit_weight(6), 1.0 / 12, 1e-17, "chi(6)");
  AF_CHECK_CLOSE(1 - 6 * AF_test::loop_limit_weight(6), 0.5, 1e-16, "centre(6)");
  AF_CHECK_CLOSE(AF_test::loop_limit_weight(3), 0.2, 1e-16, "chi(3)");
  AF_CHECK_CLOSE(AF_test::loop_vertex_weight(3), 0.1875, 1e-16, "a(3)");
  AF_CHECK_REL(AF_test::loop_limit_weight(12), 0.035265, 2e-5, "chi(12) (doc table)");

  std::printf("== generators [Surface_mesh]\n");
  test_generators<SM>("Surface_mesh");
  std::printf("== generators [Polyhedron_3]\n");
  test_generators<Poly>("Polyhedron_3");

  std::printf("== reference [Surface_mesh]\n");
  test_reference<SM>("Surface_mesh");
  std::printf("== reference [Polyhedron_3]\n");
  test_reference<Poly>("Polyhedron_3");

  std::printf("== Surface_mesh with garbage (removed elements) as control mesh\n");
  {
    SM clean, dirty;
    AF_test::make_icosphere(clean, 1);
    AF_test::make_icosphere(dirty, 1);
    const SM::Vertex_index junk = dirty.add_vertex(K::Point_3(5, 5, 5));
    dirty.remove_vertex(junk); // leaves a removed slot, dirty.has_garbage() == true
    AF_CHECK(dirty.has_garbage(), "garbage present");
    const auto a = AF_test::cgal_loop_reference(clean, 2);
    const auto b = AF_test::cgal_loop_reference(dirty, 2);
    bool same = a.samples.size() == b.samples.size();
    for(std::size_t i = 0; same && i < a.samples.size(); ++i)
      same = a.samples[i].face == b.samples[i].face && a.samples[i].xi1 == b.samples[i].xi1 &&
             a.samples[i].xi2 == b.samples[i].xi2 && a.samples[i].limit == b.samples[i].limit;
    AF_CHECK(same, "control mesh with garbage gives the same samples");
  }

  std::printf("== Surface_mesh vs Polyhedron_3\n");
  {
    const auto a = keyed_limits<SM>(3), b = keyed_limits<Poly>(3);
    Max_error e("  mixed k=3: |SM - Polyhedron| limit by control parameter");
    bool same_keys = a.size() == b.size();
    for(const auto& kv : a)
    {
      auto it = b.find(kv.first);
      if(it == b.end()) { same_keys = false; continue; }
      e.add_error(dist(kv.second, it->second));
    }
    AF_CHECK(same_keys, "SM and Polyhedron give the same parameter set");
    AF_CHECK(e.value() <= 1e-14, "SM and Polyhedron give the same limits");
    e.print();
  }
  return AF_test::report();
}
