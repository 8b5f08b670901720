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

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>
#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include "bench_cases.h"   // the mesh types, reading in order, face normals, fmt

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#ifndef AF_SOURCE_DIR
#define AF_SOURCE_DIR "."
#endif

typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;
namespace AF = CGAL::Anisotropic_fairing;


struct Quality
{
  double angle = std::numeric_limits<double>::quiet_NaN();
  double dist = std::numeric_limits<double>::quiet_NaN();
  bool ok() const { return std::isfinite(angle) && std::isfinite(dist); }
};

struct Reference
{
  explicit Reference(const Mesh& m) : mesh(m), tree(faces(m).first, faces(m).second, m)
  {
    tree.accelerate_distance_queries();
    const CGAL::Bbox_3 b = PMP::bbox(m);
    diagonal = std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                         CGAL::square(b.zmax() - b.zmin()));
    for(Mesh::Face_index f : m.faces()) normals.push_back(face_normal(m, f));
  }
  const Mesh& mesh;
  Tree tree;
  double diagonal = 0;
  std::vector<Vector> normals;
};

// Faces correspond by index (the result is a copy of Noisy, read in file order like Original).
Quality evaluate(const Mesh& m, const Reference& ref)
{
  Quality q;
  double angle = 0, dist = 0;
  std::size_t i = 0;
  for(Mesh::Face_index f : m.faces())
  {
    const Vector n = face_normal(m, f);
    const Vector& r = ref.normals[i++];
    angle += std::atan2(std::sqrt(CGAL::cross_product(n, r).squared_length()), n * r);
  }
  for(Mesh::Vertex_index v : m.vertices())
  {
    const Point& p = m.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) return q;
    dist += std::sqrt(ref.tree.squared_distance(p));
  }
  q.angle = angle / double(num_faces(m)) * 180.0 / pi;
  q.dist = dist / double(num_vertices(m)) / ref.diagonal;
  return q;
}

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

std::vector<double> our_taus = {1e-4, 3e-4, 1e-3, 3e-3};   // TAUS argument overrides
const std::vector<int> step_counts = {1, 2, 3, 5, 10};
const std::vector<double> smooth_taus = {1e-5, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2};
const std::vector<double> smooth_literal_times = {1e-5, 1e-4, 1e-3, 1e-2};
std::vector<double> aniso_lambdas = {1, 2, 5, 10, 20, 50, 100};   // LAMBDAS argument overrides
std::vector<double> aniso_epsilons = {0};                          // EPSILONS argument overrides

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
// anisotropic Loop: the steps beyond 10 are taken only while the angle still falls (from 5 to 10, 10 to 20)
const std::vector<int> aniso_step_counts = {1, 2, 3, 5, 10, 20, 40};

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

Quality limit_quality(const Mesh& m, const Reference& ref)
{
  Mesh e = m;
  AF::Loop_limit_surface<Mesh>(m).limit_positions(e.points());
  return evaluate(e, ref);
}

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
      best.consider(q, prefix + "tau_rel " + fmt("%g", tr) + " x " + std::to_string(k), tr, k, lambda_rel, epsilon_rel);
      if(best10 && k <= 10)
        best10->consider(q, prefix + "tau_rel " + fmt("%g", tr) + " x " + std::to_string(k), tr, k, lambda_rel, epsilon_rel);
    }
    if(!failure.empty()) best.note(prefix + "tau_rel " + fmt("%g", tr) + ": " + failure);
    rows.push_back(row);
  }
  seconds = timer.time();
}

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
      if(!q.ok()) best.note((relative ? "tau_rel " : "time ") + fmt("%g", t) + " x " + std::to_string(k) + ": non-finite");
      best.consider(q, (relative ? "tau_rel " : "time ") + fmt("%g", t) + " x " + std::to_string(k));
    }
    rows.push_back(row);
  }
  seconds = timer.time();
}

