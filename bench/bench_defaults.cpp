// Safe automatic defaults: how close the library's default run, anisotropic_fairing(mesh) with no
// named parameters, gets to the best explicit settings, and whether it ever folds the surface.
//
// Cases: those of bench_cases.h with 10-bit quantisation, the held-out ones ("other ..."), and noise-free default runs on armadillo.obj
// and camelhead.off (how much a clean mesh is changed).
// Per case: the default run (mean face-normal angle error to the original, status, stop reason, steps,
// seconds, folded edges = interior edges whose two faces' normals make an angle > 120 deg), the best of
// the sweeps of our_sweeps.h (ours, isotropic and anisotropic, and CGAL's smooth_shape).
// sigma/h is the noise actually added: RMS of (noisy - original) along the original's area-weighted
// normals, over the original's mean edge length (for the denoising pairs it is measured the same way).
//
// usage: bench_defaults [DATA_DIR=<repo>/../shared/data] [CASE_SUBSTRING] [PARTS=dsn]
//   PARTS: d = default run, s = sweeps (ours and smooth_shape), n = noise-free default runs, u = the automatic
//          run with the uniform tensor (diffusion_tensor(Uniform_diffusion_tensor()) alone), printed per case
//   case names: the pair directories (Fandisk0.3, ...), "<model> gauss0.2", "<model> gauss0.5", "<model> quant10", "<model> clean",
//   "other <model> gauss0.3", "other <model> every-direction0.3"

#include "our_sweeps.h"

std::string folded_str(std::size_t before, std::size_t after)
{
  return std::to_string(before) + " / " + std::to_string(after) + (after > before ? " FOLDED" : "");
}

