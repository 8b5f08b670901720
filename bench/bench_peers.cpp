// Denoising quality against widely used smoothers: the library's default run and the best of our sweeps
// (our_sweeps.h) next to the best of OpenMesh's Jacobi Laplace smoother (C0 and C1, uniform and cotangent
// weights), Taubin's lambda|mu (peer_smoothers.h) and bilateral normal filtering (bilateral_normal_filter.h), each tuned by a sweep
// and evaluated at its best cell, on the cases of bench_cases.h with 8- and 10-bit quantisation.
// Two errors per result: the mean face-normal angle to the original (degrees), and the mean distance of
// the vertices to the original surface (units of its mean edge length h: drift and shrinkage).
//
// usage: bench_peers [DATA_DIR=<repo>/../shared/data] [CASE_SUBSTRING] [PARTS=dsp]
//   PARTS: d = default run, s = our sweeps (and smooth_shape's), p = the peers

#include "our_sweeps.h"
#include "peer_smoothers.h"

struct Peers
{
  Best jacobi[4];   // C0 uniform, C0 cotangent, C1 uniform, C1 cotangent
  Best taubin, bilateral;
  double seconds = 0;
  Best umbrella() const   // the best of OpenMesh's and Taubin's
  {
    Best b = taubin;
    for(const Best& j : jacobi)
      if(std::isfinite(j.error) && !(j.error >= b.error)) b = j;
    return b;
  }
};

static const char* jacobi_name[4] = {"C0 uniform", "C0 cotangent", "C1 uniform", "C1 cotangent"};

// Runs `step(m, done, k)` (advance m from `done` to `k` iterations) over `counts`, stopping a row
// once its error rose twice.
template <typename Step>
void peer_row(const Mesh& noisy, const std::vector<Vector>& reference, const std::vector<int>& counts, bool incremental,
              const std::string& label, Best& best, Step step)
{
  Mesh m = noisy;
  int done = 0;
  std::vector<double> errors;
  std::string cells;
  for(int k : counts)
  {
    if(!incremental) { m = noisy; done = 0; }
    step(m, done, k);
    done = k;
    const double e = normal_error(m, reference);
    errors.push_back(std::isfinite(e) ? e : std::numeric_limits<double>::infinity());
    cells += " | " + std::to_string(k) + ": " + fmt("%.2f", e);
    best.consider(e, label + " x " + std::to_string(k), m);
    if(rising_twice(errors)) break;
  }
  std::printf("  %-40s%s\n", label.c_str(), cells.c_str());
  std::fflush(stdout);
}

Peers run_peers(const Mesh& noisy, const std::vector<Vector>& reference)
{
  Peers p;
  CGAL::Real_timer timer;
  timer.start();
  const std::vector<int> iterations = {1, 2, 3, 5, 8, 12, 20, 30, 50, 80, 120, 200, 300};
#ifdef AF_WITH_OPENMESH
  for(int j = 0; j < 4; ++j)
  {
    Open_mesh o = to_open_mesh(noisy);
    Jacobi_smoother smoother(o, j >= 2, j % 2 == 1);
    peer_row(noisy, reference, iterations, true, std::string("OpenMesh ") + jacobi_name[j], p.jacobi[j],
             [&](Mesh& m, int done, int k) { smoother.smooth(unsigned(k - done)); copy_points(o, m); });
  }
#else
  std::printf("  OpenMesh: not built with it (install libopenmesh-dev and configure again)\n");
#endif
  const Vertex_rings rings(noisy);
  for(double lambda : {0.33, 0.5, 0.63})
    peer_row(noisy, reference, iterations, true, "Taubin lambda " + fmt("%g", lambda), p.taubin,
             [&](Mesh& m, int done, int k) { taubin_smooth(m, rings, lambda, k - done); });
  const Bilateral_normal_filter bilateral(noisy);
  for(double sigma_s : {0.2, 0.35, 0.5, 0.7})
    peer_row(noisy, reference, {1, 2, 3, 5, 8, 12, 20, 30}, false, "bilateral sigma_s " + fmt("%g", sigma_s), p.bilateral,
             [&](Mesh& m, int, int k) { bilateral.run(m, rings.border, sigma_s, k); });
  p.seconds = timer.time();
  return p;
}

