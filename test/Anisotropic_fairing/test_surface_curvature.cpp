// Curvature at a point of a parametrised surface (Surface_curvature.h; doc/Anisotropic_fairing/design/loop-fem.md section 7), against
// closed forms on surfaces given with exact derivatives, and on Loop limit surfaces:
//  - torus x(u,v) = ((R + r cos v) cos u, (R + r cos v) sin u, r sin v): principal curvatures
//    -1/r and -cos v/(R + r cos v) for the outward normal, directions along v and u; H = (k1+k2)/2 n;
//  - sphere of radius r: H = -x/r^2;
//  - a graph surface in R^4: with nu = h = H/|H|, k1 + k2 = 2|H|, and H is normal to the tangent plane;
//  - the limit surface of a planar lattice: zero curvature; of the interpolating icosphere: the
//    principal curvatures lie near -1 (within the parametrisation noise loop-fem measures, [0.80, 1.32]);
//  - vertex curvatures (Loop_limit_surface::vertex_curvatures, hat-weighted averages of the shape
//    operator): zero on the plane, near -1 on the icosphere at valence 5 and 6 (much nearer than the
//    pointwise curvature next to extraordinary vertices), second-order convergent on the torus, and
//    resample()'s curvature map (vertex values at control vertices, exact curvature elsewhere).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>
#include <CGAL/Anisotropic_fairing/Surface_curvature.h>

#include "test_support/check.h"
#include "test_support/interpolating_sphere.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace AF = CGAL::Anisotropic_fairing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

// a point with its derivatives, in R^k (k <= 4)
struct Jet
{
  int k;
  double x[4], t1[4], t2[4], t11[4], t12[4], t22[4];
  AF::Quadrature_point_geometry geometry() const
  {
    AF::Quadrature_point_geometry q;
    q.face = 0; q.point = 0; q.dimension = k;
    q.t1 = t1; q.t2 = t2; q.t11 = t11; q.t12 = t12; q.t22 = t22;
    q.g11 = q.g12 = q.g22 = 0;
    for(int c = 0; c < k; ++c) { q.g11 += t1[c] * t1[c]; q.g12 += t1[c] * t2[c]; q.g22 += t2[c] * t2[c]; }
    q.det = q.g11 * q.g22 - q.g12 * q.g12;
    q.ring = nullptr; q.basis = nullptr; q.ring_size = 0;
    return q;
  }
};

Jet torus(double R, double r, double u, double v)
{
  const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v), sv = std::sin(v), w = R + r * cv;
  Jet j{ 3, { w * cu, w * su, r * sv }, { -w * su, w * cu, 0 }, { -r * sv * cu, -r * sv * su, r * cv },
         { -w * cu, -w * su, 0 }, { r * sv * su, -r * sv * cu, 0 }, { -r * cv * cu, -r * cv * su, -r * sv } };
  return j;
}

Jet sphere(double r, double u, double v)   // u longitude, v latitude
{
  const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v), sv = std::sin(v);
  Jet j{ 3, { r * cv * cu, r * cv * su, r * sv }, { -r * cv * su, r * cv * cu, 0 }, { -r * sv * cu, -r * sv * su, r * cv },
         { -r * cv * cu, -r * cv * su, 0 }, { r * sv * su, -r * sv * cu, 0 }, { -r * cv * cu, -r * cv * su, -r * sv } };
  return j;
}

// (u, v, f, g) with f = u^2 + 0.3 u v - 0.5 v^2 + 0.2 u^3, g = sin(u) cos(2 v)
Jet graph4(double u, double v)
{
  Jet j{ 4, { u, v, u * u + 0.3 * u * v - 0.5 * v * v + 0.2 * u * u * u, std::sin(u) * std::cos(2 * v) },
         { 1, 0, 2 * u + 0.3 * v + 0.6 * u * u, std::cos(u) * std::cos(2 * v) },
         { 0, 1, 0.3 * u - v, -2 * std::sin(u) * std::sin(2 * v) },
         { 0, 0, 2 + 1.2 * u, -std::sin(u) * std::cos(2 * v) },
         { 0, 0, 0.3, -2 * std::cos(u) * std::sin(2 * v) },
         { 0, 0, -1, -4 * std::sin(u) * std::cos(2 * v) } };
  return j;
}

