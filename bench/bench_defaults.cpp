// Safe automatic defaults: how close the library's default run, anisotropic_fairing(mesh) with no
// named parameters, gets to the best explicit settings, and whether it ever folds the surface.
//
// Cases (noisy mesh + noise-free original of identical connectivity):
//   - every <DATA_DIR>/denoising/<Name>/{Noisy,Original}.obj (the scans have borders);
//   - generated from clean models: Gaussian noise of sigma = 0.2 h and 0.5 h along the area-weighted vertex
//     normals of the original (h = its mean edge length; std::mt19937, the seed is printed), and
//     quantisation of the coordinates to 10 bits per axis of the bounding box;
//   - noise-free default runs on armadillo.obj and camelhead.off (how much a clean mesh is changed).
// Per case: the default run (mean face-normal angle error to the original, status, stop reason, steps,
// seconds, folded edges = interior edges whose two faces' normals make an angle > 120 deg), the best of
// a sweep of our explicit settings (isotropic and anisotropic tensor, incremental one-step calls as in
// bench_denoising, Loop limit positions evaluated) and the best of a sweep of CGAL's smooth_shape.
// A sweep cell "e*n" had n steps that the library shortened below tau (a rejected unsound step), so it
// is not at tau x k; one single k-step call at each best cell checks that the incremental sweep agrees.
// sigma/h is the noise actually added: RMS of (noisy - original) along the original's area-weighted
// normals, over the original's mean edge length (for the denoising pairs it is measured the same way).
//
// usage: bench_defaults [DATA_DIR=<repo>/../shared/data] [CASE_SUBSTRING] [PARTS=dsn]
//   PARTS: d = default run, s = sweeps (ours and smooth_shape), n = noise-free default runs
//   case names: the pair directories (Fandisk0.3, ...), "<model> gauss0.2", "<model> gauss0.5", "<model> quant10", "<model> clean"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>
#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include "bench_mesh_measures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#ifndef AF_SOURCE_DIR
#define AF_SOURCE_DIR "."
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace AF = CGAL::Anisotropic_fairing;
namespace PMP = CGAL::Polygon_mesh_processing;

static const double pi = 3.14159265358979323846;
static const double nan_value = std::numeric_limits<double>::quiet_NaN();

std::string fmt(const char* f, double x)
{
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

// Keeps the file's vertex and face order, so that Noisy and Original correspond by index.
bool read_obj_in_order(const std::string& path, Mesh& mesh)
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!CGAL::IO::read_OBJ(path, points, polygons) || !PMP::is_polygon_soup_a_polygon_mesh(polygons)) return false;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return num_vertices(mesh) == points.size() && num_faces(mesh) == polygons.size();
}

Vector face_normal(const Mesh& m, Mesh::Face_index f)   // length = 2 area
{
  const Mesh::Halfedge_index h = m.halfedge(f);
  const Point& a = m.point(m.source(h));
  return CGAL::cross_product(m.point(m.target(h)) - a, m.point(m.target(m.next(h))) - a);
}

std::vector<Vector> face_normals(const Mesh& m)
{
  std::vector<Vector> n;
  n.reserve(num_faces(m));
  for(Mesh::Face_index f : m.faces()) n.push_back(face_normal(m, f));
  return n;
}

// Area-weighted unit vertex normals (CGAL 5.5's compute_vertex_normals weighs by visibility, not area).
std::vector<Vector> area_weighted_normals(const Mesh& m)
{
  std::vector<Vector> n(num_vertices(m), CGAL::NULL_VECTOR);
  for(Mesh::Face_index f : m.faces())
  {
    const Vector fn = face_normal(m, f);
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(m.halfedge(f), m)) n[v.idx()] = n[v.idx()] + fn;
  }
  for(Vector& v : n)
    if(v.squared_length() > 0) v = v / std::sqrt(v.squared_length());
  return n;
}

// Mean angle (degrees) between corresponding face normals; NaN if a position is not finite.
double normal_error(const Mesh& m, const std::vector<Vector>& reference)
{
  for(Mesh::Vertex_index v : m.vertices())
  {
    const Point& p = m.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) return nan_value;
  }
  double sum = 0;
  std::size_t i = 0;
  for(Mesh::Face_index f : m.faces())
  {
    const Vector n = face_normal(m, f);
    const Vector& r = reference[i++];
    sum += std::atan2(std::sqrt(CGAL::cross_product(n, r).squared_length()), n * r);
  }
  return sum / double(num_faces(m)) * 180.0 / pi;
}