std::string cell(const Best& b, const Distance_to_original& distance)
{
  return std::isfinite(b.error) ? fmt("%.2f", b.error) + " / " + fmt("%.3f", distance(b.result)) : "-";
}

int main(int argc, char** argv)
{
  Case_arguments args;
  if(!read_case_arguments(argc, argv, "dsp", "dsp", args)) return 1;
  const std::string &dir = args.dir, &only = args.only, &parts = args.parts;
  const bool part_d = args.part('d'), part_s = args.part('s'), part_p = args.part('p');
  CGAL::Real_timer wall;
  wall.start();
  std::printf("# bench_peers: %s, cases matching \"%s\", parts %s\n", dir.c_str(), only.c_str(), parts.c_str());

  std::vector<std::string> table;
  for(Case& c : noisy_cases(dir, {8, 10}))
  {
    if(!only.empty() && c.name.find(only) == std::string::npos) continue;
    std::printf("\n## %s\n", c.name.c_str());
    if(!c.load(c)) { std::printf("skipped: %s\n", c.note.c_str()); continue; }
    const std::vector<Vector> reference = face_normals(c.original);
    const Distance_to_original distance(c.original);
    std::printf("%s%s%zu V; noise sigma/h %.3f; noisy %.2f deg / %.3f h\n", c.note.c_str(), c.note.empty() ? "" : "; ",
                num_vertices(c.noisy), measured_sigma(c), normal_error(c.noisy, reference), distance(c.noisy));
    std::fflush(stdout);
    std::string row = "| " + c.name + " | " + fmt("%.2f", normal_error(c.noisy, reference)) + " |";
    Best ours;
    if(part_d)
    {
      const Default_run d = default_run(c.noisy);
      Best b;
      b.consider(normal_error(d.result, reference), "default", d.result);
      std::printf("default: %s (%s, %s, %zu steps, %.1f s)\n", cell(b, distance).c_str(), d.status.c_str(), d.stop.c_str(), d.steps,
                  d.seconds);
      row += " " + cell(b, distance) + " |";
      ours = b;
    }
    if(part_s)
    {
      const Sweeps s = run_sweeps(c.noisy, reference);
      const Best b = s.ours();
      std::printf("best ours: %s (%s); smooth_shape %s (%s)\n", cell(b, distance).c_str(), b.setting.c_str(),
                  cell(s.smooth, distance).c_str(), s.smooth.setting.c_str());
      row += " " + cell(b, distance) + " | " + cell(s.smooth, distance) + " |";
      if(!(b.error >= ours.error)) ours = b;
    }
    if(part_p)
    {
      const Peers p = run_peers(c.noisy, reference);
      for(int j = 0; j < 4; ++j) row += " " + cell(p.jacobi[j], distance) + " |";
      row += " " + cell(p.taubin, distance) + " | " + cell(p.bilateral, distance) + " |";
      const Best u = p.umbrella();
      std::printf("peers (%.1f s): best OpenMesh/Taubin %s (%s); bilateral %s (%s)\n", p.seconds, cell(u, distance).c_str(),
                  u.setting.c_str(), cell(p.bilateral, distance).c_str(), p.bilateral.setting.c_str());
      if(part_d || part_s)
        row += std::string(" ") + (ours.error <= u.error ? "yes" : "no") + " | " + (ours.error <= p.bilateral.error ? "yes" : "no") + " |";
    }
    table.push_back(row);
    std::fflush(stdout);
  }

  std::printf("\n## Summary (each cell: mean face-normal error in degrees / mean vertex distance to the original in h, at the"
              " method's best cell by normal error)\n\n| case | noisy |%s%s%s%s\n|---|---|%s%s%s%s\n",
              part_d ? " default |" : "", part_s ? " best ours | smooth_shape |" : "",
              part_p ? " OpenMesh C0 uniform | C0 cotangent | C1 uniform | C1 cotangent | Taubin | bilateral |" : "",
              part_p && (part_d || part_s) ? " ours <= OpenMesh/Taubin | ours <= bilateral |" : "",
              part_d ? "---|" : "", part_s ? "---|---|" : "", part_p ? "---|---|---|---|---|---|" : "",
              part_p && (part_d || part_s) ? "---|---|" : "");
  for(const std::string& r : table) std::printf("%s\n", r.c_str());
  std::printf("\nwall time %.1f s\n", wall.time());
  return 0;
}
