// The default run (no named parameters) and the step control that keeps every run sound: a
// constructed fold is seen; folds where the surface was already folded do not reject a step; the stress cases of the safe-defaults issue never end in `success` with a
// folded, collapsed, unmoved or non-finite surface; noise-free meshes are left nearly alone; several
// components are each faired as if alone; zero-area faces are faired; the noise estimate recovers the
// deviation of generated noise; and the default run denoises the Fandisk0.3 pair.
//
// argv[1]: the test data folder (test/Anisotropic_fairing/data), the only place it reads meshes from.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Local_time_scale.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Step_safety.h>

#include "test_support/check.h"
#include "test_support/mesh_coordinates.h"
#include "test_support/mesh_generators.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace AF = CGAL::Anisotropic_fairing;
namespace PMP = CGAL::Polygon_mesh_processing;
using AF_test::byte_identical;
using AF_test::coordinates;

std::string DATA;   // the test data folder

// the benchmark's measure: interior edges whose faces turn by more than 120 degrees
std::size_t folded_edges(const Mesh& m)
{
  std::size_t count = 0;
  for(auto e : m.edges())
  {
    if(m.is_border(e)) continue;
    const auto h = m.halfedge(e);
    if(PMP::compute_face_normal(m.face(h), m) * PMP::compute_face_normal(m.face(m.opposite(h)), m) < -0.5) ++count;
  }
  return count;
}

double bbox_diagonal(const Mesh& m)
{
  const CGAL::Bbox_3 b = PMP::bbox(m);
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) + CGAL::square(b.zmax() - b.zmin()));
}

double mean_displacement(const Mesh& a, const Mesh& b)
{
  double sum = 0;
  for(auto v : a.vertices()) sum += std::sqrt(CGAL::squared_distance(a.point(v), b.point(v)));
  return sum / double(num_vertices(a));
}

double mean_edge(const Mesh& m)
{
  double sum = 0;
  for(auto e : m.edges()) sum += std::sqrt(CGAL::squared_distance(m.point(m.source(m.halfedge(e))), m.point(m.target(m.halfedge(e)))));
  return sum / double(num_edges(m));
}

// A folded run is never a success: it ends on a sound surface (no more folded edges than the input,
// finite) with a stop reason that says so, or fails and leaves the mesh as it was.
void check_sound(const char* name, const Mesh& input, const Mesh& output, const AF::Fairing_report& r)
{
  const std::size_t before = folded_edges(input), after = folded_edges(output);
  bool finite = true;
  for(double x : coordinates(output)) finite = finite && std::isfinite(x);
  std::printf("%s: %s, stop %s after %zu steps (%zu rejected), folded edges %zu -> %zu: %s\n", name, AF::to_string(r.status),
              AF::to_string(r.stop_reason), r.steps.size(), r.rejected_steps, before, after, r.message.c_str());
  if(r.succeeded())
  {
    AF_CHECK(finite, std::string(name) + ": a success is finite");
    AF_CHECK(after <= before, std::string(name) + ": a success has no more folded edges than the input");
    if(r.stop_reason == AF::Stop_reason::STEP_REJECTED)
    {
      AF_CHECK(!r.message.empty(), std::string(name) + ": an early end says why");
      AF_CHECK(!r.steps.empty(), std::string(name) + ": a run that kept no step (an unmoved surface) is no success");
    }
  }
  else
  {
    AF_CHECK(!r.message.empty(), std::string(name) + ": a failure says why");
    AF_CHECK(byte_identical(coordinates(input), coordinates(output)), std::string(name) + ": a failure leaves the mesh as it was");
  }
}

