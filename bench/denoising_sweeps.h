// The sweeps of bench_denoising: each method is run over a grid of time steps x step counts and
// measured against Original (denoising_quality.h) after each step count; the best cell by angle is kept.
//
// One physical time for all methods: with l^2 = Area(Noisy)/(4 pi) (the flat noisy mesh),
// tau = tau_rel * l^2, passed as time_step(tau) to our methods and as time = tau/4 to smooth_shape
// (see bench_denoising.cpp). Our sweep is incremental: number_of_iterations(1) with output CONTROL_POINTS,
// repeated on the same mesh, the Loop limit positions evaluated after each step count.

#ifndef AF_BENCH_DENOISING_SWEEPS_H
#define AF_BENCH_DENOISING_SWEEPS_H

#include <CGAL/Real_timer.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include "bench_cases.h"
#include "denoising_quality.h"

#include <cstdio>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace AF = CGAL::Anisotropic_fairing;

// The best cell of one method's sweep.
struct Best
{
  Quality q;
  std::string setting;
  std::string notes;   // failures, refusals
  bool refused = false;
  bool run = false;    // false: method not selected
  double tau_rel = 0, lambda_rel = 0, epsilon_rel = 0;   // of the best cell (ours)
  int steps = 0;
  void consider(const Quality& c, const std::string& s, double tr = 0, int k = 0, double lr = 0, double er = 0)
  {
    if(c.ok() && (!q.ok() || c.angle < q.angle)) { q = c; setting = s; tau_rel = tr; steps = k; lambda_rel = lr; epsilon_rel = er; }
  }
  void note(const std::string& s) { notes += (notes.empty() ? "" : "; ") + s; }
};

// The grids (the program's arguments TAUS, LAMBDAS and EPSILONS override the three that are not const).
std::vector<double> our_taus = {1e-4, 3e-4, 1e-3, 3e-3};
const std::vector<int> step_counts = {1, 2, 3, 5, 10};
const std::vector<double> smooth_taus = {1e-5, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2};
const std::vector<double> smooth_literal_times = {1e-5, 1e-4, 1e-3, 1e-2};
std::vector<double> aniso_lambdas = {1, 2, 5, 10, 20, 50, 100};
std::vector<double> aniso_epsilons = {0};
// anisotropic Loop: the steps beyond 10 are taken only while the angle still falls (from 5 to 10, 10 to 20)
const std::vector<int> aniso_step_counts = {1, 2, 3, 5, 10, 20, 40};

// The anisotropic tensor with an absolute threshold and prefilter time (model units); the prefilter
// needs a library whose tensor takes (lambda, relative, epsilon).
constexpr bool has_prefilter = std::is_constructible<AF::Anisotropic_diffusion_tensor, double, bool, double>::value;
template <typename T = AF::Anisotropic_diffusion_tensor>
T aniso_tensor(double threshold, double epsilon, bool relative = false)
{
  if constexpr(std::is_constructible<T, double, bool, double>::value) return T(threshold, relative, epsilon);
  else return T(threshold, relative);
}
std::string aniso_prefix(double lambda_rel, double epsilon_rel)
{
  return (aniso_epsilons.size() > 1 || epsilon_rel > 0 ? "eps_rel " + fmt("%g", epsilon_rel) + ", " : "") +
         "lambda_rel " + fmt("%g", lambda_rel) + ", ";
}

// One line of the sweep detail: quality after each step count.
struct Sweep_row
{
  std::string label;
  std::vector<std::string> cells;
};

void print_sweep(const std::string& title, const std::vector<Sweep_row>& rows, const std::vector<int>& step_counts = ::step_counts)
{
  std::printf("\n%s\n\n| setting |", title.c_str());
  for(int k : step_counts) std::printf(" %d |", k);
  std::printf("\n|---|");
  for(std::size_t i = 0; i < step_counts.size(); ++i) std::printf("---|");
  std::printf("\n");
  for(const Sweep_row& r : rows)
  {
    std::printf("| %s |", r.label.c_str());
    for(const std::string& c : r.cells) std::printf(" %s |", c.c_str());
    std::printf("\n");
  }
}