// Incremental (1 step per call, CONTROL_POINTS, limit evaluated here) vs one call with k steps and
// LIMIT_SURFACE output: the largest vertex difference over the bbox diagonal.
double equivalence(const Mesh& noisy, double tau, int k, AF::Linear_solver solver, double diagonal, bool* factorised = nullptr)
{
  Mesh direct = noisy;
  const AF::Fairing_report r = AF::anisotropic_fairing(direct, AF::parameters::time_step(tau).number_of_iterations(k)
                                      .stopping_criteria(AF::Stopping_criteria::none())
                                      .linear_solver(solver)
                                      .output_positions(AF::Output_positions::LIMIT_SURFACE));
  if(factorised) *factorised = r.used_cholesky;
  Mesh m = noisy;
  for(int i = 0; i < k; ++i)
    AF::anisotropic_fairing(m, AF::parameters::time_step(tau).number_of_iterations(1)
                                   .stopping_criteria(AF::Stopping_criteria::none())
                                   .linear_solver(solver)
                                   .output_positions(AF::Output_positions::CONTROL_POINTS));
  Mesh e = m;
  AF::Loop_limit_surface<Mesh>(m).limit_positions(e.points());
  double d = 0;
  for(Mesh::Vertex_index v : e.vertices()) d = std::max(d, std::sqrt(CGAL::squared_distance(e.point(v), direct.point(v))));
  return d / diagonal;
}

// k incremental one-step calls (CONTROL_POINTS) of Loop with `tensor`; returns the control points.
template <typename Tensor>
Mesh run_incremental(const Mesh& noisy, double tau, int k, const Tensor& tensor)
{
  Mesh m = noisy;
  for(int i = 0; i < k; ++i)
    AF::anisotropic_fairing(m, AF::parameters::time_step(tau).number_of_iterations(1)
                                   .stopping_criteria(AF::Stopping_criteria::none())
                                   .diffusion_tensor(tensor)
                                   .output_positions(AF::Output_positions::CONTROL_POINTS));
  return m;
}

// The anisotropic sweep's incremental form (absolute threshold lambda_rel / l0) vs one k-step
// LIMIT_SURFACE call with the relative tensor: the largest vertex difference over the bbox diagonal.
double equivalence_aniso(const Mesh& noisy, double tau, int k, double lambda_rel, double epsilon_rel, double l0, double diagonal)
{
  Mesh direct = noisy;
  AF::anisotropic_fairing(direct, AF::parameters::time_step(tau).number_of_iterations(k)
                                      .stopping_criteria(AF::Stopping_criteria::none())
                                      .diffusion_tensor(aniso_tensor(lambda_rel, epsilon_rel, true))
                                      .output_positions(AF::Output_positions::LIMIT_SURFACE));
  const Mesh m = run_incremental(noisy, tau, k, aniso_tensor(lambda_rel / l0, epsilon_rel * l0 * l0));
  Mesh e = m;
  AF::Loop_limit_surface<Mesh>(m).limit_positions(e.points());
  double d = 0;
  for(Mesh::Vertex_index v : e.vertices()) d = std::max(d, std::sqrt(CGAL::squared_distance(e.point(v), direct.point(v))));
  return d / diagonal;
}

// Per face of `m` (control mesh), max and min of |k1|, |k2| of its Loop limit surface at the face centre, times l0.
void face_curvatures(const Mesh& m, double l0, std::vector<double>& kmax, std::vector<double>& kmin)
{
  const AF::Loop_limit_surface<Mesh> s(m);
  kmax.clear();
  kmin.clear();
  for(Mesh::Face_index f : m.faces())
  {
    const auto c = s.curvature(f, { { 1.0 / 3, 1.0 / 3, 1.0 / 3 } });
    kmax.push_back(std::max(std::abs(c.k1), std::abs(c.k2)) * l0);
    kmin.push_back(std::min(std::abs(c.k1), std::abs(c.k2)) * l0);
  }
}

std::vector<double> face_angles(const Mesh& m, const Reference& ref)
{
  std::vector<double> a;
  std::size_t i = 0;
  for(Mesh::Face_index f : m.faces())
  {
    const Vector n = face_normal(m, f);
    const Vector& r = ref.normals[i++];
    a.push_back(std::atan2(std::sqrt(CGAL::cross_product(n, r).squared_length()), n * r) * 180.0 / pi);
  }
  return a;
}

double quantile(std::vector<double> v, double q)
{
  if(v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, std::size_t(q * double(v.size())))];
}