void constructed_fold()
{
  // two triangles on the edge (0,1), opened by 100 degrees and then folded to 150 (their normals turn by that much)
  for(double turn : { 100.0, 150.0 })
  {
    const double a = turn * 3.14159265358979323846 / 180;
    CGAL::Anisotropic_fairing::internal::Control_matrix Y(4, 3);
    Y << 0, 0, 0,  1, 0, 0,  0.5, 1, 0,  0.5, -std::cos(a), std::sin(a);
    std::vector<CGAL::Anisotropic_fairing::internal::Triangle_topology::Face> faces = { { { 0, 1, 2 } }, { { 1, 0, 3 } } };
    const CGAL::Anisotropic_fairing::internal::Triangle_topology topo(4, faces, 0, false);
    const std::size_t folded = CGAL::Anisotropic_fairing::internal::count_folded_edges(topo, 2, Y, { 0, 0 }, { 1.0 });
    std::printf("two triangles whose normals turn by %.0f degrees: %zu folded edge(s)\n", turn, folded);
    AF_CHECK(folded == (turn > 120 ? 1u : 0u), "an edge counts as folded exactly when its faces turn by more than 120 degrees");
  }
  // the step control sees the fold mean-curvature flow makes of a coarse scan with a huge time step
  Mesh bunny;
  AF_CHECK(CGAL::IO::read_polygon_mesh(std::string(DATA) + "/bunny.off", bunny), "read bunny.off");
  Mesh m = bunny;
  const AF::Fairing_report r = AF::anisotropic_fairing(m, AF::parameters::relative_time_step(0.1).number_of_iterations(3u)
                                                             .stopping_criteria(AF::Stopping_criteria::none()));
  check_sound("bunny, tau = 0.1 l^2 x 3 steps", bunny, m, r);
  AF_CHECK(r.rejected_steps > 0, "the folding steps were rejected");
}

// a flat n x n grid of vertices, two triangles a square; the halfedge of the diagonal of square (i, j)
namespace AFI = CGAL::Anisotropic_fairing::internal;
struct Grid
{
  static constexpr int n = 20;
  std::vector<AFI::Triangle_topology::Face> faces;
  Grid()
  {
    for(int j = 0; j + 1 < n; ++j)
      for(int i = 0; i + 1 < n; ++i)
      {
        const int v = j * n + i;
        faces.push_back({ { v, v + 1, v + n + 1 } });
        faces.push_back({ { v, v + n + 1, v + n } });
      }
  }
  static int diagonal(int i, int j) { return 3 * 2 * (j * (n - 1) + i) + 2; }   // (v + n + 1, v) in the first face
};

void known_fold_places()
{
  // A candidate with more folds than the accepted surface had near-folds is rejected, unless all of them lie
  // where the accepted surface or the input was folded (within two rings): an input's tangle
  const Grid grid;
  const AFI::Triangle_topology topo(std::size_t(Grid::n * Grid::n), grid.faces, 0, false);
  const std::size_t real_faces = grid.faces.size();
  AF_CHECK(topo.opposite(Grid::diagonal(2, 2)) >= 0, "the diagonal is an interior edge");
  AFI::Surface_soundness accepted, candidate;
  accepted.folded_edges = accepted.bent_edges = 1;
  accepted.folded_edge_list = { Grid::diagonal(2, 2) };
  const std::vector<int> input_folds = { Grid::diagonal(14, 14) };
  const auto known = [&](const AFI::Surface_soundness& c) {
    AFI::Fold_sites sites(topo, real_faces);
    sites.add(accepted.folded_edge_list, accepted.statistics.reversed_face_list);
    sites.add(input_folds, {});
    sites.widen();
    return sites.hold(c);
  };
  const AFI::Lowest_curvature lowest(accepted.statistics);
  struct Case { std::vector<int> edges; std::vector<std::size_t> faces; bool sound; const char* what; };
  const std::vector<Case> cases = {
    { { Grid::diagonal(2, 2), Grid::diagonal(3, 3) }, {}, true, "two folds at and next to the accepted surface's fold" },
    { { Grid::diagonal(2, 2), Grid::diagonal(14, 15) }, { 2 * std::size_t(13 * (Grid::n - 1) + 13) }, true,
      "folds and a reversed face at the accepted fold and near the input's" },
    { { Grid::diagonal(2, 2), Grid::diagonal(8, 8) }, {}, false, "a fold four rings away from every known place" },
    { { Grid::diagonal(2, 2) }, { 2 * std::size_t(8 * (Grid::n - 1) + 8) }, false, "a face reversed away from them" },
  };
  for(const Case& c : cases)
  {
    candidate = AFI::Surface_soundness();
    candidate.folded_edges = c.edges.size();
    candidate.folded_edge_list = c.edges;
    candidate.statistics.reversed_faces = c.faces.size();
    candidate.statistics.reversed_face_list = c.faces;
    std::string why;
    const AFI::Step_verdict v = AFI::judge_step(accepted, accepted, 1, lowest, candidate, why, known);
    const AFI::Step_verdict counted = AFI::judge_step(accepted, accepted, 1, lowest, candidate, why);
    std::printf("%s: %s (by number only: %s)\n", c.what, v == AFI::Step_verdict::SOUND ? "sound" : "unsound",
                counted == AFI::Step_verdict::SOUND ? "sound" : "unsound");
    AF_CHECK((v == AFI::Step_verdict::SOUND) == c.sound, c.what);
    AF_CHECK(counted == AFI::Step_verdict::UNSOUND, "more folds than near-folds: unsound by number");
    AF_CHECK(AFI::edges_folded(accepted, 1, candidate, why, known) == (c.edges.size() > 1 && !c.sound), "the edges alone, judged the same way");
  }
}

