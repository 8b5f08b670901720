// anisotropic_fairing() as a user calls it: the fidelity steady state and collapse of the sphere
// (doc/Anisotropic_fairing/design/loop-fem-flow.md section 11c), constrained vertices, Surface_mesh = Polyhedron_3, failures that leave
// the mesh byte-identical, relative units (a model scaled by 10 is faired identically), the stopping
// criteria (27)-(29) against the report's own numbers, the callback, and the P1 variant's shrink
// rate on the sphere against its discretisation error.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Real_timer.h>

#include "test_support/check.h"
#include "test_support/mesh_coordinates.h"
#include "test_support/interpolating_sphere.h"
#include "test_support/mesh_generators.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
namespace AF = CGAL::Anisotropic_fairing;
const double pi = 3.14159265358979323846;

using AF_test::byte_identical;
using AF_test::coordinates;
using AF_test::max_abs_difference;

void fidelity_steady_state()
{
  // r* = (r0 + sqrt(r0^2 - 8/w))/2 for w >= 8/r0^2 (loop-fem-flow.md 11c), reached by time stepping
  for(double w : { 10.0, 20.0 })
  {
    Mesh sphere;
    AF_test::make_interpolating_icosphere(sphere, 2);
    AF::Stopping_criteria only_steady = AF::Stopping_criteria::none();
    only_steady.steady_speed = 1e-7;
    const AF::Fairing_report r = AF::anisotropic_fairing(sphere,
        AF::parameters::time_step(0.01).fidelity_weight(w).number_of_iterations(2000u).stopping_criteria(only_steady)
                       .output_positions(AF::Output_positions::CONTROL_POINTS));
    AF_CHECK(r.succeeded(), "fidelity run succeeds: " + r.message);
    AF_CHECK(r.stop_reason == AF::Stop_reason::STEADY_STATE, "the run ends in the steady state");
    if(r.steps.empty()) continue;
    const double r0 = std::sqrt(r.initial.area / (4 * pi)), rs = std::sqrt(r.steps.back().area / (4 * pi));
    const double exact = (1 + std::sqrt(1 - 8 / w)) / 2;
    std::printf("fidelity w = %g: r*/r0 = %.6f after %zu steps (exact %.6f)\n", w, rs / r0, r.steps.size(), exact);
    AF_CHECK_CLOSE(rs / r0, exact, 2e-3, "sphere with fidelity w settles at (r0 + sqrt(r0^2 - 8/w))/2");
  }
  // w = 5 < 8/r0^2: the sphere collapses; the run must say so and leave the mesh as it was
  Mesh sphere;
  AF_test::make_interpolating_icosphere(sphere, 2);
  const std::vector<double> before = coordinates(sphere);
  const std::size_t properties = sphere.properties<Mesh::Vertex_index>().size();
  const AF::Fairing_report r = AF::anisotropic_fairing(sphere,
      AF::parameters::time_step(0.01).fidelity_weight(5.0).number_of_iterations(1000u)
                     .stopping_criteria(AF::Stopping_criteria::none()));
  std::printf("fidelity w = 5: status %s after %zu steps: %s\n", AF::to_string(r.status), r.steps.size(), r.message.c_str());
  AF_CHECK(!r.succeeded() && (r.status == AF::Fairing_status::COLLAPSED || r.status == AF::Fairing_status::DEGENERATE_METRIC),
           "w = 5 collapses with a clear status");
  AF_CHECK(r.stop_reason == AF::Stop_reason::FAILURE && !r.message.empty(), "a failure carries a message");
  AF_CHECK(byte_identical(before, coordinates(sphere)), "collapse leaves the mesh byte-identical");
  AF_CHECK(properties == sphere.properties<Mesh::Vertex_index>().size(), "no property added to the mesh");
}