std::string cell(const Quality& q) { return q.ok() ? fmt("%.2f", q.angle) + " / " + fmt("%.2e", q.dist) : "non-finite"; }

// Our method, incrementally: one step per call, control points kept, limit evaluated for LOOP.
// `lambda_rel` > 0 only labels the cells of the anisotropic sweep (the tensor carries the threshold and prefilter).
template <typename Tensor>
void sweep_ours(const Mesh& noisy, const Reference& ref, AF::Finite_element element, double l2, double h,
                Best& best, std::vector<Sweep_row>& rows, double& seconds, const Tensor& tensor, double lambda_rel = 0,
                const std::vector<int>& step_counts = ::step_counts, Best* best10 = nullptr, double epsilon_rel = 0)
{
  CGAL::Real_timer timer;
  timer.start();
  const bool loop = element == AF::Finite_element::LOOP;
  const std::string prefix = lambda_rel > 0 ? aniso_prefix(lambda_rel, epsilon_rel) : "";
  for(double tr : our_taus)
  {
    const double tau = tr * l2;
    Sweep_row row;
    row.label = prefix + "tau_rel " + fmt("%g", tr) + " (tau/h^2 " + fmt("%.2f", tau / (h * h)) + ")";
    Mesh m = noisy;
    int done = 0;
    std::string failure;
    double previous = std::numeric_limits<double>::infinity(), last = std::numeric_limits<double>::infinity();
    for(int k : step_counts)
    {
      if(k > 10 && failure.empty() && !(last < previous)) { row.cells.push_back("skipped"); continue; }
      while(failure.empty() && done < k)
      {
        AF::Fairing_report r = AF::anisotropic_fairing(m, AF::parameters::time_step(tau)
                                                           .number_of_iterations(1)
                                                           .stopping_criteria(AF::Stopping_criteria::none())
                                                           .finite_element(element)
                                                           .diffusion_tensor(tensor)
                                                           .output_positions(AF::Output_positions::CONTROL_POINTS));
        if(!r.succeeded()) failure = std::string(AF::to_string(r.status)) + " at step " + std::to_string(done + 1);
        else ++done;
      }
      if(!failure.empty()) { row.cells.push_back("failed"); continue; }
      const Quality q = loop ? limit_quality(m, ref) : evaluate(m, ref);
      row.cells.push_back(cell(q));
      previous = last;
      last = q.ok() ? q.angle : std::numeric_limits<double>::infinity();
      const std::string setting = prefix + "tau_rel " + fmt("%g", tr) + " x " + std::to_string(k);
      best.consider(q, setting, tr, k, lambda_rel, epsilon_rel);
      if(best10 && k <= 10) best10->consider(q, setting, tr, k, lambda_rel, epsilon_rel);
    }
    if(!failure.empty()) best.note(prefix + "tau_rel " + fmt("%g", tr) + ": " + failure);
    rows.push_back(row);
  }
  seconds = timer.time();
}

// CGAL's smooth_shape at time t * scale for each t of `times`, from the noisy mesh for each step count;
// `relative`: t is a tau_rel (the row labels say so).
void sweep_smooth_shape(const Mesh& noisy, const Reference& ref, const std::vector<double>& times, double scale,
                        Best& best, std::vector<Sweep_row>& rows, double& seconds, bool relative)
{
  CGAL::Real_timer timer;
  timer.start();
  for(double t : times)
  {
    Sweep_row row;
    const double time = t * scale;
    row.label = relative ? "tau_rel " + fmt("%g", t) + " (time " + fmt("%.3g", time) + ")" : "time " + fmt("%g", t);
    for(int k : step_counts)
    {
      Mesh m = noisy;
      PMP::smooth_shape(m, time, CGAL::parameters::number_of_iterations(k));
      const Quality q = evaluate(m, ref);
      row.cells.push_back(cell(q));
      const std::string setting = (relative ? "tau_rel " : "time ") + fmt("%g", t) + " x " + std::to_string(k);
      if(!q.ok()) best.note(setting + ": non-finite");
      best.consider(q, setting);
    }
    rows.push_back(row);
  }
  seconds = timer.time();
}

#endif // AF_BENCH_DENOISING_SWEEPS_H
