// The curvature-driven diffusion tensor (Anisotropic_diffusion_tensor; doc/Anisotropic_fairing/design/loop-fem.md section 7):
//  - cylinder oracle: an open Loop cylinder (32 x 30 net, ends held) shrinks at dr/dt = -g(1/r)/r for
//    lambda = infinity, 0.5 and 0.25 (one step of tau = 1e-4, radius measured in the middle), to 1e-3;
//    with the prefilter M_eps at -g(1/r_eps)/r, r_eps the radius after the isotropic step of eps;
//  - L(D) is symmetric, positive semi-definite, L(D) 1 = 0, and L(D) -> L(I) as lambda -> infinity;
//  - g is even, continuous, 1 below lambda; the relative threshold scales with the model;
//  - a user's own tensor that reads a per-vertex weight map through the basis functions;
//  - normal motion (the default): every control point's displacement is normal to the limit surface at
//    its vertex (of M_eps with a prefilter); on the face scan one step no longer folds the limit surface
//    (int |H|^2 stays of the order of the input's, where keeping the tangential motion multiplies it by 6e4).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>
#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>
#include <CGAL/Anisotropic_fairing/internal/assembly/Fem_assembly.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Indexed_mesh.h>
#include <CGAL/Anisotropic_fairing/internal/element/Patch_cache.h>

#include "test_support/check.h"
#include "test_support/mesh_coordinates.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace AF = CGAL::Anisotropic_fairing;
namespace AFI = CGAL::Anisotropic_fairing::internal;

// An open cylinder of control radius 1: n around, m rings along, spacing h; quads split alike.
Mesh cylinder(int n, int m, double h)
{
  Mesh c;
  std::vector<Vertex> v;
  const double two_pi = 6.283185307179586;
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < n; ++i) v.push_back(c.add_vertex(K::Point_3(std::cos(two_pi * i / n), std::sin(two_pi * i / n), j * h)));
  for(int j = 0; j + 1 < m; ++j)
    for(int i = 0; i < n; ++i)
    {
      const int a = j * n + i, b = j * n + (i + 1) % n, cc = a + n, d = b + n;
      c.add_face(v[std::size_t(a)], v[std::size_t(b)], v[std::size_t(d)]);
      c.add_face(v[std::size_t(a)], v[std::size_t(d)], v[std::size_t(cc)]);
    }
  return c;
}

// mean distance to the z axis of the limit points of the middle rings
double middle_radius(const Mesh& c, int n, int m)
{
  const AF::Loop_limit_surface<Mesh> s(c);
  std::map<Vertex, K::Point_3> lp;
  s.limit_positions(boost::make_assoc_property_map(lp));
  double r = 0;
  int count = 0;
  for(auto v : c.vertices())
  {
    const int ring = int(std::size_t(v)) / n;
    if(ring < m / 2 - 2 || ring > m / 2 + 2) continue;
    r += std::hypot(lp[v].x(), lp[v].y());
    ++count;
  }
  return r / count;
}

// dr/dt of the middle of the cylinder c0 (n x m) over one step of tau with the tensor D; -1e300 on failure
double cylinder_rate(const Mesh& c0, int n, int m, double tau, const AF::Anisotropic_diffusion_tensor& D)
{
  Mesh c = c0;
  const AF::Fairing_report r = AF::anisotropic_fairing(c,
      AF::parameters::diffusion_tensor(D).time_step(tau).number_of_iterations(1u).linear_solver(AF::Linear_solver::CHOLESKY)
                     .output_positions(AF::Output_positions::CONTROL_POINTS).stopping_criteria(AF::Stopping_criteria::none()));
  AF_CHECK(r.succeeded(), "cylinder step");
  return r.succeeded() ? (middle_radius(c, n, m) - middle_radius(c0, n, m)) / tau : -1e300;
}

