// Speed of one isotropic fairing step, and the linear solvers' work.
//
//   (u) units: one step of P1 fairing and of CGAL's smooth_shape on a sphere with two vertices held
//       fixed (which turns off smooth_shape's volume rescaling): does smooth_shape's "time" t move
//       the sphere like our physical time tau = 4t?
//   (a) one step of isotropic Loop (CONJUGATE_GRADIENT; P1 alongside) vs one smooth_shape step, in the
//       same run, medians of RUNS: fertility Loop-subdivided twice (144,000 triangles) and the closed
//       bunny subdivided once (278,688 triangles). Same physical time: tau = 1e-3 l^2 for ours
//       (l^2 = Area/(4 pi) of the limit surface) and time = tau/4 for smooth_shape.
//   (b) CG iterations per step, Loop vs P1, at tau/h^2 = 0.1, 1, 3 (h = mean edge length; absolute
//       time_step), 4 steps, on bumpy.off, bunny.off and the 144k fertility.
//   (c) CHOLESKY vs CONJUGATE_GRADIENT per-step solve time of the Loop system at 1k-35k vertices
//       (small meshes Loop-subdivided), at tau_rel 1e-4, 1e-3 and 1e-2 (where CG's iterations grow),
//       and what Linear_solver::AUTOMATIC makes of it (whole call, and which steps it factorised).
//   (d) where a one-step Loop call's time goes on the 144k mesh, timed with the internal classes as
//       the driver uses them (numbering, locality ordering, element set-up, stepper set-up, one
//       assembly with TBB and with one thread, the statistics-only assembly of the last step, limit
//       evaluation). Internal API: update with the driver.
//   (e) what the diffusion tensor costs per step: isotropic, anisotropic (lambda_rel 2) on the current
//       surface, and anisotropic with the prefilter M_eps (the default eps_rel 1e-3: one more isotropic
//       assembly and CG solve per step, counted in the step's assemble_seconds); both anisotropic ones
//       with normal motion (the default). 3 steps of tau_rel 1e-3 with CONJUGATE_GRADIENT, on the
//       Fandisk0.3 noisy mesh and the 144k fertility; medians of RUNS.
//
// (a), (c) and (e) use the library's default solver tolerance; (b) sets 1e-8 explicitly.
//
// usage: bench_step_speed [DATA_DIR=<repo>/../shared/data] [PARTS=uabcde] [RUNS=5]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include "bench_median.h"
#include "bench_mesh_measures.h"
#include <CGAL/Anisotropic_fairing/internal/assembly/Fem_assembly.h>
#include <CGAL/Anisotropic_fairing/internal/element/Ghosted_patch_cache.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Indexed_mesh.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Locality_ordering.h>
#include <CGAL/Anisotropic_fairing/internal/element/Patch_cache.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Time_stepper.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Vertex_limit_masks.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <string>
#include <vector>

#ifndef AF_SOURCE_DIR
#define AF_SOURCE_DIR "."
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace AF = CGAL::Anisotropic_fairing;
namespace PMP = CGAL::Polygon_mesh_processing;

static const double pi = 3.14159265358979323846;

double mean(const std::vector<double>& v)
{
  double s = 0;
  for(double x : v) s += x;
  return v.empty() ? std::nan("") : s / double(v.size());
}


struct Named_mesh
{
  std::string name;
  Mesh mesh;
};