// Where the anisotropic tensor can and cannot tell creases from noise (see the header).
void aniso_diagnostics(const Mesh& noisy, const Mesh& original, const Reference& ref, double l0, double l2,
                       const Best& aniso, const Best& loop)
{
  // faces of Original: 0 = on a crease (an edge with dihedral angle > 30 deg), 1 = sharing a vertex with one, 2 = other
  std::vector<int> cls(num_faces(original), 2);
  const double cos30 = std::cos(30.0 * pi / 180.0);
  for(Mesh::Face_index f : original.faces())
    for(Mesh::Halfedge_index hh : CGAL::halfedges_around_face(original.halfedge(f), original))
    {
      const Mesh::Face_index g = original.face(original.opposite(hh));
      if(g == Mesh::null_face()) continue;
      const Vector a = face_normal(original, f), b = face_normal(original, g);
      if(a * b < cos30 * std::sqrt(a.squared_length() * b.squared_length())) cls[std::size_t(f)] = 0;
    }
  for(Mesh::Face_index f : original.faces())
    if(cls[std::size_t(f)] == 0)
      for(Mesh::Vertex_index v : CGAL::vertices_around_face(original.halfedge(f), original))
        for(Mesh::Face_index g : CGAL::faces_around_target(original.halfedge(v), original))
          if(g != Mesh::null_face() && cls[std::size_t(g)] == 2) cls[std::size_t(g)] = 1;
  const char* names[3] = { "crease", "next to crease", "other" };
  std::size_t count[3] = { 0, 0, 0 };
  for(int c : cls) ++count[c];

  const double tau = aniso.tau_rel * l2;
  const Mesh result = run_incremental(noisy, tau, aniso.steps, aniso_tensor(aniso.lambda_rel / l0, aniso.epsilon_rel * l0 * l0));
  // M_eps of Noisy: one isotropic implicit step of eps (what the prefilter computes at the first step)
  const Mesh noisy_eps = aniso.epsilon_rel > 0 ? run_incremental(noisy, aniso.epsilon_rel * l0 * l0, 1, AF::Isotropic_diffusion_tensor()) : noisy;
  const Mesh iso_same = run_incremental(noisy, tau, aniso.steps, AF::Isotropic_diffusion_tensor());
  std::printf("\ncurvature diagnostics (best anisotropic cell %s; l0 = %.4g): faces of Original: %zu crease, %zu next to crease, %zu other\n",
              aniso.setting.c_str(), l0, count[0], count[1], count[2]);
  std::printf("k = max(|k1|,|k2|) l0, kmin = min(|k1|,|k2|) l0 of the Loop limit surface at face centres; "
              "'g<0.5 @L' = fraction of faces with g(k) < 0.5 (k > 2L) for lambda_rel L\n\n| surface | faces | k p10 | k p50 | k p90 | kmin p50 |");
  for(double L : aniso_lambdas) std::printf(" g<0.5 @%g |", L);
  std::printf("\n|---|---|---|---|---|---|");
  for(std::size_t i = 0; i < aniso_lambdas.size(); ++i) std::printf("---|");
  std::printf("\n");
  struct Named { const char* name; const Mesh* m; };
  std::vector<Named> surfaces = { { "Noisy", &noisy } };
  const std::string eps_name = "M_eps of Noisy (eps_rel " + fmt("%g", aniso.epsilon_rel) + ")";
  if(aniso.epsilon_rel > 0) surfaces.push_back({ eps_name.c_str(), &noisy_eps });
  surfaces.push_back({ "Original", &original });
  surfaces.push_back({ "aniso result", &result });
  for(const Named& sf : surfaces)
  {
    std::vector<double> kmax, kmin;
    face_curvatures(*sf.m, l0, kmax, kmin);
    for(int c = 0; c < 3; ++c)
    {
      std::vector<double> a, b;
      for(std::size_t i = 0; i < cls.size(); ++i)
        if(cls[i] == c) { a.push_back(kmax[i]); b.push_back(kmin[i]); }
      std::printf("| %s, %s | %zu | %.1f | %.1f | %.1f | %.1f |", sf.name, names[c], a.size(), quantile(a, 0.1),
                  quantile(a, 0.5), quantile(a, 0.9), quantile(b, 0.5));
      for(double L : aniso_lambdas)
      {
        std::size_t damped = 0;
        for(double k : a) damped += k > 2 * L ? 1 : 0;
        std::printf(" %.2f |", a.empty() ? 0.0 : double(damped) / double(a.size()));
      }
      std::printf("\n");
    }
  }
  // mean normal angle error per face class
  auto limit = [](const Mesh& m) { Mesh e = m; AF::Loop_limit_surface<Mesh>(m).limit_positions(e.points()); return e; };
  std::vector<std::pair<std::string, Mesh> > results;
  results.emplace_back("Loop limit of Noisy", limit(noisy));
  results.emplace_back("isotropic Loop, same tau x steps (" + fmt("%g", aniso.tau_rel) + " x " + std::to_string(aniso.steps) + ")", limit(iso_same));
  if(loop.run && loop.q.ok())
    results.emplace_back("isotropic Loop best (" + loop.setting + ")", limit(run_incremental(noisy, loop.tau_rel * l2, loop.steps, AF::Isotropic_diffusion_tensor())));
  results.emplace_back("anisotropic Loop best (" + aniso.setting + ")", limit(result));
  results.emplace_back("the same, control points (no limit projection)", result);
  results.emplace_back("Loop limit of Original (what a limit-surface output loses at creases)", limit(original));
  std::printf("\nmean normal angle error (deg) per face class of Original\n\n| result | crease | next to crease | other | all |\n|---|---|---|---|---|\n");
  for(const auto& r : results)
  {
    const std::vector<double> a = face_angles(r.second, ref);
    double sum[3] = { 0, 0, 0 }, all = 0;
    for(std::size_t i = 0; i < a.size(); ++i) { sum[cls[i]] += a[i]; all += a[i]; }
    std::printf("| %s | %.2f | %.2f | %.2f | %.2f |\n", r.first.c_str(), sum[0] / double(std::max<std::size_t>(count[0], 1)),
                sum[1] / double(std::max<std::size_t>(count[1], 1)), sum[2] / double(std::max<std::size_t>(count[2], 1)), all / double(a.size()));
  }
}

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
  for(const auto& entry : std::filesystem::directory_iterator(dir))
    if(entry.is_directory() && std::filesystem::exists(entry.path() / "Noisy.obj") &&
       std::filesystem::exists(entry.path() / "Original.obj"))
      if(only.empty() || entry.path().filename().string().find(only) != std::string::npos)
        models.push_back(entry.path().filename().string());
  std::sort(models.begin(), models.end());
  if(models.empty()) { std::fprintf(stderr, "no <Model>/{Noisy,Original}.obj pairs in %s\n", dir.c_str()); return 1; }

  std::printf("# bench_denoising: %s (%zu pairs), methods:%s%s%s%s\n", dir.c_str(), models.size(), run_loop ? " loop" : "",
              run_p1 ? " p1" : "", run_smooth ? " smooth" : "", run_aniso ? " aniso" : "");
  std::printf("sweep: ours tau_rel {%s} x steps {1,2,3,5,10}; smooth_shape tau_rel {1e-5,1e-4,3e-4,1e-3,3e-3,1e-2}"
              " x iterations {1,2,3,5,10} (time = tau_rel*l^2/4), and its literal times {1e-5,1e-4,1e-3,1e-2};"
              " anisotropic Loop: eps_rel {%s} x lambda_rel {%s} x ours, with steps 20 and 40 while the angle still falls;"
              " l^2 = Area(Noisy)/(4 pi); cells: angle(deg) / dist(/bbox diag)\n", [] {
                std::string l;
                for(double T : our_taus) l += (l.empty() ? "" : ",") + fmt("%g", T);
                return l;
              }().c_str(), [] {
                std::string l;
                for(double E : aniso_epsilons) l += (l.empty() ? "" : ",") + fmt("%g", E);
                return l;
              }().c_str(), [] {
                std::string l;
                for(double L : aniso_lambdas) l += (l.empty() ? "" : ",") + fmt("%g", L);
                return l;
              }().c_str());

  std::vector<Row> table;
  bool checked_cholesky = false;
  for(const std::string& name : models)
  {
    const std::string base = dir + "/" + name;
    Mesh noisy, original;
    if(!read_obj_in_order(base + "/Noisy.obj", noisy) || !read_obj_in_order(base + "/Original.obj", original))
    { std::fprintf(stderr, "cannot read %s\n", base.c_str()); return 1; }
    if(num_vertices(noisy) != num_vertices(original) || num_faces(noisy) != num_faces(original))
    { std::fprintf(stderr, "%s: Noisy and Original differ in size\n", name.c_str()); return 1; }
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
