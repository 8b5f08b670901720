// Functions on surfaces (Bajaj & Xu's cases a-d; doc/Anisotropic_fairing/design/loop-fem.md section 7, loop-fem-flow.md sections 8 and 11b-d):
//  - the Laplace-Beltrami spectrum of the fixed interpolating icosphere (642 vertices): the generalised
//    eigenvalues of (L, M) are l(l+1), multiplicity 2l+1, for l = 1..4;
//  - attributes-only time stepping of Y_l (l = 1, 2, 3) to t = 0.1 with tau = 1e-3: the M-norm ratio is
//    (1 + tau l(l+1))^-n; with a fidelity weight w the steady state is w/(w + l(l+1)) Y_l;
//  - a constant attribute is unchanged in every mode; the geometry is not written in attributes-only
//    mode, the attributes not in geometry-only mode;
//  - every supported value type (and a user type with its own traits) gives the same result through a
//    Surface_mesh property map; colours are the clamped, rounded values of the same run in doubles;
//  - coupled mode: trace(X^T L X) = 2 Area in R^kappa, and int |H|^2 equals an independent evaluation
//    of the mean-curvature vector by the Christoffel symbols, H . t_k = 0;
//  - the attribute control values given back (attribute_control_map) have the written values as their
//    Loop limit values in every mode (default run included); geometry-only writes none.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>
#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>
#include <CGAL/Anisotropic_fairing/internal/assembly/Fem_assembly.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Indexed_mesh.h>
#include <CGAL/Anisotropic_fairing/internal/element/Patch_cache.h>

#include "test_support/check.h"
#include "test_support/interpolating_sphere.h"
#include "test_support/mesh_coordinates.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace AF = CGAL::Anisotropic_fairing;
namespace AFI = CGAL::Anisotropic_fairing::internal;

std::string data_dir;

Eigen::SparseMatrix<double> with_values(const CGAL::Anisotropic_fairing::internal::Sparse_structure& pattern, const CGAL::Anisotropic_fairing::internal::Value_array& v)
{
  return pattern.matrix(v);
}

// real spherical harmonics (unnormalised) of degree 1, 2, 3 at a unit vector
double harmonic(int l, const K::Point_3& p)
{
  const double r = std::sqrt(p.x() * p.x() + p.y() * p.y() + p.z() * p.z());
  const double x = p.x() / r, y = p.y() / r, z = p.z() / r;
  switch(l)
  {
    case 1: return z;
    case 2: return x * y;
    default: return x * (x * x - 3 * y * y);
  }
}

struct Sphere_operators
{
  Eigen::MatrixXd M, L;
};

Sphere_operators sphere_operators(const Mesh& sphere)
{
  AFI::Indexed_mesh<Mesh> im(sphere);
  const AFI::Control_matrix X = im.read_points(sphere.points());
  AFI::Patch_cache cache(im.topology());
  cache.prepare_quadrature(AFI::Quadrature_spec());
  AFI::Fem_assembler<AFI::Patch_cache> as(cache, im.number_of_vertices());
  CGAL::Anisotropic_fairing::internal::Value_array mv, lv;
  as.assemble(X, 3, AF::Isotropic_diffusion_tensor(), mv, lv);
  return { Eigen::MatrixXd(with_values(as.pattern(), mv)), Eigen::MatrixXd(with_values(as.pattern(), lv)) };
}

void spectrum(const Sphere_operators& op)
{
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(op.L, op.M);
  AF_CHECK(es.info() == Eigen::Success, "generalised eigenproblem solved");
  const Eigen::VectorXd& lambda = es.eigenvalues();
  AF_CHECK(std::abs(lambda[0]) <= 1e-10, "the constants: eigenvalue 0");
  int k = 1;
  for(int l = 1; l <= 4; ++l)
  {
    const double exact = l * (l + 1);
    double worst = 0;
    for(int j = 0; j < 2 * l + 1; ++j, ++k) worst = std::max(worst, std::abs(lambda[k] - exact) / exact);
    std::printf("Laplace-Beltrami spectrum, l = %d: %d eigenvalues, largest relative error to l(l+1) = %g: %.3g "
                "(next eigenvalue %.4f)\n", l, 2 * l + 1, exact, worst, lambda[k]);
    AF_CHECK(worst <= 5e-4, "eigenvalue l(l+1) with multiplicity 2l+1");
  }
}