void constrained_vertices(const Mesh& input)
{
  for(AF::Output_positions out : { AF::Output_positions::LIMIT_SURFACE, AF::Output_positions::CONTROL_POINTS })
  {
    Mesh m = input;
    auto fixed = m.add_property_map<Mesh::Vertex_index, bool>("v:fixed", false).first;
    std::size_t count = 0;
    for(auto v : vertices(m)) if(std::size_t(v) % 7 == 0) { put(fixed, v, true); ++count; }
    const std::vector<double> before = coordinates(m);
    const AF::Fairing_report r = AF::anisotropic_fairing(m,
        AF::parameters::number_of_iterations(5u).vertex_is_constrained_map(fixed).output_positions(out)
                       .stopping_criteria(AF::Stopping_criteria::none()));
    AF_CHECK(r.succeeded() && r.constrained_vertices == count, "constrained run succeeds");
    const std::vector<double> after = coordinates(m);
    bool fixed_kept = true;
    std::size_t moved = 0;
    for(auto v : vertices(m))
    {
      const std::size_t i = 3 * std::size_t(v);
      const bool same = std::memcmp(&before[i], &after[i], 3 * sizeof(double)) == 0;
      if(get(fixed, v)) fixed_kept = fixed_kept && same;
      else if(!same) ++moved;
    }
    std::printf("constrained vertices (%zu of %zu): kept exactly %d, free vertices moved %zu\n", count,
                num_vertices(m), int(fixed_kept), moved);
    AF_CHECK(fixed_kept, "constrained vertices stay put (byte-identical)");
    AF_CHECK(moved == num_vertices(m) - count, "every free vertex moves");
  }
}

void surface_mesh_equals_polyhedron(const std::string& file)
{
  Mesh sm;
  Polyhedron poly;
  CGAL::IO::read_polygon_mesh(file, sm);
  CGAL::IO::read_polygon_mesh(file, poly);
  for(AF::Finite_element e : { AF::Finite_element::LOOP, AF::Finite_element::LINEAR })
  {
    Mesh a = sm;
    Polyhedron b = poly;
    const auto np = AF::parameters::number_of_iterations(4u).finite_element(e).stopping_criteria(AF::Stopping_criteria::none());
    const AF::Fairing_report ra = AF::anisotropic_fairing(a, np);
    const AF::Fairing_report rb = AF::anisotropic_fairing(b, np);
    const double d = max_abs_difference(coordinates(a), coordinates(b));
    std::printf("Surface_mesh vs Polyhedron_3 (%s): max |difference| %.3g\n", e == AF::Finite_element::LOOP ? "Loop" : "P1", d);
    AF_CHECK(ra.succeeded() && rb.succeeded(), "both runs succeed");
    AF_CHECK(d <= 1e-14, "Surface_mesh and Polyhedron_3 give the same result");
  }
}