void stress_rows()
{
  Mesh bunny;
  CGAL::IO::read_polygon_mesh(std::string(DATA) + "/bunny.off", bunny);
  {
    // a time step whose system overflows in double precision: the surface collapses at once
    Mesh m = bunny;
    const AF::Fairing_report r = AF::anisotropic_fairing(m, AF::parameters::time_step(1e300));
    check_sound("bunny, tau = 1e300", bunny, m, r);
    AF_CHECK(!r.succeeded(), "tau = 1e300 is not a success (nothing sound can be reached)");
  }
  {
    // a long fidelity run: int |H|^2 stays bounded or the run ends early
    Mesh m = bunny;
    const AF::Fairing_report r = AF::anisotropic_fairing(m, AF::parameters::relative_fidelity_weight(1000.0).number_of_iterations(150u)
                                                               .stopping_criteria(AF::Stopping_criteria::none()));
    check_sound("bunny, relative fidelity 1000 x 150 steps", bunny, m, r);
    double lowest = r.initial.H_integral;
    for(const AF::Fairing_step& s : r.steps) lowest = std::min(lowest, s.H_integral);
    const double last = r.steps.empty() ? r.initial.H_integral : r.steps.back().H_integral;
    std::printf("  int |H|^2: initial %.4g, lowest %.4g, last %.4g\n", r.initial.H_integral, lowest, last);
    AF_CHECK(last <= 4 * lowest, "int |H|^2 ends within 4 times its lowest value");
  }
}

void noise_free(const std::string& file, double bound_percent)
{
  Mesh input;
  AF_CHECK(CGAL::IO::read_polygon_mesh(file, input), "read " + file);
  Mesh m = input;
  const AF::Fairing_report r = AF::anisotropic_fairing(m);
  check_sound(file.c_str(), input, m, r);
  const double moved = 100 * mean_displacement(input, m) / bbox_diagonal(input);
  std::printf("  noise %.3g h, mean displacement %.4f%% of the bounding-box diagonal (bound %.2f%%)\n", r.noise_level, moved, bound_percent);
  AF_CHECK(r.succeeded() && r.automatic_parameters, "the default run succeeds with automatic parameters");
  AF_CHECK(moved <= bound_percent, "a noise-free mesh is left nearly alone");
  AF_CHECK(folded_edges(m) <= folded_edges(input), "no new folded edge");
  // a run that takes no step assembles no anisotropic operator (its M_eps and L(D)): the input's area and
  // curvature integral are known, the tensor's energy is not
  if(r.steps.empty())
    AF_CHECK(!std::isfinite(r.initial.energy) && r.initial.area > 0 && std::isfinite(r.initial.H_integral),
             "no step: the tensor's operator is not assembled");
}