double m_norm(const Eigen::MatrixXd& M, const Eigen::VectorXd& a) { return std::sqrt(a.dot(M * a)); }

// The control values of Y_l: f0 = Lambda^-1 Y_l(limit points), the limit points being Lambda X (loop-fem-flow.md 11b)
Eigen::VectorXd harmonic_control_values(const Mesh& sphere, int l)
{
  const Eigen::SparseMatrix<double> Lambda = AF_test::limit_mask_matrix(sphere);
  Eigen::MatrixXd X(sphere.number_of_vertices(), 3);
  for(auto v : sphere.vertices()) X.row(std::size_t(v)) << sphere.point(v).x(), sphere.point(v).y(), sphere.point(v).z();
  const Eigen::MatrixXd P = Lambda * X;
  Eigen::MatrixXd Y(sphere.number_of_vertices(), 1);
  for(Eigen::Index i = 0; i < P.rows(); ++i) Y(i, 0) = harmonic(l, K::Point_3(P(i, 0), P(i, 1), P(i, 2)));
  return AF_test::interpolating_control_values(sphere, Y).col(0);
}

// Attributes-only diffusion of Y_l on the fixed sphere: decay, and the steady state with fidelity
void harmonic_decay(const Mesh& sphere, const Sphere_operators& op)
{
  for(int l = 1; l <= 3; ++l)
  {
    const Eigen::VectorXd y = harmonic_control_values(sphere, l);
    Mesh m = sphere;
    auto f = m.add_property_map<Vertex, double>("v:f", 0.0).first;
    for(auto v : m.vertices()) f[v] = y[Eigen::Index(std::size_t(v))];
    Eigen::VectorXd a0(m.number_of_vertices()), a(m.number_of_vertices());
    for(auto v : m.vertices()) a0[Eigen::Index(std::size_t(v))] = f[v];
    const std::vector<double> before = AF_test::coordinates(m);
    const AF::Fairing_report r = AF::anisotropic_fairing(m, m.points(), f,
        AF::parameters::attribute_mode(AF::Attribute_mode::ATTRIBUTES_ONLY).time_step(1e-3).number_of_iterations(100u)
                       .stopping_criteria(AF::Stopping_criteria::none()).output_positions(AF::Output_positions::CONTROL_POINTS));
    AF_CHECK(r.succeeded() && r.steps.size() == 100 && r.attribute_dimension == 1, "attributes-only run of 100 steps");
    AF_CHECK(r.used_cholesky, "factorised (once) for 642 vertices");
    AF_CHECK(AF_test::byte_identical(before, AF_test::coordinates(m)), "attributes only: the geometry is not written");
    for(auto v : m.vertices()) a[Eigen::Index(std::size_t(v))] = f[v];
    const double ratio = m_norm(op.M, a) / m_norm(op.M, a0);
    const double expected = std::pow(1 + 1e-3 * l * (l + 1), -100.0);
    std::printf("Y_%d, attributes only, tau = 1e-3, 100 steps: M-norm ratio %.8f, (1 + tau l(l+1))^-n = %.8f, rel. error %.3g\n",
                l, ratio, expected, std::abs(ratio - expected) / expected);
    AF_CHECK_REL(ratio, expected, 5e-4, "M-norm decay of Y_l");
    // the energy reported is the attributes' Dirichlet energy, decreasing
    AF_CHECK(r.steps.back().energy < r.initial.energy && r.steps.back().area == r.initial.area, "energy falls, area fixed");

    // fidelity: steady state w/(w + l(l+1)) Y_l
    Mesh s = sphere;
    auto g = s.add_property_map<Vertex, double>("v:g", 0.0).first;
    for(auto v : s.vertices()) g[v] = y[Eigen::Index(std::size_t(v))];
    AF::Stopping_criteria steady = AF::Stopping_criteria::none();
    steady.steady_speed = 1e-12;
    const double w = 10;
    const AF::Fairing_report rs = AF::anisotropic_fairing(s, s.points(), g,
        AF::parameters::attribute_mode(AF::Attribute_mode::ATTRIBUTES_ONLY).time_step(0.01).fidelity_weight(w)
                       .number_of_iterations(2000u).stopping_criteria(steady).output_positions(AF::Output_positions::CONTROL_POINTS));
    Eigen::VectorXd as(s.number_of_vertices());
    for(auto v : s.vertices()) as[Eigen::Index(std::size_t(v))] = g[v];
    // the fixed point of the scheme solves (w M + L) a* = w M a0; its amplitude along Y_l is w/(w + l(l+1)).
    // f0 is Y_l of the limit surface, not an exact eigenvector of (L, M): the part of a* orthogonal to
    // f0 is the discretisation's mixing of modes, measured and bounded separately.
    const Eigen::VectorXd direct = (w * op.M + op.L).ldlt().solve(w * (op.M * a0));
    const double to_direct = m_norm(op.M, as - direct) / m_norm(op.M, direct);
    const double factor = w / (w + l * (l + 1));
    const double amplitude = as.dot(op.M * a0) / a0.dot(op.M * a0);
    const double remainder = m_norm(op.M, as - amplitude * a0) / m_norm(op.M, as);
    std::printf("Y_%d with fidelity w = %g: steady after %zu steps (%s); vs the direct solve %.3g; amplitude %.7f, "
                "w/(w+l(l+1)) = %.7f (rel. error %.3g); part orthogonal to Y_l %.3g\n", l, w, rs.steps.size(),
                AF::to_string(rs.stop_reason), to_direct, amplitude, factor, std::abs(amplitude - factor) / factor, remainder);
    AF_CHECK(rs.succeeded() && rs.stop_reason == AF::Stop_reason::STEADY_STATE, "the steady state is reached");
    AF_CHECK(to_direct <= 1e-8, "time stepping reaches the fixed point (w M + L) a = w M a0");
    AF_CHECK_REL(amplitude, factor, 1e-4, "steady state w/(w + l(l+1)) Y_l");
    AF_CHECK(remainder <= 1e-3, "little mixing with other modes");
  }
}

