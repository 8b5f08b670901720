// Curvature at a point of a parametrised surface (Surface_curvature.h; loop-fem.md section 7), against
// closed forms on surfaces given with exact derivatives, and on Loop limit surfaces:
//  - torus x(u,v) = ((R + r cos v) cos u, (R + r cos v) sin u, r sin v): principal curvatures
//    -1/r and -cos v/(R + r cos v) for the outward normal, directions along v and u; H = (k1+k2)/2 n;
//  - sphere of radius r: H = -x/r^2;
//  - a graph surface in R^4: with nu = h = H/|H|, k1 + k2 = 2|H|, and H is normal to the tangent plane;
//  - the limit surface of a planar lattice: zero curvature; of the interpolating icosphere: the
//    principal curvatures lie near -1 (within the parametrisation noise loop-fem measures, [0.80, 1.32]).

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
  std::printf("planar lattice (with its ghost layer): largest |k| or |H| %.3g\n", worst);
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
}

// The interpolating Loop torus: a regular n x m lattice (every vertex of valence 6, so every patch a
// box spline) whose limit surface passes through the torus points; its principal curvatures against
// the torus's at the same (u, v), converging as the lattice is refined.
double torus_curvature_error(int n, int m, double R, double r)
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
  const AF::Loop_limit_surface<Mesh> s(t);
  double worst = 0;
  for(auto f : faces(t))
  {
    const auto p = s.evaluate(f, { 1. / 3, 1. / 3, 1. / 3 });
    const auto c = s.curvature(f, { 1. / 3, 1. / 3, 1. / 3 });
    const double rho = std::hypot(p.position.x(), p.position.y());
    const double w = std::atan2(p.position.z(), rho - R);
    // outward normal (the lattice is oriented like the parametrisation): k = -1/r and -cos w/(R + r cos w)
    const double ka = -1 / r, kb = -std::cos(w) / (R + r * std::cos(w));
    worst = std::max({ worst, std::abs(c.k1 - std::min(ka, kb)), std::abs(c.k2 - std::max(ka, kb)) });
  }
  return worst;
}

void loop_torus()
{
  const double coarse = torus_curvature_error(24, 12, 2, 0.6), fine = torus_curvature_error(48, 24, 2, 0.6);
  const double finer = torus_curvature_error(96, 48, 2, 0.6);
  std::printf("interpolating Loop torus (R = 2, r = 0.6): largest principal-curvature error at face centres "
              "%.3e (24x12), %.3e (48x24), %.3e (96x48); ratios %.2f, %.2f\n", coarse, fine, finer, coarse / fine, fine / finer);
  AF_CHECK(finer <= 5e-3 * (1 / 0.6), "torus principal curvatures agree to 0.5% of 1/r on the finest lattice");
  AF_CHECK(coarse / fine >= 3 && fine / finer >= 3, "the error falls about fourfold as the lattice is halved");
}

int main()
{
  analytic_surfaces();
  loop_surfaces();
  loop_torus();
  return AF_test::report();
}
