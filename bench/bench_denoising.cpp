// Denoising quality of fairing on the standard mesh-denoising pairs
// (<DIR>/<Model><sigma>/{Noisy,Original}.obj, same connectivity in both files): isotropic Loop
// (limit-surface output), isotropic P1, CGAL::Polygon_mesh_processing::smooth_shape, and anisotropic
// Loop (Anisotropic_diffusion_tensor, limit-surface output), each at the best point of a small sweep
// (best = smallest mean face-normal angle to Original).
//
// Measures, per model and method:
//   angle  mean angle in degrees between corresponding face normals of the result and of Original
//   dist   mean distance of the result's vertices to the Original surface (AABB tree), divided by
//          the bounding-box diagonal of Original
//
// One physical time for all methods: with l^2 = Area(Noisy)/(4 pi) (the flat noisy mesh),
// tau = tau_rel * l^2, passed as time_step(tau) to our methods and as time = tau/4 to smooth_shape
// (CGAL 5.5's smooth_shape solves (D - t L) X = D X_n with D_ii = sum of incident face areas / 6 and
// L_ij = cot a + cot b, i.e. 4x the usual Laplace-Beltrami, so its "time" t is physical time 4t of
// the flow dx/dt = Delta x = 2H that our tau measures). smooth_shape also keeps the stiffness of the
// input (conformalized MCF) and rescales closed meshes to their initial volume after every step.
//
// Our sweep is run incrementally: number_of_iterations(1) with output CONTROL_POINTS, repeated on
// the same mesh, evaluating the Loop limit positions (Loop_limit_surface::limit_positions) after
// steps 1, 2, 3, 5, 10. The program checks that this equals one call with number_of_iterations(k) and
// output LIMIT_SURFACE (to round-off with CHOLESKY; to the CG tolerance with CG, which the single
// call warm-starts from the previous step's displacement, and the one-step calls from zero).
//
// Anisotropic Loop: the same incremental sweep with diffusion_tensor(Anisotropic_diffusion_tensor)
// for lambda_rel in {1, 2, 5, 10, 20, 50, 100}. The threshold is passed in absolute units,
// lambda_rel / l0 with l0 = sqrt(Area/4 pi) of the Loop limit surface of Noisy (what one multi-step call
// with the relative tensor uses: it measures l once on its input; a one-step call with the relative
// tensor would re-measure l on the shrinking surface at every step). The program checks this against
// one 3-step LIMIT_SURFACE call with the relative tensor. For the best cell it also prints curvature
// diagnostics: max(|k1|,|k2|) l0 at face centres of the Loop limit surfaces of Noisy, Original and the
// result, split into faces on a crease of Original (an edge with dihedral angle > 30 deg), faces next to
// one (sharing a vertex) and the rest, with the fraction of faces whose g(k_max) < 0.5 per lambda, and
// the mean normal angle error per class.
//
// The anisotropic sweep also takes 20 and 40 steps, each only while the angle still fell over the
// previous interval (5 -> 10, 10 -> 20); the best cell is reported over all steps and over steps <= 10.
//
// usage: bench_denoising [DIR=<repo>/../shared/data/denoising] [MODEL_SUBSTRING] [METHODS=loop,p1,smooth] [LAMBDAS=1,2,5,10,20,50,100]
//                        [EPSILONS=0] [TAUS=1e-4,3e-4,1e-3,3e-3]
//   METHODS: "all" or a comma-separated subset of loop, p1, smooth (both smooth_shape sweeps), aniso (default: all but aniso)
//   LAMBDAS: the lambda_rel values of the anisotropic sweep
//   EPSILONS: prefilter times eps_rel (curvature read on M_eps, one isotropic implicit step of eps_rel l0^2;
//             default 0: on the current surface), swept as an outer loop around LAMBDAS
//   TAUS: the tau_rel values of our sweeps (Loop, P1, anisotropic)