// ---------------------------------------------------------------------------------------------------
void constant_attribute(const Mesh& bumpy)
{
  for(AF::Attribute_mode mode : { AF::Attribute_mode::SEPARATE, AF::Attribute_mode::COUPLED, AF::Attribute_mode::ATTRIBUTES_ONLY,
                                  AF::Attribute_mode::GEOMETRY_ONLY })
  {
    Mesh m = bumpy;
    auto c = m.add_property_map<Vertex, std::array<double, 2>>("v:c", { { 0.25, -3.0 } }).first;
    const std::vector<double> before = AF_test::coordinates(m);
    const AF::Fairing_report r = AF::anisotropic_fairing(m, m.points(), c,
        AF::parameters::relative_time_step(1e-3).attribute_mode(mode).number_of_iterations(3u).stopping_criteria(AF::Stopping_criteria::none()));
    double worst = 0;
    for(auto v : m.vertices()) worst = std::max({ worst, std::abs(c[v][0] - 0.25), std::abs(c[v][1] + 3.0) });
    const double moved = AF_test::max_abs_difference(before, AF_test::coordinates(m));
    std::printf("constant attribute, mode %d: largest change %.3g, geometry moved %.3g, dimension %zu\n", int(mode), worst,
                moved, r.attribute_dimension);
    AF_CHECK(r.succeeded(), "constant attribute run");
    AF_CHECK(worst <= 1e-12, "a constant attribute is unchanged");
    AF_CHECK((moved == 0) == (mode == AF::Attribute_mode::ATTRIBUTES_ONLY), "only attributes-only mode leaves the geometry");
    AF_CHECK(r.attribute_dimension == (mode == AF::Attribute_mode::GEOMETRY_ONLY ? 0u : 2u), "attribute dimension reported");
  }
  // geometry only with an attribute map: the map is not written
  Mesh m = bumpy;
  auto c = m.add_property_map<Vertex, double>("v:c", 0.0).first;
  for(auto v : m.vertices()) c[v] = std::sin(m.point(v).x());
  const Mesh before = m;
  auto c0 = before.property_map<Vertex, double>("v:c").first;
  AF::anisotropic_fairing(m, m.points(), c, AF::parameters::relative_time_step(1e-3).attribute_mode(AF::Attribute_mode::GEOMETRY_ONLY).number_of_iterations(2u));
  bool same = true;
  for(auto v : m.vertices()) same = same && c[v] == c0[v];
  AF_CHECK(same, "geometry only: the attribute map is not written");
  // coupled and attributes-only modes need an attribute map
  bool thrown = false;
  try { AF::anisotropic_fairing(m, AF::parameters::relative_time_step(1e-3).attribute_mode(AF::Attribute_mode::COUPLED)); }
  catch(const AF::Input_error& e) { thrown = e.kind() == AF::Input_error::INVALID_PARAMETER; }
  AF_CHECK(thrown, "coupled mode without an attribute map is refused");
}