void analytic_surfaces()
{
  AF_test::Max_error kerr("torus: principal curvatures vs -1/r, -cos v/(R + r cos v)");
  AF_test::Max_error derr("torus: principal directions vs the v and u lines (|sin angle|)");
  AF_test::Max_error herr("torus: H vs (k1 + k2)/2 n");
  const double R = 2, r = 0.6;
  for(int a = 0; a < 12; ++a)
    for(int b = 0; b < 12; ++b)
    {
      const double u = 0.3 + 0.5 * a, v = 0.1 + 0.52 * b;
      const Jet j = torus(R, r, u, v);
      const AF::Quadrature_point_geometry q = j.geometry();
      const AF::Principal_curvatures pc = AF::principal_curvatures(q);
      // t1 x t2 points outward here (away from the tube's centre line)
      const double ka = -1 / r, kb = -std::cos(v) / (R + r * std::cos(v));
      const double lo = std::min(ka, kb), hi = std::max(ka, kb);
      kerr.add(pc.k1, lo);
      kerr.add(pc.k2, hi);
      // the direction of -1/r is along t2 (the tube), the other along t1
      const std::array<double, 2>& ctube = ka < kb ? pc.c1 : pc.c2;
      const std::array<double, 2>& cring = ka < kb ? pc.c2 : pc.c1;
      derr.add_error(std::abs(ctube[0]) * std::sqrt(q.g11));   // the t1 component of a G-unit vector
      derr.add_error(std::abs(cring[1]) * std::sqrt(q.g22));
      double H[3], n[3] = { q.t1[1] * q.t2[2] - q.t1[2] * q.t2[1], q.t1[2] * q.t2[0] - q.t1[0] * q.t2[2], q.t1[0] * q.t2[1] - q.t1[1] * q.t2[0] };
      const double nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      AF::mean_curvature_vector(q, H);
      for(int c = 0; c < 3; ++c) herr.add(H[c], 0.5 * (pc.k1 + pc.k2) * n[c] / nl);
      AF_CHECK(pc.defined, "torus: normal defined");
    }
  kerr.print(); derr.print(); herr.print();
  AF_CHECK(kerr.value() <= 1e-13 && derr.value() <= 1e-13 && herr.value() <= 1e-13, "torus curvature");

  AF_test::Max_error serr("sphere r = 1.7: H vs -x/r^2");
  for(int a = 0; a < 10; ++a)
  {
    const Jet j = sphere(1.7, 0.4 + 0.6 * a, -1.2 + 0.25 * a);
    double H[3];
    AF::mean_curvature_vector(j.geometry(), H);
    for(int c = 0; c < 3; ++c) serr.add(H[c], -j.x[c] / (1.7 * 1.7));
  }
  serr.print();
  AF_CHECK(serr.value() <= 1e-14, "sphere mean-curvature vector");

  AF_test::Max_error gerr("graph in R^4: k1 + k2 - 2|H| w.r.t. h");
  AF_test::Max_error nerr("graph in R^4: |H . t_a| / (|H| |t_a|)");
  for(int a = 0; a < 9; ++a)
    for(int b = 0; b < 9; ++b)
    {
      const Jet j = graph4(-0.8 + 0.2 * a, -0.8 + 0.2 * b);
      const AF::Quadrature_point_geometry q = j.geometry();
      double H[4];
      AF::mean_curvature_vector(q, H);
      double h = 0, d1 = 0, d2 = 0, l1 = 0, l2 = 0;
      for(int c = 0; c < 4; ++c) { h += H[c] * H[c]; d1 += H[c] * j.t1[c]; d2 += H[c] * j.t2[c]; l1 += j.t1[c] * j.t1[c]; l2 += j.t2[c] * j.t2[c]; }
      h = std::sqrt(h);
      const AF::Principal_curvatures pc = AF::principal_curvatures(q, 1e-10);
      if(!pc.defined) continue;
      gerr.add(pc.k1 + pc.k2, 2 * h);
      nerr.add_error(std::max(std::abs(d1) / std::sqrt(l1), std::abs(d2) / std::sqrt(l2)) / h);
      // the directions are G-orthonormal
      const double c11 = pc.c1[0] * pc.c1[0] * q.g11 + 2 * pc.c1[0] * pc.c1[1] * q.g12 + pc.c1[1] * pc.c1[1] * q.g22;
      const double c12 = pc.c1[0] * pc.c2[0] * q.g11 + (pc.c1[0] * pc.c2[1] + pc.c1[1] * pc.c2[0]) * q.g12 + pc.c1[1] * pc.c2[1] * q.g22;
      AF_CHECK(std::abs(c11 - 1) <= 1e-13 && std::abs(c12) <= 1e-13, "c^T G c = I");
    }
  gerr.print(); nerr.print();
  AF_CHECK(gerr.count() > 70 && gerr.value() <= 1e-13, "k1 + k2 = 2|H| in R^4");
  AF_CHECK(nerr.value() <= 1e-13, "H normal to the tangent plane in R^4");
  // a planar point of a surface in R^4: h undefined, reported as such
  Jet flat{ 4, { 0, 0, 0, 0 }, { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 0, 0 }, { 0, 0, 0, 0 }, { 0, 0, 0, 0 } };
  const AF::Principal_curvatures pf = AF::principal_curvatures(flat.geometry(), 1e-10);
  AF_CHECK(!pf.defined && pf.k1 == 0 && pf.k2 == 0, "planar point in R^4: h undefined, k = 0");
}