void failures_leave_mesh_unchanged(const Mesh& input)
{
  {
    Mesh m = input;
    const std::vector<double> before = coordinates(m);
    const AF::Fairing_report r = AF::anisotropic_fairing(m, AF::parameters::relative_time_step(1e-3)
        .linear_solver(AF::Linear_solver::CONJUGATE_GRADIENT).solver_maximum_iterations(2));
    std::printf("CG limited to 2 iterations: %s: %s\n", AF::to_string(r.status), r.message.c_str());
    AF_CHECK(r.status == AF::Fairing_status::SOLVER_FAILED, "a solver failure is reported");
    AF_CHECK(byte_identical(before, coordinates(m)), "a solver failure leaves the mesh byte-identical");
  }
  {
    // long mean-curvature flow shrinks bumpy to a point at t ~ l^2/4 (like a sphere of radius l): the
    // run must end with a failure status, not silently write a speck
    Mesh m = input;
    const std::vector<double> before = coordinates(m);
    const AF::Fairing_report r = AF::anisotropic_fairing(m,
        AF::parameters::relative_time_step(6.3e-3).number_of_iterations(60u).stopping_criteria(AF::Stopping_criteria::none()));
    std::printf("bumpy under long mean-curvature flow: %s after %zu steps (t / l^2 = %.3f): %s\n", AF::to_string(r.status),
                r.steps.size(), r.steps.empty() ? 0.0 : r.steps.back().time / (r.scale * r.scale), r.message.c_str());
    AF_CHECK(r.status == AF::Fairing_status::COLLAPSED || r.status == AF::Fairing_status::DEGENERATE_METRIC,
             "shrinking to a point is reported as a failure");
    AF_CHECK(byte_identical(before, coordinates(m)), "and leaves the mesh byte-identical");
  }
  {
    // a surface with zero metric (every control point at one place) is degenerate from the start
    Mesh m = input;
    for(auto v : vertices(m)) m.point(v) = K::Point_3(1, 2, 3);
    const std::vector<double> before = coordinates(m);
    const AF::Fairing_report r = AF::anisotropic_fairing(m);
    std::printf("all vertices at one point: %s: %s\n", AF::to_string(r.status), r.message.c_str());
    AF_CHECK(r.status == AF::Fairing_status::DEGENERATE_METRIC && r.steps.empty(), "a zero metric is reported as degenerate");
    AF_CHECK(byte_identical(before, coordinates(m)), "and leaves the mesh byte-identical");
  }
  {
    Mesh m = input;
    m.point(*std::next(vertices(m).begin(), 10)) = K::Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
    const std::vector<double> before = coordinates(m);
    bool thrown = false;
    try { AF::anisotropic_fairing(m); }
    catch(const AF::Input_error& e) { thrown = e.kind() == AF::Input_error::NON_FINITE_COORDINATE && e.element() == 10; }
    AF_CHECK(thrown, "a NaN coordinate throws Input_error naming the vertex");
    const std::vector<double> after = coordinates(m);
    AF_CHECK(std::memcmp(before.data(), after.data(), before.size() * sizeof(double)) == 0, "and the mesh is untouched");
  }
  {
    Mesh m = input;
    bool thrown = false;
    try { AF::anisotropic_fairing(m, AF::parameters::time_step(1.0).relative_time_step(1.0)); }
    catch(const AF::Input_error& e) { thrown = e.kind() == AF::Input_error::INVALID_PARAMETER; }
    AF_CHECK(thrown, "time_step and relative_time_step together are refused");
    thrown = false;
    try { AF::anisotropic_fairing(m, AF::parameters::relative_time_step(-1.0)); }
    catch(const AF::Input_error& e) { thrown = e.kind() == AF::Input_error::INVALID_PARAMETER; }
    AF_CHECK(thrown, "a negative time step is refused");
  }
}

void relative_units(const Mesh& clean)
{
  // with a relative time step and the paper's criteria on bumpy, and with automatic parameters on a
  // noisy bumpy (the noise estimate and the units of the automatic run are scale-free too)
  Mesh noisy = clean;
  double h = 0;
  for(auto e : edges(clean)) h += std::sqrt(CGAL::squared_distance(clean.point(source(e, clean)), clean.point(target(e, clean))));
  h /= double(num_edges(clean));
  AF_test::perturb_vertices(noisy, 0.5 * h, 5);
  for(int automatic = 0; automatic < 2; ++automatic)
  {
    const Mesh& input = automatic ? noisy : clean;
    Mesh a = input, b = input;
    const double s = 10.0;
    for(auto v : vertices(b)) { const K::Point_3& p = b.point(v); b.point(v) = K::Point_3(s * p.x(), s * p.y(), s * p.z()); }
    AF::Fairing_report ra, rb;
    if(automatic) { ra = AF::anisotropic_fairing(a); rb = AF::anisotropic_fairing(b); }
    else
    {
      const auto np = AF::parameters::relative_time_step(1e-3).number_of_iterations(100u);   // default criteria
      ra = AF::anisotropic_fairing(a, np);
      rb = AF::anisotropic_fairing(b, np);
    }
    std::vector<double> ca = coordinates(a), cb = coordinates(b);
    double err = 0, size = 0;
    for(std::size_t i = 0; i < ca.size(); ++i) { err = std::max(err, std::abs(s * ca[i] - cb[i])); size = std::max(size, std::abs(cb[i])); }
    std::printf("%s and x 10, %s: %zu and %zu steps (%s, %s), max relative difference %.3g\n", automatic ? "noisy bumpy" : "bumpy",
                automatic ? "automatic parameters" : "relative time step", ra.steps.size(), rb.steps.size(),
                AF::to_string(ra.stop_reason), AF::to_string(rb.stop_reason), err / size);
    AF_CHECK(ra.succeeded() && rb.succeeded(), "both scales fair");
    AF_CHECK(ra.steps.size() == rb.steps.size() && ra.stop_reason == rb.stop_reason, "the same steps at both scales");
    AF_CHECK(ra.stop_reason != AF::Stop_reason::MAXIMUM_STEPS && !ra.steps.empty(), "the default criteria end a run on bumpy");
    AF_CHECK(err <= 1e-9 * size, "a scaled model is faired into the scaled result (relative units)");
    AF_CHECK(ra.flow_order == rb.flow_order, "the same flow at both scales");
    AF_CHECK_REL(rb.time_step, std::pow(s, ra.flow_order) * ra.time_step, 1e-12,
                 "the absolute time step scales with the size to the flow's order (2, or 4 for the fourth-order flow)");
  }
}

