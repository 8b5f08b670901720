// The user's bound on the deviation (named parameter relative_maximum_deviation): every written vertex
// stays within the bound of its input position, for several bounds, on a noisy sphere and on the
// Fandisk0.3 denoising pair (and a vertex far from the origin, clamped to a tiny bound); as the bound goes
// to 0 the output tends to the input; with a bound the run never reaches, the result is byte for byte the
// unbounded run's; a bound near the noise still removes noise (the output is closer to the true sphere than
// the input); the bound holds with both tensors,
// the fourth-order flow, the linear element, borders, constrained vertices, the automatic defaults, and
// for attributes (separate, coupled, attributes only) with a bound of their own. Run to a steady state, the
// bounded flow settles within the bound where the unbounded one shrinks past it: on a sphere at the radius
// where the uniform weight it chose balances the mean curvature, omega (r0 - r) = 2 / r. The control points
// the run gives back (control_point_map) have the written points as their limit points.
//
// argv[1]: the test data folder.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>
#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include "test_support/check.h"
#include "test_support/mesh_coordinates.h"
#include "test_support/mesh_generators.h"

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace AF = CGAL::Anisotropic_fairing;
using AF_test::byte_identical;
using AF_test::coordinates;

// the largest |x_i(out) - x_i(in)| over the vertices
double largest_deviation(const std::vector<double>& in, const std::vector<double>& out)
{
  double d = 0;
  for(std::size_t i = 0; i + 2 < in.size(); i += 3)
    d = std::max(d, std::sqrt(std::pow(out[i] - in[i], 2) + std::pow(out[i + 1] - in[i + 1], 2) + std::pow(out[i + 2] - in[i + 2], 2)));
  return d;
}

// root mean square of |x| - 1: the distance to the unit sphere
double sphere_error(const std::vector<double>& x)
{
  double s = 0;
  for(std::size_t i = 0; i + 2 < x.size(); i += 3) s += std::pow(std::sqrt(x[i] * x[i] + x[i + 1] * x[i + 1] + x[i + 2] * x[i + 2]) - 1, 2);
  return std::sqrt(s / double(x.size() / 3));
}

Mesh noisy_sphere(unsigned int seed, double amplitude)
{
  Mesh m;
  AF_test::make_icosphere(m, 4);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0, amplitude);
  for(auto v : m.vertices())
  {
    const K::Vector_3 n = m.point(v) - CGAL::ORIGIN;
    m.point(v) = m.point(v) + noise(rng) * n / std::sqrt(n.squared_length());
  }
  return m;
}

// Vertices far from the origin, carried far past a bound much smaller than their coordinates: the write-back
// puts each on the bound (within it, and not back at the input), though rounding the point near the input
// errs by many times 1e-15 of the bound, either way.
void clamped_far_from_origin()
{
  namespace AFI = AF::internal;
  const int n = 2000;
  AFI::Control_matrix input(n, 3), Y(n, 3);
  std::mt19937 rng(5);
  std::normal_distribution<double> normal(0, 1);
  for(int i = 0; i < n; ++i)
  {
    input.row(i) << 1000.3 + normal(rng), -700.1 + normal(rng), 500.7 + normal(rng);
    Y.row(i) = input.row(i) + 1e-2 * Eigen::RowVector3d(normal(rng), normal(rng), normal(rng));
  }
  for(double radius : { 1e-6, 1e-9, 1e-10 })
  {
    AFI::Control_matrix Yc = Y;
    std::vector<bool> moved(n, false);
    AFI::clamp_to_bound(Yc, input, AFI::Column_bound{ 0, 3, radius }, std::vector<bool>(n, true), moved);
    int on_bound = 0;
    for(int i = 0; i < n; ++i)
    {
      const double d = (Yc.row(i) - input.row(i)).norm();
      on_bound += moved[std::size_t(i)] && d <= radius && d > 0.99 * radius ? 1 : 0;
    }
    char what[96];
    std::snprintf(what, sizeof what, "clamped to a bound of %g at 1000: %d of %d vertices on the bound", radius, on_bound, n);
    AF_CHECK(on_bound == n, what);
  }
}