void cylinder_oracle()
{
  const int n = 32, m = 30;
  const Mesh c0 = cylinder(n, m, 6.283185307179586 / n);
  const double r0 = middle_radius(c0, n, m);
  const double tau = 1e-4;
  for(double lambda : { std::numeric_limits<double>::infinity(), 0.5, 0.25 })
  {
    const AF::Anisotropic_diffusion_tensor D(lambda, false, 0);
    const double rate = cylinder_rate(c0, n, m, tau, D);
    const double predicted = -D.edge_stopping(1 / r0) / r0;
    std::printf("cylinder (r0 = %.5f), lambda = %g: dr/dt = %.5f, predicted -g(1/r)/r = %.5f (g = %.4f), rel. error %.2e\n",
                r0, lambda, rate, predicted, D.edge_stopping(1 / r0), std::abs(rate - predicted) / std::abs(predicted));
    AF_CHECK_REL(rate, predicted, 1e-3, "cylinder shrink rate -g(1/r)/r");
  }
  // with the prefilter M_eps the curvature is that of the cylinder after an isotropic implicit step
  // of eps: r_eps = (r0 + sqrt(r0^2 - 4 eps))/2, so the rate is -g(1/r_eps)/r0
  const double eps = 1e-3, r_eps = 0.5 * (r0 + std::sqrt(r0 * r0 - 4 * eps));
  {
    const AF::Anisotropic_diffusion_tensor D(0.5, false, eps);
    const double rate = cylinder_rate(c0, n, m, tau, D);
    const double predicted = -D.edge_stopping(1 / r_eps) / r0;
    std::printf("cylinder, lambda = 0.5, prefilter eps = %g (r_eps = %.5f): dr/dt = %.5f, predicted -g(1/r_eps)/r0 = %.5f, "
                "rel. error %.2e\n", eps, r_eps, rate, predicted, std::abs(rate - predicted) / std::abs(predicted));
    AF_CHECK_REL(rate, predicted, 1e-3, "prefiltered cylinder rate");
  }
  // an infinite threshold with a prefilter is the isotropic flow, bit for bit (when the tangential
  // motion is kept, as the isotropic flow keeps it)
  {
    Mesh a = c0, b = c0;
    const auto np = AF::parameters::time_step(tau).number_of_iterations(2u).linear_solver(AF::Linear_solver::CHOLESKY)
                                   .stopping_criteria(AF::Stopping_criteria::none());
    AF::anisotropic_fairing(a, np.diffusion_tensor(AF::Anisotropic_diffusion_tensor(std::numeric_limits<double>::infinity(), false, eps, false)));
    AF::anisotropic_fairing(b, np);
    const double d = AF_test::max_abs_difference(AF_test::coordinates(a), AF_test::coordinates(b));
    std::printf("prefilter with lambda = infinity vs isotropic: largest difference %.3g\n", d);
    AF_CHECK(d == 0, "prefiltered tensor with lambda = infinity is isotropic");
  }
}

Eigen::MatrixXd stiffness(const Mesh& mesh, const AF::Anisotropic_diffusion_tensor& D, Eigen::MatrixXd* L_iso = nullptr)
{
  AFI::Indexed_mesh<Mesh> im(mesh);
  const AFI::Control_matrix X = im.read_points(mesh.points());
  AFI::Patch_cache cache(im.topology());
  cache.prepare_quadrature(AFI::Quadrature_spec());
  AFI::Fem_assembler<AFI::Patch_cache> as(cache, im.number_of_vertices());
  CGAL::Anisotropic_fairing::internal::Value_array mv, lv;
  as.assemble(X, 3, D, mv, lv);
  const Eigen::SparseMatrix<double> L = as.pattern().matrix(lv);
  if(L_iso)
  {
    as.assemble(X, 3, AF::Isotropic_diffusion_tensor(), mv, lv);
    *L_iso = Eigen::MatrixXd(as.pattern().matrix(lv));
  }
  return Eigen::MatrixXd(L);
}