// Recomputes the criteria from the report's numbers: the stop happens at the first step where one holds.
void stopping_criteria(const Mesh& input)
{
  struct Case { const char* name; AF::Stopping_criteria c; AF::Stop_reason expected; };
  // the first step's rate of the curvature functional, to set a (28) threshold that the run must reach
  Mesh probe = input;
  const AF::Fairing_report first_step = AF::anisotropic_fairing(probe, AF::parameters::number_of_iterations(1u)
      .stopping_criteria(AF::Stopping_criteria::none()));
  const double rate1 = (first_step.steps[0].H_integral / first_step.initial.H_integral - 1) /
                       (first_step.time_step / (first_step.scale * first_step.scale));
  const double threshold28 = std::abs(rate1) / 3;
  std::printf("bumpy: first-step rate of int |H|^2 / int |H0|^2 per unit of t / l^2: %.4g\n", rate1);
  AF::Stopping_criteria only27 = AF::Stopping_criteria::none(); only27.curvature_rate_ratio = 0.3;
  AF::Stopping_criteria only28 = AF::Stopping_criteria::none(); only28.curvature_rate = threshold28;
  AF::Stopping_criteria only29 = AF::Stopping_criteria::none(); only29.displacement = 0.05;
  const Case cases[] = { { "(27)", only27, AF::Stop_reason::CURVATURE_RATE_RATIO },
                         { "(28)", only28, AF::Stop_reason::CURVATURE_RATE },
                         { "(29)", only29, AF::Stop_reason::DISPLACEMENT } };
  for(const Case& k : cases)
  {
    Mesh m = input;
    const AF::Fairing_report r = AF::anisotropic_fairing(m, AF::parameters::number_of_iterations(200u).stopping_criteria(k.c));
    AF_CHECK(r.succeeded() && r.stop_reason == k.expected, std::string("criterion ") + k.name + " ends the run");
    // first step at which the criterion holds, from the report
    const double L = r.scale, tau_rel = r.time_step / (L * L);
    double prev = 1, rate0 = 0;
    std::size_t first = 0;
    for(const AF::Fairing_step& s : r.steps)
    {
      const double H = s.H_integral / r.initial.H_integral, rate = (H - prev) / tau_rel;
      if(s.step == 1) rate0 = rate;
      prev = H;
      const bool holds = k.expected == AF::Stop_reason::CURVATURE_RATE_RATIO ? (s.step >= 2 && std::abs(rate / rate0) <= 0.3)
                       : k.expected == AF::Stop_reason::CURVATURE_RATE ? std::abs(rate) <= threshold28
                       : s.max_displacement >= 0.05 * L;
      if(holds && first == 0) first = s.step;
    }
    std::printf("criterion %s alone: stopped after step %zu, first step where it holds (from the report) %zu\n", k.name,
                r.steps.size(), first);
    AF_CHECK(first == r.steps.size() && first > 1, std::string("criterion ") + k.name + " stops exactly where it first holds");
  }
  // the callback ends a run
  Mesh m = input;
  std::size_t seen = 0;
  const AF::Fairing_report r = AF::anisotropic_fairing(m, AF::parameters::number_of_iterations(50u)
      .stopping_criteria(AF::Stopping_criteria::none())
      .callback([&seen](const AF::Fairing_step& s) { seen = s.step; return s.step < 3; }));
  AF_CHECK(r.succeeded() && r.stop_reason == AF::Stop_reason::CALLBACK && r.steps.size() == 3 && seen == 3,
           "the callback sees every step and stops the run after step 3");
}