// the bound holds on every vertex to rounding; the report says so
void check_bound(const std::vector<double>& in, const std::vector<double>& out, const AF::Fairing_report& r, double bound,
                 const std::string& what)
{
  AF_CHECK(r.succeeded(), what + ": the run succeeds (" + r.message + ")");
  AF_CHECK_REL(r.absolute_maximum_deviation, bound, 1e-12, what + ": the report gives the bound in model units");
  AF_CHECK(r.maximum_deviation == r.absolute_maximum_deviation, what + ": the deprecated name of the report's bound still holds it");
  const double d = largest_deviation(in, out);
  AF_CHECK(d <= bound * (1 + 1e-12), what + ": every vertex within the bound (" + std::to_string(d) + " vs " + std::to_string(bound) + ")");
  AF_CHECK(r.largest_deviation <= bound * (1 + 1e-12) && std::abs(r.largest_deviation - d) <= 1e-12 * bound,
           what + ": the report's largest deviation is the output's");
}

void sphere_bounds()
{
  const Mesh input = noisy_sphere(1, 0.01);
  const std::vector<double> in = coordinates(input);
  const auto fixed = AF::parameters::relative_time_step(2e-3).number_of_iterations(10u).stopping_criteria(AF::Stopping_criteria::none());
  Mesh free_run = input;
  const AF::Fairing_report r0 = AF::anisotropic_fairing(free_run, fixed);
  const std::vector<double> unbounded = coordinates(free_run);
  const double moved = largest_deviation(in, unbounded);
  AF_CHECK(r0.succeeded() && r0.absolute_maximum_deviation == 0, "the unbounded run reports no bound");
  for(double relative : { 0.002, 0.005, 0.01 })
  {
    Mesh m = input;
    const AF::Fairing_report r = AF::anisotropic_fairing(m, fixed.relative_maximum_deviation(relative));
    const std::vector<double> out = coordinates(m);
    const std::string what = "sphere, relative bound " + std::to_string(relative);
    AF_CHECK(moved > relative * r.scale, what + ": the unbounded run goes beyond it (the bound is tested)");
    check_bound(in, out, r, relative * r.scale, what);
    AF_CHECK(r.bound_fidelity_weight > 0 && r.bound_held_vertices > 0, what + ": vertices were held by their fidelity");
    // the noise is 0.01: a bound at or above it still removes noise
    if(relative >= 0.005)
      AF_CHECK(sphere_error(out) < 0.75 * sphere_error(in), what + ": closer to the sphere than the input (" +
               std::to_string(sphere_error(out)) + " vs " + std::to_string(sphere_error(in)) + ")");
  }
  // the deprecated spelling maximum_deviation still means the relative bound: the same result, bit for bit
  // (with one solver: the automatic choice between them goes by measured time); two spellings are refused
  {
    Mesh m = input, d = input;
    const auto one_solver = fixed.linear_solver(AF::Linear_solver::CONJUGATE_GRADIENT);
    const AF::Fairing_report r = AF::anisotropic_fairing(m, one_solver.relative_maximum_deviation(0.005));
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
    const AF::Fairing_report rd = AF::anisotropic_fairing(d, one_solver.maximum_deviation(0.005));
    bool refused = false;
    try { Mesh e = input; AF::anisotropic_fairing(e, fixed.maximum_deviation(0.005).relative_maximum_deviation(0.005)); }
    catch(const AF::Input_error&) { refused = true; }
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
    AF_CHECK(r.succeeded() && rd.succeeded() && byte_identical(coordinates(m), coordinates(d)) &&
             r.absolute_maximum_deviation == rd.absolute_maximum_deviation, "sphere: maximum_deviation is relative_maximum_deviation's former spelling");
    AF_CHECK(refused, "sphere: maximum_deviation and relative_maximum_deviation together are refused");
  }
  // the absolute bound
  {
    Mesh m = input;
    const AF::Fairing_report r = AF::anisotropic_fairing(m, fixed.absolute_maximum_deviation(0.004));
    check_bound(in, coordinates(m), r, 0.004, "sphere, absolute bound 0.004");
  }
  // as the bound goes to zero, the output tends to the input
  for(double relative : { 1e-4, 1e-7 })
  {
    Mesh m = input;
    const AF::Fairing_report r = AF::anisotropic_fairing(m, fixed.relative_maximum_deviation(relative));
    check_bound(in, coordinates(m), r, relative * r.scale, "sphere, bound " + std::to_string(relative));
  }
  // a bound the run never reaches changes nothing, to the last bit
  {
    Mesh m = input;
    const AF::Fairing_report r = AF::anisotropic_fairing(m, fixed.relative_maximum_deviation(10.0));
    AF_CHECK(byte_identical(coordinates(m), unbounded), "sphere, bound 10: the unbounded result, byte for byte");
    AF_CHECK(r.bound_held_vertices == 0 && r.clamped_vertices == 0, "sphere, bound 10: no vertex held");
    AF_CHECK(r.steps.size() == r0.steps.size(), "sphere, bound 10: as many steps");
  }
  // the same with the other settings a user may combine with it
  const double bound = 0.004;
  {
    Mesh m = input;
    const AF::Fairing_report r = AF::anisotropic_fairing(m, fixed.absolute_maximum_deviation(bound).flow_order(4));
    check_bound(in, coordinates(m), r, bound, "sphere, fourth-order flow");
  }
  {
    Mesh m = input;
    const AF::Fairing_report r = AF::anisotropic_fairing(m, fixed.absolute_maximum_deviation(bound).finite_element(AF::Finite_element::LINEAR));
    check_bound(in, coordinates(m), r, bound, "sphere, linear element");
  }
  {
    Mesh m = input;
    const AF::Fairing_report r = AF::anisotropic_fairing(m, fixed.absolute_maximum_deviation(bound)
                                                               .output_positions(AF::Output_positions::CONTROL_POINTS));
    check_bound(in, coordinates(m), r, bound, "sphere, control points written");
  }
  {
    Mesh m = input;
    auto held = m.add_property_map<Mesh::Vertex_index, bool>("v:held", false).first;
    std::size_t k = 0;
    for(auto v : m.vertices()) held[v] = (k++ % 17) == 0;
    const AF::Fairing_report r = AF::anisotropic_fairing(m, fixed.absolute_maximum_deviation(bound).vertex_is_constrained_map(held));
    const std::vector<double> out = coordinates(m);
    check_bound(in, out, r, bound, "sphere, constrained vertices");
    bool kept = true;
    k = 0;
    for(auto v : m.vertices())
      if(held[v]) kept = kept && out[3 * k] == in[3 * k] && out[3 * k + 1] == in[3 * k + 1] && out[3 * k + 2] == in[3 * k + 2], ++k;
      else ++k;
    AF_CHECK(kept, "sphere, constrained vertices: held exactly");
  }
  // the automatic defaults with only a bound
  {
    Mesh m = input;
    const AF::Fairing_report r = AF::anisotropic_fairing(m, AF::parameters::absolute_maximum_deviation(bound));
    const std::vector<double> out = coordinates(m);
    check_bound(in, out, r, bound, "sphere, automatic defaults");
    AF_CHECK(sphere_error(out) < sphere_error(in), "sphere, automatic defaults: noise removed");
  }
}