void two_spheres()
{
  // a unit sphere and a sphere of radius 1000 in one mesh: each faired as if it were alone
  AF_test::Triangle_soup small = AF_test::icosphere_soup(3), both = small;
  const std::size_t n = small.points.size();
  for(const auto& p : small.points) both.points.push_back({ { 1000 * p[0] + 5000, 1000 * p[1], 1000 * p[2] } });
  for(const auto& f : small.faces) both.faces.push_back({ { f[0] + n, f[1] + n, f[2] + n } });
  Mesh alone, pair;
  AF_test::soup_to_mesh(small, alone);
  AF_test::soup_to_mesh(both, pair);
  const auto np = AF::parameters::relative_time_step(1e-3).number_of_iterations(10u).stopping_criteria(AF::Stopping_criteria::none());
  Mesh a = alone, b = pair;
  const AF::Fairing_report ra = AF::anisotropic_fairing(a, np), rb = AF::anisotropic_fairing(b, np);
  double radius = 0, difference = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const K::Point_3 p = b.point(Mesh::Vertex_index(std::uint32_t(i)));
    radius += std::sqrt(CGAL::squared_distance(p, K::Point_3(0, 0, 0))) / double(n);
    difference = std::max(difference, std::sqrt(CGAL::squared_distance(p, a.point(Mesh::Vertex_index(std::uint32_t(i))))));
  }
  std::printf("two spheres (radius 1 and 1000), 10 steps of 1e-3 l^2: %s, %zu components, small sphere's mean radius %.6f, "
              "largest difference to the small sphere faired alone %.3g\n", AF::to_string(rb.status), rb.components, radius, difference);
  AF_CHECK(ra.succeeded() && rb.succeeded() && rb.components == 2, "both runs succeed, two components seen");
  AF_CHECK(radius > 0.95, "the small sphere keeps its size");
  AF_CHECK(difference < 1e-6, "the small sphere is faired as if it were alone");
  Mesh c = pair;
  const AF::Fairing_report rc = AF::anisotropic_fairing(c);
  check_sound("two spheres, default run", pair, c, rc);
}

void zero_area_faces()
{
  // coordinates rounded to 8 bits of the bounding box: coincident and collinear vertices
  Mesh m;
  CGAL::IO::read_polygon_mesh(std::string(DATA) + "/camelhead.off", m);
  const CGAL::Bbox_3 b = PMP::bbox(m);
  const double q = (b.xmax() - b.xmin()) / 256;
  for(auto v : m.vertices())
  {
    const K::Point_3 p = m.point(v);
    m.point(v) = K::Point_3(std::round(p.x() / q) * q, std::round(p.y() / q) * q, std::round(p.z() / q) * q);
  }
  std::size_t zero = 0;
  for(auto f : m.faces()) zero += PMP::face_area(f, m) == 0 ? 1 : 0;
  Mesh out = m;
  const AF::Fairing_report r = AF::anisotropic_fairing(out);
  std::printf("camel head quantised to 8 bits: %zu zero-area faces; noise %.3g h\n", zero, r.noise_level);
  check_sound("quantised camel head, default run", m, out, r);
  AF_CHECK(zero > 100, "the quantised mesh has many zero-area faces");
  AF_CHECK(r.succeeded() && !r.steps.empty(), "a scan with zero-area faces is faired, not refused");
  // a mesh with no surface at all is refused with a clear status
  Mesh flat = m;
  for(auto v : flat.vertices()) flat.point(v) = K::Point_3(1, 2, 3);
  const AF::Fairing_report rf = AF::anisotropic_fairing(flat);
  std::printf("all vertices at one point: %s: %s\n", AF::to_string(rf.status), rf.message.c_str());
  AF_CHECK(rf.status == AF::Fairing_status::DEGENERATE_METRIC, "a mesh with no area is refused as degenerate");
}