void operator_properties(const Mesh& bumpy)
{
  Eigen::MatrixXd Li;
  for(double lambda : { 0.5, 2.0, 1e300 })
  {
    AF::Anisotropic_diffusion_tensor D(lambda, false, 0);
    const Eigen::MatrixXd L = stiffness(bumpy, D, &Li);
    const double asym = (L - L.transpose()).cwiseAbs().maxCoeff();
    const double rows = (L * Eigen::VectorXd::Ones(L.rows())).cwiseAbs().maxCoeff() / L.diagonal().cwiseAbs().maxCoeff();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(L, Eigen::EigenvaluesOnly);
    const double lmin = es.eigenvalues()[0], lmax = es.eigenvalues()[L.rows() - 1];
    const double to_iso = (L - Li).cwiseAbs().maxCoeff() / Li.cwiseAbs().maxCoeff();
    std::printf("bumpy, lambda = %g: |L - L^T| %.2e, |L 1| / max diag %.2e, eigenvalues [%.3e, %.3e], |L(D) - L(I)| / |L(I)| %.3e\n",
                lambda, asym, rows, lmin, lmax, to_iso);
    AF_CHECK(asym == 0, "L(D) exactly symmetric");
    AF_CHECK(rows <= 1e-13, "L(D) 1 = 0");
    AF_CHECK(lmin >= -1e-12 * lmax, "L(D) positive semi-definite");
    if(lambda > 1e100) AF_CHECK(to_iso <= 1e-14, "L(D) = L(I) for lambda -> infinity");
    else AF_CHECK(to_iso > 1e-3, "a finite lambda changes the operator on bumpy");
  }
  // g: even, continuous at lambda, 1 below, 1/2 at 2 lambda
  const AF::Anisotropic_diffusion_tensor D(0.7, false);
  AF_CHECK(D.edge_stopping(0.69) == 1 && D.edge_stopping(-0.69) == 1 && D.edge_stopping(1.4) == 0.5 && D.edge_stopping(-1.4) == 0.5,
           "g(s): 1 below lambda, even, 1/2 at 2 lambda");
  AF_CHECK(std::abs(D.edge_stopping(0.7 + 1e-9) - 1) <= 1e-15, "g continuous at lambda");
}

// relative threshold: a model scaled by 10 is faired into the scaled result
void scale_invariance(const Mesh& bumpy)
{
  Mesh a = bumpy, b = bumpy;
  for(auto v : b.vertices()) b.point(v) = K::Point_3(10 * b.point(v).x(), 10 * b.point(v).y(), 10 * b.point(v).z());
  const auto np = AF::parameters::relative_time_step(1e-3).diffusion_tensor(AF::Anisotropic_diffusion_tensor(2.0)).number_of_iterations(3u)
                                 .linear_solver(AF::Linear_solver::CHOLESKY).stopping_criteria(AF::Stopping_criteria::none());
  const AF::Fairing_report ra = AF::anisotropic_fairing(a, np), rb = AF::anisotropic_fairing(b, np);
  double worst = 0, moved = 0;
  for(auto v : a.vertices())
  {
    worst = std::max(worst, std::sqrt(CGAL::squared_distance(K::Point_3(10 * a.point(v).x(), 10 * a.point(v).y(), 10 * a.point(v).z()), b.point(v))) / 10);
    moved = std::max(moved, std::sqrt(CGAL::squared_distance(a.point(v), bumpy.point(v))));
  }
  std::printf("relative lambda: bumpy x1 and x10 differ by %.3g (relative to the scale), largest motion %.3g\n", worst, moved);
  AF_CHECK(ra.succeeded() && rb.succeeded() && worst <= 1e-12 && moved > 1e-3, "the relative threshold scales with the model");
}

// A user tensor: D = w I with w interpolated from a per-vertex map by the basis functions. With w = 2
// everywhere, one step of tau equals one isotropic step of 2 tau.
struct Weighted_tensor
{
  const std::vector<double>* weight;   // per vertex, in the order of vertices(tm)
  AF::Parametric_tensor operator()(const AF::Quadrature_point_geometry& q) const
  {
    double w = 0;
    for(int j = 0; j < q.ring_size; ++j) w += q.basis[j] * (*weight)[std::size_t(q.ring[j])];
    const double inv = w / q.det;
    return AF::Parametric_tensor{ q.g22 * inv, -q.g12 * inv, q.g11 * inv };
  }
};