// A user's own value type, made fairable by specialising the traits (as the documentation shows).
struct Rgb_float { float r, g, b; };
namespace CGAL { namespace Anisotropic_fairing {
template <> struct Vector_attribute_traits<Rgb_float>
{
  static constexpr int static_dimension = 3;
  static std::size_t dimension(const Rgb_float&) { return 3; }
  static double get(const Rgb_float& v, std::size_t i) { return i == 0 ? v.r : i == 1 ? v.g : v.b; }
  static Rgb_float make(const Rgb_float&, const double* x) { return Rgb_float{ float(x[0]), float(x[1]), float(x[2]) }; }
};
} }

// ---------------------------------------------------------------------------------------------------
// The same three columns through every value type: results agree with the run in doubles.
template <typename Value, typename Make, typename Read>
void value_type_case(const Mesh& mesh, const std::vector<std::array<double, 3>>& data, int components, const char* name,
                     Make make, Read read, const std::vector<std::array<double, 3>>& reference, double tolerance)
{
  Mesh m = mesh;
  auto map = m.add_property_map<Vertex, Value>("v:attribute").first;
  for(auto v : m.vertices()) map[v] = make(data[std::size_t(v)]);
  const AF::Fairing_report r = AF::anisotropic_fairing(m, m.points(), map,
      AF::parameters::relative_time_step(1e-3).attribute_mode(AF::Attribute_mode::ATTRIBUTES_ONLY).number_of_iterations(2u)
                     .stopping_criteria(AF::Stopping_criteria::none()));
  double worst = 0;
  for(auto v : m.vertices())
  {
    const std::array<double, 3> x = read(map[v]);
    for(int k = 0; k < components; ++k) worst = std::max(worst, std::abs(x[std::size_t(k)] - reference[std::size_t(v)][std::size_t(k)]));
  }
  std::printf("value type %-28s dimension %zu, largest difference to the double run %.3g\n", name, r.attribute_dimension, worst);
  AF_CHECK(r.succeeded() && r.attribute_dimension == std::size_t(components), std::string(name) + ": runs with its dimension");
  AF_CHECK(worst <= tolerance, std::string(name) + ": same result as doubles");
}