// P1 elements on the polyhedral icosphere: the shrink rate d(A/4pi)/dt of mean-curvature flow is -4
// up to the element's own error, which is of the order of the polyhedron's area deficit and falls as h^2.
void linear_element_sphere()
{
  double previous = 0;
  for(int level = 2; level <= 4; ++level)
  {
    Mesh sphere;
    AF_test::make_icosphere(sphere, level);
    const double tau = 1e-4;
    const AF::Fairing_report r = AF::anisotropic_fairing(sphere,
        AF::parameters::finite_element(AF::Finite_element::LINEAR).time_step(tau).number_of_iterations(10u)
                       .stopping_criteria(AF::Stopping_criteria::none()));
    AF_CHECK(r.succeeded() && r.steps.size() == 10, "P1 sphere flow runs");
    if(r.steps.size() != 10) continue;
    const double rate = (r.steps.back().area - r.initial.area) / (4 * pi * r.steps.back().time);
    const double r2 = r.initial.area / (4 * pi);
    const double err = std::abs(rate / -4.0 - 1), deficit = 1 - r2;
    std::printf("P1 icosphere(%d): d(A/4pi)/dt = %.6f (exact -4), relative error %.3g, area deficit 1 - A/4pi = %.3g\n", level,
                rate, err, deficit);
    AF_CHECK(err <= 2 * deficit, "P1 shrink rate within its discretisation error (2 x area deficit)");
    if(previous > 0) AF_CHECK(err < previous / 3, "P1 shrink-rate error falls like h^2 under refinement");
    previous = err;
  }
}

// Linear_solver::AUTOMATIC: a CG failure is retried by the factorisation (a slow CG step making the next
// one a factorised trial: automatic_solver_gives_way). Results agree with the explicit solvers.
void automatic_solver(const std::string& data)
{
  Mesh hemisphere;
  CGAL::IO::read_polygon_mesh(data + "/hemisphere.off", hemisphere);
  Mesh a = hemisphere, b = hemisphere, c = hemisphere;
  const auto np = AF::parameters::relative_time_step(2e-2).number_of_iterations(4u)
                     .stopping_criteria(AF::Stopping_criteria::none()).output_positions(AF::Output_positions::CONTROL_POINTS);
  const AF::Fairing_report rc = AF::anisotropic_fairing(c, np.linear_solver(AF::Linear_solver::CHOLESKY));
  const AF::Fairing_report ra = AF::anisotropic_fairing(a, np.solver_maximum_iterations(5));   // AUTOMATIC
  std::printf("AUTOMATIC with CG capped at 5 iterations: %s, direct steps %d%d%d\n", AF::to_string(ra.status),
              int(ra.steps.size() > 0 && ra.steps[0].direct_solve), int(ra.steps.size() > 1 && ra.steps[1].direct_solve),
              int(ra.steps.size() > 2 && ra.steps[2].direct_solve));
  AF_CHECK(ra.succeeded() && ra.steps.size() == 4 && ra.steps[0].direct_solve && ra.used_cholesky,
           "AUTOMATIC retries a step whose CG fails with the factorisation");
  const double d = max_abs_difference(coordinates(a), coordinates(c));
  AF_CHECK(d == 0.0, "the retried steps equal the factorised run");
  const AF::Fairing_report rb = AF::anisotropic_fairing(b, np);
  const double e = max_abs_difference(coordinates(b), coordinates(c));
  std::printf("AUTOMATIC vs CHOLESKY: max |difference| %.3g (hemisphere of radius 1)\n", e);
  AF_CHECK(rb.succeeded() && rb.steps.size() == 4, "AUTOMATIC runs the 4 steps");
  AF_CHECK(e < 1e-7, "AUTOMATIC agrees with the factorised run to the CG tolerance");
}

