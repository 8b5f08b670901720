// Denoising quality of isotropic fairing on the standard mesh-denoising pairs
// (<DIR>/<Model><sigma>/{Noisy,Original}.obj, same connectivity in both files): isotropic Loop
// (limit-surface output), isotropic P1, and CGAL::Polygon_mesh_processing::smooth_shape, each at
// the best point of a small sweep (best = smallest mean face-normal angle to Original).
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
// usage: bench_denoising [DIR=<repo>/../shared/data/denoising] [MODEL_SUBSTRING]

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

#include "bench_mesh_measures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#ifndef AF_SOURCE_DIR
#define AF_SOURCE_DIR "."
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;
namespace AF = CGAL::Anisotropic_fairing;
namespace PMP = CGAL::Polygon_mesh_processing;

static const double pi = 3.14159265358979323846;

// Reads an OBJ keeping the file's vertex and face order (read_polygon_mesh may repair and reorder).
bool read_obj_in_order(const std::string& path, Mesh& mesh)
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!CGAL::IO::read_OBJ(path, points, polygons)) return false;
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons)) return false;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return num_vertices(mesh) == points.size() && num_faces(mesh) == polygons.size();
}

Vector face_normal(const Mesh& m, Mesh::Face_index f)
{
  Mesh::Halfedge_index h = m.halfedge(f);
  const Point& a = m.point(m.source(h));
  const Point& b = m.point(m.target(h));
  const Point& c = m.point(m.target(m.next(h)));
  return CGAL::cross_product(b - a, c - a);
}


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
  void consider(const Quality& c, const std::string& s)
  {
    if(c.ok() && (!q.ok() || c.angle < q.angle)) { q = c; setting = s; }
  }
  void note(const std::string& s) { notes += (notes.empty() ? "" : "; ") + s; }
};

