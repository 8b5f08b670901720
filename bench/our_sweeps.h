// Our side of the denoising benchmarks (bench_defaults, bench_peers): the library's default run, and
// sweeps of explicit settings (isotropic and anisotropic tensor, incremental one-step calls as in
// bench_denoising, Loop limit positions evaluated) next to a sweep of CGAL's smooth_shape.
// A sweep cell "e*n" had n steps that the library shortened below tau (a rejected unsound step), so it
// is not at tau x k; one single k-step call at each best cell checks that the incremental sweep agrees.

#ifndef AF_BENCH_OUR_SWEEPS_H
#define AF_BENCH_OUR_SWEEPS_H

#include <CGAL/Real_timer.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>

#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>
#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include "bench_cases.h"
#include "loop_limit.h"

#include <exception>

namespace AF = CGAL::Anisotropic_fairing;

struct Default_run
{
  bool run = false;
  std::string status = "-", stop = "-";
  std::size_t steps = 0, folded = 0;
  double seconds = 0, error = nan_value;
  Mesh result;
};

// The library's default: no named parameters, the mesh is overwritten with the limit positions; with
// `uniform`, the automatic parameters with the uniform tensor (diffusion_tensor only).
Default_run default_run(const Mesh& input, bool uniform = false)
{
  Default_run d;
  d.run = true;
  d.result = input;
  CGAL::Real_timer timer;
  timer.start();
  try
  {
    const AF::Fairing_report r = uniform ? AF::anisotropic_fairing(d.result, AF::parameters::diffusion_tensor(AF::Uniform_diffusion_tensor()))
                                         : AF::anisotropic_fairing(d.result);
    d.status = AF::to_string(r.status);
    d.stop = AF::to_string(r.stop_reason);
    d.steps = r.steps.size();
  }
  catch(const std::exception& e) { d.status = std::string("threw: ") + e.what(); }
  d.seconds = timer.time();
  d.folded = folded_edges(d.result);
  return d;
}

struct Best
{
  double error = nan_value;
  std::string setting = "-";
  std::string notes;
  double tau = 0, threshold = 0, prefilter = 0;   // ours: the cell's tau and tensor (threshold 0: isotropic)
  int steps = 0;
  Mesh result;   // the best cell's mesh
  void consider(double e, const std::string& s, const Mesh& m, double t = 0, int k = 0, double th = 0, double pf = 0)
  {
    if(std::isfinite(e) && !(e >= error)) { error = e; setting = s; result = m; tau = t; steps = k; threshold = th; prefilter = pf; }
  }
  std::string str() const { return std::isfinite(error) ? fmt("%.2f", error) + " (" + setting + ")" : "-"; }
};

// True when the error rose over the last two evaluation points: the row is past its optimum.
bool rising_twice(const std::vector<double>& e)
{
  const std::size_t n = e.size();
  return n >= 3 && e[n - 1] > e[n - 2] && e[n - 2] > e[n - 3];
}

// One sweep row of ours: one step per call (control points kept), Loop limit evaluated after `steps`.
double threshold_of(const AF::Isotropic_diffusion_tensor&) { return 0; }
double threshold_of(const AF::Anisotropic_diffusion_tensor& t) { return t.threshold(); }
double prefilter_of(const AF::Isotropic_diffusion_tensor&) { return 0; }
double prefilter_of(const AF::Anisotropic_diffusion_tensor& t) { return t.prefilter_time(); }

template <typename Tensor>
void sweep_row(const Mesh& noisy, const std::vector<Vector>& reference, double tau, const Tensor& tensor,
               const std::vector<int>& steps, const std::string& label, Best& best)
{
  Mesh m = noisy;
  int done = 0;
  std::vector<double> errors;
  std::string cells;
  int shortened = 0;          // steps the library took with less than tau so far
  double shortened_time = 0;  // the time they lost, in units of tau (printed)
  for(int k : steps)
  {
    for(; done < k; ++done)
    {
      const AF::Fairing_report r = AF::anisotropic_fairing(m, AF::parameters::time_step(tau)
                                                                 .number_of_iterations(1)
                                                                 .stopping_criteria(AF::Stopping_criteria::none())
                                                                 .diffusion_tensor(tensor)
                                                                 .output_positions(AF::Output_positions::CONTROL_POINTS));
      // a call that failed, or took no full step (a rejected step ends the run early), ends the row
      if(!r.succeeded() || r.steps.size() != 1 || r.stop_reason != AF::Stop_reason::MAXIMUM_STEPS)
      {
        const std::string why = std::string(AF::to_string(r.status)) + "/" + AF::to_string(r.stop_reason) + " at step " +
                                std::to_string(done + 1) + (r.message.empty() ? "" : " (" + r.message + ")");
        best.notes += (best.notes.empty() ? "" : "; ") + label + ": " + why;
        std::printf("  %-40s%s | %s\n", label.c_str(), cells.c_str(), why.c_str());
        return;
      }
      // the library may retry an unsound step with a fraction of tau: then the cell is not at tau x k
      if(r.steps[0].time < 0.999 * tau) { ++shortened; shortened_time += tau - r.steps[0].time; }
    }
    const Mesh limit = limit_mesh(m);
    const double e = normal_error(limit, reference);
    errors.push_back(std::isfinite(e) ? e : std::numeric_limits<double>::infinity());
    cells += " | " + std::to_string(k) + ": " + fmt("%.2f", e) + (shortened ? "*" + std::to_string(shortened) : "");
    best.consider(e, label + " x " + std::to_string(k) + (shortened ? " (" + std::to_string(shortened) + " shortened)" : ""), limit,
                   tau, k, threshold_of(tensor), prefilter_of(tensor));
    if(rising_twice(errors)) break;
  }
  std::printf("  %-40s%s%s\n", label.c_str(), cells.c_str(),
              shortened ? (" (*n: n steps so far shorter than tau, " + fmt("%.1f", shortened_time / tau) + " tau lost)").c_str() : "");
}