void value_types(const Mesh& bumpy)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 255);
  std::vector<std::array<double, 3>> data(bumpy.number_of_vertices());
  for(auto& d : data) d = { { u(rng), u(rng), u(rng) } };
  // the reference: std::array<double, 3>
  Mesh ref = bumpy;
  auto rmap = ref.add_property_map<Vertex, std::array<double, 3>>("v:r").first;
  for(auto v : ref.vertices()) rmap[v] = data[std::size_t(v)];
  AF::anisotropic_fairing(ref, ref.points(), rmap, AF::parameters::relative_time_step(1e-3).attribute_mode(AF::Attribute_mode::ATTRIBUTES_ONLY)
                                                       .number_of_iterations(2u).stopping_criteria(AF::Stopping_criteria::none()));
  std::vector<std::array<double, 3>> reference(bumpy.number_of_vertices());
  double overshoot = 0;
  for(auto v : ref.vertices())
  {
    reference[std::size_t(v)] = rmap[v];
    for(double x : rmap[v]) overshoot = std::max({ overshoot, -x, x - 255 });
  }
  typedef std::array<double, 3> A3;
  // scalar types see the first column only: their reference is a separate scalar run
  Mesh sref = bumpy;
  auto smap = sref.add_property_map<Vertex, double>("v:s").first;
  for(auto v : sref.vertices()) smap[v] = data[std::size_t(v)][0];
  AF::anisotropic_fairing(sref, sref.points(), smap, AF::parameters::relative_time_step(1e-3).attribute_mode(AF::Attribute_mode::ATTRIBUTES_ONLY)
                                                        .number_of_iterations(2u).stopping_criteria(AF::Stopping_criteria::none()));
  std::vector<A3> scalar_reference(bumpy.number_of_vertices());
  for(auto v : sref.vertices()) scalar_reference[std::size_t(v)] = { { smap[v], 0, 0 } };

  value_type_case<double>(bumpy, data, 1, "double", [](const A3& d) { return d[0]; }, [](double x) { return A3{ { x, 0, 0 } }; },
                          scalar_reference, 0);
  value_type_case<float>(bumpy, data, 1, "float", [](const A3& d) { return float(d[0]); },
                         [](float x) { return A3{ { double(x), 0, 0 } }; }, scalar_reference, 2e-4);
  value_type_case<int>(bumpy, data, 1, "int (rounded input)", [](const A3& d) { return int(std::lround(d[0])); },
                       [](int x) { return A3{ { double(x), 0, 0 } }; }, scalar_reference, 1.0);
  value_type_case<std::array<float, 3>>(bumpy, data, 3, "std::array<float,3>",
      [](const A3& d) { return std::array<float, 3>{ { float(d[0]), float(d[1]), float(d[2]) } }; },
      [](const std::array<float, 3>& x) { return A3{ { x[0], x[1], x[2] } }; }, reference, 2e-4);
  value_type_case<Rgb_float>(bumpy, data, 3, "user type (own traits)",
      [](const A3& d) { return Rgb_float{ float(d[0]), float(d[1]), float(d[2]) }; },
      [](const Rgb_float& x) { return A3{ { x.r, x.g, x.b } }; }, reference, 2e-4);
  value_type_case<std::vector<double>>(bumpy, data, 3, "std::vector<double>",
      [](const A3& d) { return std::vector<double>(d.begin(), d.end()); },
      [](const std::vector<double>& x) { return A3{ { x[0], x[1], x[2] } }; }, reference, 1e-12);
  value_type_case<Eigen::Vector3d>(bumpy, data, 3, "Eigen::Vector3d", [](const A3& d) { return Eigen::Vector3d(d[0], d[1], d[2]); },
      [](const Eigen::Vector3d& x) { return A3{ { x[0], x[1], x[2] } }; }, reference, 1e-12);
  value_type_case<Eigen::VectorXd>(bumpy, data, 3, "Eigen::VectorXd",
      [](const A3& d) { Eigen::VectorXd x(3); x << d[0], d[1], d[2]; return x; },
      [](const Eigen::VectorXd& x) { return A3{ { x[0], x[1], x[2] } }; }, reference, 1e-12);
  value_type_case<K::Vector_3>(bumpy, data, 3, "CGAL Vector_3", [](const A3& d) { return K::Vector_3(d[0], d[1], d[2]); },
      [](const K::Vector_3& x) { return A3{ { x.x(), x.y(), x.z() } }; }, reference, 1e-12);
  value_type_case<K::Point_3>(bumpy, data, 3, "CGAL Point_3", [](const A3& d) { return K::Point_3(d[0], d[1], d[2]); },
      [](const K::Point_3& x) { return A3{ { x.x(), x.y(), x.z() } }; }, reference, 1e-12);
  // two-component types: the reference is a run on the first two columns
  Mesh ref2 = bumpy;
  auto rmap2 = ref2.add_property_map<Vertex, std::array<double, 2>>("v:r2").first;
  for(auto v : ref2.vertices()) rmap2[v] = { { data[std::size_t(v)][0], data[std::size_t(v)][1] } };
  AF::anisotropic_fairing(ref2, ref2.points(), rmap2, AF::parameters::relative_time_step(1e-3).attribute_mode(AF::Attribute_mode::ATTRIBUTES_ONLY)
                                                         .number_of_iterations(2u).stopping_criteria(AF::Stopping_criteria::none()));
  std::vector<A3> reference2(bumpy.number_of_vertices());
  for(auto v : ref2.vertices()) reference2[std::size_t(v)] = { { rmap2[v][0], rmap2[v][1], 0 } };
  value_type_case<K::Vector_2>(bumpy, data, 2, "CGAL Vector_2", [](const A3& d) { return K::Vector_2(d[0], d[1]); },
      [](const K::Vector_2& x) { return A3{ { x.x(), x.y(), 0 } }; }, reference2, 1e-12);
  value_type_case<K::Point_2>(bumpy, data, 2, "CGAL Point_2", [](const A3& d) { return K::Point_2(d[0], d[1]); },
      [](const K::Point_2& x) { return A3{ { x.x(), x.y(), 0 } }; }, reference2, 1e-12);
  // colours: exactly the clamped, rounded double results. Isolated full-intensity spots on black make the
  // consistent-mass scheme undershoot 0 next to them, so the clamping is exercised.
  std::vector<A3> idata(data.size());
  for(std::size_t i = 0; i < data.size(); ++i)
    for(int k = 0; k < 3; ++k) idata[i][std::size_t(k)] = (i + std::size_t(k)) % 61 == 0 ? 255.0 : 0.0;
  Mesh cref = bumpy;
  auto cmap = cref.add_property_map<Vertex, A3>("v:cr").first;
  for(auto v : cref.vertices()) cmap[v] = idata[std::size_t(v)];
  AF::anisotropic_fairing(cref, cref.points(), cmap, AF::parameters::relative_time_step(1e-3).attribute_mode(AF::Attribute_mode::ATTRIBUTES_ONLY)
                                                        .number_of_iterations(2u).stopping_criteria(AF::Stopping_criteria::none()));
  std::vector<A3> colour_reference(bumpy.number_of_vertices());
  std::size_t clamped = 0;
  for(auto v : cref.vertices())
    for(int k = 0; k < 3; ++k)
    {
      const double x = cmap[v][std::size_t(k)];
      clamped += (x < 0 || x > 255) ? 1 : 0;
      colour_reference[std::size_t(v)][std::size_t(k)] = double(std::lround(std::min(255.0, std::max(0.0, x))));
    }
  value_type_case<CGAL::IO::Color>(bumpy, idata, 3, "CGAL::IO::Color",
      [](const A3& d) { return CGAL::IO::Color((unsigned char)d[0], (unsigned char)d[1], (unsigned char)d[2], 77); },
      [](const CGAL::IO::Color& c) { AF_CHECK(c.alpha() == 77, "alpha kept"); return A3{ { double(c.r()), double(c.g()), double(c.b()) } }; },
      colour_reference, 0);
  std::printf("colours: %zu channel values of the double run fell outside 0..255 and were clamped (the smooth random data "
              "overshot by %.3g)\n", clamped, overshoot);
  AF_CHECK(clamped > 0, "the salt-and-pepper colours overshoot in doubles, so clamping was tested");

  // a dynamic dimension that differs between vertices is refused before anything is written
  Mesh m = bumpy;
  auto dyn = m.add_property_map<Vertex, Eigen::VectorXd>("v:dyn", Eigen::VectorXd::Zero(2)).first;
  dyn[*std::next(m.vertices().begin(), 5)] = Eigen::VectorXd::Zero(3);
  bool thrown = false;
  try { AF::anisotropic_fairing(m, m.points(), dyn); }
  catch(const AF::Input_error& e)
  {
    thrown = e.kind() == AF::Input_error::ATTRIBUTE_DIMENSION && e.element() == 5;
    std::printf("varying dimension: %s\n", e.what());
  }
  AF_CHECK(thrown, "varying attribute dimension refused, naming vertex 5");
}