std::string fmt(const char* f, double x)
{
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

const std::vector<double> our_taus = {1e-4, 3e-4, 1e-3, 3e-3};
const std::vector<int> step_counts = {1, 2, 3, 5, 10};
const std::vector<double> smooth_taus = {1e-5, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2};
const std::vector<double> smooth_literal_times = {1e-5, 1e-4, 1e-3, 1e-2};

// One line of the sweep detail: quality after each step count.
struct Sweep_row
{
  std::string label;
  std::vector<std::string> cells;
};

void print_sweep(const std::string& title, const std::vector<Sweep_row>& rows)
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
void sweep_ours(const Mesh& noisy, const Reference& ref, AF::Finite_element element, double l2, double h,
                Best& best, std::vector<Sweep_row>& rows, double& seconds, Quality* limit_of_noisy)
{
  CGAL::Real_timer timer;
  timer.start();
  const bool loop = element == AF::Finite_element::LOOP;
  if(loop && limit_of_noisy)
  {
    Mesh e = noisy;
    AF::Loop_limit_surface<Mesh>(noisy).limit_positions(e.points());
    *limit_of_noisy = evaluate(e, ref);
  }
  for(double tr : our_taus)
  {
    const double tau = tr * l2;
    Sweep_row row;
    row.label = "tau_rel " + fmt("%g", tr) + " (tau/h^2 " + fmt("%.2f", tau / (h * h)) + ")";
    Mesh m = noisy;
    int done = 0;
    std::string failure;
    for(int k : step_counts)
    {
      while(failure.empty() && done < k)
      {
        AF::Fairing_report r = AF::anisotropic_fairing(m, AF::parameters::time_step(tau)
                                                           .number_of_iterations(1)
                                                           .stopping_criteria(AF::Stopping_criteria::none())
                                                           .finite_element(element)
                                                           .output_positions(AF::Output_positions::CONTROL_POINTS));
        if(!r.succeeded()) failure = std::string(AF::to_string(r.status)) + " at step " + std::to_string(done + 1);
        else ++done;
      }
      if(!failure.empty()) { row.cells.push_back("failed"); continue; }
      Quality q;
      if(loop)
      {
        Mesh e = m;
        AF::Loop_limit_surface<Mesh>(m).limit_positions(e.points());
        q = evaluate(e, ref);
      }
      else q = evaluate(m, ref);
      row.cells.push_back(cell(q));
      best.consider(q, "tau_rel " + fmt("%g", tr) + " x " + std::to_string(k));
    }
    if(!failure.empty()) best.note("tau_rel " + fmt("%g", tr) + ": " + failure);
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

struct Row
{
  std::string model, size;
  Best loop, p1, smooth, literal;
  Quality noisy, noisy_limit;
};

std::string summary(const Best& b)
{
  if(b.refused) return b.notes;
  std::string s = b.q.ok() ? fmt("%.2f", b.q.angle) + "°, " + fmt("%.2e", b.q.dist) + " (" + b.setting + ")" : "no result";
  if(!b.notes.empty()) s += " [" + b.notes + "]";
  return s;
}

int main(int argc, char** argv)
{
  std::string dir = argc > 1 && argv[1][0] ? argv[1] : std::string(AF_SOURCE_DIR) + "/../shared/data/denoising";
  const std::string only = argc > 2 ? argv[2] : "";
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

  std::printf("# bench_denoising: %s (%zu pairs)\n", dir.c_str(), models.size());
  std::printf("sweep: ours tau_rel {1e-4,3e-4,1e-3,3e-3} x steps {1,2,3,5,10}; smooth_shape tau_rel {1e-5,1e-4,3e-4,1e-3,3e-3,1e-2}"
              " x iterations {1,2,3,5,10} (time = tau_rel*l^2/4), and its literal times {1e-5,1e-4,1e-3,1e-2};"
              " l^2 = Area(Noisy)/(4 pi); cells: angle(deg) / dist(/bbox diag)\n");

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
    const double area = PMP::area(noisy);
    const double l2 = area / (4 * pi);
    const double h = mean_edge_length(noisy);
    const std::size_t borders = [&] { std::size_t b = 0; for(auto hh : noisy.halfedges()) b += noisy.is_border(hh) ? 1 : 0; return b; }();
    std::printf("\n## %s: %s vertices / faces, %zu border edges, l = %.4g, h = %.4g, l^2/h^2 = %.0f, bbox diag %.4g\n",
                name.c_str(), row.size.c_str(), borders, std::sqrt(l2), h, l2 / (h * h), ref.diagonal);
    std::printf("noisy input: %s\n", cell(row.noisy).c_str());

    double t_loop = 0, t_p1 = 0, t_smooth = 0, t_literal = 0;
    std::vector<Sweep_row> rows_loop, rows_p1, rows_smooth, rows_literal;
    try
    {
      sweep_ours(noisy, ref, AF::Finite_element::LOOP, l2, h, row.loop, rows_loop, t_loop, &row.noisy_limit);
      std::printf("Loop limit of the noisy mesh (0 steps): %s\n", cell(row.noisy_limit).c_str());
    }
    catch(const AF::Input_error& e) { row.loop.refused = true; row.loop.notes = std::string("refused: ") + e.what(); }
    try { sweep_ours(noisy, ref, AF::Finite_element::LINEAR, l2, h, row.p1, rows_p1, t_p1, nullptr); }
    catch(const AF::Input_error& e) { row.p1.refused = true; row.p1.notes = std::string("refused: ") + e.what(); }
    sweep_smooth_shape(noisy, ref, smooth_taus, l2 / 4, row.smooth, rows_smooth, t_smooth, true);
    sweep_smooth_shape(noisy, ref, smooth_literal_times, 1.0, row.literal, rows_literal, t_literal, false);

    if(!row.loop.refused)
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

    if(!row.loop.refused) print_sweep("Loop (limit positions), " + fmt("%.1f s", t_loop), rows_loop);
    else std::printf("Loop: %s\n", row.loop.notes.c_str());
    if(!row.p1.refused) print_sweep("P1, " + fmt("%.1f s", t_p1), rows_p1);
    else std::printf("P1: %s\n", row.p1.notes.c_str());
    print_sweep("smooth_shape (same physical time), " + fmt("%.1f s", t_smooth), rows_smooth);
    print_sweep("smooth_shape (literal time argument), " + fmt("%.1f s", t_literal), rows_literal);
    std::printf("model total %.1f s\n", model_timer.time());
    std::fflush(stdout);
    table.push_back(row);
  }

  std::printf("\n## Summary: best of each sweep by mean normal angle (angle to Original, mean vertex distance to the Original surface / bbox diagonal, setting = tau_rel x steps)\n\n");
  std::printf("| model | V / F | Loop | P1 | smooth_shape | noisy input | Loop limit of noisy (0 steps) |\n|---|---|---|---|---|---|---|\n");
  for(const Row& r : table)
    std::printf("| %s | %s | %s | %s | %s | %s | %s |\n", r.model.c_str(), r.size.c_str(), summary(r.loop).c_str(),
                summary(r.p1).c_str(), summary(r.smooth).c_str(),
                (fmt("%.2f", r.noisy.angle) + "°, " + fmt("%.2e", r.noisy.dist)).c_str(),
                r.loop.refused ? "-" : (fmt("%.2f", r.noisy_limit.angle) + "°, " + fmt("%.2e", r.noisy_limit.dist)).c_str());
  std::printf("\nsmooth_shape with its literal time argument {1e-5,1e-4,1e-3,1e-2} (model units, not scaled):\n\n"
              "| model | best |\n|---|---|\n");
  for(const Row& r : table) std::printf("| %s | %s |\n", r.model.c_str(), summary(r.literal).c_str());
  std::printf("\nwall time of the whole run: %.1f s\n", wall.time());
  return 0;
}