void noise_estimate()
{
  // Gaussian noise of known deviation along the normals of a fine sphere and of the camel head
  for(const char* which : { "sphere", "camelhead" })
    for(double sigma : { 0.2, 0.4 })
    {
      Mesh m;
      if(std::string(which) == "sphere") AF_test::make_icosphere(m, 5);
      else CGAL::IO::read_polygon_mesh(std::string(DATA) + "/camelhead.off", m);
      const double h = mean_edge(m);
      auto normals = m.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:n").first;
      PMP::compute_vertex_normals(m, normals);
      std::mt19937 rng(7);
      std::normal_distribution<double> gauss(0, sigma * h);
      for(auto v : m.vertices()) m.point(v) = m.point(v) + gauss(rng) * normals[v];
      const AF::Fairing_report r = AF::anisotropic_fairing(m, AF::parameters::number_of_iterations(0u));
      const double estimate = r.noise_deviation / h;
      std::printf("%s with noise %.2f h: estimated %.3f h\n", which, sigma, estimate);
      AF_CHECK(std::abs(estimate / sigma - 1) <= 0.25, "the noise estimate is within 25% of the generated noise");
    }
}

double normal_error(const Mesh& m, const Mesh& original)
{
  double error = 0;
  for(auto f : m.faces())
    error += std::acos(std::max(-1.0, std::min(1.0, PMP::compute_face_normal(f, m) * PMP::compute_face_normal(f, original)))) / double(num_faces(m));
  return error * 180 / 3.14159265358979323846;
}

// The report's runs (Fairing_report::runs): each timed, their time within the call's, exactly one kept, whose
// steps and stop are the report's, and the lowest estimate is the kept one's
void check_runs(const char* name, const AF::Fairing_report& r, std::size_t expected_runs)
{
  std::size_t kept = 0;
  double seconds = 0, lowest = std::numeric_limits<double>::infinity();
  const AF::Fairing_run* kept_run = nullptr;
  for(const AF::Fairing_run& run : r.runs)
  {
    std::printf("  %s: run '%s': %zu steps, %.3f s, estimate %g%s\n", name, run.name.c_str(), run.steps, run.seconds,
                run.estimate, run.kept ? ", kept" : "");
    seconds += run.seconds;
    if(run.kept) { ++kept; kept_run = &run; }
    if(std::isfinite(run.estimate)) lowest = std::min(lowest, run.estimate);
    AF_CHECK(run.seconds > 0, "every run is timed");
  }
  AF_CHECK(r.runs.size() == expected_runs, "the report lists every run the call made");
  AF_CHECK(seconds <= r.total_seconds, "the runs' time is within the call's");
  AF_CHECK(kept == 1 && kept_run->steps == r.steps.size() && kept_run->stop_reason == r.stop_reason,
           "exactly one run is kept, the one whose steps the report gives");
  AF_CHECK(expected_runs == 1 || kept_run->estimate == lowest, "the kept run has the lowest estimate");
}