// the denoising pair: both tensors, several bounds
void fandisk_bounds(const std::string& data)
{
  Mesh input;
  if(!AF_CHECK(CGAL::IO::read_polygon_mesh(data + "/fandisk0.3_noisy.obj", input), "read fandisk0.3_noisy.obj")) return;
  const std::vector<double> in = coordinates(input);
  for(double relative : { 0.001, 0.003 })
  {
    Mesh m = input;
    const AF::Fairing_report r = AF::anisotropic_fairing(m, AF::parameters::relative_time_step(1e-4).number_of_iterations(8u)
        .diffusion_tensor(AF::Anisotropic_diffusion_tensor::automatic()).stopping_criteria(AF::Stopping_criteria::none())
        .relative_maximum_deviation(relative));
    check_bound(in, coordinates(m), r, relative * r.scale, "fandisk, anisotropic, bound " + std::to_string(relative));
    Mesh d = input;
    const AF::Fairing_report rd = AF::anisotropic_fairing(d, AF::parameters::relative_maximum_deviation(relative));
    check_bound(in, coordinates(d), rd, relative * rd.scale, "fandisk, default run, bound " + std::to_string(relative));
  }
}

// a noisy hemisphere: its border held, the rest bounded
void border_bound(const std::string& data)
{
  Mesh input;
  if(!AF_CHECK(CGAL::IO::read_polygon_mesh(data + "/hemisphere.off", input), "read hemisphere.off")) return;
  AF_test::perturb_vertices(input, 0.01, 3);
  const std::vector<double> in = coordinates(input);
  Mesh m = input;
  const AF::Fairing_report r = AF::anisotropic_fairing(m, AF::parameters::relative_time_step(1e-3).number_of_iterations(10u)
      .stopping_criteria(AF::Stopping_criteria::none()).absolute_maximum_deviation(0.003));
  check_bound(in, coordinates(m), r, 0.003, "hemisphere with its border");
}