struct Sweeps
{
  bool run = false;
  Best iso, aniso, smooth;
  double seconds = 0;
  void drop_results() { iso.result = aniso.result = smooth.result = Mesh(); }
  Best ours() const
  {
    if(!std::isfinite(aniso.error) || iso.error <= aniso.error) return iso;
    return aniso;
  }
};

// One call of k steps with LIMIT_SURFACE output at a sweep's best cell: does the incremental sweep
// (one call per step) stand for what a user's single call gives?
std::string direct_check(const Mesh& noisy, const std::vector<Vector>& reference, const Best& b)
{
  if(b.steps == 0) return "-";
  Mesh m = noisy;
  const auto np = AF::parameters::time_step(b.tau).number_of_iterations(b.steps).stopping_criteria(AF::Stopping_criteria::none());
  const AF::Fairing_report r = b.threshold > 0
      ? AF::anisotropic_fairing(m, np.diffusion_tensor(AF::Anisotropic_diffusion_tensor(b.threshold, false, b.prefilter)))
      : AF::anisotropic_fairing(m, np);
  return fmt("%.2f", normal_error(m, reference)) + " (" + AF::to_string(r.status) + ", " + AF::to_string(r.stop_reason) + ", " +
         std::to_string(r.steps.size()) + " steps)";
}

Sweeps run_sweeps(const Mesh& noisy, const std::vector<Vector>& reference)
{
  Sweeps s;
  s.run = true;
  CGAL::Real_timer timer;
  timer.start();
  const double l2 = PMP::area(noisy) / (4 * pi);   // the flat noisy mesh, as in bench_denoising
  try
  {
    for(double tr : {1e-4, 3e-4, 1e-3})
      sweep_row(noisy, reference, tr * l2, AF::Isotropic_diffusion_tensor(), {1, 2, 3, 5, 8, 12, 20},
                "iso tau_rel " + fmt("%g", tr), s.iso);
    // absolute threshold and prefilter, from l0 of the Loop limit of Noisy: what one multi-step call
    // with the relative tensor would use (one-step calls would re-measure l every step)
    const double l0 = std::sqrt(AF::Loop_limit_surface<Mesh>(noisy).area() / (4 * pi));
    for(double lr : {2.0, 8.0})
      for(double tr : {1e-4, 3e-4})
        sweep_row(noisy, reference, tr * l2, AF::Anisotropic_diffusion_tensor(lr / l0, false, 1e-3 * l0 * l0),
                  {1, 2, 3, 5, 8, 12, 20, 30, 40}, "aniso lambda_rel " + fmt("%g", lr) + " tau_rel " + fmt("%g", tr), s.aniso);
  }
  catch(const std::exception& e) { s.iso.notes += std::string("threw: ") + e.what(); }
  try
  {
    std::printf("  one call of the best cell's steps (LIMIT_SURFACE): iso %s, aniso %s\n", direct_check(noisy, reference, s.iso).c_str(),
                direct_check(noisy, reference, s.aniso).c_str());
  }
  catch(const std::exception& e) { std::printf("  one call of the best cell: threw %s\n", e.what()); }
  // smooth_shape's time t is physical time 4t (its L is 4x the Laplace-Beltrami): time = tau/4
  for(double tr : {1e-4, 3e-4, 1e-3, 3e-3})
  {
    std::vector<double> errors;
    std::string cells;
    for(int k : {1, 2, 3, 5, 10})
    {
      Mesh m = noisy;
      PMP::smooth_shape(m, tr * l2 / 4, CGAL::parameters::number_of_iterations(k));
      const double e = normal_error(m, reference);
      errors.push_back(std::isfinite(e) ? e : std::numeric_limits<double>::infinity());
      cells += " | " + std::to_string(k) + ": " + fmt("%.2f", e);
      s.smooth.consider(e, "tau_rel " + fmt("%g", tr) + " x " + std::to_string(k), m);
      if(rising_twice(errors)) break;
    }
    std::printf("  %-40s%s\n", ("smooth_shape tau_rel " + fmt("%g", tr)).c_str(), cells.c_str());
  }
  s.seconds = timer.time();
  return s;
}

#endif // AF_BENCH_OUR_SWEEPS_H