void denoising_pair()
{
  Mesh noisy, original;
  CGAL::IO::read_polygon_mesh(std::string(DATA) + "/fandisk0.3_noisy.obj", noisy);
  CGAL::IO::read_polygon_mesh(std::string(DATA) + "/fandisk0.3_original.obj", original);
  Mesh m = noisy, isotropic = noisy;
  const AF::Fairing_report r = AF::anisotropic_fairing(m);
  const double error = normal_error(m, original);
  std::printf("Fandisk0.3, default run: %.2f degrees mean normal error (noisy 28.42), %zu steps, %s; %s\n", error, r.steps.size(),
              AF::to_string(r.stop_reason), r.choices.c_str());
  check_sound("Fandisk0.3 default", noisy, m, r);
  AF_CHECK(r.stop_reason == AF::Stop_reason::NOISE_LEVEL, "the default run stops at the noise level");
  AF_CHECK(error < 4.0, "the default run denoises Fandisk0.3 below 4 degrees");
  // of the candidates, the one with the lowest estimated error (Tensor_selection.h) is kept: on a CAD part
  // the anisotropic one, which is the better against the truth
  AF::anisotropic_fairing(isotropic, AF::parameters::diffusion_tensor(AF::Isotropic_diffusion_tensor()));
  std::printf("  the isotropic run: %.2f degrees\n", normal_error(isotropic, original));
  AF_CHECK(r.selected_tensor == "anisotropic", "the anisotropic result is kept on Fandisk0.3");
  AF_CHECK(error < normal_error(isotropic, original), "the kept result is the better one");
  // the uniform flow, the isotropic one (its carried estimate a lower bound, above the lowest: none), the
  // anisotropic one last, and its probe replaying its steps on an operator of its own: its estimate
  check_runs("Fandisk0.3 default", r, 4);
  AF_CHECK(r.runs[0].name == "uniform fourth-order flow" && std::isfinite(r.runs[0].estimate) &&
             r.runs[1].name == "isotropic flow" && !std::isfinite(r.runs[1].estimate) &&
             r.runs[2].name == "anisotropic flow" && r.runs[2].kept &&
             r.runs[3].name == "anisotropic flow on the probed input" && r.runs[3].steps == r.runs[2].steps &&
             !std::isfinite(r.runs[3].estimate), "the runs are named, in order; the probe takes the run's steps");
  // a step budget of the user's: the anisotropic flow first, the same result
  Mesh budget = noisy;
  const AF::Fairing_report b = AF::anisotropic_fairing(budget, AF::parameters::number_of_iterations(200));
  check_runs("Fandisk0.3, 200 steps given", b, 4);
  AF_CHECK(b.runs[0].name == "anisotropic flow" && b.runs[0].kept, "the anisotropic flow first");
  double moved = 0;
  for(auto v : m.vertices()) moved = std::max(moved, std::sqrt(CGAL::squared_distance(m.point(v), budget.point(v))));
  AF_CHECK(moved == 0.0, "the same result");
  Mesh once = noisy;
  const AF::Fairing_report one = AF::anisotropic_fairing(
    once, AF::parameters::diffusion_tensor(AF::Isotropic_diffusion_tensor()).number_of_iterations(2));
  check_runs("one isotropic run", one, 1);
}

// camelhead.off (clean) with Gaussian noise of sigma_h mean edge lengths along its vertex normals (noisy)
void noisy_camel_head(double sigma_h, unsigned seed, Mesh& clean, Mesh& noisy)
{
  CGAL::IO::read_polygon_mesh(std::string(DATA) + "/camelhead.off", clean);
  noisy = clean;
  const double h = mean_edge(noisy);
  auto normals = noisy.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:n").first;
  PMP::compute_vertex_normals(noisy, normals);
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0, sigma_h * h);
  for(auto v : noisy.vertices()) noisy.point(v) = noisy.point(v) + gauss(rng) * normals[v];
  noisy.remove_property_map(normals);
}

