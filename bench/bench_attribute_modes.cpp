// Cost of fairing functions on surfaces, by attribute mode (Bajaj & Xu's cases a-d), side by side in
// one run: geometry only; 3 attribute columns carried with the geometry (separate); the same coupled
// in R^6; attributes only on the fixed surface (one assembly and one factorisation, then a solve per
// step). Median of several runs of a 5-step call with relative_time_step(1e-3) and no early stop.
//
// usage: bench_attribute_modes [DATA_DIR] [RUNS]     (default <repo>/../shared/data, 3 runs)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "bench_median.h"

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace AF = CGAL::Anisotropic_fairing;

int main(int argc, char** argv)
{
  const std::string dir = argc > 1 && argv[1][0] ? argv[1] : std::string(AF_SOURCE_DIR) + "/../shared/data";
  const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
  std::printf("# bench_attribute_modes: %s, median of %d runs, 5 steps of relative_time_step 1e-3, Stopping_criteria::none()\n\n",
              dir.c_str(), runs);
  std::printf("| mesh | mode | columns | whole call | set-up | assembly per step | solve per step | first / last solve | solver |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|---:|---|\n");
  for(const char* file : { "bunny-closed.off", "armadillo.obj" })
  {
    Mesh input;
    if(!CGAL::IO::read_polygon_mesh(dir + "/" + file, input)) { std::fprintf(stderr, "cannot read %s\n", file); return 1; }
    // a smooth field with 1% noise, its range a tenth of the model's size: in the coupled mode the
    // attributes then shape the manifold without dominating it (with a unit range on the 0.15-wide
    // bunny, the coupled surface is mostly attribute noise and pinched at step 4; with 10% noise,
    // about two edge lengths on the armadillo, it pinched at step 5)
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(input);
    const double size = std::max({ box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin() });
    std::mt19937 rng(1);
    std::normal_distribution<double> noise(0, 0.01);
    std::vector<std::array<double, 3>> values(input.number_of_vertices());
    for(Vertex v : input.vertices())
    {
      const K::Point_3& p = input.point(v);
      const double x = (p.x() - box.xmin()) / size, y = (p.y() - box.ymin()) / size, z = (p.z() - box.zmin()) / size;
      values[std::size_t(v)] = { { 0.1 * size * (std::sin(6 * x) + noise(rng)), 0.1 * size * (std::cos(5 * y) + noise(rng)),
                                   0.1 * size * (z + noise(rng)) } };
    }
    struct Mode { AF::Attribute_mode mode; const char* name; };
    for(const Mode& m : { Mode{ AF::Attribute_mode::GEOMETRY_ONLY, "geometry only (d)" }, Mode{ AF::Attribute_mode::SEPARATE, "separate (b)" },
                          Mode{ AF::Attribute_mode::COUPLED, "coupled (a)" }, Mode{ AF::Attribute_mode::ATTRIBUTES_ONLY, "attributes only (c)" } })
    {
      std::vector<double> whole, setup, assemble, solve, first_solve, last_solve;
      AF::Fairing_report r;
      for(int k = 0; k < runs; ++k)
      {
        Mesh mesh = input;
        auto a = mesh.add_property_map<Vertex, std::array<double, 3>>("v:a").first;
        for(Vertex v : mesh.vertices()) a[v] = values[std::size_t(v)];
        r = AF::anisotropic_fairing(mesh, mesh.points(), a,
                                    AF::parameters::attribute_mode(m.mode).number_of_iterations(5u)
                                                   .stopping_criteria(AF::Stopping_criteria::none()));
        if(!r.succeeded()) { std::fprintf(stderr, "%s, %s: %s\n", file, m.name, r.message.c_str()); return 1; }
        double as = 0, so = 0;
        for(const AF::Fairing_step& s : r.steps) { as += s.assemble_seconds; so += s.solve_seconds; }
        first_solve.push_back(r.steps.front().solve_seconds);
        last_solve.push_back(r.steps.back().solve_seconds);
        whole.push_back(r.total_seconds);
        setup.push_back(r.setup_seconds);
        assemble.push_back(as / double(r.steps.size()));
        solve.push_back(so / double(r.steps.size()));
      }
      std::printf("| %s (%zu V) | %s | %zu | %.3f | %.3f | %.3f | %.3f | %.3f / %.3f | %s |\n", file, input.number_of_vertices(),
                  m.name, m.mode == AF::Attribute_mode::ATTRIBUTES_ONLY ? r.attribute_dimension : 3 + r.attribute_dimension,
                  median(whole), median(setup), median(assemble), median(solve), median(first_solve), median(last_solve),
                  r.used_cholesky ? "LDL^T" : "CG");
    }
  }
  return 0;
}