void user_tensor(const Mesh& bumpy)
{
  const std::vector<double> two(bumpy.number_of_vertices(), 2.0);
  Mesh a = bumpy, b = bumpy;
  const auto common = AF::parameters::number_of_iterations(1u).linear_solver(AF::Linear_solver::CHOLESKY)
                                     .stopping_criteria(AF::Stopping_criteria::none());
  AF::anisotropic_fairing(a, common.diffusion_tensor(Weighted_tensor{ &two }).time_step(1e-4));
  AF::anisotropic_fairing(b, common.time_step(2e-4));
  const double d = AF_test::max_abs_difference(AF_test::coordinates(a), AF_test::coordinates(b));
  std::printf("user tensor w I with w = 2 from a vertex map vs isotropic with 2 tau: largest difference %.3g\n", d);
  AF_CHECK(d <= 1e-12, "a user tensor reading a per-vertex map");
}

// A user tensor with a prefilter time and no length scale (the package's tensor in absolute units,
// wrapped so that set_length_scale is hidden) reads its curvature on M_eps from the first step, as the
// package's tensor does: the two runs agree.
struct Unscaled_tensor
{
  AF::Anisotropic_diffusion_tensor inner;
  AF::Parametric_tensor operator()(const AF::Quadrature_point_geometry& q) const { return inner(q); }
  double prefilter_time() const { return inner.prefilter_time(); }
  bool normal_motion_only() const { return inner.normal_motion_only(); }
};

void user_tensor_with_prefilter(const Mesh& bumpy)
{
  Mesh a = bumpy, b = bumpy;
  const auto common = AF::parameters::number_of_iterations(2u).time_step(1e-4).linear_solver(AF::Linear_solver::CHOLESKY)
                                     .stopping_criteria(AF::Stopping_criteria::none());
  const AF::Anisotropic_diffusion_tensor absolute(20.0, false, 1e-4);
  const AF::Fairing_report ra = AF::anisotropic_fairing(a, common.diffusion_tensor(absolute));
  Unscaled_tensor wrapped{ absolute };
  wrapped.inner.set_length_scale(ra.scale);   // (in absolute units this sets only where curvature is undefined)
  const AF::Fairing_report rb = AF::anisotropic_fairing(b, common.diffusion_tensor(wrapped));
  const double d = AF_test::max_abs_difference(AF_test::coordinates(a), AF_test::coordinates(b));
  std::printf("user tensor with a prefilter, without a length scale, vs the package's tensor: largest difference %.3g\n", d);
  AF_CHECK(ra.succeeded() && rb.succeeded() && d <= 1e-12, "a user tensor's prefilter applies from the first step");
}