void tensor_selection()
{
  // on a graded organic scan with strong noise (the CAD case: denoising_pair), the uniform tensor's
  // fourth-order result has the lowest estimated error and is kept: it is that run's own, and closer to
  // the truth than the cotangent flow's and the uniform second-order one's
  Mesh clean, noisy;
  noisy_camel_head(0.5, 11, clean, noisy);
  Mesh kept = noisy, isotropic = noisy, uniform = noisy, uniform2 = noisy;
  const AF::Fairing_report c = AF::anisotropic_fairing(kept);
  AF::anisotropic_fairing(isotropic, AF::parameters::diffusion_tensor(AF::Isotropic_diffusion_tensor()));
  AF::anisotropic_fairing(uniform, AF::parameters::diffusion_tensor(AF::Uniform_diffusion_tensor()).flow_order(4));
  AF::anisotropic_fairing(uniform2, AF::parameters::diffusion_tensor(AF::Uniform_diffusion_tensor()));
  std::printf("camel head with noise 0.5 h: kept the %s result (order %d), %.2f degrees (noisy %.2f, cotangent flow %.2f, uniform "
              "second-order flow %.2f); %s\n", c.selected_tensor.c_str(), c.flow_order, normal_error(kept, clean),
              normal_error(noisy, clean), normal_error(isotropic, clean), normal_error(uniform2, clean), c.choices.c_str());
  check_sound("camel head with noise 0.5 h", noisy, kept, c);
  AF_CHECK(c.selected_tensor == "uniform" && c.flow_order == 4, "the uniform fourth-order flow's result is kept on the noisy camel head");
  AF_CHECK(byte_identical(coordinates(kept), coordinates(uniform)), "the kept result is that run's, unchanged");
  AF_CHECK(normal_error(kept, clean) < normal_error(isotropic, clean), "the kept result beats the cotangent flow");
  AF_CHECK(normal_error(kept, clean) < normal_error(uniform2, clean), "the kept result beats the uniform second-order flow");
}

void fourth_order_noise_removed()
{
  // the fourth-order flow barely shrinks, so its displacement levels off once the noise is gone: asked to
  // move three times the noise, it must end on its own (noise_removed), long before the step limit, with
  // the noise removed and the shape kept (closer to the truth than the noisy input by far)
  Mesh clean, noisy;
  noisy_camel_head(0.2, 5, clean, noisy);
  AF::Stopping_criteria far = AF::Stopping_criteria::automatic();
  far.noise_discrepancy = 3;
  Mesh faired = noisy;
  const AF::Fairing_report r = AF::anisotropic_fairing(faired, AF::parameters::diffusion_tensor(AF::Uniform_diffusion_tensor())
                                                                   .flow_order(4).stopping_criteria(far));
  std::printf("camel head 0.2 h, fourth order asked for 3 x the noise: %s after %zu steps, displacement %.3g h (noise %.3g h), "
              "%.2f degrees (noisy %.2f)\n", AF::to_string(r.stop_reason), r.steps.size(), r.noise_displacement, r.noise_level,
              normal_error(faired, clean), normal_error(noisy, clean));
  check_sound("camel head 0.2 h, fourth order", noisy, faired, r);
  AF_CHECK(r.stop_reason == AF::Stop_reason::NOISE_REMOVED && r.steps.size() < 50, "the fourth-order run ends where the noise is removed");
  AF_CHECK(r.noise_displacement < 3 * r.noise_level, "short of the level it was asked for");
  AF_CHECK(normal_error(faired, clean) < 0.25 * normal_error(noisy, clean), "the noise is removed");
}

