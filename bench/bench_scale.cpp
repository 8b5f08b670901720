// Speed and memory at scale (issue 16): the package against one CGAL::Polygon_mesh_processing::smooth_shape
// step on Loop-refined real meshes from 144k to 2.3M triangles, in the same run.
//
// Every measurement runs in its own child process (this program re-executed with --child), so that
// its peak resident memory (wait4's ru_maxrss) is its own and no run warms the next one's caches; the
// children of one row alternate (ours, smooth_shape, ours, ...). Times are medians over RUNS children; (s) also
// gives the ratio of the fastest children, which a busy machine (other tenants, a sub-second call) disturbs least.
// The meshes get Gaussian noise along the vertex normals (sigma = 0.2 of the mean edge length, seed 1),
// the kind of input the package is for, and are written once as binary PLY into MESH_DIR.
//
// Parts (letters of PARTS):
//   m  forming M and L (isotropic) at 144k triangles, TBB: the median of 5 assemblies in one child
//   s  one isotropic and one anisotropic (prefilter) step, relative time step 1e-3, whole library
//      call, against one smooth_shape step of the same physical time (its time argument tau / 4), at
//      every size: the growth of the time per step, and the 2M row
//   c  CG iterations of one isotropic step at fixed tau / h^2 = 1 at every size
//   d  the default run (no named parameters) at 1.1M triangles against one smooth_shape step
//   a  attributes-only steps on a fixed surface (a noisy scalar field, 6 steps): first against later, with
//      CG and (144k only) with the constant system factorised once
//   t  the tool's whole process (one isotropic step) against a program that reads, calls and writes
//
// usage: bench_scale [DATA_DIR=<repo>/../shared/data] [PARTS=mscdat] [RUNS=5] [MAX_TRIANGLES=2400000] [MESH_DIR=bench_scale_meshes]
// Writes the table on stdout and bench_scale.csv (plot: bench/plot_scale.py bench_scale.csv).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>
#include <CGAL/Anisotropic_fairing/internal/assembly/Fem_assembly.h>
#include <CGAL/Anisotropic_fairing/internal/element/Ghosted_patch_cache.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Indexed_mesh.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Locality_ordering.h>

#include "bench_median.h"
#include "bench_mesh_measures.h"

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#ifndef AF_SOURCE_DIR
#define AF_SOURCE_DIR "."
#endif
#ifndef AF_TOOL_PATH
#define AF_TOOL_PATH ""
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace AF = CGAL::Anisotropic_fairing;
namespace PMP = CGAL::Polygon_mesh_processing;

// ------------------------------------------------------------------------------------------------
// children: one measurement each, printed as key=value lines

typedef std::map<std::string, double> Values;

static double value(const Values& v, const std::string& key)
{
  const auto it = v.find(key);
  return it == v.end() ? std::nan("") : it->second;
}

static void print(const Values& v)
{
  for(const auto& kv : v) std::printf("%s=%.17g\n", kv.first.c_str(), kv.second);
}

static void put_step(Values& v, const AF::Fairing_report& r)
{
  v["status_ok"] = r.succeeded() ? 1 : 0;
  v["steps"] = double(r.steps.size());
  v["rejected"] = double(r.rejected_steps);   // each one more assembly and solve
  v["setup"] = r.setup_seconds;
  v["call"] = r.total_seconds;
  double assemble = 0, solve = 0;
  int its = 0;
  for(const AF::Fairing_step& s : r.steps) { assemble += s.assemble_seconds; solve += s.solve_seconds; its = std::max(its, s.solver_iterations); }
  v["assemble"] = assemble;
  v["solve"] = solve;
  v["iterations"] = its;
}

static AF::Fairing_report one_step(Mesh& m, bool anisotropic, double absolute_tau = 0)
{
  const auto np = AF::parameters::number_of_iterations(1).stopping_criteria(AF::Stopping_criteria::none());
  if(absolute_tau > 0) return AF::anisotropic_fairing(m, np.time_step(absolute_tau));
  if(anisotropic) return AF::anisotropic_fairing(m, np.relative_time_step(1e-3).diffusion_tensor(AF::Anisotropic_diffusion_tensor()));
  return AF::anisotropic_fairing(m, np.relative_time_step(1e-3));
}