#include <CGAL/Real_timer.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>
#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include "bench_cases.h"           // the mesh types, reading in order, face normals, fmt
#include "crease_diagnostics.h"    // aniso_diagnostics
#include "denoising_checks.h"      // equivalence, equivalence_aniso
#include "denoising_quality.h"     // Quality, Reference, evaluate
#include "denoising_sweeps.h"      // Best, the grids, sweep_ours, sweep_smooth_shape, print_sweep

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

// One model's line of the summary.
struct Row
{
  std::string model, size;
  Best loop, p1, smooth, literal, aniso, aniso10;
  Quality noisy, noisy_limit;
};

std::string summary(const Best& b)
{
  if(!b.run) return "not run";
  if(b.refused) return b.notes;
  std::string s = b.q.ok() ? fmt("%.2f", b.q.angle) + "°, " + fmt("%.2e", b.q.dist) + " (" + b.setting + ")" : "no result";
  if(!b.notes.empty()) s += " [" + b.notes + "]";
  return s;
}

// a comma-separated list of positive numbers (or non-negative ones) into `out`
bool parse_list(const char* text, const char* name, bool zero_allowed, std::vector<double>& out)
{
  out.clear();
  for(const char* c = text; *c;)
  {
    char* end = nullptr;
    const double x = std::strtod(c, &end);
    if(end == c || !(x > 0 || (zero_allowed && x == 0)))
    {
      std::fprintf(stderr, "%s: a comma-separated list of %s numbers\n", name, zero_allowed ? "non-negative" : "positive");
      return false;
    }
    out.push_back(x);
    c = *end == ',' ? end + 1 : end;
  }
  return true;
}

// {1e-4, 3e-4} -> "0.0001,0.0003"
std::string join(const std::vector<double>& values)
{
  std::string l;
  for(double x : values) l += (l.empty() ? "" : ",") + fmt("%g", x);
  return l;
}