// ---------------------------------------------------------------------------------------------------
// Coupled mode: the manifold in R^(3+d)
void coupled(const Mesh& bumpy)
{
  Mesh m = bumpy;
  auto c = m.add_property_map<Vertex, std::array<double, 2>>("v:c").first;
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0, 0.05);
  for(auto v : m.vertices()) c[v] = { { std::sin(2 * m.point(v).x()) + noise(rng), m.point(v).y() * m.point(v).z() } };
  const double weight = 0.7;
  const AF::Fairing_report r = AF::anisotropic_fairing(m, m.points(), c,
      AF::parameters::relative_time_step(1e-3).attribute_mode(AF::Attribute_mode::COUPLED).attribute_weight(weight).number_of_iterations(1u)
                     .stopping_criteria(AF::Stopping_criteria::none()));
  std::printf("coupled (kappa = 5): energy %.15g, 2 Area %.15g\n", r.initial.energy, 2 * r.initial.area);
  AF_CHECK(r.succeeded(), "coupled run");
  AF_CHECK_REL(r.initial.energy, 2 * r.initial.area, 1e-12, "trace(X^T L X) = 2 Area in R^5");

  // int |H|^2 of the same manifold, with H = G^ij (x_ij - Gamma^k_ij x_k)/2 by the Christoffel symbols
  const Mesh& input = bumpy;
  AFI::Indexed_mesh<Mesh> im(input);
  AFI::Control_matrix X(Eigen::Index(im.number_of_vertices()), 5);
  X.leftCols(3) = im.read_points(input.points());
  {
    Mesh again = bumpy;
    auto c2 = again.add_property_map<Vertex, std::array<double, 2>>("v:c").first;
    std::mt19937 rng2(5);
    std::normal_distribution<double> noise2(0, 0.05);
    for(auto v : again.vertices()) c2[v] = { { std::sin(2 * again.point(v).x()) + noise2(rng2), again.point(v).y() * again.point(v).z() } };
    X.rightCols(2) = weight * im.read_attributes(c2);
  }
  AFI::Patch_cache cache(im.topology());
  cache.prepare_quadrature(AFI::Quadrature_spec());
  double integral = 0, normality = 0;
  for(std::size_t f = 0; f < cache.number_of_faces(); ++f)
  {
    const int cat = cache.category(f);
    const int* ring = cache.ring(f);
    const Eigen::VectorXd& w = cache.quadrature_weights(cat);
    for(Eigen::Index q = 0; q < w.size(); ++q)
    {
      Eigen::Matrix<double, 5, 1> t[6];
      for(int row = 0; row < 6; ++row)
      {
        t[row].setZero();
        const auto& R = cache.quadrature_rows(cat, row);
        for(int j = 0; j < cache.ring_size(f); ++j) t[row] += R(q, j) * X.row(ring[j]).transpose();
      }
      const auto &x1 = t[AFI::D1], &x2 = t[AFI::D2];
      Eigen::Matrix2d G;
      G << x1.dot(x1), x1.dot(x2), x1.dot(x2), x2.dot(x2);
      const Eigen::Matrix2d Gi = G.inverse();
      const Eigen::Matrix<double, 5, 1>* second[2][2] = { { &t[AFI::D11], &t[AFI::D12] }, { &t[AFI::D12], &t[AFI::D22] } };
      const Eigen::Matrix<double, 5, 1>* first[2] = { &x1, &x2 };
      Eigen::Matrix<double, 5, 1> H = Eigen::Matrix<double, 5, 1>::Zero();
      for(int i = 0; i < 2; ++i)
        for(int j = 0; j < 2; ++j)
        {
          // Gamma^k_ij = G^kl <x_ij, x_l>
          Eigen::Matrix<double, 5, 1> v = *second[i][j];
          for(int k = 0; k < 2; ++k)
          {
            double gamma = 0;
            for(int l = 0; l < 2; ++l) gamma += Gi(k, l) * second[i][j]->dot(*first[l]);
            v -= gamma * *first[k];
          }
          H += 0.5 * Gi(i, j) * v;
        }
      normality = std::max(normality, std::max(std::abs(H.dot(x1)) / x1.norm(), std::abs(H.dot(x2)) / x2.norm()) /
                                          std::max(1.0, H.norm()));
      integral += w[q] * H.squaredNorm() * std::sqrt(G.determinant());
    }
  }
  std::printf("coupled: int |H|^2 reported %.15g, by Christoffel symbols %.15g; largest |H . t_k| / |t_k| %.3g\n",
              r.initial.H_integral, integral, normality);
  AF_CHECK_REL(r.initial.H_integral, integral, 1e-12, "int |H|^2 in R^5 agrees with the Christoffel-symbol mean-curvature vector");
  AF_CHECK(normality <= 1e-12, "the mean-curvature vector is normal to the tangent plane");
}