// the time of M and L (isotropic) on the mesh, with the internal classes as the driver uses them
static double assembly_seconds(const Mesh& mesh)
{
  namespace AFi = AF::internal;
  AFi::Indexed_mesh<Mesh> im(mesh, AFi::Borders::GHOSTED);
  const AFi::Control_matrix P = im.read_points(mesh.points());
  const AFi::Locality_ordering ordering = AFi::make_locality_ordering(im.ghost_layer());
  AFi::Control_matrix X(P.rows(), 3);
  for(std::size_t i = 0; i < im.number_of_vertices(); ++i) X.row(Eigen::Index(i)) = P.row(ordering.old_of_new_vertex[i]);
  AFi::Ghosted_patch_cache cache(ordering.layer, AFi::Quadrature_spec());
  AFi::Fem_assembler<AFi::Ghosted_patch_cache> assembler(cache, im.number_of_vertices());
  AFi::Value_array M, L;
  std::vector<double> times;
  assembler.assemble(X, 3, AF::Isotropic_diffusion_tensor(), M, L);   // warm-up (allocations)
  for(int k = 0; k < 5; ++k)
  {
    CGAL::Real_timer t;
    t.start();
    assembler.assemble(X, 3, AF::Isotropic_diffusion_tensor(), M, L);
    times.push_back(t.time());
  }
  return median(times);
}

static int child(const std::string& kind, const std::string& file)
{
  CGAL::Real_timer whole;
  whole.start();
  Mesh m;
  if(!CGAL::IO::read_polygon_mesh(file, m)) { std::fprintf(stderr, "cannot read %s\n", file.c_str()); return 1; }
  Values v;
  CGAL::Real_timer t;
  t.start();
  if(kind == "smooth_shape")
  {
    const double l2 = PMP::area(m) / (4 * 3.14159265358979323846);
    t.reset();
    PMP::smooth_shape(m, 1e-3 * l2 / 4, CGAL::parameters::number_of_iterations(1));
  }
  else if(kind == "isotropic" || kind == "anisotropic") put_step(v, one_step(m, kind == "anisotropic"));
  else if(kind == "isotropic_h2")
  {
    const double h = mean_edge_length(m);
    t.reset();
    put_step(v, one_step(m, false, h * h));
  }
  else if(kind == "default")
  {
    const AF::Fairing_report r = AF::anisotropic_fairing(m);
    put_step(v, r);
    v["tensor_chosen_anisotropic"] = r.feature_threshold > 0 ? 1 : 0;
  }
  else if(kind == "assembly") v["assembly"] = assembly_seconds(m);
  else if(kind == "attributes" || kind == "attributes_cholesky")
  {
    auto f = m.add_property_map<Mesh::Vertex_index, double>("v:field").first;
    std::mt19937 rng(2);
    std::normal_distribution<double> noise(0, 0.1);
    for(auto u : m.vertices()) f[u] = std::sin(m.point(u).x()) + noise(rng);
    t.reset();
    const AF::Fairing_report r = AF::anisotropic_fairing(m, m.points(), f,
        AF::parameters::attribute_mode(AF::Attribute_mode::ATTRIBUTES_ONLY).relative_time_step(1e-3)
                       .number_of_iterations(6).stopping_criteria(AF::Stopping_criteria::none())
                       .linear_solver(kind == "attributes" ? AF::Linear_solver::AUTOMATIC : AF::Linear_solver::CHOLESKY));
    put_step(v, r);
    std::vector<double> later, later_iterations;
    for(std::size_t k = 1; k < r.steps.size(); ++k)
    {
      later.push_back(r.steps[k].assemble_seconds + r.steps[k].solve_seconds);
      later_iterations.push_back(r.steps[k].solver_iterations);
    }
    v["first_iterations"] = r.steps.empty() ? 0 : r.steps[0].solver_iterations;
    v["later_iterations"] = median(later_iterations);
    v["first_step"] = r.steps.empty() ? std::nan("") : r.steps[0].assemble_seconds + r.steps[0].solve_seconds;
    v["later_step"] = median(later);
  }
  else if(kind == "read_call_write")
  {
    put_step(v, one_step(m, false));
    CGAL::IO::write_polygon_mesh(file + ".out.ply", m, CGAL::parameters::stream_precision(17).use_binary_mode(true));
  }
  else { std::fprintf(stderr, "unknown kind %s\n", kind.c_str()); return 1; }
  v["seconds"] = t.time();
  v["process_seconds"] = whole.time();
  print(v);
  return 0;
}

// ------------------------------------------------------------------------------------------------
// the parent: meshes, children, medians, the table

struct Child_result { bool ok = false; Values values; double wall = 0; double peak_mb = 0; };