int main(int argc, char** argv)
{
  Case_arguments args;
  if(!read_case_arguments(argc, argv, "dsn", "dsnu", args)) return 1;
  const std::string &dir = args.dir, &only = args.only, &parts = args.parts;
  const bool part_d = args.part('d'), part_s = args.part('s'), part_n = args.part('n'), part_u = args.part('u');
  CGAL::Real_timer wall;
  wall.start();

  // noisy cases: the denoising pairs, then the generated ones
  std::vector<Case> cases = noisy_cases(dir, {10});
  for(Case& c : held_out_cases(dir)) cases.push_back(std::move(c));

  std::printf("# bench_defaults: %s, cases matching \"%s\", parts %s\n", dir.c_str(), only.c_str(), parts.c_str());
  if(part_s)
    std::printf("sweeps: iso tau_rel {1e-4,3e-4,1e-3} x steps {1,2,3,5,8,12,20}; aniso lambda_rel {2,8}, eps_rel 1e-3,"
                " tau_rel {1e-4,3e-4} x steps {1,...,40}; smooth_shape tau_rel {1e-4,3e-4,1e-3,3e-3} x {1,2,3,5,10};"
                " a row stops when the error rose twice; tau = tau_rel l^2, l^2 = Area(noisy)/4pi\n");

  struct Row
  {
    std::string name, size, sigma;
    double noisy_error = nan_value;
    std::size_t noisy_folded = 0;
    Default_run d;
    Sweeps s;
  };
  std::vector<Row> rows;
  if(part_d || part_s || part_u)
    for(Case& c : cases)
    {
      if(!only.empty() && c.name.find(only) == std::string::npos) continue;
      CGAL::Real_timer timer;
      timer.start();
      std::printf("\n## %s\n", c.name.c_str());
      if(!c.load(c)) { std::printf("skipped: %s\n", c.note.c_str()); continue; }
      Row r;
      r.name = c.name;
      r.size = std::to_string(num_vertices(c.noisy));
      const std::vector<Vector> reference = face_normals(c.original);
      const double sigma = measured_sigma(c);
      r.sigma = fmt("%.3f", sigma);
      r.noisy_error = normal_error(c.noisy, reference);
      r.noisy_folded = folded_edges(c.noisy);
      std::size_t borders = 0;
      for(Mesh::Halfedge_index h : c.noisy.halfedges()) borders += c.noisy.is_border(h) ? 1 : 0;
      std::printf("%s%s%zu V, %zu border edges, h = %.4g, bbox diag %.4g; noise sigma/h: measured %.3f%s; noisy error %.2f deg,"
                  " %zu folded edges\n", c.note.c_str(), c.note.empty() ? "" : "; ", num_vertices(c.noisy), borders,
                  mean_edge_length(c.original), bbox_diagonal(c.original), sigma,
                  std::isfinite(c.nominal_sigma) ? (", nominal " + fmt("%.3f", c.nominal_sigma)).c_str() : "",
                  r.noisy_error, r.noisy_folded);
      std::fflush(stdout);
      if(part_d)
      {
        r.d = default_run(c.noisy);
        r.d.error = normal_error(r.d.result, reference);
        r.d.result = Mesh();
        std::printf("default: %.2f deg, %s, %s, %zu steps, %.2f s, folded edges %s\n", r.d.error, r.d.status.c_str(),
                    r.d.stop.c_str(), r.d.steps, r.d.seconds, folded_str(r.noisy_folded, r.d.folded).c_str());
        std::fflush(stdout);
      }
      if(part_u)
      {
        Default_run u = default_run(c.noisy, true);
        std::printf("uniform: %.2f deg, %s, %s, %zu steps, %.2f s, folded edges %s\n", normal_error(u.result, reference),
                    u.status.c_str(), u.stop.c_str(), u.steps, u.seconds, folded_str(r.noisy_folded, u.folded).c_str());
        std::fflush(stdout);
      }
      if(part_s)
      {
        r.s = run_sweeps(c.noisy, reference);
        r.s.drop_results();
        std::string notes = r.s.iso.notes + (r.s.iso.notes.empty() || r.s.aniso.notes.empty() ? "" : "; ") + r.s.aniso.notes;
        std::printf("best iso %s; best aniso %s; smooth_shape %s; sweeps %.1f s%s%s\n", r.s.iso.str().c_str(), r.s.aniso.str().c_str(),
                    r.s.smooth.str().c_str(), r.s.seconds, notes.empty() ? "" : "; failures: ", notes.c_str());
      }
      std::printf("case total %.1f s\n", timer.time());
      std::fflush(stdout);
      rows.push_back(std::move(r));
    }

  if(!rows.empty())
  {
    std::printf("\n## Summary (errors: mean face-normal angle to the original, degrees; sigma/h: measured noise; folded: interior edges"
                " with a dihedral turn > 120 deg, input / result)\n\n| case | V | sigma/h | noisy err |");
    if(part_d) std::printf(" default err | status | stop | steps | s |");
    if(part_s) std::printf(" best ours (setting) | best iso (setting) | best aniso (setting) | smooth_shape best (setting) | sweeps s |");
    if(part_d && part_s) std::printf(" default / best ours | default < best iso? |");
    if(part_d) std::printf(" folded in / out |");
    std::printf("\n|---|---|---|---|%s%s%s%s\n", part_d ? "---|---|---|---|---|" : "", part_s ? "---|---|---|---|---|" : "",
                part_d && part_s ? "---|---|" : "", part_d ? "---|" : "");
    for(const Row& r : rows)
    {
      std::printf("| %s | %s | %s | %.2f |", r.name.c_str(), r.size.c_str(), r.sigma.c_str(), r.noisy_error);
      if(part_d) std::printf(" %.2f | %s | %s | %zu | %.2f |", r.d.error, r.d.status.c_str(), r.d.stop.c_str(), r.d.steps, r.d.seconds);
      if(part_s)
        std::printf(" %s | %s | %s | %s | %.1f |", r.s.ours().str().c_str(), r.s.iso.str().c_str(), r.s.aniso.str().c_str(),
                    r.s.smooth.str().c_str(), r.s.seconds);
      if(part_d && part_s)
      {
        const double best = r.s.ours().error;
        std::printf(" %s | %s |", fmt("%.2f", r.d.error / best).c_str(),
                    std::isfinite(r.d.error) && std::isfinite(r.s.iso.error) ? (r.d.error < r.s.iso.error ? "yes" : "no") : "-");
      }
      if(part_d) std::printf(" %s |", folded_str(r.noisy_folded, r.d.folded).c_str());
      std::printf("\n");
    }
  }

  // noise-free inputs: how much the default run changes a clean mesh
  if(part_n)
  {
    std::vector<std::string> rows_n;
    for(const std::string file : {"armadillo.obj", "camelhead.off"})
    {
      const std::string name = file.substr(0, file.rfind('.')) + " clean";
      if(!only.empty() && name.find(only) == std::string::npos) continue;
      Mesh m;
      std::string note;
      if(!read_clean(dir + "/" + file, m, note)) { std::printf("\n%s: skipped: %s\n", name.c_str(), note.c_str()); continue; }
      const Default_run d = default_run(m);
      double displacement = 0;
      for(Mesh::Vertex_index v : m.vertices()) displacement += std::sqrt(CGAL::squared_distance(m.point(v), d.result.point(v)));
      displacement /= double(num_vertices(m)) * bbox_diagonal(m);
      rows_n.push_back("| " + name + " | " + std::to_string(num_vertices(m)) + " | " + fmt("%.4f", 100 * displacement) + " | " +
                       folded_str(folded_edges(m), d.folded) + " | " + d.status + " | " + d.stop + " | " + std::to_string(d.steps) +
                       " | " + fmt("%.2f", d.seconds) + " |" + (note.empty() ? "" : " " + note));
      std::printf("\n## %s (noise-free)\n%s\n", name.c_str(), rows_n.back().c_str());
      std::fflush(stdout);
    }
    if(!rows_n.empty())
    {
      std::printf("\n## Noise-free inputs, default run\n\n| case | V | mean displacement / bbox diag (%%) | folded before / after | status | stop | steps | s |\n"
                  "|---|---|---|---|---|---|---|---|\n");
      for(const std::string& r : rows_n) std::printf("%s\n", r.c_str());
    }
  }
  std::printf("\nwall time %.1f s\n", wall.time());
  return 0;
}