void local_time_scale_of_a_graded_grid()
{
  // a flat grid of a x b cells, cut by one diagonal each, whose cells are half as wide on the right:
  // away from the change and from the border (more than the three rings the lengths are averaged over),
  // s_i = (h_i / h)^2 exactly, h_i the mean of a vertex's six edges, h the mean over the faces' edges
  namespace AI = CGAL::Anisotropic_fairing::internal;
  const int W = 24, H = 14;
  const double a = 1.0, b = 0.8;
  auto x_of = [&](int j) { return j <= W / 2 ? j * a : (W / 2) * a + (j - W / 2) * a / 2; };
  AI::Control_matrix X((W + 1) * (H + 1), 3);
  for(int k = 0; k <= H; ++k)
    for(int j = 0; j <= W; ++j) X.row(k * (W + 1) + j) << x_of(j), k * b, 0.0;
  std::vector<AI::Triangle_topology::Face> faces;
  for(int k = 0; k < H; ++k)
    for(int j = 0; j < W; ++j)
    {
      const int v = k * (W + 1) + j;
      faces.push_back({ { v, v + 1, v + W + 2 } });
      faces.push_back({ { v, v + W + 2, v + W + 1 } });
    }
  double sum = 0;
  for(const auto& f : faces)
    for(int e = 0; e < 3; ++e) sum += (X.row(f[e]) - X.row(f[(e + 1) % 3])).norm();
  const std::vector<double> edge = { sum / double(3 * faces.size()) };
  const AI::Triangle_topology topo(std::size_t(X.rows()), faces, 0, false);
  const AI::Mesh_components components = AI::make_mesh_components(topo, std::size_t(X.rows()), faces.size());
  const std::vector<double> s = AI::local_time_scale(topo, faces.size(), X, components, edge);
  const double left = (2 * a + 2 * b + 2 * std::hypot(a, b)) / 6, right = (a + 2 * b + 2 * std::hypot(a / 2, b)) / 6;
  double worst = 0;
  for(int k = 5; k <= H - 5; ++k)
  {
    const int v = k * (W + 1);
    worst = std::max(worst, std::abs(s[std::size_t(v + 5)] / std::pow(left / edge[0], 2) - 1));
    worst = std::max(worst, std::abs(s[std::size_t(v + W - 5)] / std::pow(right / edge[0], 2) - 1));
  }
  std::printf("local time scale of a graded grid: coarse %.4f, fine %.4f, largest relative error %.1e\n", s[5 * (W + 1) + 5],
              s[5 * (W + 1) + W - 5], worst);
  AF_CHECK(worst < 1e-12, "s_i = (h_i / h)^2 away from the change of density");
  X *= 1000;   // relative to the mesh's own edge length: the same at any size
  const std::vector<double> scaled = AI::local_time_scale(topo, faces.size(), X, components, { edge[0] * 1000 });
  for(std::size_t i = 0; i < s.size(); ++i) worst = std::max(worst, std::abs(scaled[i] / s[i] - 1));
  AF_CHECK(worst < 1e-12, "the local time scale does not depend on the mesh's size");
}

void local_time_scale_on_a_graded_scan()
{
  // the automatic isotropic run (time step 0.3 h_i^2) against the same run with one time step 0.3 h^2:
  // on the graded camel head the ears and nostrils keep their shape
  Mesh clean, noisy;
  noisy_camel_head(0.2, 7, clean, noisy);
  Mesh local = noisy, global = noisy;
  const AF::Fairing_report r = AF::anisotropic_fairing(local, AF::parameters::diffusion_tensor(AF::Isotropic_diffusion_tensor()));
  const double h = r.mean_edge_length;
  const AF::Fairing_report g = AF::anisotropic_fairing(global, AF::parameters::diffusion_tensor(AF::Isotropic_diffusion_tensor())
                                                                   .time_step(0.3 * h * h).number_of_iterations(100)
                                                                   .stopping_criteria(AF::Stopping_criteria::automatic()));
  std::printf("camel head with noise 0.2 h, isotropic: %.2f degrees with the local time step, %.2f with one time step (noisy %.2f)\n",
              normal_error(local, clean), normal_error(global, clean), normal_error(noisy, clean));
  check_sound("camel head, local time step", noisy, local, r);
  AF_CHECK(r.stop_reason == AF::Stop_reason::NOISE_LEVEL && g.stop_reason == AF::Stop_reason::NOISE_LEVEL, "both end at the noise level");
  AF_CHECK(normal_error(local, clean) < 0.95 * normal_error(global, clean), "the local time step denoises the graded scan better");
}

int main(int argc, char** argv)
{
  DATA = argc > 1 ? argv[1] : "data";
  constructed_fold();
  known_fold_places();
  stress_rows();
  noise_free(DATA + "/armadillo.obj", 0.05);
  noise_free(DATA + "/camelhead.off", 0.05);
  two_spheres();
  zero_area_faces();
  noise_estimate();
  denoising_pair();
  tensor_selection();
  fourth_order_noise_removed();
  local_time_scale_of_a_graded_grid();
  local_time_scale_on_a_graded_scan();
  return AF_test::report();
}