// runs argv as a child process, reads its key=value lines, its wall time and peak memory
static Child_result run_child(const std::vector<std::string>& args)
{
  Child_result res;
  int fd[2];
  if(pipe(fd) != 0) return res;
  CGAL::Real_timer t;
  t.start();
  const pid_t pid = fork();
  if(pid == 0)
  {
    dup2(fd[1], 1);
    close(fd[0]); close(fd[1]);
    std::vector<char*> argv;
    for(const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  close(fd[1]);
  std::string out;
  char buf[4096];
  ssize_t n;
  while((n = read(fd[0], buf, sizeof buf)) > 0) out.append(buf, std::size_t(n));
  close(fd[0]);
  int status = 0;
  struct rusage usage;
  wait4(pid, &status, 0, &usage);
  res.wall = t.time();
  res.peak_mb = double(usage.ru_maxrss) / 1024.0;
  res.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  std::istringstream lines(out);
  std::string line;
  while(std::getline(lines, line))
  {
    const std::size_t eq = line.find('=');
    if(eq != std::string::npos) res.values[line.substr(0, eq)] = std::atof(line.c_str() + eq + 1);
  }
  return res;
}

struct Sized_mesh { std::string name, file; std::size_t triangles = 0; };

static bool exists(const std::string& f) { struct stat s; return stat(f.c_str(), &s) == 0; }

// DATA_DIR/file Loop-subdivided `sub` times, with noise along the normals, as MESH_DIR/name.ply
static bool make_mesh(const std::string& data, const std::string& dir, const char* file, int sub, Sized_mesh& out)
{
  out.name = std::string(file) + " Loop x" + std::to_string(sub);
  out.file = dir + "/" + std::string(file).substr(0, std::string(file).find('.')) + "-loop" + std::to_string(sub) + "-noisy.ply";
  if(!exists(out.file))
  {
    Mesh m;
    if(!CGAL::IO::read_polygon_mesh(data + "/" + file, m)) { std::fprintf(stderr, "cannot read %s/%s\n", data.c_str(), file); return false; }
    CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(sub));
    const double sigma = 0.2 * mean_edge_length(m);
    auto normal = m.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:bench_normal").first;
    PMP::compute_vertex_normals(m, normal);
    std::mt19937 rng(1);
    std::normal_distribution<double> gauss(0, sigma);
    for(auto v : m.vertices()) m.point(v) = m.point(v) + gauss(rng) * normal[v];
    m.remove_property_map(normal);
    if(!CGAL::IO::write_polygon_mesh(out.file, m, CGAL::parameters::stream_precision(17).use_binary_mode(true))) return false;
  }
  Mesh m;
  if(!CGAL::IO::read_polygon_mesh(out.file, m)) return false;
  out.triangles = num_faces(m);
  return true;
}

struct Row_stats { double seconds = std::nan(""), fastest = std::nan(""), peak_mb = std::nan(""), iterations = std::nan(""), wall = std::nan(""); Values last; int failed = 0; };

struct Bench
{
  std::string self, csv_name = "bench_scale.csv";
  int runs = 5;
  FILE* csv = nullptr;

  // `runs` children of each kind, alternating, on one mesh; medians of `key` (default: seconds)
  std::vector<Row_stats> measure(const Sized_mesh& mesh, const std::vector<std::string>& kinds, const std::string& key = "seconds", int count = 0)
  {
    const int n = count > 0 ? count : runs;
    std::vector<std::vector<double>> sec(kinds.size()), mem(kinds.size()), its(kinds.size()), wall(kinds.size());
    std::vector<Row_stats> out(kinds.size());
    for(int r = 0; r < n; ++r)
      for(std::size_t k = 0; k < kinds.size(); ++k)
      {
        std::vector<std::string> args;
        if(kinds[k] == "tool")
          args = { AF_TOOL_PATH, mesh.file, mesh.file + ".tool.ply", "--relative-time-step", "1e-3", "--steps", "1", "--stop", "off", "--quiet" };
        else
          args = { self, "--child", kinds[k], mesh.file };
        const Child_result c = run_child(args);
        if(!c.ok) { ++out[k].failed; continue; }
        sec[k].push_back(kinds[k] == "tool" ? c.wall : (c.values.count(key) ? c.values.at(key) : c.values.at("seconds")));
        mem[k].push_back(c.peak_mb);
        wall[k].push_back(c.wall);
        if(c.values.count("iterations")) its[k].push_back(c.values.at("iterations"));
        out[k].last = c.values;
      }
    for(std::size_t k = 0; k < kinds.size(); ++k)
    {
      out[k].seconds = median(sec[k]);
      if(!sec[k].empty()) out[k].fastest = *std::min_element(sec[k].begin(), sec[k].end());
      out[k].peak_mb = median(mem[k]);
      out[k].iterations = median(its[k]);
      out[k].wall = median(wall[k]);
      if(csv) std::fprintf(csv, "%s,%zu,%s,%s,%.6g,%.6g,%.6g,%.1f\n", mesh.name.c_str(), mesh.triangles, kinds[k].c_str(), key.c_str(),
                           out[k].seconds, out[k].wall, out[k].iterations, out[k].peak_mb);
    }
    return out;
  }
};

static const char* verdict(bool ok) { return ok ? "yes" : "**no**"; }

int main(int argc, char** argv)
{
  if(argc >= 4 && std::string(argv[1]) == "--child") return child(argv[2], argv[3]);
  const std::string data = argc > 1 && argv[1][0] ? argv[1] : std::string(AF_SOURCE_DIR) + "/../shared/data";
  const std::string parts = argc > 2 && argv[2][0] ? argv[2] : "mscdat";
  Bench bench;
  bench.runs = argc > 3 ? std::max(1, std::atoi(argv[3])) : 5;
  const std::size_t max_triangles = argc > 4 ? std::size_t(std::atof(argv[4])) : 2400000;
  const std::string dir = argc > 5 ? argv[5] : "bench_scale_meshes";
  char self[4096];
  const ssize_t len = readlink("/proc/self/exe", self, sizeof self - 1);
  if(len <= 0) return 1;
  self[len] = 0;
  bench.self = self;
  mkdir(dir.c_str(), 0755);
  bench.csv = std::fopen(bench.csv_name.c_str(), "w");
  if(bench.csv) std::fprintf(bench.csv, "mesh,triangles,kind,quantity,median_seconds,median_process_seconds,cg_iterations,peak_mb\n");

  struct Source { const char* file; int sub; };
  const Source sources[] = { { "fertility.off", 2 }, { "fertility.off", 3 }, { "bunny-closed.off", 2 }, { "armadillo.obj", 2 }, { "fertility.off", 4 } };
  std::vector<Sized_mesh> meshes;
  for(const Source& s : sources)
  {
    Sized_mesh m;
    if(make_mesh(data, dir, s.file, s.sub, m) && m.triangles <= max_triangles) meshes.push_back(m);
  }
  if(meshes.empty()) { std::fprintf(stderr, "no mesh\n"); return 1; }
  auto find = [&](std::size_t around) {
    const Sized_mesh* best = &meshes.front();
    for(const Sized_mesh& m : meshes) if(std::fabs(double(m.triangles) - double(around)) < std::fabs(double(best->triangles) - double(around))) best = &m;
    return *best;
  };
  const Sized_mesh small = find(144000), million = find(1100000);
  std::printf("# bench_scale: %s, parts %s, medians of %d child processes; peak memory = the child's maximum resident set\n",
              data.c_str(), parts.c_str(), bench.runs);
#ifdef CGAL_LINKED_WITH_TBB
  std::printf("TBB: yes (assembly on every core)\n");
#endif

  if(parts.find('m') != std::string::npos)
  {
    const std::vector<Row_stats> r = bench.measure(small, { "assembly" }, "assembly");
    std::printf("\n## (m) Forming M and L, isotropic, %s (%zu triangles)\n\n| measure | seconds | target | met |\n|---|---:|---:|---|\n", small.name.c_str(), small.triangles);
    std::printf("| M and L with the statistics of the step, median of 5 in each of %d children | %.3f | 0.25 | %s |\n",
                bench.runs, r[0].seconds, verdict(r[0].seconds <= 0.25));
  }
  if(parts.find('s') != std::string::npos)
  {
    std::printf("\n## (s) One step, whole library call, against one smooth_shape step (same physical time)\n\n");
    std::printf("| mesh | triangles | smooth_shape s | isotropic s | ratio (target <= 1.1) | ratio of the fastest | CG its | assemble / solve / set-up s | anisotropic s (rejected steps) | ratio (target <= 2.0) | peak MB smooth_shape / iso / aniso | iso s per million triangles |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---|---:|---:|---|---:|\n");
    for(const Sized_mesh& m : meshes)
    {
      const std::vector<Row_stats> r = bench.measure(m, { "isotropic", "smooth_shape", "anisotropic" });
      std::printf("| %s | %zu | %.2f | %.2f | %.2f %s | %.2f | %.0f | %.2f / %.2f / %.2f | %.2f (%.0f) | %.2f %s | %.0f / %.0f / %.0f | %.2f |\n",
                  m.name.c_str(), m.triangles, r[1].seconds, r[0].seconds, r[0].seconds / r[1].seconds, verdict(r[0].seconds <= 1.1 * r[1].seconds),
                  r[0].fastest / r[1].fastest, r[0].iterations, value(r[0].last, "assemble"), value(r[0].last, "solve"), value(r[0].last, "setup"), r[2].seconds, value(r[2].last, "rejected"), r[2].seconds / r[1].seconds,
                  verdict(r[2].seconds <= 2.0 * r[1].seconds), r[1].peak_mb, r[0].peak_mb, r[2].peak_mb, r[0].seconds / (double(m.triangles) * 1e-6));
      std::fflush(stdout);
    }
    std::printf("\nThe 2M target: one step <= 15 s and peak memory <= 6 GB on the largest mesh.\n");
  }
  if(parts.find('c') != std::string::npos)
  {
    std::printf("\n## (c) CG iterations of one isotropic step at tau = h^2 (h: mean edge length), default tolerance\n\n| mesh | triangles | CG its | seconds |\n|---|---:|---:|---:|\n");
    for(const Sized_mesh& m : meshes)
    {
      const std::vector<Row_stats> r = bench.measure(m, { "isotropic_h2" }, "seconds", 1);
      std::printf("| %s | %zu | %.0f | %.2f |\n", m.name.c_str(), m.triangles, r[0].iterations, r[0].seconds);
      std::fflush(stdout);
    }
  }
  if(parts.find('d') != std::string::npos)
  {
    const std::vector<Row_stats> r = bench.measure(million, { "default", "smooth_shape" });
    std::printf("\n## (d) The default run (no named parameters), %s (%zu triangles)\n\n| measure | value | target | met |\n|---|---:|---:|---|\n", million.name.c_str(), million.triangles);
    std::printf("| default run, seconds | %.1f | | |\n| one smooth_shape step, seconds | %.2f | | |\n", r[0].seconds, r[1].seconds);
    std::printf("| ratio | %.1f | <= 10 | %s |\n| peak memory, MB | %.0f | <= 3072 | %s |\n| steps of the kept result | %.0f | | |\n",
                r[0].seconds / r[1].seconds, verdict(r[0].seconds <= 10 * r[1].seconds), r[0].peak_mb, verdict(r[0].peak_mb <= 3072), value(r[0].last, "steps"));
  }
  if(parts.find('a') != std::string::npos)
  {
    // the constant system factorised once (LDL^T) on the small mesh only: the larger one's factor does not fit
    std::printf("\n## (a) Attributes only on a fixed surface (a noisy scalar, 6 steps of tau_rel 1e-3)\n\n| mesh | triangles | solver | first step s | later steps s (median) | later iterations | later / first (target <= 5%%) |\n|---|---:|---|---:|---:|---:|---:|\n");
    // the ratio is always to the first step with CG: the factorised run's first step carries its factorisation
    for(const Sized_mesh* m : { &small, &million })
    {
      double first_cg = 0;
      for(const char* kind : { "attributes", "attributes_cholesky" })
      {
        if(m == &million && std::string(kind) == "attributes_cholesky") continue;
        const std::vector<Row_stats> f = bench.measure(*m, { kind }, "first_step");
        const std::vector<Row_stats> l = bench.measure(*m, { kind }, "later_step");
        if(first_cg == 0) first_cg = f[0].seconds;
        const double ratio = l[0].seconds / first_cg;
        std::printf("| %s | %zu | %s | %.3f | %.4f | %.0f | %.1f%% %s |\n", m->name.c_str(), m->triangles,
                    std::string(kind) == "attributes" ? "automatic (CG)" : "LDL^T once", f[0].seconds, l[0].seconds,
                    value(l[0].last, "later_iterations"), 100 * ratio, verdict(ratio <= 0.05));
      }
    }
  }
  if(parts.find('t') != std::string::npos && std::string(AF_TOOL_PATH).size() > 0)
  {
    std::printf("\n## (t) The tool's whole process against read + library call + write (one isotropic step, binary PLY)\n\n| mesh | triangles | read+call+write process s | tool process s | ratio (target <= 1.1) |\n|---|---:|---:|---:|---:|\n");
    for(const Sized_mesh* m : { &small, &million })
    {
      const std::vector<Row_stats> r = bench.measure(*m, { "read_call_write", "tool" });
      std::printf("| %s | %zu | %.2f | %.2f | %.2f %s |\n", m->name.c_str(), m->triangles, r[0].wall, r[1].wall, r[1].wall / r[0].wall, verdict(r[1].wall <= 1.1 * r[0].wall));
    }
  }
  if(bench.csv) std::fclose(bench.csv);
  return 0;
}