// attributes: a noisy scalar on the sphere, bounded in its own units
void attribute_bounds()
{
  const Mesh input = noisy_sphere(2, 0.01);
  const std::vector<double> in = coordinates(input);
  for(AF::Attribute_mode mode : { AF::Attribute_mode::SEPARATE, AF::Attribute_mode::COUPLED, AF::Attribute_mode::ATTRIBUTES_ONLY })
  {
    Mesh m = input;
    auto f = m.add_property_map<Mesh::Vertex_index, double>("v:f", 0.0).first;
    std::mt19937 rng(5);
    std::normal_distribution<double> noise(0, 0.2);
    for(auto v : m.vertices()) f[v] = m.point(v).z() + noise(rng);
    std::vector<double> f0;
    for(auto v : m.vertices()) f0.push_back(f[v]);
    const double bound = 0.05;
    const AF::Fairing_report r = AF::anisotropic_fairing(m, m.points(), f, AF::parameters::relative_time_step(2e-3).number_of_iterations(8u)
        .stopping_criteria(AF::Stopping_criteria::none()).attribute_mode(mode).attribute_weight(2.0)
        .attribute_maximum_deviation(bound).absolute_maximum_deviation(0.004));
    const std::string what = "attributes, mode " + std::to_string(int(mode));
    AF_CHECK(r.succeeded(), what + ": succeeds");
    double largest = 0, moved = 0;
    std::size_t k = 0;
    for(auto v : m.vertices()) { largest = std::max(largest, std::abs(f[v] - f0[k])); moved += std::abs(f[v] - f0[k]); ++k; }
    AF_CHECK(largest <= bound * (1 + 1e-12), what + ": every value within its bound (" + std::to_string(largest) + ")");
    AF_CHECK(moved / double(k) > 0.1 * bound, what + ": the values were faired");
    AF_CHECK(std::abs(r.largest_attribute_deviation - largest) <= 1e-12, what + ": the report's largest attribute deviation");
    AF_CHECK(r.attribute_maximum_deviation == bound, what + ": the report's attribute bound");
    if(mode != AF::Attribute_mode::ATTRIBUTES_ONLY) AF_CHECK(largest_deviation(in, coordinates(m)) <= 0.004 * (1 + 1e-12), what + ": the geometry within its bound");
    else AF_CHECK(byte_identical(in, coordinates(m)), what + ": the geometry untouched");
  }
}

// mean |x| over the vertices
double mean_radius(const std::vector<double>& x)
{
  double s = 0;
  for(std::size_t i = 0; i + 2 < x.size(); i += 3) s += std::sqrt(x[i] * x[i] + x[i + 1] * x[i + 1] + x[i + 2] * x[i + 2]);
  return s / double(x.size() / 3);
}