// The attribute control values given back (attribute_control_map) have the written attribute values as
// their Loop limit values, in the attributes' own units, in every mode that faires them; in the
// geometry-only mode the map is left alone
void attribute_controls_given_back(const Mesh& bumpy)
{
  typedef std::array<double, 2> Value;
  auto run = [&](AF::Attribute_mode mode, bool automatic, const std::string& what) {
    Mesh m = bumpy;
    auto c = m.add_property_map<Vertex, Value>("v:c").first;
    std::mt19937 rng(11);
    std::normal_distribution<double> noise(0, 0.05);
    for(auto v : m.vertices()) c[v] = { { std::sin(2 * m.point(v).x()) + noise(rng), 3 * m.point(v).y() * m.point(v).z() } };
    std::vector<K::Point_3> control(num_vertices(m));
    const Value untouched = { { -7, -7 } };
    std::vector<Value> control_values(num_vertices(m), untouched);
    const auto given_back = AF::parameters::attribute_mode(mode).attribute_weight(0.7)
                              .control_point_map(CGAL::make_property_map(control))
                              .attribute_control_map(CGAL::make_property_map(control_values));
    const AF::Fairing_report r = automatic ? AF::anisotropic_fairing(m, m.points(), c, given_back)
                                           : AF::anisotropic_fairing(m, m.points(), c, given_back.relative_time_step(1e-3).number_of_iterations(3u)
                                                                                       .stopping_criteria(AF::Stopping_criteria::none()));
    if(!AF_CHECK(r.succeeded(), what + ": succeeds")) return;
    if(mode == AF::Attribute_mode::GEOMETRY_ONLY)
    {
      bool alone = true;
      for(const Value& x : control_values) alone = alone && x == untouched;
      AF_CHECK(alone, what + ": no attribute control values without faired attributes");
      return;
    }
    Mesh control_mesh = m;
    for(auto v : control_mesh.vertices()) control_mesh.point(v) = control[std::size_t(v)];
    std::vector<Value> limit(num_vertices(m));
    AF::Loop_limit_surface<Mesh>(control_mesh).limit_values(CGAL::make_property_map(control_values), CGAL::make_property_map(limit));
    double largest = 0, moved = 0;
    for(auto v : m.vertices())
      for(int k = 0; k < 2; ++k)
      {
        largest = std::max(largest, std::abs(limit[std::size_t(v)][k] - c[v][k]));
        moved = std::max(moved, std::abs(control_values[std::size_t(v)][k] - c[v][k]));
      }
    std::printf("%s: written attributes vs limit of the control values %.3g (control values differ by up to %.3g)\n", what.c_str(), largest, moved);
    AF_CHECK(largest <= 1e-12, what + ": the written attribute values are the limit values of the control values given back");
    AF_CHECK(moved > 1e-3, what + ": the control values are not the written values (the check can fail)");
  };
  run(AF::Attribute_mode::SEPARATE, false, "attribute control values, separate");
  run(AF::Attribute_mode::COUPLED, false, "attribute control values, coupled (weight 0.7)");
  run(AF::Attribute_mode::ATTRIBUTES_ONLY, false, "attribute control values, attributes only");
  run(AF::Attribute_mode::SEPARATE, true, "attribute control values, default run");
  run(AF::Attribute_mode::GEOMETRY_ONLY, false, "attribute control values, geometry only");
}

int main(int argc, char** argv)
{
  data_dir = argc > 1 ? argv[1] : "data";
  Mesh sphere;
  AF_test::make_interpolating_icosphere(sphere, 3);
  AF_CHECK(sphere.number_of_vertices() == 642, "the 642-vertex interpolating icosphere");
  const Sphere_operators op = sphere_operators(sphere);
  spectrum(op);
  harmonic_decay(sphere, op);
  Mesh bumpy;
  AF_CHECK(CGAL::IO::read_polygon_mesh(data_dir + "/bumpy.off", bumpy), "read bumpy.off");
  constant_attribute(bumpy);
  value_types(bumpy);
  coupled(bumpy);
  attribute_controls_given_back(bumpy);
  return AF_test::report();
}