// Interior edges whose two faces' normals make an angle > 120 degrees (cos < -1/2): folds.
std::size_t folded_edges(const Mesh& m)
{
  std::size_t count = 0;
  for(Mesh::Edge_index e : m.edges())
  {
    const Mesh::Halfedge_index h = m.halfedge(e);
    if(m.is_border(h) || m.is_border(m.opposite(h))) continue;
    const Vector a = face_normal(m, m.face(h)), b = face_normal(m, m.face(m.opposite(h)));
    if(a * b < -0.5 * std::sqrt(a.squared_length() * b.squared_length())) ++count;
  }
  return count;
}

double bbox_diagonal(const Mesh& m)
{
  const CGAL::Bbox_3 b = PMP::bbox(m);
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) + CGAL::square(b.zmax() - b.zmin()));
}

double limit_error(const Mesh& control, const std::vector<Vector>& reference)
{
  Mesh e = control;
  AF::Loop_limit_surface<Mesh>(control).limit_positions(e.points());
  return normal_error(e, reference);
}

struct Default_run
{
  bool run = false;
  std::string status = "-", stop = "-";
  std::size_t steps = 0, folded = 0;
  double seconds = 0, error = nan_value;
  Mesh result;
};

// The library's default: no named parameters, the mesh is overwritten with the limit positions.
Default_run default_run(const Mesh& input)
{
  Default_run d;
  d.run = true;
  d.result = input;
  CGAL::Real_timer timer;
  timer.start();
  try
  {
    const AF::Fairing_report r = AF::anisotropic_fairing(d.result);
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
  void consider(double e, const std::string& s, double t = 0, int k = 0, double th = 0, double pf = 0)
  {
    if(std::isfinite(e) && !(e >= error)) { error = e; setting = s; tau = t; steps = k; threshold = th; prefilter = pf; }
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
    const double e = limit_error(m, reference);
    errors.push_back(std::isfinite(e) ? e : std::numeric_limits<double>::infinity());
    cells += " | " + std::to_string(k) + ": " + fmt("%.2f", e) + (shortened ? "*" + std::to_string(shortened) : "");
    best.consider(e, label + " x " + std::to_string(k) + (shortened ? " (" + std::to_string(shortened) + " shortened)" : ""),
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
      s.smooth.consider(e, "tau_rel " + fmt("%g", tr) + " x " + std::to_string(k));
      if(rising_twice(errors)) break;
    }
    std::printf("  %-40s%s\n", ("smooth_shape tau_rel " + fmt("%g", tr)).c_str(), cells.c_str());
  }
  s.seconds = timer.time();
  return s;
}

struct Case
{
  std::string name;
  std::function<bool(Case&)> load;   // fills the meshes; false: unreadable or unsuitable
  Mesh noisy, original;
  std::string note;
  double nominal_sigma = nan_value;  // generated cases: the sigma asked for, in units of h
};

// Reads a clean model, triangulated if needed; `closed` refuses a mesh with borders.
bool read_clean(const std::string& path, Mesh& m, std::string& note, bool closed = false)
{
  if(!CGAL::IO::read_polygon_mesh(path, m) || num_faces(m) == 0) { note = "cannot read " + path; return false; }
  if(!CGAL::is_triangle_mesh(m))
  {
    if(closed) { note = "not a triangle mesh"; return false; }
    PMP::triangulate_faces(m);
    note = "triangulated; ";
  }
  if(closed && !CGAL::is_closed(m)) { note = "has borders"; return false; }
  return true;
}

void add_gaussian(Case& c, double relative_sigma, unsigned seed)
{
  const std::vector<Vector> n = area_weighted_normals(c.original);
  const double sigma = relative_sigma * mean_edge_length(c.original);
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, sigma);
  c.noisy = c.original;
  for(Mesh::Vertex_index v : c.noisy.vertices()) c.noisy.point(v) = c.noisy.point(v) + gauss(rng) * n[v.idx()];
  c.nominal_sigma = relative_sigma;
  c.note += "Gaussian sigma " + std::to_string(relative_sigma).substr(0, 3) + " h along the normals, seed " + std::to_string(seed);
}

