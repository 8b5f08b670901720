// The same bytes on any number of threads (the manual's Validation page, "Reproducibility"): the default
// run, an anisotropic run of fixed steps and a coupled attribute run, each inside TBB task arenas of 1, 2, 3
// and 8 threads, write the same coordinates and attribute values to the last bit. The assembly's chunks
// follow from the number of faces alone (Face_chunks.h), every reduction sums fixed blocks in a fixed order,
// and the automatic solver choice counts operations instead of timing them. Before, one and two threads
// differed in the 14th digit. Without TBB the runs are serial and the test compares a run with itself.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include "test_support/check.h"
#include "test_support/mesh_coordinates.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace AF = CGAL::Anisotropic_fairing;

namespace {

const int thread_counts[] = { 1, 2, 3, 8 };

// what `run` returns when the library runs on at most `threads` threads
std::vector<double> with_threads(int threads, const std::function<std::vector<double>()>& run)
{
#ifdef CGAL_LINKED_WITH_TBB
  tbb::task_arena arena(threads);
  std::vector<double> out;
  arena.execute([&] { out = run(); });
  return out;
#else
  (void)threads;
  return run();
#endif
}

void same_on_every_count(const char* what, const std::function<std::vector<double>()>& run)
{
  const std::vector<double> one = with_threads(thread_counts[0], run);
  AF_CHECK(!one.empty(), (std::string(what) + ": the run succeeded").c_str());
  for(int t : thread_counts)
  {
    if(t == thread_counts[0]) continue;
    const std::vector<double> other = with_threads(t, run);
    const double d = AF_test::max_abs_difference(one, other);
    std::printf("%s: 1 thread against %d: largest difference %.3g%s\n", what, t, d,
                AF_test::byte_identical(one, other) ? " (the same bytes)" : "");
    AF_CHECK(AF_test::byte_identical(one, other), (std::string(what) + ": the same bytes on " + std::to_string(t) +
                                                   " threads as on one").c_str());
  }
}

// the camel head scan (a border, 22,704 faces: a dozen of the assembly's chunks) with Gaussian noise of 0.2
// mean edge lengths on each coordinate, and a scalar function on it with noise of its own
Mesh noisy_camelhead(const std::string& data)
{
  Mesh m;
  CGAL::IO::read_polygon_mesh(data + "/camelhead.off", m);
  double edge = 0;
  for(auto e : edges(m)) edge += CGAL::Polygon_mesh_processing::edge_length(halfedge(e, m), m);
  edge /= double(num_edges(m));
  std::mt19937 random(55);
  std::normal_distribution<double> gauss(0.0, 0.2 * edge);
  auto f = m.add_property_map<Vertex, double>("v:f", 0.0).first;
  for(Vertex v : m.vertices())
  {
    const K::Point_3 p = m.point(v);
    m.point(v) = K::Point_3(p.x() + gauss(random), p.y() + gauss(random), p.z() + gauss(random));
    f[v] = std::sin(10 * p.x()) + 0.1 * gauss(random) / edge;
  }
  return m;
}

} // namespace

int main(int argc, char** argv)
{
  const std::string data = argc > 1 ? argv[1] : "data";
#ifdef CGAL_LINKED_WITH_TBB
  // workers for the largest arena, also on a machine with fewer cores
  const tbb::global_control workers(tbb::global_control::max_allowed_parallelism, std::size_t(8));
#endif
  Mesh fandisk;
  AF_CHECK(CGAL::IO::read_polygon_mesh(data + "/fandisk0.3_noisy.obj", fandisk), "read fandisk0.3_noisy.obj");
  const Mesh camelhead = noisy_camelhead(data);

  same_on_every_count("the default run (Fandisk0.3)", [&] {
    Mesh m = fandisk;
    const AF::Fairing_report r = AF::anisotropic_fairing(m);
    return r.succeeded() && r.steps.size() > 0 ? AF_test::coordinates(m) : std::vector<double>();
  });
  same_on_every_count("anisotropic, 4 steps (noisy camel head)", [&] {
    Mesh m = camelhead;
    const AF::Fairing_report r = AF::anisotropic_fairing(
      m, AF::parameters::relative_time_step(1e-3).number_of_iterations(4u)
           .stopping_criteria(AF::Stopping_criteria::none()).diffusion_tensor(AF::Anisotropic_diffusion_tensor()));
    return r.succeeded() && r.steps.size() == 4 ? AF_test::coordinates(m) : std::vector<double>();
  });
  same_on_every_count("coupled attribute, 3 steps (noisy camel head)", [&] {
    Mesh m = camelhead;
    auto f = m.property_map<Vertex, double>("v:f").first;
    const AF::Fairing_report r = AF::anisotropic_fairing(
      m, m.points(), f, AF::parameters::relative_time_step(1e-3).attribute_mode(AF::Attribute_mode::COUPLED)
                          .number_of_iterations(3u).stopping_criteria(AF::Stopping_criteria::none()));
    std::vector<double> out = AF_test::coordinates(m);
    for(Vertex v : m.vertices()) out.push_back(f[v]);
    return r.succeeded() && r.steps.size() == 3 ? out : std::vector<double>();
  });
  return AF_test::report();
}