// Conjugate gradients that stall give way to the factorisation early: on the path graph's Laplacian plus
// a shift of 1e-4 (condition number about 4e4, so the factorisation's relative residual is near 1e-16 x
// 4e4; Jacobi-preconditioned CG needs thousands of iterations),
// AUTOMATIC stops iterating as soon as their rate says that ten times the trial threshold would not do,
// factorises, and its answer solves the system. The next matrix is iterated again; only after giving way
// twice in a row does it factorise, and a shorter step than the one that gave way is iterated again. A
// system that CG solves within the limit (a larger shift) is not given up on.
void automatic_solver_gives_way()
{
  namespace I = CGAL::Anisotropic_fairing::internal;
  const int n = 4000;
  std::vector<Eigen::Triplet<double>> entries;
  for(int i = 0; i < n; ++i)
  {
    entries.emplace_back(i, i, 2.0 + 1e-4);
    if(i > 0) { entries.emplace_back(i, i - 1, -1.0); entries.emplace_back(i - 1, i, -1.0); }
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  I::Control_matrix B(n, 1), X = I::Control_matrix::Zero(n, 1);
  for(int i = 0; i < n; ++i) B(i, 0) = std::sin(0.37 * i) + 1e-3 * i;
  I::Block_conjugate_gradient cg(1e-12, 100000), unlimited(1e-12, 100000);
  I::Control_matrix Xcg = X;
  const I::Solve_statistics full = unlimited.solve(A, B, Xcg);
  std::printf("CG alone on the shifted path Laplacian (n = %d): %d iterations\n", n, full.iterations);
  AF_CHECK(full.ok && full.iterations > 10 * AF::automatic_cholesky_trial_iterations,
           "the test matrix needs more CG iterations than AUTOMATIC allows before giving way");
  const auto product = [&A](const I::Control_matrix& P, I::Control_matrix& AP) { I::symmetric_product(A, P, AP); };
  const Eigen::VectorXd diagonal = A.diagonal();
  I::Control_matrix Xrate = X;
  const I::Solve_statistics rated = cg.solve(product, diagonal, B, Xrate, 10 * AF::automatic_cholesky_trial_iterations);
  std::printf("CG with a limit of %d iterations: gave way after %d (%s)\n", 10 * AF::automatic_cholesky_trial_iterations,
              rated.iterations, rated.message.c_str());
  AF_CHECK(!rated.ok && rated.iterations < 10 * AF::automatic_cholesky_trial_iterations / 2,
           "stalled iterations give way on their rate, well before the limit");
  // a system within reach: the shift that makes CG need about half the limit
  double shift = 1e-4;
  I::Solve_statistics reach;
  Eigen::SparseMatrix<double> S = A;
  for(; shift < 1; shift *= 1.5)
  {
    for(int i = 0; i < n; ++i) S.coeffRef(i, i) = 2.0 + shift;
    I::Control_matrix Xs = I::Control_matrix::Zero(n, 1);
    reach = unlimited.solve(S, B, Xs);
    if(reach.iterations <= 10 * AF::automatic_cholesky_trial_iterations / 2) break;
  }
  I::Control_matrix Xs = I::Control_matrix::Zero(n, 1);
  const Eigen::VectorXd sdiag = S.diagonal();
  const I::Solve_statistics within = cg.solve([&S](const I::Control_matrix& P, I::Control_matrix& AP) { I::symmetric_product(S, P, AP); },
                                              sdiag, B, Xs, 10 * AF::automatic_cholesky_trial_iterations);
  std::printf("shift %.3g: CG alone %d iterations, with the limit %d (ok %d)\n", shift, reach.iterations, within.iterations, int(within.ok));
  AF_CHECK(reach.iterations > 2 * AF::automatic_cholesky_trial_iterations && within.ok && within.iterations == reach.iterations,
           "a system CG solves within the limit is solved, not given up on");

  // A as the package stores a system: a structure and its values
  A.makeCompressed();
  const I::Sparse_structure structure(n, std::vector<int>(A.outerIndexPtr(), A.outerIndexPtr() + n + 1),
                                      std::vector<int>(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros()));
  const I::Value_array values(A.valuePtr(), A.valuePtr() + A.nonZeros());
  I::Solver_choice choice(AF::Linear_solver::AUTOMATIC, std::size_t(n));
  AF_CHECK(choice.fall_back_iterations() == 10 * AF::automatic_cholesky_trial_iterations,
           "before any timing, CG gives way after ten times the trial threshold");
  bool direct = false;
  CGAL::Real_timer clock;
  clock.start();
  const I::Solve_statistics first = choice.solve(structure, values, B, X, cg, direct);
  choice.record(direct, first, clock.time());
  const double residual = (B - A * X).norm() / B.norm();
  std::printf("AUTOMATIC: direct %d, relative residual %.3g\n", int(direct), residual);
  AF_CHECK(first.ok && direct && residual < 1e-10, "the stalled iterations gave way to the factorisation, which solved the system");
  AF_CHECK(!choice.factorise_now(), "after giving way once, the next matrix is iterated again");
  X.setZero();
  clock.reset();
  const I::Solve_statistics second = choice.solve(structure, values, B, X, cg, direct);
  choice.record(direct, second, clock.time());
  AF_CHECK(second.ok && direct && choice.factorise_now(), "after giving way twice in a row, the run factorises");
  choice.set_step_factor(1.0);
  AF_CHECK(choice.factorise_now(), "a step as long as the one that gave way is factorised");
  choice.set_step_factor(0.25);
  AF_CHECK(!choice.factorise_now(), "a step retried shorter than the one that gave way is iterated again");

  // the policy, on counted operations: a CG solve above the trial threshold makes the next one a factorised
  // trial, kept while it costs less than the CG step predicted (the path's factor is as sparse as the matrix:
  // it does); a fast CG solve keeps conjugate gradients. The same counts on every machine.
  const auto structure_of = [n](const Eigen::SparseMatrix<double>& M) {
    return I::Sparse_structure(n, std::vector<int>(M.outerIndexPtr(), M.outerIndexPtr() + n + 1),
                               std::vector<int>(M.innerIndexPtr(), M.innerIndexPtr() + M.nonZeros()));
  };
  S.makeCompressed();
  const I::Sparse_structure slow_structure = structure_of(S);
  const I::Value_array slow_values(S.valuePtr(), S.valuePtr() + S.nonZeros());
  I::Solver_choice policy(AF::Linear_solver::AUTOMATIC, std::size_t(n));
  I::Control_matrix Y = I::Control_matrix::Zero(n, 1);
  const I::Solve_statistics iterated = policy.solve(slow_structure, slow_values, B, Y, cg, direct);
  policy.record(direct, iterated, 1.0);
  AF_CHECK(iterated.ok && !direct && iterated.iterations > AF::automatic_cholesky_trial_iterations && policy.factorise_now(),
           "after a CG step above the trial threshold, the next step is a factorised trial");
  Y.setZero();
  const I::Solve_statistics trial = policy.solve(slow_structure, slow_values, B, Y, cg, direct);
  policy.record(direct, trial, 1e6);   // the time is not read: the operations are counted
  AF_CHECK(trial.ok && direct && policy.factorise_now(), "a trial that costs less than the predicted CG step is kept");
  Eigen::SparseMatrix<double> W = A;
  for(int i = 0; i < n; ++i) W.coeffRef(i, i) = 4.0;
  W.makeCompressed();
  const I::Sparse_structure fast_structure = structure_of(W);
  const I::Value_array fast_values(W.valuePtr(), W.valuePtr() + W.nonZeros());
  I::Solver_choice other(AF::Linear_solver::AUTOMATIC, std::size_t(n));
  Y.setZero();
  const I::Solve_statistics fast = other.solve(fast_structure, fast_values, B, Y, cg, direct);
  other.record(direct, fast, 1e6);
  AF_CHECK(fast.ok && !direct && !other.factorise_now(), "a fast CG step keeps conjugate gradients");
}

// The sparse_linear_solver named parameter (CGAL's SparseLinearAlgebraWithFactorTraits_d) replaces the
// package's LDL^T wherever it factorises: the steps, the prefilter, the constant system of a fixed surface.
// A traits that counts its factorisations shows that it is the one used; its results equal the package's.
typedef CGAL::Eigen_sparse_matrix<double>::EigenType Eigen_matrix;
template <typename EigenSolver>
struct Counting_traits : CGAL::Eigen_solver_traits<EigenSolver>
{
  typedef CGAL::Eigen_solver_traits<EigenSolver> Base;
  std::shared_ptr<int> factorisations = std::make_shared<int>(0);
  bool factor(const typename Base::Matrix& A, typename Base::NT& D) { ++*factorisations; return Base::factor(A, D); }
};

void user_sparse_linear_solver(const std::string& data)
{
  Mesh hemisphere;
  CGAL::IO::read_polygon_mesh(data + "/hemisphere.off", hemisphere);
  const auto np = AF::parameters::relative_time_step(2e-2).number_of_iterations(3u).linear_solver(AF::Linear_solver::CHOLESKY)
                     .stopping_criteria(AF::Stopping_criteria::none()).output_positions(AF::Output_positions::CONTROL_POINTS);
  Mesh ours = hemisphere, ldlt = hemisphere, lu = hemisphere;
  AF::anisotropic_fairing(ours, np);
  Counting_traits<Eigen::SimplicialLDLT<Eigen_matrix>> ldlt_traits;
  const AF::Fairing_report r1 = AF::anisotropic_fairing(ldlt, np.sparse_linear_solver(ldlt_traits));
  Counting_traits<Eigen::SparseLU<Eigen_matrix, Eigen::COLAMDOrdering<int>>> lu_traits;
  const AF::Fairing_report r2 = AF::anisotropic_fairing(lu, np.sparse_linear_solver(lu_traits));
  const double d1 = max_abs_difference(coordinates(ldlt), coordinates(ours)), d2 = max_abs_difference(coordinates(lu), coordinates(ours));
  std::printf("sparse_linear_solver: Eigen_solver_traits<SimplicialLDLT> %d factorisations, |difference| %.3g; SparseLU %d, %.3g\n",
              *ldlt_traits.factorisations, d1, *lu_traits.factorisations, d2);
  AF_CHECK(r1.succeeded() && r2.succeeded() && r1.used_cholesky, "runs with the user's factorisation succeed");
  AF_CHECK(*ldlt_traits.factorisations == 3 && *lu_traits.factorisations == 3, "the user's solver factorises each of the 3 steps");
  AF_CHECK(d1 < 1e-12 && d2 < 1e-12, "the user's factorisations give the package's result");

  // the prefilter of the anisotropic tensor factorises with it too: two factorisations per step
  Counting_traits<Eigen::SimplicialLDLT<Eigen_matrix>> prefilter_traits;
  Mesh aniso = hemisphere;
  AF::anisotropic_fairing(aniso, np.diffusion_tensor(AF::Anisotropic_diffusion_tensor()).sparse_linear_solver(prefilter_traits));
  AF_CHECK(*prefilter_traits.factorisations >= 6, "the prefilter uses the user's factorisation");

  // a fixed surface: one constant system, factorised once for all steps
  Counting_traits<Eigen::SimplicialLDLT<Eigen_matrix>> fixed_traits;
  Mesh fixed = hemisphere;
  auto height = fixed.add_property_map<Mesh::Vertex_index, double>("v:height", 0.0).first;
  for(auto v : vertices(fixed)) height[v] = fixed.point(v).z() + 0.01 * std::sin(17 * fixed.point(v).x());
  const AF::Fairing_report r3 = AF::anisotropic_fairing(fixed, fixed.points(), height,
      np.attribute_mode(AF::Attribute_mode::ATTRIBUTES_ONLY).sparse_linear_solver(fixed_traits));
  AF_CHECK(r3.succeeded() && r3.steps.size() == 3 && *fixed_traits.factorisations == 1,
           "on a fixed surface the user's solver factorises once");
}

int main(int argc, char** argv)
{
  const std::string data = argc > 1 ? argv[1] : "data";
  Mesh bumpy;
  AF_CHECK(CGAL::IO::read_polygon_mesh(data + "/bumpy.off", bumpy), "read bumpy.off");
  fidelity_steady_state();
  constrained_vertices(bumpy);
  surface_mesh_equals_polyhedron(data + "/bumpy.off");
  failures_leave_mesh_unchanged(bumpy);
  relative_units(bumpy);
  stopping_criteria(bumpy);
  linear_element_sphere();
  automatic_solver(data);
  automatic_solver_gives_way();
  user_sparse_linear_solver(data);
  return AF_test::report();
}