// Runs to a steady state (no fidelity weight of the user's): the bound sets the weight that stops the
// shrinking within it
void steady_state_bounds(const std::string& data)
{
  AF::Stopping_criteria steady = AF::Stopping_criteria::none();
  steady.steady_speed = 1e-3;
  const auto flow = AF::parameters::relative_time_step(2e-3).number_of_iterations(2000u).stopping_criteria(steady);
  // the unit sphere: the weight omega holds a sphere of limit radius r0 at r with omega (r0 - r) = 2 / r
  {
    Mesh input;
    AF_test::make_icosphere(input, 3);
    const std::vector<double> in = coordinates(input);
    Mesh limit = input;
    AF::Loop_limit_surface<Mesh>(input).limit_positions(limit.points());
    const double r0 = mean_radius(coordinates(limit));
    const double bound = 0.05;
    Mesh free_run = input;
    const AF::Fairing_report r_free = AF::anisotropic_fairing(free_run, flow.number_of_iterations(200u));
    AF_CHECK(!r_free.succeeded() || largest_deviation(in, coordinates(free_run)) > 2 * bound, "sphere to a steady state: unbounded, it shrinks past the bound");
    Mesh m = input;
    const AF::Fairing_report r = AF::anisotropic_fairing(m, flow.absolute_maximum_deviation(bound));
    const std::vector<double> out = coordinates(m);
    check_bound(in, out, r, bound, "sphere to a steady state");
    AF_CHECK(r.stop_reason == AF::Stop_reason::STEADY_STATE, std::string("sphere to a steady state: reached (") + AF::to_string(r.stop_reason) + ")");
    AF_CHECK(r.bound_uniform_weight > 0, "sphere to a steady state: a uniform weight was chosen");
    const double radius = mean_radius(out);
    AF_CHECK_REL(r.bound_uniform_weight * (r0 - radius), 2 / radius, 0.03,
                 "sphere to a steady state: the weight balances the mean curvature at the radius reached");
    AF_CHECK(largest_deviation(in, out) > 0.5 * bound, "sphere to a steady state: it fairs up to the bound's neighbourhood");
  }
  // bumpy.off: bumps on a sphere; held one by one, the vertices that reach the bound first would become tents
  {
    Mesh input;
    if(!AF_CHECK(CGAL::IO::read_polygon_mesh(data + "/bumpy.off", input), "read bumpy.off")) return;
    const std::vector<double> in = coordinates(input);
    for(double relative : { 0.05, 0.2 })
    {
      Mesh m = input;
      const AF::Fairing_report r = AF::anisotropic_fairing(m, flow.relative_maximum_deviation(relative));
      const std::string what = "bumpy.off to a steady state, bound " + std::to_string(relative);
      check_bound(in, coordinates(m), r, relative * r.scale, what);
      AF_CHECK(r.stop_reason == AF::Stop_reason::STEADY_STATE, what + ": reached (" + AF::to_string(r.stop_reason) + ": " + r.message + ")");
      AF_CHECK(!r.steps.empty() && r.steps.back().H_integral < r.initial.H_integral, what + ": smoother than the input, no tent");
      AF_CHECK(CGAL::Polygon_mesh_processing::area(m) < CGAL::Polygon_mesh_processing::area(input), what + ": faired (the area shrank)");
    }
  }
}

// The control points given back have the written points as their Loop limit points: with a bound and in
// the default run, whose result is one of three candidates
void control_points_given_back(const std::string& data)
{
  Mesh input;
  if(!AF_CHECK(CGAL::IO::read_polygon_mesh(data + "/fandisk0.3_noisy.obj", input), "read fandisk0.3_noisy.obj")) return;
  auto check = [&](const Mesh& m, const std::vector<K::Point_3>& control, const AF::Fairing_report& r, const std::string& what) {
    AF_CHECK(r.succeeded(), what + ": succeeds");
    Mesh c = m;
    for(auto v : c.vertices()) c.point(v) = control[std::size_t(v)];
    Mesh limit = m;
    AF::Loop_limit_surface<Mesh>(c).limit_positions(limit.points());
    double largest = 0;
    std::size_t differ = 0;
    for(auto v : m.vertices())
    {
      const double e = std::sqrt(CGAL::squared_distance(limit.point(v), m.point(v)));
      largest = std::max(largest, e);
      differ += e > 1e-12 ? 1 : 0;
    }
    AF_CHECK(differ <= r.clamped_vertices, what + ": the written points are the control points' limit points (" + std::to_string(differ) +
             " differ, " + std::to_string(r.clamped_vertices) + " put on the bound; largest " + std::to_string(largest) + ")");
  };
  {
    Mesh m = input;
    std::vector<K::Point_3> control(num_vertices(m));
    const AF::Fairing_report r = AF::anisotropic_fairing(m, AF::parameters::relative_maximum_deviation(0.003)
                                                               .control_point_map(CGAL::make_property_map(control)));
    check(m, control, r, "control points, default run with a bound");
  }
  {
    Mesh m = input;
    std::vector<K::Point_3> control(num_vertices(m));
    const AF::Fairing_report r = AF::anisotropic_fairing(m, AF::parameters::control_point_map(CGAL::make_property_map(control)));
    check(m, control, r, "control points, default run (" + r.selected_tensor + " kept)");
  }
}

int main(int argc, char** argv)
{
  const std::string data = argc > 1 ? argv[1] : "data";
  clamped_far_from_origin();
  sphere_bounds();
  fandisk_bounds(data);
  border_bound(data);
  attribute_bounds();
  steady_state_bounds(data);
  control_points_given_back(data);
  return AF_test::report();
}
