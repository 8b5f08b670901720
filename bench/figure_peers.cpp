// The peers of the manual's denoising figure (scripts/figures/make_figures.py): CGAL's smooth_shape and our
// isotropic Loop flow, each at the best cell of the sweeps of bench_denoising (denoising_sweeps.h), by the
// mean face-normal angle to the noise-free original; written so that the figure shows what the benchmark
// compares against.
//
//   smooth_shape: time tau_rel * l^2 / 4 for tau_rel in smooth_taus, x iterations in step_counts (each cell
//                 from the noisy mesh; l^2 = Area(Noisy)/(4 pi), the benchmark's one physical time);
//   isotropic:    Isotropic_diffusion_tensor, Loop elements, time step tau_rel * l^2 for tau_rel in our_taus,
//                 x steps in step_counts, the Loop limit positions of the best cell (sweep_ours), then that
//                 cell run again to write it.
//
// usage: figure_peers NOISY.obj CLEAN.obj SMOOTH_SHAPE_OUT.off ISOTROPIC_OUT.off
// NOISY and CLEAN: the same connectivity in file order (a denoising pair). The outputs keep the vertex and
// face order of NOISY, with 17 significant digits. Prints one line per method:
//   <method> <angle in degrees> <distance / bbox diagonal> <setting>

#include <CGAL/Real_timer.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include "bench_cases.h"         // Mesh, read_obj_in_order, mean_edge_length, fmt, pi
#include "denoising_quality.h"   // Reference, evaluate, limit_mesh
#include "denoising_sweeps.h"    // the grids, Best, sweep_ours, print_sweep

#include <cstdio>
#include <string>
#include <vector>

namespace {

bool write_result(const std::string& path, const Mesh& m)
{
  return CGAL::IO::write_OFF(path, m, CGAL::parameters::stream_precision(17));
}

// The smooth_shape grid of the benchmark's "same physical time" sweep; the best mesh is kept.
Mesh best_smooth_shape(const Mesh& noisy, const Reference& ref, double l2, Best& best)
{
  Mesh kept = noisy;
  std::vector<Sweep_row> rows;
  for(double t : smooth_taus)
  {
    Sweep_row row;
    row.label = "tau_rel " + fmt("%g", t);
    for(int k : step_counts)
    {
      Mesh m = noisy;
      PMP::smooth_shape(m, t * l2 / 4, CGAL::parameters::number_of_iterations(k));
      const Quality q = evaluate(m, ref);
      row.cells.push_back(cell(q));
      const std::string before = best.setting;
      best.consider(q, "tau_rel " + fmt("%g", t) + " x " + std::to_string(k), t, k);
      if(best.setting != before) kept = m;
    }
    rows.push_back(row);
  }
  print_sweep("smooth_shape (time tau_rel l^2/4), cells: angle / dist", rows);
  return kept;
}

// The best cell of the isotropic Loop sweep run again: one-step calls with control-point output, as the
// sweep measured them, then the Loop limit positions.
Mesh best_isotropic(const Mesh& noisy, const Reference& ref, double l2, double h, Best& best)
{
  std::vector<Sweep_row> rows;
  double seconds = 0;
  sweep_ours(noisy, ref, AF::Finite_element::LOOP, l2, h, best, rows, seconds, AF::Isotropic_diffusion_tensor());
  print_sweep("isotropic Loop (limit positions), " + fmt("%.1f s", seconds) + ", cells: angle / dist", rows);
  Mesh m = noisy;
  for(int k = 0; k < best.steps; ++k)
    AF::anisotropic_fairing(m, AF::parameters::time_step(best.tau_rel * l2)
                                   .number_of_iterations(1)
                                   .stopping_criteria(AF::Stopping_criteria::none())
                                   .finite_element(AF::Finite_element::LOOP)
                                   .diffusion_tensor(AF::Isotropic_diffusion_tensor())
                                   .output_positions(AF::Output_positions::CONTROL_POINTS));
  return limit_mesh(m);
}

} // namespace

int main(int argc, char** argv)
{
  if(argc != 5)
  {
    std::fprintf(stderr, "usage: figure_peers NOISY.obj CLEAN.obj SMOOTH_SHAPE_OUT.off ISOTROPIC_OUT.off\n");
    return 2;
  }
  Mesh noisy, clean;
  if(!read_obj_in_order(argv[1], noisy) || !read_obj_in_order(argv[2], clean) ||
     num_vertices(noisy) != num_vertices(clean) || num_faces(noisy) != num_faces(clean))
  {
    std::fprintf(stderr, "figure_peers: cannot read %s and %s as a denoising pair (OBJ, same connectivity)\n", argv[1], argv[2]);
    return 1;
  }
  CGAL::Real_timer timer;
  timer.start();
  const Reference ref(clean);
  const double l2 = PMP::area(noisy) / (4 * pi);
  const double h = mean_edge_length(noisy);

  Best smooth, iso;
  const Mesh smoothed = best_smooth_shape(noisy, ref, l2, smooth);
  const Mesh isotropic = best_isotropic(noisy, ref, l2, h, iso);
  const Quality q_smooth = evaluate(smoothed, ref), q_iso = evaluate(isotropic, ref);
  if(!q_smooth.ok() || !q_iso.ok() || !write_result(argv[3], smoothed) || !write_result(argv[4], isotropic))
  {
    std::fprintf(stderr, "figure_peers: no finite result, or cannot write %s / %s\n", argv[3], argv[4]);
    return 1;
  }
  std::printf("\nnoisy %.4f %.4e input\n", evaluate(noisy, ref).angle, evaluate(noisy, ref).dist);
  std::printf("smooth_shape %.4f %.4e %s\n", q_smooth.angle, q_smooth.dist, smooth.setting.c_str());
  std::printf("isotropic %.4f %.4e %s\n", q_iso.angle, q_iso.dist, iso.setting.c_str());
  std::printf("(%.1f s)\n", timer.time());
  return 0;
}