void loop_surfaces()
{
  // a tilted planar lattice: zero curvature everywhere on the limit surface
  Mesh grid;
  std::vector<Mesh::Vertex_index> v;
  for(int i = 0; i < 6; ++i)
    for(int j = 0; j < 7; ++j) v.push_back(grid.add_vertex(K::Point_3(j, i, 0.2 * j - 0.4 * i)));
  for(int i = 0; i + 1 < 6; ++i)
    for(int j = 0; j + 1 < 7; ++j)
    {
      const int a = i * 7 + j, b = a + 1, c = a + 7, d = c + 1;
      grid.add_face(v[std::size_t(a)], v[std::size_t(b)], v[std::size_t(d)]);
      grid.add_face(v[std::size_t(a)], v[std::size_t(d)], v[std::size_t(c)]);
    }
  const AF::Loop_limit_surface<Mesh> plane(grid);
  double worst = 0;
  for(auto f : faces(grid))
  {
    const auto c = plane.curvature(f, { 0.2, 0.3, 0.5 });
    worst = std::max({ worst, std::abs(c.k1), std::abs(c.k2), std::sqrt(c.mean_curvature_vector.squared_length()) });
  }
  // and at its vertices, interior and border (half stars), valences 2 to 6
  auto planar_vertex_curvature = grid.add_property_map<Mesh::Vertex_index, AF::Loop_limit_surface<Mesh>::Curvature>("v:c").first;
  plane.vertex_curvatures(planar_vertex_curvature);
  const K::Vector_3 plane_normal = K::Vector_3(-0.2, 0.4, 1) / std::sqrt(1.2);
  for(auto x : vertices(grid))
  {
    const auto& c = planar_vertex_curvature[x];
    worst = std::max({ worst, std::abs(c.k1), std::abs(c.k2), std::sqrt(c.mean_curvature_vector.squared_length()),
                       std::abs(c.d1 * plane_normal), std::abs(c.d2 * plane_normal), std::abs(c.d1.squared_length() - 1) });
  }
  std::printf("planar lattice (with its ghost layer): largest |k| or |H| at points and vertices, |d . n|, ||d| - 1|: %.3g\n", worst);
  AF_CHECK(worst <= 1e-13, "the limit surface of a planar lattice is flat");

  // the interpolating icosphere: outward-oriented, so k1, k2 near -1
  Mesh sphere;
  AF_test::make_interpolating_icosphere(sphere, 3);
  const AF::Loop_limit_surface<Mesh> s(sphere);
  double kmin = 0, kmax = -10, mean = 0, area_weight = 0, identity = 0;
  for(auto f : faces(sphere))
    for(const auto& b : { std::array<double, 3>{ { 1. / 3, 1. / 3, 1. / 3 } }, std::array<double, 3>{ { 0.6, 0.2, 0.2 } } })
    {
      const auto c = s.curvature(f, b);
      const auto p = s.evaluate(f, b);
      kmin = std::min(kmin, c.k1);
      kmax = std::max(kmax, c.k2);
      mean += 0.5 * (c.k1 + c.k2);
      area_weight += 1;
      // k1 + k2 = 2 H . n
      identity = std::max(identity, std::abs(c.k1 + c.k2 - 2 * (c.mean_curvature_vector * p.normal)));
    }
  mean /= area_weight;
  std::printf("interpolating icosphere (642): k in [%.4f, %.4f], mean of (k1+k2)/2 %.5f, |k1 + k2 - 2 H.n| <= %.3g\n",
              kmin, kmax, mean, identity);
  AF_CHECK(kmin >= -1.35 && kmax <= -0.75, "principal curvatures within the parametrisation noise of -1");
  AF_CHECK(std::abs(mean + 1) <= 0.02, "mean curvature about -1");
  AF_CHECK(identity <= 1e-12, "k1 + k2 = 2 H . n");

  // vertex curvatures: the 12 vertices of valence 5, where the limit curvature is not finite, get
  // the same kind of value as the others; both classes near -1, H along the limit normal
  auto vc = sphere.add_property_map<Mesh::Vertex_index, AF::Loop_limit_surface<Mesh>::Curvature>("v:c").first;
  auto vn = sphere.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:n").first;
  s.vertex_curvatures(vc);
  s.limit_normals(vn);
  double lo[2] = { 0, 0 }, hi[2] = { -10, -10 }, normal_error = 0;
  for(auto x : vertices(sphere))
  {
    const int e = degree(x, sphere) == 6 ? 0 : 1;
    lo[e] = std::min(lo[e], vc[x].k1);
    hi[e] = std::max(hi[e], vc[x].k2);
    normal_error = std::max({ normal_error, (vc[x].mean_curvature_vector - 0.5 * (vc[x].k1 + vc[x].k2) * vn[x]).squared_length(),
                              std::abs(vc[x].d1 * vn[x]), std::abs(vc[x].d2 * vn[x]), std::abs(vc[x].d1 * vc[x].d2),
                              (CGAL::cross_product(vc[x].d1, vc[x].d2) - vn[x]).squared_length() });
  }
  std::printf("  its vertex curvatures: valence 6 in [%.4f, %.4f], valence 5 in [%.4f, %.4f]; frame error %.2g\n",
              lo[0], hi[0], lo[1], hi[1], normal_error);
  AF_CHECK(lo[0] >= -1.35 && hi[0] <= -0.75 && lo[1] >= -1.35 && hi[1] <= -0.75, "vertex curvatures near -1, extraordinary ones too");
  AF_CHECK(normal_error <= 1e-14, "H = (k1 + k2)/2 n, and (d1, d2, n) a right-handed orthonormal frame");

  // Why a vertex gets an average even where the limit curvature is finite: on the interpolating
  // icosphere the pointwise curvature is noisy and does not improve under refinement (the non-uniform
  // parametrisation around its extraordinary vertices, loop-fem.md section 7); the average smooths it.
  for(int level = 3; level <= 4; ++level)
  {
    Mesh fine;
    AF_test::make_interpolating_icosphere(fine, level);
    const AF::Loop_limit_surface<Mesh> f(fine);
    auto c = fine.add_property_map<Mesh::Vertex_index, AF::Loop_limit_surface<Mesh>::Curvature>("v:c").first;
    f.vertex_curvatures(c);
    double averaged[2] = { 0, 0 }, pointwise = 0;
    for(auto x : vertices(fine))
    {
      const int e = degree(x, fine) == 6 ? 0 : 1;
      averaged[e] = std::max({ averaged[e], std::abs(c[x].k1 + 1), std::abs(c[x].k2 + 1) });
      if(e == 1) continue;
      const auto g = face(halfedge(x, fine), fine);
      std::array<double, 3> corner{ { 0, 0, 0 } };
      int k = 0;
      for(auto y : vertices_around_face(halfedge(g, fine), fine)) corner[std::size_t(k++)] = y == x ? 1 : 0;
      const auto fc = f.curvature(g, corner);
      pointwise = std::max({ pointwise, std::abs(fc.k1 + 1), std::abs(fc.k2 + 1) });
    }
    std::printf("  interpolating icosphere (%zu): vertex curvature error, valence 5 %.4f, valence 6 %.4f; "
                "pointwise limit curvature at valence 6 %.4f\n", num_vertices(fine), averaged[1], averaged[0], pointwise);
    AF_CHECK(averaged[0] <= 0.05 && averaged[1] <= 0.05, "vertex curvatures within 0.05 of -1");
    AF_CHECK(pointwise >= 3 * averaged[0], "the average is much closer to -1 than the pointwise value next to extraordinary vertices");
  }
}