void add_quantisation(Case& c)
{
  const CGAL::Bbox_3 b = PMP::bbox(c.original);
  double step[3], sum2 = 0;
  for(int a = 0; a < 3; ++a) { step[a] = (b.max(a) - b.min(a)) / 1023.0; sum2 += step[a] * step[a]; }
  c.noisy = c.original;
  for(Mesh::Vertex_index v : c.noisy.vertices())
  {
    const Point& p = c.noisy.point(v);
    double q[3];
    for(int a = 0; a < 3; ++a) q[a] = step[a] > 0 ? b.min(a) + std::round((p[a] - b.min(a)) / step[a]) * step[a] : p[a];
    c.noisy.point(v) = Point(q[0], q[1], q[2]);
  }
  // uniform rounding error: variance step^2/12 per axis (mean over the axes, for a random normal)
  c.nominal_sigma = std::sqrt(sum2 / 3 / 12) / mean_edge_length(c.original);
  c.note += "10-bit quantisation, steps " + fmt("%.3g", step[0]) + ", " + fmt("%.3g", step[1]) + ", " + fmt("%.3g", step[2]);
}

// RMS of the displacement noisy - original along the original's normals, in units of its h.
double measured_sigma(const Case& c)
{
  const std::vector<Vector> n = area_weighted_normals(c.original);
  double sum = 0;
  for(Mesh::Vertex_index v : c.original.vertices()) sum += CGAL::square((c.noisy.point(v) - c.original.point(v)) * n[v.idx()]);
  return std::sqrt(sum / double(num_vertices(c.original))) / mean_edge_length(c.original);
}

std::string folded_str(std::size_t before, std::size_t after)
{
  return std::to_string(before) + " / " + std::to_string(after) + (after > before ? " FOLDED" : "");
}

int main(int argc, char** argv)
{
  const std::string dir = argc > 1 && argv[1][0] ? argv[1] : std::string(AF_SOURCE_DIR) + "/../shared/data";
  const std::string only = argc > 2 ? argv[2] : "";
  const std::string parts = argc > 3 && argv[3][0] ? argv[3] : "dsn";
  if(parts.find_first_not_of("dsn") != std::string::npos) { std::fprintf(stderr, "PARTS: letters of d, s, n\n"); return 1; }
  const bool part_d = parts.find('d') != std::string::npos, part_s = parts.find('s') != std::string::npos,
             part_n = parts.find('n') != std::string::npos;
  CGAL::Real_timer wall;
  wall.start();

  // noisy cases: the denoising pairs, then the generated ones (the seed depends on the case index)
  std::vector<Case> cases;
  std::vector<std::string> pairs;
  if(std::filesystem::is_directory(dir + "/denoising"))
    for(const auto& entry : std::filesystem::directory_iterator(dir + "/denoising"))
      if(std::filesystem::exists(entry.path() / "Noisy.obj") && std::filesystem::exists(entry.path() / "Original.obj"))
        pairs.push_back(entry.path().filename().string());
  std::sort(pairs.begin(), pairs.end());
  for(const std::string& p : pairs)
    cases.push_back({p, [dir, p](Case& c) {
                       const std::string base = dir + "/denoising/" + p;
                       if(!read_obj_in_order(base + "/Noisy.obj", c.noisy) || !read_obj_in_order(base + "/Original.obj", c.original))
                       { c.note = "cannot read " + base; return false; }
                       if(num_vertices(c.noisy) != num_vertices(c.original) || num_faces(c.noisy) != num_faces(c.original))
                       { c.note = "Noisy and Original differ in size"; return false; }
                       return true;
                     }});
  const unsigned seed_base = 20261121u;
  const std::vector<std::string> models = {"bunny-closed.off", "camelhead.off", "face.obj", "rocker-arm.obj", "fandisk.off"};
  for(std::size_t i = 0; i < models.size(); ++i)
  {
    const std::string file = models[i], stem = file.substr(0, file.rfind('.'));
    const bool closed = stem == "fandisk";   // taken only if it is a closed triangle mesh
    for(const double sigma : { 0.2, 0.5 })
    {
      const unsigned seed = seed_base + unsigned(cases.size());
      cases.push_back({stem + " gauss" + std::to_string(sigma).substr(0, 3), [dir, file, closed, sigma, seed](Case& c) {
                         if(!read_clean(dir + "/" + file, c.original, c.note, closed)) return false;
                         add_gaussian(c, sigma, seed);
                         return true;
                       }});
    }
    cases.push_back({stem + " quant10", [dir, file, closed](Case& c) {
                       if(!read_clean(dir + "/" + file, c.original, c.note, closed)) return false;
                       add_quantisation(c);
                       return true;
                     }});
  }

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
  if(part_d || part_s)
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
      if(part_s)
      {
        r.s = run_sweeps(c.noisy, reference);
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