// Normal motion only: the displacement of each control point is parallel to the limit normal at its
// vertex (Loop_limit_surface::limit_normals of the input), to round-off; boundary vertices stay put.
void normal_motion(const Mesh& scan)
{
  Mesh m = scan;
  auto normal = m.add_property_map<Vertex, K::Vector_3>("v:limit_normal").first;
  AF::Loop_limit_surface<Mesh>(m).limit_normals(normal);
  const auto np = AF::parameters::relative_time_step(1e-3).number_of_iterations(1u).stopping_criteria(AF::Stopping_criteria::none())
                    .output_positions(AF::Output_positions::CONTROL_POINTS);
  const AF::Fairing_report r = AF::anisotropic_fairing(m, np.diffusion_tensor(AF::Anisotropic_diffusion_tensor(2, true, 0)));
  AF_CHECK(r.succeeded() && r.normal_motion_only, "the anisotropic tensor moves along the normal only by default (reported)");
  double tangential = 0, largest = 0;
  for(Vertex v : vertices(m))
  {
    const K::Vector_3 d = m.point(v) - scan.point(v);
    largest = std::max(largest, std::sqrt(d.squared_length()));
    tangential = std::max(tangential, std::sqrt(CGAL::cross_product(d, normal[v]).squared_length()));
  }
  std::printf("face scan, one step of the anisotropic tensor without prefilter: largest displacement %.3g, largest tangential part %.2e\n",
              largest, tangential);
  AF_CHECK(largest > 0 && tangential <= 1e-12 * largest, "control points move along their limit normals");

  // with a prefilter the normal is M_eps's: M_eps is one isotropic implicit step of eps (solved here
  // by the factorisation; the library's prefilter uses CG to 1e-10)
  {
    const double eps = 2e-3 * r.scale * r.scale;
    Mesh filtered = scan, moved = scan;
    AF::anisotropic_fairing(filtered, AF::parameters::time_step(eps).number_of_iterations(1u).stopping_criteria(AF::Stopping_criteria::none())
                                        .output_positions(AF::Output_positions::CONTROL_POINTS).linear_solver(AF::Linear_solver::CHOLESKY));
    auto eps_normal = filtered.add_property_map<Vertex, K::Vector_3>("v:limit_normal").first;
    AF::Loop_limit_surface<Mesh>(filtered).limit_normals(eps_normal);
    const AF::Fairing_report e = AF::anisotropic_fairing(moved, np.diffusion_tensor(AF::Anisotropic_diffusion_tensor(2 / r.scale, false, eps)));
    double off_eps = 0, off_current = 0, step = 0;
    for(Vertex v : vertices(moved))
    {
      const K::Vector_3 d = moved.point(v) - scan.point(v);
      step = std::max(step, std::sqrt(d.squared_length()));
      off_eps = std::max(off_eps, std::sqrt(CGAL::cross_product(d, eps_normal[v]).squared_length()));
      off_current = std::max(off_current, std::sqrt(CGAL::cross_product(d, normal[v]).squared_length()));
    }
    std::printf("  with the prefilter eps = 2e-3 l^2: largest displacement %.3g, its part off the normal of M_eps %.2e, "
                "off the current normal %.2e\n", step, off_eps, off_current);
    AF_CHECK(e.succeeded() && off_eps <= 1e-7 * step, "with a prefilter, control points move along the limit normals of M_eps");
    AF_CHECK(off_current >= 1e-3 * step, "... which are not the current surface's");
  }

  // what the tangential part does to a noisy scan, with the paper's scheme and without it
  double H[2];
  for(int keep = 0; keep < 2; ++keep)
  {
    Mesh c = scan;
    const AF::Fairing_report k = AF::anisotropic_fairing(c, np.diffusion_tensor(AF::Anisotropic_diffusion_tensor(2, true, 0, keep == 0)));
    AF_CHECK(k.normal_motion_only == (keep == 0), "the report says whether the motion was normal");
    AF_CHECK(keep == 1 || k.succeeded(), "normal motion fairs the scan");
    // keeping the tangential motion folds the scan: the step control rejects the step (or ends the run)
    if(keep == 1) std::printf("  keeping the tangential motion: %s, %zu rejected steps: %s\n", AF::to_string(k.status), k.rejected_steps, k.message.c_str());
    if(keep == 1) AF_CHECK(k.rejected_steps > 0, "the folding step of the paper's scheme is rejected");
    H[keep] = k.steps.empty() ? 0 : k.steps[0].H_integral / k.initial.H_integral;
  }
  std::printf("  int |H|^2 after one step / before: %.3g with normal motion only, %.3g keeping the tangential motion\n", H[0], H[1]);
  AF_CHECK(H[0] <= 5, "with normal motion the limit surface does not fold (int |H|^2 within 5x the input's)");
  const AF::Fairing_report iso = AF::anisotropic_fairing(m, np);
  AF_CHECK(!iso.normal_motion_only, "the isotropic flow keeps the paper's scheme");
}

int main(int argc, char** argv)
{
  const std::string data = argc > 1 ? argv[1] : "data";
  cylinder_oracle();
  Mesh bumpy;
  AF_CHECK(CGAL::IO::read_polygon_mesh(data + "/bumpy.off", bumpy), "read bumpy.off");
  operator_properties(bumpy);
  scale_invariance(bumpy);
  user_tensor(bumpy);
  user_tensor_with_prefilter(bumpy);
  Mesh scan;
  AF_CHECK(CGAL::IO::read_polygon_mesh(data + "/face.obj", scan), "read face.obj");
  normal_motion(scan);
  return AF_test::report();
}