bool load(const std::string& dir, const std::string& file, int subdivisions, Named_mesh& out)
{
  out.mesh.clear();
  if(!CGAL::IO::read_polygon_mesh(dir + "/" + file, out.mesh))
  {
    std::fprintf(stderr, "cannot read %s/%s\n", dir.c_str(), file.c_str());
    return false;
  }
  if(subdivisions > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(out.mesh, CGAL::parameters::number_of_iterations(subdivisions));
  out.name = file + (subdivisions > 0 ? " Loop x" + std::to_string(subdivisions) : std::string());
  return true;
}

// A mesh file of DATA_DIR, Loop-subdivided `sub` times.
struct Input { const char* file; int sub; };

// Loads each input in turn and calls `f` with it; one that cannot be read is reported and skipped.
template <typename F>
void for_each_mesh(const std::string& dir, std::initializer_list<Input> inputs, F f)
{
  for(const Input& in : inputs)
  {
    Named_mesh s;
    if(load(dir, in.file, in.sub, s)) f(s);
  }
}

std::string sizes(const Mesh& m)
{
  char b[64];
  std::snprintf(b, sizeof b, "%zu V / %zu F", std::size_t(num_vertices(m)), std::size_t(num_faces(m)));
  return b;
}

template <typename NP>
AF::Fairing_report run(Mesh& m, const NP& np, double& wall)
{
  CGAL::Real_timer t;
  t.start();
  AF::Fairing_report r = AF::anisotropic_fairing(m, np);
  wall = t.time();
  return r;
}

// `steps` steps of relative_time_step(tau_rel) with `solver` and no stopping criterion, on a copy of `input`.
AF::Fairing_report run_steps(const Mesh& input, double tau_rel, int steps, AF::Linear_solver solver, double& wall)
{
  Mesh m = input;
  return run(m, AF::parameters::relative_time_step(tau_rel).number_of_iterations(steps)
                  .stopping_criteria(AF::Stopping_criteria::none())
                  .linear_solver(solver), wall);
}

const char* element_name(AF::Finite_element e) { return e == AF::Finite_element::LOOP ? "Loop" : "P1"; }

// ---------------------------------------------------------------------------------------------
// (u) time units of smooth_shape
void part_units(const std::string& dir)
{
  Named_mesh s;
  if(!load(dir, "sphere.off", 0, s)) return;
  Mesh& m = s.mesh;
  // centre and radius of the input, and two opposite vertices to hold
  double cx = 0, cy = 0, cz = 0;
  for(auto v : m.vertices()) { cx += m.point(v).x(); cy += m.point(v).y(); cz += m.point(v).z(); }
  const double nv = double(num_vertices(m));
  const Point c(cx / nv, cy / nv, cz / nv);
  auto radius = [&](const Mesh& mm) {
    double r = 0;
    for(auto v : mm.vertices()) r += std::sqrt(CGAL::squared_distance(mm.point(v), c));
    return r / double(num_vertices(mm));
  };
  const double R = radius(m);
  Mesh::Vertex_index a = *m.vertices().begin(), b = a;
  double far = 0;
  for(auto v : m.vertices())
  {
    const double d = CGAL::squared_distance(m.point(v), m.point(a));
    if(d > far) { far = d; b = v; }
  }
  auto fixed = m.add_property_map<Mesh::Vertex_index, bool>("v:fixed", false).first;
  put(fixed, a, true);
  put(fixed, b, true);
  const double h = mean_edge_length(m);
  const double tau = 0.5 * h * h;
  std::printf("\n## (u) Time units: %s (%s), mean radius R = %.6g, h = %.4g, two opposite vertices fixed, one step of tau = 0.5 h^2 = %.4g\n\n",
              s.name.c_str(), sizes(m).c_str(), R, h, tau);
  std::printf("exact mean-curvature flow of a sphere: R(t)^2 = R^2 - 4t, dR = %.4e\n\n", std::sqrt(R * R - 4 * tau) - R);
  std::printf("| method | time argument | dR (mean radius change) | dR / (expected for physical time tau) |\n|---|---|---:|---:|\n");
  const double expected = std::sqrt(R * R - 4 * tau) - R;
  {
    Mesh mm = m;
    AF::anisotropic_fairing(mm, AF::parameters::time_step(tau).number_of_iterations(1)
                                  .stopping_criteria(AF::Stopping_criteria::none())
                                  .finite_element(AF::Finite_element::LINEAR)
                                  .vertex_is_constrained_map(fixed));
    const double d = radius(mm) - R;
    std::printf("| anisotropic_fairing, P1 | time_step(tau) | %.4e | %.3f |\n", d, d / expected);
  }
  for(double f : {1.0, 0.25})
  {
    Mesh mm = m;
    auto fx = mm.property_map<Mesh::Vertex_index, bool>("v:fixed").first;
    PMP::smooth_shape(mm, f * tau, CGAL::parameters::number_of_iterations(1).vertex_is_constrained_map(fx));
    const double d = radius(mm) - R;
    std::printf("| smooth_shape | %s | %.4e | %.3f |\n", f == 1.0 ? "tau" : "tau/4", d, d / expected);
  }
}

// ---------------------------------------------------------------------------------------------
// (a) one step, ours vs smooth_shape
void part_step(const std::string& dir, int runs)
{
  std::printf("\n## (a) One step: isotropic Loop / P1 (CONJUGATE_GRADIENT) vs smooth_shape, median of %d runs, seconds\n", runs);
  std::printf("\nassemble, solve: the step's assemble_seconds (assembly at X_0 and forming the system) and solve_seconds;"
              " set-up: report.setup_seconds; rest = whole call - assemble - solve: numbering and validation, set-up,"
              " the stepper's sparsity patterns, the statistics-only assembly at X_1, the limit evaluation and the write-back.\n\n");
  std::printf("| mesh | method | tau/h^2 | CG its | whole call | set-up | assemble | solve | rest |\n"
              "|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for_each_mesh(dir, {{"fertility.off", 2}, {"bunny-closed.off", 1}}, [&](const Named_mesh& s)
  {
    const double h = mean_edge_length(s.mesh);
    const std::string label = s.name + " (" + sizes(s.mesh) + ")";
    double tau = 0;
    for(AF::Finite_element e : {AF::Finite_element::LOOP, AF::Finite_element::LINEAR})
    {
      std::vector<double> whole, setup, assemble, solve, rest;
      int its = 0;
      std::string failure;
      for(int r = 0; r < runs; ++r)
      {
        Mesh m = s.mesh;
        double wall = 0;
        const AF::Fairing_report rep = run(m, AF::parameters::relative_time_step(1e-3).number_of_iterations(1)
                                                  .stopping_criteria(AF::Stopping_criteria::none())
                                                  .finite_element(e)
                                                  .linear_solver(AF::Linear_solver::CONJUGATE_GRADIENT), wall);
        if(!rep.succeeded() || rep.steps.empty()) { failure = rep.message; break; }
        if(e == AF::Finite_element::LOOP) tau = rep.time_step;   // the same physical time for smooth_shape
        const AF::Fairing_step& st = rep.steps[0];
        whole.push_back(wall);
        setup.push_back(rep.setup_seconds);
        assemble.push_back(st.assemble_seconds);
        solve.push_back(st.solve_seconds);
        rest.push_back(wall - st.assemble_seconds - st.solve_seconds);
        its = st.solver_iterations;
      }
      if(!failure.empty()) { std::printf("| %s | %s | | | failed: %s | | | | |\n", label.c_str(), element_name(e), failure.c_str()); continue; }
      std::printf("| %s | %s, tau_rel 1e-3 | %.2f | %d | %.3f | %.3f | %.3f | %.3f | %.3f |\n", label.c_str(), element_name(e),
                  tau / (h * h), its, median(whole), median(setup), median(assemble), median(solve), median(rest));
      std::fflush(stdout);
    }
    if(tau > 0)
    {
      std::vector<double> whole;
      for(int r = 0; r < runs; ++r)
      {
        Mesh m = s.mesh;
        CGAL::Real_timer t;
        t.start();
        PMP::smooth_shape(m, tau / 4, CGAL::parameters::number_of_iterations(1));
        whole.push_back(t.time());
      }
      std::printf("| %s | smooth_shape, time = tau/4 = %.3g | %.2f | | %.3f | | | | |\n", label.c_str(), tau / 4, tau / (h * h),
                  median(whole));
    }
    std::printf("| %s | CHOLESKY | | | not run (%zu vertices; above ~30k the factorisation is too slow) | | | | |\n",
                label.c_str(), std::size_t(num_vertices(s.mesh)));
    std::fflush(stdout);
  });
}

// ---------------------------------------------------------------------------------------------
// (b) CG iterations, Loop vs P1
std::string iteration_list(const AF::Fairing_report& r)
{
  std::string s;
  for(const AF::Fairing_step& st : r.steps) s += (s.empty() ? "" : ",") + std::to_string(st.solver_iterations);
  if(!r.succeeded()) s += (s.empty() ? "" : ", then ") + std::string(AF::to_string(r.status)) + " at step " + std::to_string(r.steps.size() + 1);
  return s;
}

double solve_per_step(const AF::Fairing_report& r)
{
  std::vector<double> v;
  for(const AF::Fairing_step& st : r.steps) v.push_back(st.solve_seconds);
  return mean(v);
}

void part_iterations(const std::string& dir)
{
  std::printf("\n## (b) Conjugate-gradient iterations per step, Loop vs P1: time_step(ratio h^2), 4 steps, stopping none, solver_tolerance(1e-8) (relative residual, as in doc/Anisotropic_fairing/design/loop-fem-flow.md section 9), warm start\n\n");
  std::printf("| mesh | tau/h^2 | tau_rel | CG its Loop | CG its P1 | solve s/step Loop | solve s/step P1 |\n|---|---:|---:|---|---|---:|---:|\n");
  for_each_mesh(dir, {{"bumpy.off", 0}, {"bunny.off", 0}, {"fertility.off", 2}}, [&](const Named_mesh& s)
  {
    const double h = mean_edge_length(s.mesh);
    for(double ratio : {0.1, 1.0, 3.0})
    {
      AF::Fairing_report rep[2];
      int i = 0;
      for(AF::Finite_element e : {AF::Finite_element::LOOP, AF::Finite_element::LINEAR})
      {
        Mesh m = s.mesh;
        double wall = 0;
        rep[i++] = run(m, AF::parameters::time_step(ratio * h * h).number_of_iterations(4)
                              .stopping_criteria(AF::Stopping_criteria::none())
                              .finite_element(e)
                              .linear_solver(AF::Linear_solver::CONJUGATE_GRADIENT)
                              .solver_tolerance(1e-8), wall);
      }
      std::printf("| %s (%zu V) | %g | %.2e | %s | %s | %.4f | %.4f |\n", s.name.c_str(), std::size_t(num_vertices(s.mesh)), ratio,
                  ratio * h * h / (rep[0].scale * rep[0].scale), iteration_list(rep[0]).c_str(), iteration_list(rep[1]).c_str(),
                  solve_per_step(rep[0]), solve_per_step(rep[1]));
      for(int k = 0; k < 2; ++k)
        if(!rep[k].succeeded()) std::printf("|  | | | %s: %s | | | |\n", k == 0 ? "Loop" : "P1", rep[k].message.c_str());
      std::fflush(stdout);
    }
  });
}

// ---------------------------------------------------------------------------------------------
// (c) CHOLESKY vs CG on the Loop system
void part_solvers(const std::string& dir, int runs)
{
  const int steps = 4;
  std::printf("\n## (c) Loop system: CHOLESKY (Eigen SimplicialLDLT) vs CONJUGATE_GRADIENT, %d steps of relative_time_step(tau_rel), seconds"
              " (median of %d runs below 20k vertices, 1 run above)\n\n", steps, runs);
  std::printf("CHOLESKY: step 1 includes the symbolic analysis; later steps factorise and solve. CG: mean over the %d steps."
              " whole = the whole call with %d steps. AUTOMATIC: CG, a factorised trial step after a step of more than %d"
              " iterations, up to %d free vertices; 'steps' lists the solver of each step (C = CG, D = direct).\n\n",
              steps, steps, AF::automatic_cholesky_trial_iterations, AF::automatic_cholesky_limit);
  std::printf("| mesh | V | tau_rel | tau/h^2 | CG its/step | CG solve/step | CHOL solve step 1 | CHOL solve later steps | CHOL/CG per step | whole CG | whole CHOL | whole AUTOMATIC (steps) |\n"
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
  for_each_mesh(dir, {{"bumpy.off", 0}, {"bunny.off", 0}, {"fertility.off", 0}, {"bumpy.off", 1},
                      {"fandisk.off", 0}, {"bunny.off", 1}, {"fertility.off", 1}, {"bumpy.off", 2},
                      {"bunny-closed.off", 0}}, [&](const Named_mesh& s)
  {
    const std::size_t nv = num_vertices(s.mesh);
    const int r_count = nv < 20000 ? runs : 1;
    const double h = mean_edge_length(s.mesh);
    // CHOLESKY once per mesh (its cost does not depend on tau)
    std::vector<double> ch1, chl, chw;
    std::string chol_failure;
    for(int r = 0; r < r_count; ++r)
    {
      double wall = 0;
      const AF::Fairing_report rep = run_steps(s.mesh, 1e-3, steps, AF::Linear_solver::CHOLESKY, wall);
      if(!rep.succeeded()) { chol_failure = rep.message; break; }
      ch1.push_back(rep.steps[0].solve_seconds);
      std::vector<double> later;
      for(std::size_t k = 1; k < rep.steps.size(); ++k) later.push_back(rep.steps[k].solve_seconds);
      chl.push_back(mean(later));
      chw.push_back(wall);
    }
    for(double tr : {1e-4, 1e-3, 1e-2})
    {
      std::vector<double> cg, cgw, its;
      std::string failure;
      double tau = 0;
      for(int r = 0; r < r_count; ++r)
      {
        double wall = 0;
        const AF::Fairing_report rep = run_steps(s.mesh, tr, steps, AF::Linear_solver::CONJUGATE_GRADIENT, wall);
        if(!rep.succeeded()) { failure = rep.message; break; }
        tau = rep.time_step;
        cg.push_back(solve_per_step(rep));
        cgw.push_back(wall);
        double sum = 0;
        for(const AF::Fairing_step& st : rep.steps) sum += st.solver_iterations;
        its.push_back(sum / double(rep.steps.size()));
      }
      if(!failure.empty()) { std::printf("| %s | %zu | %g | | CG failed: %s | | | | | | | |\n", s.name.c_str(), nv, tr, failure.c_str()); continue; }
      std::vector<double> autow;
      std::string auto_steps;
      for(int r = 0; r < r_count; ++r)
      {
        double wall = 0;
        const AF::Fairing_report rep = run_steps(s.mesh, tr, steps, AF::Linear_solver::AUTOMATIC, wall);
        autow.push_back(wall);
        auto_steps.clear();
        for(const AF::Fairing_step& st : rep.steps) auto_steps += st.direct_solve ? 'D' : 'C';
        if(!rep.succeeded()) auto_steps += std::string(" ") + AF::to_string(rep.status);
      }
      char auto_cell[96];
      std::snprintf(auto_cell, sizeof auto_cell, "%.3f (%s)", median(autow), auto_steps.c_str());
      const bool chol_here = tr == 1e-3;
      if(chol_here && !chol_failure.empty())
      { std::printf("| %s | %zu | %g | %.2f | %.0f | %.4f | CHOLESKY failed: %s | | | %.3f | | %s |\n", s.name.c_str(), nv, tr, tau / (h * h),
                    median(its), median(cg), chol_failure.c_str(), median(cgw), auto_cell); continue; }
      if(chol_here)
        std::printf("| %s | %zu | %g | %.2f | %.0f | %.4f | %.4f | %.4f | %.2f | %.3f | %.3f | %s |\n", s.name.c_str(), nv, tr, tau / (h * h),
                    median(its), median(cg), median(ch1), median(chl), median(chl) / median(cg), median(cgw), median(chw), auto_cell);
      else
        std::printf("| %s | %zu | %g | %.2f | %.0f | %.4f | (same) | (same) | %.2f | %.3f | | %s |\n", s.name.c_str(), nv, tr, tau / (h * h),
                    median(its), median(cg), median(chl) / median(cg), median(cgw), auto_cell);
      std::fflush(stdout);
    }
  });
}

// ---------------------------------------------------------------------------------------------
// (d) where the time of a one-step Loop call goes
void part_breakdown(const std::string& dir, int runs)
{
  namespace AFi = AF::internal;
  Named_mesh s;
  if(!load(dir, "fertility.off", 2, s)) return;
  std::vector<double> t_index, t_order, t_cache, t_stepper, t_asm, t_asm1, t_stats, t_limit;
  for(int r = 0; r < runs; ++r)
  {
    CGAL::Real_timer t;
    t.start();
    AFi::Indexed_mesh<Mesh> im(s.mesh, AFi::Borders::GHOSTED);
    const AFi::Control_matrix P = im.read_points(s.mesh.points());
    t_index.push_back(t.time());
    t.reset();
    // as the driver does: a private locality-friendly numbering, then the element cache in it
    const AFi::Locality_ordering ordering = AFi::make_locality_ordering(im.ghost_layer());
    AFi::Control_matrix X(P.rows(), 3);
    for(std::size_t i = 0; i < im.number_of_vertices(); ++i) X.row(Eigen::Index(i)) = P.row(ordering.old_of_new_vertex[i]);
    t_order.push_back(t.time());
    t.reset();
    AFi::Ghosted_patch_cache cache(ordering.layer, AFi::Quadrature_spec());
    t_cache.push_back(t.time());
    t.reset();
    const std::vector<bool> constrained(im.number_of_vertices(), false);
    const AFi::Mesh_components components = AFi::make_mesh_components(*ordering.layer.topology, im.number_of_vertices(),
                                                                       ordering.layer.real_faces);
    const double h = mean_edge_length(s.mesh);
    const std::vector<double> component_edge(components.count, h);   // one h for all: only the set-up is timed
    AFi::Time_stepper<AFi::Ghosted_patch_cache> stepper(cache, im.number_of_vertices(), constrained, ordering.layer, components,
                                                        component_edge, h);
    t_stepper.push_back(t.time());
    AFi::Value_array M, L;
    {
      AFi::Fem_assembler<AFi::Ghosted_patch_cache> assembler(cache, im.number_of_vertices());
      assembler.assemble(X, 3, AF::Isotropic_diffusion_tensor(), M, L);   // warm-up (allocations)
      t.reset();
      assembler.assemble(X, 3, AF::Isotropic_diffusion_tensor(), M, L);
      t_asm.push_back(t.time());
      t.reset();
      assembler.assemble(X, 3, AF::Isotropic_diffusion_tensor(), M, L, false);
      t_stats.push_back(t.time());
    }
#ifdef CGAL_LINKED_WITH_TBB
    tbb::task_arena one(1);
    one.execute([&] {
      AFi::Fem_assembler<AFi::Ghosted_patch_cache> assembler(cache, im.number_of_vertices());
      assembler.assemble(X, 3, AF::Isotropic_diffusion_tensor(), M, L);
      t.reset();
      assembler.assemble(X, 3, AF::Isotropic_diffusion_tensor(), M, L);
      t_asm1.push_back(t.time());
    });
#endif
    t.reset();
    AFi::Control_matrix limit(X.rows(), X.cols());
    for(std::size_t i = 0; i < im.number_of_vertices(); ++i)
      AFi::vertex_limit_value(*ordering.layer.topology, X, int(i), limit.row(Eigen::Index(i)).data());
    t_limit.push_back(t.time());
  }
  std::printf("\n## (d) Where a one-step Loop call goes, %s (%s), median of %d runs, seconds\n\n", s.name.c_str(), sizes(s.mesh).c_str(), runs);
  std::printf("| part | seconds |\n|---|---:|\n");
  std::printf("| numbering, validation, reading the points (Indexed_mesh) | %.3f |\n", median(t_index));
  std::printf("| locality ordering (Cuthill-McKee) and reordering the points | %.3f |\n", median(t_order));
  std::printf("| element set-up: patch categories + quadrature stencils | %.3f |\n", median(t_cache));
  std::printf("| stepper set-up: ring sparsity pattern + the free-free system pattern (Time_stepper constructor) | %.3f |\n", median(t_stepper));
  std::printf("| one assembly of M, L and the diagnostics (TBB, %d threads) | %.3f |\n",
#ifdef CGAL_LINKED_WITH_TBB
              tbb::this_task_arena::max_concurrency(),
#else
              1,
#endif
              median(t_asm));
  if(!t_asm1.empty()) std::printf("| one assembly, one thread | %.3f |\n", median(t_asm1));
  std::printf("| statistics only (area, energy, int |H|^2; the last step's), TBB | %.3f |\n", median(t_stats));
  std::printf("| limit positions of all vertices | %.3f |\n", median(t_limit));
  std::printf("\nA one-step call assembles at X_0 (matrices and statistics) and at X_1 (statistics only: the step's area, energy, int |H|^2 and the stopping test).\n");
}

// ---------------------------------------------------------------------------------------------
// (e) the cost of the diffusion tensor
void part_tensor(const std::string& dir, int runs)
{
  std::printf("\n## (e) Cost of the diffusion tensor per step: 3 steps of tau_rel 1e-3, CONJUGATE_GRADIENT, median of %d runs, seconds\n\n"
              "assemble: per step, mean of the 3 steps' assemble_seconds (with the prefilter: its isotropic assembly and CG solve too);"
              " solve: per step, mean solve_seconds; CG its: the steps' iterations.\n\n", runs);
  std::printf("| mesh | tensor | whole call | assemble / step | solve / step | CG its | whole / isotropic |\n"
              "|---|---|---:|---:|---:|---|---:|\n");
  for_each_mesh(dir, {{"denoising/Fandisk0.3/Noisy.obj", 0}, {"fertility.off", 2}}, [&](const Named_mesh& s)
  {
    const std::string label = s.name + " (" + sizes(s.mesh) + ")";
    struct Variant { const char* name; AF::Anisotropic_diffusion_tensor tensor; bool isotropic; };
    const Variant variants[] = { { "isotropic", AF::Anisotropic_diffusion_tensor(), true },
                                 { "anisotropic, no prefilter (lambda_rel 2, eps_rel 0)", AF::Anisotropic_diffusion_tensor(2, true, 0), false },
                                 { "anisotropic, default (lambda_rel 2, eps_rel 1e-3)", AF::Anisotropic_diffusion_tensor(), false } };
    double isotropic_whole = 0;
    for(const Variant& v : variants)
    {
      std::vector<double> whole, assemble, solve;
      std::string its, failure;
      for(int r = 0; r < runs; ++r)
      {
        Mesh m = s.mesh;
        double wall = 0;
        const auto np = AF::parameters::relative_time_step(1e-3).number_of_iterations(3)
                          .stopping_criteria(AF::Stopping_criteria::none())
                          .linear_solver(AF::Linear_solver::CONJUGATE_GRADIENT);
        const AF::Fairing_report rep = v.isotropic ? run(m, np.diffusion_tensor(AF::Isotropic_diffusion_tensor()), wall)
                                                   : run(m, np.diffusion_tensor(v.tensor), wall);
        if(!rep.succeeded() || rep.steps.size() != 3) { failure = rep.message; break; }
        whole.push_back(wall);
        double a = 0, b = 0;
        its.clear();
        for(const AF::Fairing_step& st : rep.steps)
        {
          a += st.assemble_seconds / 3;
          b += st.solve_seconds / 3;
          its += (its.empty() ? "" : ",") + std::to_string(st.solver_iterations);
        }
        assemble.push_back(a);
        solve.push_back(b);
      }
      if(!failure.empty()) { std::printf("| %s | %s | failed: %s | | | | |\n", label.c_str(), v.name, failure.c_str()); continue; }
      if(v.isotropic) isotropic_whole = median(whole);
      std::printf("| %s | %s | %.3f | %.3f | %.3f | %s | %.2f |\n", label.c_str(), v.name, median(whole), median(assemble),
                  median(solve), its.c_str(), median(whole) / isotropic_whole);
      std::fflush(stdout);
    }
  });
}

int main(int argc, char** argv)
{
  const std::string dir = argc > 1 && argv[1][0] ? argv[1] : std::string(AF_SOURCE_DIR) + "/../shared/data";
  const std::string parts = argc > 2 ? argv[2] : "uabcde";
  const int runs = argc > 3 ? std::max(1, std::atoi(argv[3])) : 5;
  CGAL::Real_timer wall;
  wall.start();
  std::printf("# bench_step_speed: data %s, parts %s, runs %d\n", dir.c_str(), parts.c_str(), runs);
  if(parts.find('u') != std::string::npos) part_units(dir);
  if(parts.find('a') != std::string::npos) part_step(dir, runs);
  if(parts.find('b') != std::string::npos) part_iterations(dir);
  if(parts.find('c') != std::string::npos) part_solvers(dir, runs);
  if(parts.find('d') != std::string::npos) part_breakdown(dir, runs);
  if(parts.find('e') != std::string::npos) part_tensor(dir, runs);
  std::printf("\nwall time of the whole run: %.1f s\n", wall.time());
  return 0;
}