// The interpolating Loop torus: a regular n x m lattice (every vertex of valence 6, so every patch a
// box spline) whose limit surface passes through the torus points; its principal curvatures against
// the torus's at the same (u, v), converging as the lattice is refined. At face centres the exact
// limit curvature (`curvature()`), at the vertices the hat-weighted average (`vertex_curvatures()`,
// also through `resample()`'s curvature map), whose directions must follow the meridian and the parallel.
struct Torus_errors { double centre, vertex, direction, resampled_control, resampled_new; };

Torus_errors torus_curvature_error(int n, int m, double R, double r)
{
  Mesh t;
  std::vector<Mesh::Vertex_index> v;
  const double two_pi = 6.283185307179586;
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < n; ++i)
    {
      const double u = two_pi * i / n, w = two_pi * j / m;
      v.push_back(t.add_vertex(K::Point_3((R + r * std::cos(w)) * std::cos(u), (R + r * std::cos(w)) * std::sin(u), r * std::sin(w))));
    }
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < n; ++i)
    {
      const int a = j * n + i, b = j * n + (i + 1) % n, c = ((j + 1) % m) * n + i, d = ((j + 1) % m) * n + (i + 1) % n;
      t.add_face(v[std::size_t(a)], v[std::size_t(b)], v[std::size_t(d)]);
      t.add_face(v[std::size_t(a)], v[std::size_t(d)], v[std::size_t(c)]);
    }
  AF_test::make_interpolating(t);
  typedef AF::Loop_limit_surface<Mesh> Limit;
  const Limit s(t);
  // outward normal (the lattice is oriented like the parametrisation): k = -1/r and -cos w/(R + r cos w)
  auto principal = [&](const K::Point_3& p) {
    const double w = std::atan2(p.z(), std::hypot(p.x(), p.y()) - R);
    return std::array<double, 2>{ { -1 / r, -std::cos(w) / (R + r * std::cos(w)) } };
  };
  Torus_errors e{ 0, 0, 0, 0, 0 };
  for(auto f : faces(t))
  {
    const auto p = s.evaluate(f, { 1. / 3, 1. / 3, 1. / 3 });
    const auto c = s.curvature(f, { 1. / 3, 1. / 3, 1. / 3 });
    const auto k = principal(p.position);
    e.centre = std::max({ e.centre, std::abs(c.k1 - std::min(k[0], k[1])), std::abs(c.k2 - std::max(k[0], k[1])) });
  }
  auto limit_point = t.add_property_map<Mesh::Vertex_index, K::Point_3>("v:limit").first;
  auto curvature = t.add_property_map<Mesh::Vertex_index, Limit::Curvature>("v:curvature").first;
  s.limit_positions(limit_point);
  s.vertex_curvatures(curvature);
  for(auto x : vertices(t))
  {
    const K::Point_3 p = limit_point[x];
    const auto k = principal(p);
    const Limit::Curvature& c = curvature[x];
    e.vertex = std::max({ e.vertex, std::abs(c.k1 - std::min(k[0], k[1])), std::abs(c.k2 - std::max(k[0], k[1])) });
    // k1 = -1/r belongs to the meridian: d1 is orthogonal to the parallel's tangent (-y, x, 0)
    const double rho = std::hypot(p.x(), p.y());
    const K::Vector_3 parallel(-p.y() / rho, p.x() / rho, 0);
    e.direction = std::max({ e.direction, std::abs(c.d1 * parallel), std::abs(std::abs(c.d2 * parallel) - 1),
                             std::abs(c.mean_curvature_vector.squared_length() - 0.25 * (c.k1 + c.k2) * (c.k1 + c.k2)) });
  }
  // resample(): the control vertices first, with the vertex values, then exact curvature elsewhere
  Mesh dense;
  auto dense_curvature = dense.add_property_map<Mesh::Vertex_index, Limit::Curvature>("v:curvature").first;
  s.resample(1, dense, AF::parameters::vertex_curvature_map(dense_curvature));
  std::size_t i = 0;
  for(auto x : vertices(dense))
  {
    const Limit::Curvature& c = dense_curvature[x];
    if(i < num_vertices(t))
    {
      const Limit::Curvature& cv = curvature[Mesh::Vertex_index(Mesh::size_type(i))];
      e.resampled_control = std::max({ e.resampled_control, std::abs(c.k1 - cv.k1), std::abs(c.k2 - cv.k2), (c.d1 - cv.d1).squared_length() });
    }
    else
    {
      const auto k = principal(dense.point(x));
      e.resampled_new = std::max({ e.resampled_new, std::abs(c.k1 - std::min(k[0], k[1])), std::abs(c.k2 - std::max(k[0], k[1])) });
    }
    ++i;
  }
  return e;
}

