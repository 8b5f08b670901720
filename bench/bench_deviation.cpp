// The guaranteed bound on the deviation (named parameter maximum_deviation, issue 17).
//
//   p  the denoising pairs (<DATA_DIR>/denoising/<Name>/{Noisy,Original}.obj): the default run without a bound,
//      with the bound at 1, 2 and 3 times the noise level sigma (measured on the pair: the root mean square
//      of the noise along the original's normals), and with fixed fidelity weights omega instead: the mean
//      face-normal error against the original (degrees), the largest and the mean deviation off the input (in
//      units of sigma), the vertices written on the bound, the seconds.
//   t  the paper's Table I on a mesh of ours (bumpy.off of the examples, 1250 vertices): the isotropic flow with
//      tau = 0.0019 l^2 (the paper's tau = 0.01 on its model of area 66.11) and the paper's omega (times its
//      l^2 = 5.26: omega in units of 1/l^2) until it stops moving; the surface area, the steps, the largest and
//      the mean deviation. Next to each, the same flow with no omega and the bound set to that row's largest
//      deviation, and the uniform fidelity weight the bound chose (Deviation_bound.h).
//
// usage: bench_deviation [DATA_DIR=<repo>/../shared/data] [CASE_SUBSTRING] [PARTS=pt]

#include "bench_cases.h"

#include <CGAL/Real_timer.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

namespace AF = CGAL::Anisotropic_fairing;

struct Deviation { double largest = 0, mean = 0; };

Deviation deviation(const Mesh& a, const Mesh& b)
{
  Deviation d;
  for(Mesh::Vertex_index v : a.vertices())
  {
    const double e = std::sqrt(CGAL::squared_distance(a.point(v), b.point(v)));
    d.largest = std::max(d.largest, e);
    d.mean += e;
  }
  d.mean /= double(num_vertices(a));
  return d;
}

// one run of the pairs' table: a row of it
template <typename NP>
void pair_row(const char* what, const Mesh& noisy, const std::vector<Vector>& reference, double sigma, const NP& np)
{
  Mesh m = noisy;
  CGAL::Real_timer t;
  t.start();
  const AF::Fairing_report r = AF::anisotropic_fairing(m, np);
  const double seconds = t.time();
  const Deviation d = deviation(m, noisy);
  if(!r.succeeded()) { std::printf("| %s | %s | | | | | |\n", what, AF::to_string(r.status)); return; }
  std::printf("| %s | %.2f | %.2f | %.2f | %zu | %s | %.1f |\n", what, normal_error(m, reference), d.largest / sigma, d.mean / sigma,
              r.clamped_vertices, AF::to_string(r.stop_reason), seconds);
  std::fflush(stdout);
}

void pairs(const std::string& dir, const std::string& only)
{
  for(const std::string& name : denoising_pairs(dir + "/denoising"))
  {
    if(!only.empty() && name.find(only) == std::string::npos) continue;
    Mesh noisy, original;
    std::string note;
    if(!read_denoising_pair(dir + "/denoising/" + name, noisy, original, note)) { std::printf("%s: %s\n", name.c_str(), note.c_str()); continue; }
    Case c;
    c.noisy = noisy;
    c.original = original;
    const double sigma = measured_sigma(c) * mean_edge_length(original);
    const std::vector<Vector> reference = face_normals(original);
    std::printf("\n### %s (%zu vertices), sigma = %.4g (model units), input normal error %.2f\n\n", name.c_str(),
                num_vertices(noisy), sigma, normal_error(noisy, reference));
    std::printf("| run | normal error (deg) | largest deviation / sigma | mean deviation / sigma | on the bound | stop | s |\n|---|---:|---:|---:|---:|---|---:|\n");
    pair_row("default, no bound", noisy, reference, sigma, AF::parameters::default_values());
    for(double k : { 1.0, 2.0, 3.0 })
      pair_row(("default, bound " + fmt("%.0f", k) + " sigma").c_str(), noisy, reference, sigma,
               AF::parameters::absolute_maximum_deviation(k * sigma));
    for(double w : { 10.0, 100.0, 1000.0 })
      pair_row(("default, omega " + fmt("%.0f", w) + " / l^2").c_str(), noisy, reference, sigma,
               AF::parameters::relative_fidelity_weight(w));
  }
}

void table_one(const std::string& source)
{
  Mesh input;
  if(!CGAL::IO::read_polygon_mesh(source + "/examples/Anisotropic_fairing/data/bumpy.off", input)) { std::printf("cannot read bumpy.off\n"); return; }
  const double area0 = PMP::area(input);
  std::printf("\n### Table I on bumpy.off (%zu vertices, area %.4g)\n\n", num_vertices(input), area0);
  std::printf("| omega (1/l^2) | area | steps | largest deviation | mean deviation | with the bound instead: omega chosen (1/l^2) | area | steps | largest | mean | held / on the bound |\n"
              "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  AF::Stopping_criteria steady = AF::Stopping_criteria::none();
  steady.steady_speed = 1e-3;   // in l per unit time l^2
  const auto flow = AF::parameters::relative_time_step(0.0019).number_of_iterations(2000u).stopping_criteria(steady)
                      .diffusion_tensor(AF::Isotropic_diffusion_tensor());
  for(double paper_omega : { 1.25, 2.5, 5.0, 10.0, 20.0, 40.0, 80.0 })
  {
    const double w = paper_omega * 66.11 / (4 * pi);
    Mesh m = input;
    const AF::Fairing_report r = AF::anisotropic_fairing(m, flow.relative_fidelity_weight(w));
    if(!r.succeeded()) { std::printf("| %.3g | %s | %zu | | | | | | | | |\n", w, AF::to_string(r.status), r.steps.size()); std::fflush(stdout); continue; }
    const Deviation d = deviation(m, input);
    Mesh b = input;
    const AF::Fairing_report rb = AF::anisotropic_fairing(b, flow.absolute_maximum_deviation(d.largest));
    const Deviation db = deviation(b, input);
    std::printf("| %.3g | %.4g | %zu (%s) | %.4g | %.4g | %.3g | %s | %zu (%s) | %.4g | %.4g | %zu / %zu |\n", w, PMP::area(m), r.steps.size(),
                AF::to_string(r.stop_reason), d.largest, d.mean, rb.bound_uniform_weight * rb.scale * rb.scale,
                rb.succeeded() ? fmt("%.4g", PMP::area(b)).c_str() : AF::to_string(rb.status),
                rb.steps.size(), AF::to_string(rb.stop_reason), db.largest, db.mean, rb.bound_held_vertices, rb.clamped_vertices);
    std::fflush(stdout);
  }
}

int main(int argc, char** argv)
{
  Case_arguments a;
  if(!read_case_arguments(argc, argv, "pt", "pt", a)) return 2;
  if(a.part('t')) table_one(AF_SOURCE_DIR);
  if(a.part('p')) pairs(a.dir, a.only);
  return 0;
}