int main(int argc, char** argv)
{
  std::string dir = argc > 1 && argv[1][0] ? argv[1] : std::string(AF_SOURCE_DIR) + "/../shared/data/denoising";
  const std::string only = argc > 2 ? argv[2] : "";
  // the anisotropic sweep (7 thresholds, up to 40 steps) is opt-in: with it the 8 pairs take hours
  const std::string methods = argc > 3 && argv[3][0] ? argv[3] : "loop,p1,smooth";
  if(argc > 4 && argv[4][0] && !parse_list(argv[4], "LAMBDAS", false, aniso_lambdas)) return 1;
  bool run_loop = false, run_p1 = false, run_smooth = false, run_aniso = false;
  {
    std::size_t start = 0;
    while(start <= methods.size())
    {
      const std::size_t end = std::min(methods.find(',', start), methods.size());
      const std::string m = methods.substr(start, end - start);
      if(m == "all") run_loop = run_p1 = run_smooth = run_aniso = true;
      else if(m == "loop") run_loop = true;
      else if(m == "p1") run_p1 = true;
      else if(m == "smooth") run_smooth = true;
      else if(m == "aniso") run_aniso = true;
      else if(!m.empty())
      {
        std::fprintf(stderr, "unknown method '%s'; METHODS is \"all\" or a comma-separated subset of loop, p1, smooth, aniso\n", m.c_str());
        return 1;
      }
      start = end + 1;
    }
  }
  if(argc > 5 && argv[5][0])
  {
    if(!parse_list(argv[5], "EPSILONS", true, aniso_epsilons)) return 1;
    for(double E : aniso_epsilons)
      if(E > 0 && !has_prefilter) { std::fprintf(stderr, "EPSILONS: this library's Anisotropic_diffusion_tensor has no prefilter\n"); return 1; }
  }
  if(argc > 6 && argv[6][0] && !parse_list(argv[6], "TAUS", false, our_taus)) return 1;
  CGAL::Real_timer wall;
  wall.start();

  std::vector<std::string> models;
  for(const std::string& name : denoising_pairs(dir))
    if(only.empty() || name.find(only) != std::string::npos) models.push_back(name);
  if(models.empty()) { std::fprintf(stderr, "no <Model>/{Noisy,Original}.obj pairs in %s\n", dir.c_str()); return 1; }

  std::printf("# bench_denoising: %s (%zu pairs), methods:%s%s%s%s\n", dir.c_str(), models.size(), run_loop ? " loop" : "",
              run_p1 ? " p1" : "", run_smooth ? " smooth" : "", run_aniso ? " aniso" : "");
  std::printf("sweep: ours tau_rel {%s} x steps {1,2,3,5,10}; smooth_shape tau_rel {1e-5,1e-4,3e-4,1e-3,3e-3,1e-2}"
              " x iterations {1,2,3,5,10} (time = tau_rel*l^2/4), and its literal times {1e-5,1e-4,1e-3,1e-2};"
              " anisotropic Loop: eps_rel {%s} x lambda_rel {%s} x ours, with steps 20 and 40 while the angle still falls;"
              " l^2 = Area(Noisy)/(4 pi); cells: angle(deg) / dist(/bbox diag)\n",
              join(our_taus).c_str(), join(aniso_epsilons).c_str(), join(aniso_lambdas).c_str());

  std::vector<Row> table;
  bool checked_cholesky = false;
  for(const std::string& name : models)
  {
    const std::string base = dir + "/" + name;
    Mesh noisy, original;
    std::string why;
    if(!read_denoising_pair(base, noisy, original, why)) { std::fprintf(stderr, "%s: %s\n", name.c_str(), why.c_str()); return 1; }
    CGAL::Real_timer model_timer;
    model_timer.start();
    const Reference ref(original);
    Row row;
    row.model = name;
    row.size = std::to_string(num_vertices(noisy)) + " / " + std::to_string(num_faces(noisy));
    row.noisy = evaluate(noisy, ref);
    row.loop.run = run_loop;
    row.p1.run = run_p1;
    row.smooth.run = row.literal.run = run_smooth;
    row.aniso.run = row.aniso10.run = run_aniso;
    const double area = PMP::area(noisy);
    const double l2 = area / (4 * pi);
    const double h = mean_edge_length(noisy);
    const std::size_t borders = [&] { std::size_t b = 0; for(auto hh : noisy.halfedges()) b += noisy.is_border(hh) ? 1 : 0; return b; }();
    std::printf("\n## %s: %s vertices / faces, %zu border edges, l = %.4g, h = %.4g, l^2/h^2 = %.0f, bbox diag %.4g\n",
                name.c_str(), row.size.c_str(), borders, std::sqrt(l2), h, l2 / (h * h), ref.diagonal);
    std::printf("noisy input: %s\n", cell(row.noisy).c_str());

    double t_loop = 0, t_p1 = 0, t_smooth = 0, t_literal = 0;
    std::vector<Sweep_row> rows_loop, rows_p1, rows_smooth, rows_literal, rows_aniso;
    bool limit_refused = false;
    if(run_loop || run_aniso)
    {
      try
      {
        row.noisy_limit = limit_quality(noisy, ref);
        std::printf("Loop limit of the noisy mesh (0 steps): %s\n", cell(row.noisy_limit).c_str());
      }
      catch(const AF::Input_error& e) { limit_refused = true; }
    }
    if(run_loop)
    {
      try { sweep_ours(noisy, ref, AF::Finite_element::LOOP, l2, h, row.loop, rows_loop, t_loop, AF::Isotropic_diffusion_tensor()); }
      catch(const AF::Input_error& e) { row.loop.refused = true; row.loop.notes = std::string("refused: ") + e.what(); }
    }
    if(run_p1)
    {
      try { sweep_ours(noisy, ref, AF::Finite_element::LINEAR, l2, h, row.p1, rows_p1, t_p1, AF::Isotropic_diffusion_tensor()); }
      catch(const AF::Input_error& e) { row.p1.refused = true; row.p1.notes = std::string("refused: ") + e.what(); }
    }
    if(run_smooth)
    {
      sweep_smooth_shape(noisy, ref, smooth_taus, l2 / 4, row.smooth, rows_smooth, t_smooth, true);
      sweep_smooth_shape(noisy, ref, smooth_literal_times, 1.0, row.literal, rows_literal, t_literal, false);
    }
    double t_aniso = 0, l0 = 0;
    std::vector<double> t_per_lambda;
    if(run_aniso)
    {
      try
      {
        // l0 of the Loop limit surface of Noisy: what a multi-step call with the relative tensor measures
        l0 = std::sqrt(AF::Loop_limit_surface<Mesh>(noisy).area() / (4 * pi));
        std::printf("anisotropic Loop: l0 = sqrt(Area(Loop limit of Noisy)/4pi) = %.4g (l of the flat noisy mesh %.4g); "
                    "threshold lambda_rel/l0, i.e. lambda_rel * h/l0 = lambda_rel * %.4f per edge length\n", l0, std::sqrt(l2), h / l0);
        for(double E : aniso_epsilons)
          for(double L : aniso_lambdas)
          {
            double t = 0;
            sweep_ours(noisy, ref, AF::Finite_element::LOOP, l2, h, row.aniso, rows_aniso, t,
                       aniso_tensor(L / l0, E * l0 * l0), L, aniso_step_counts, &row.aniso10, E);
            t_per_lambda.push_back(t);
            t_aniso += t;
            std::printf("  %s%.1f s\n", aniso_prefix(L, E).c_str(), t);
            std::fflush(stdout);
          }
      }
      catch(const AF::Input_error& e)
      {
        row.aniso.refused = row.aniso10.refused = true;
        row.aniso.notes = row.aniso10.notes = std::string("refused: ") + e.what();
      }
    }

    if(run_loop && !row.loop.refused)
    {
      // equivalence of the incremental sweep with one call (tau_rel 1e-3, 3 steps)
      const double tau = 1e-3 * l2;
      if(!checked_cholesky)
      {
        std::printf("equivalence (incremental vs one 3-step LIMIT_SURFACE call, tau_rel 1e-3), CHOLESKY: max |diff|/diag = %.2e\n",
                    equivalence(noisy, tau, 3, AF::Linear_solver::CHOLESKY, ref.diagonal));
        checked_cholesky = true;
      }
      bool factorised = false;
      const double d = equivalence(noisy, tau, 3, AF::Linear_solver::AUTOMATIC, ref.diagonal, &factorised);
      std::printf("equivalence, AUTOMATIC (%s here): max |diff|/diag = %.2e\n", factorised ? "factorised" : "CG", d);
    }
    if(run_aniso && !row.aniso.refused)
      std::printf("equivalence, anisotropic (incremental with threshold lambda_rel/l0 and prefilter eps_rel l0^2 vs one 3-step LIMIT_SURFACE call with "
                  "the relative tensor, lambda_rel 10, eps_rel %g, tau_rel 1e-3, AUTOMATIC): max |diff|/diag = %.2e\n", aniso_epsilons.back(),
                  equivalence_aniso(noisy, 1e-3 * l2, 3, 10.0, aniso_epsilons.back(), l0, ref.diagonal));

    if(limit_refused) std::printf("Loop limit of the noisy mesh: refused\n");
    if(run_loop)
    {
      if(!row.loop.refused) print_sweep("Loop (limit positions), " + fmt("%.1f s", t_loop), rows_loop);
      else std::printf("Loop: %s\n", row.loop.notes.c_str());
    }
    if(run_p1)
    {
      if(!row.p1.refused) print_sweep("P1, " + fmt("%.1f s", t_p1), rows_p1);
      else std::printf("P1: %s\n", row.p1.notes.c_str());
    }
    if(run_smooth)
    {
      print_sweep("smooth_shape (same physical time), " + fmt("%.1f s", t_smooth), rows_smooth);
      print_sweep("smooth_shape (literal time argument), " + fmt("%.1f s", t_literal), rows_literal);
    }
    if(run_aniso)
    {
      if(!row.aniso.refused)
      {
        print_sweep("anisotropic Loop (limit positions; steps 20 and 40 only while the angle still falls), " + fmt("%.1f s", t_aniso),
                    rows_aniso, aniso_step_counts);
        const char* with_eps = aniso_epsilons.size() > 1 || aniso_epsilons.back() > 0 ? "eps_rel, " : "";
        std::printf("\nbest per %slambda_rel (all steps; steps <= 10 only):\n\n| %slambda_rel | best cell (angle / dist) | setting | best with <= 10 steps | setting | seconds |\n|---|---|---|---|---|---|\n",
                    with_eps, with_eps);
        for(std::size_t i = 0; i < aniso_lambdas.size() * aniso_epsilons.size(); ++i)
        {
          Best b, b10;
          for(std::size_t r = i * our_taus.size(); r < (i + 1) * our_taus.size() && r < rows_aniso.size(); ++r)
            for(std::size_t c = 0; c < rows_aniso[r].cells.size(); ++c)
            {
              Quality q;
              if(std::sscanf(rows_aniso[r].cells[c].c_str(), "%lf / %lf", &q.angle, &q.dist) == 2)
              {
                const std::string set = "tau_rel " + fmt("%g", our_taus[r - i * our_taus.size()]) + " x " + std::to_string(aniso_step_counts[c]);
                b.consider(q, set);
                if(aniso_step_counts[c] <= 10) b10.consider(q, set);
              }
            }
          const double E = aniso_epsilons[i / aniso_lambdas.size()], L = aniso_lambdas[i % aniso_lambdas.size()];
          const std::string label = (with_eps[0] ? fmt("%g", E) + ", " : std::string()) + fmt("%g", L);
          std::printf("| %s | %s | %s | %s | %s | %.1f |\n", label.c_str(), cell(b.q).c_str(), b.setting.c_str(), cell(b10.q).c_str(), b10.setting.c_str(),
                      i < t_per_lambda.size() ? t_per_lambda[i] : 0.0);
        }
        CGAL::Real_timer diag;
        diag.start();
        aniso_diagnostics(noisy, original, ref, l0, l2, row.aniso, row.loop);
        std::printf("(diagnostics %.1f s)\n", diag.time());
      }
      else std::printf("anisotropic Loop: %s\n", row.aniso.notes.c_str());
    }
    std::printf("model total %.1f s\n", model_timer.time());
    std::fflush(stdout);
    table.push_back(row);
  }

  std::printf("\n## Summary: best of each sweep by mean normal angle (angle to Original, mean vertex distance to the Original surface / bbox diagonal, setting = [[eps_rel,] lambda_rel,] tau_rel x steps)\n\n");
  std::printf("| model | V / F | Loop | anisotropic Loop | anisotropic Loop, <= 10 steps | P1 | smooth_shape | noisy input | Loop limit of noisy (0 steps) |\n|---|---|---|---|---|---|---|---|---|\n");
  for(const Row& r : table)
    std::printf("| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", r.model.c_str(), r.size.c_str(), summary(r.loop).c_str(),
                summary(r.aniso).c_str(), summary(r.aniso10).c_str(), summary(r.p1).c_str(), summary(r.smooth).c_str(),
                (fmt("%.2f", r.noisy.angle) + "°, " + fmt("%.2e", r.noisy.dist)).c_str(),
                r.noisy_limit.ok() ? (fmt("%.2f", r.noisy_limit.angle) + "°, " + fmt("%.2e", r.noisy_limit.dist)).c_str() : "-");
  if(run_smooth)
  {
    std::printf("\nsmooth_shape with its literal time argument {1e-5,1e-4,1e-3,1e-2} (model units, not scaled):\n\n"
                "| model | best |\n|---|---|\n");
    for(const Row& r : table) std::printf("| %s | %s |\n", r.model.c_str(), summary(r.literal).c_str());
  }
  std::printf("\nwall time of the whole run: %.1f s\n", wall.time());
  return 0;
}