void loop_torus()
{
  const Torus_errors coarse = torus_curvature_error(24, 12, 2, 0.6), fine = torus_curvature_error(48, 24, 2, 0.6);
  const Torus_errors finer = torus_curvature_error(96, 48, 2, 0.6);
  std::printf("interpolating Loop torus (R = 2, r = 0.6): largest principal-curvature error at face centres "
              "%.3e (24x12), %.3e (48x24), %.3e (96x48); ratios %.2f, %.2f\n", coarse.centre, fine.centre, finer.centre,
              coarse.centre / fine.centre, fine.centre / finer.centre);
  AF_CHECK(finer.centre <= 5e-3 * (1 / 0.6), "torus principal curvatures agree to 0.5% of 1/r on the finest lattice");
  AF_CHECK(coarse.centre / fine.centre >= 3 && fine.centre / finer.centre >= 3, "the error falls about fourfold as the lattice is halved");
  std::printf("  at the vertices (vertex_curvatures): %.3e, %.3e, %.3e; ratios %.2f, %.2f; direction error %.2e, %.2e, %.2e\n",
              coarse.vertex, fine.vertex, finer.vertex, coarse.vertex / fine.vertex, fine.vertex / finer.vertex,
              coarse.direction, fine.direction, finer.direction);
  AF_CHECK(finer.vertex <= 5e-3 * (1 / 0.6), "vertex curvatures agree to 0.5% of 1/r on the finest lattice");
  AF_CHECK(coarse.vertex / fine.vertex >= 3 && fine.vertex / finer.vertex >= 3, "the vertex error is second order too");
  AF_CHECK(finer.direction <= 1.5e-3 && coarse.direction / fine.direction >= 3 && fine.direction / finer.direction >= 3,
           "vertex principal directions along meridian and parallel (second order), |H| = |k1 + k2|/2");
  std::printf("  resample(1) curvature map: control vertices differ from vertex_curvatures by %.1e; error at the new vertices "
              "%.3e, %.3e, %.3e\n", std::max({ coarse.resampled_control, fine.resampled_control, finer.resampled_control }),
              coarse.resampled_new, fine.resampled_new, finer.resampled_new);
  AF_CHECK(std::max({ coarse.resampled_control, fine.resampled_control, finer.resampled_control }) == 0,
           "resample's curvature map holds vertex_curvatures() at the control vertices");
  AF_CHECK(finer.resampled_new <= 5e-3 * (1 / 0.6) && coarse.resampled_new / fine.resampled_new >= 3 && fine.resampled_new / finer.resampled_new >= 3,
           "resample's curvature map: the exact limit curvature at the new vertices (second-order accurate)");
}

int main()
{
  analytic_surfaces();
  loop_surfaces();
  loop_torus();
  return AF_test::report();
}
