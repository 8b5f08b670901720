// Which private vertex numbering the solver should work in: the package's own Cuthill-McKee
// (Locality_ordering.h: a pseudo-peripheral start, neighbours by increasing valence, walked on the
// mesh's halfedges) against boost::cuthill_mckee_ordering (Boost.Graph, on an adjacency_list built from
// the faces), and the user's order as the baseline. For each: the time to compute the numbering
// (and, for Boost, to build its graph), the bandwidth of the vertex adjacency, and what the numbering is
// for: one assembly of M and L and one conjugate-gradient solve of (M + tau L) x = M b on the Loop
// element. Medians of RUNS, in the same run.
//
// usage: bench_vertex_ordering [DATA_DIR=<repo>/../shared/data] [RUNS=5]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/internal/assembly/Fem_assembly.h>
#include <CGAL/Anisotropic_fairing/internal/element/Ghosted_patch_cache.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Indexed_mesh.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Locality_ordering.h>
#include <CGAL/Anisotropic_fairing/internal/solve/Spd_solvers.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/cuthill_mckee_ordering.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "bench_median.h"

#ifndef AF_SOURCE_DIR
#define AF_SOURCE_DIR "."
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace AF = CGAL::Anisotropic_fairing;
namespace AFi = CGAL::Anisotropic_fairing::internal;

// the user's order: the identity
static AFi::Locality_ordering identity_ordering(const AFi::Ghost_layer& gl)
{
  AFi::Locality_ordering o;
  for(std::size_t v = 0; v < gl.real_vertices; ++v) o.old_of_new_vertex.push_back(int(v));
  o.new_of_old_vertex = o.old_of_new_vertex;
  AFi::order_faces_and_renumber(gl, o);
  return o;
}

// Boost.Graph's Cuthill-McKee on the vertex adjacency of the real faces
static AFi::Locality_ordering boost_ordering(const AFi::Ghost_layer& gl)
{
  typedef boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS,
                                boost::property<boost::vertex_color_t, boost::default_color_type,
                                                boost::property<boost::vertex_degree_t, int>>> Graph;
  const AFi::Triangle_topology& topo = *gl.topology;
  Graph g(gl.real_vertices);
  for(std::size_t f = 0; f < gl.real_faces; ++f)
    for(int k = 0; k < 3; ++k)
    {
      const int a = topo.face(f)[k], b = topo.face(f)[(k + 1) % 3];
      if(a < b || topo.opposite(3 * int(f) + k) < 0 || topo.face_of(topo.opposite(3 * int(f) + k)) >= int(gl.real_faces))
        boost::add_edge(std::size_t(a), std::size_t(b), g);   // each edge once
    }
  AFi::Locality_ordering o;
  o.old_of_new_vertex.resize(gl.real_vertices);
  std::vector<std::size_t> order(gl.real_vertices);
  boost::cuthill_mckee_ordering(g, order.begin(), boost::get(boost::vertex_color, g), boost::make_degree_map(g));
  o.new_of_old_vertex.assign(gl.real_vertices, -1);
  for(std::size_t k = 0; k < order.size(); ++k)
  {
    o.old_of_new_vertex[k] = int(order[k]);
    o.new_of_old_vertex[order[k]] = int(k);
  }
  AFi::order_faces_and_renumber(gl, o);
  return o;
}

// the largest |new(a) - new(b)| over the edges
static int bandwidth(const AFi::Locality_ordering& o)
{
  const AFi::Triangle_topology& topo = *o.layer.topology;
  int w = 0;
  for(std::size_t f = 0; f < o.layer.real_faces; ++f)
    for(int k = 0; k < 3; ++k) w = std::max(w, std::abs(topo.face(f)[k] - topo.face(f)[(k + 1) % 3]));
  return w;
}

struct Timing
{
  std::vector<double> order, assemble, solve;
  int bandwidth = 0, iterations = 0;
};

static void measure(const AFi::Indexed_mesh<Mesh>& im, const AFi::Control_matrix& P,
                    const std::function<AFi::Locality_ordering(const AFi::Ghost_layer&)>& make, Timing& t)
{
  CGAL::Real_timer clock;
  clock.start();
  const AFi::Locality_ordering o = make(im.ghost_layer());
  t.order.push_back(clock.time());
  t.bandwidth = bandwidth(o);
  const std::size_t n = im.number_of_vertices();
  AFi::Control_matrix X(P.rows(), 3);
  for(std::size_t i = 0; i < n; ++i) X.row(Eigen::Index(i)) = P.row(o.old_of_new_vertex[i]);
  AFi::Ghosted_patch_cache cache(o.layer, AFi::Quadrature_spec());
  AFi::Fem_assembler<AFi::Ghosted_patch_cache> assembler(cache, n);
  AFi::Value_array M, L;
  assembler.assemble(X, 3, AF::Isotropic_diffusion_tensor(), M, L);   // warm-up (allocations)
  clock.reset();
  const AFi::Assembly_statistics a = assembler.assemble(X, 3, AF::Isotropic_diffusion_tensor(), M, L);
  t.assemble.push_back(clock.time());
  // (M + tau L) dX = -tau L X, tau = 1e-3 l^2: a time step
  const double tau = 1e-3 * a.area / (4 * 3.14159265358979323846);
  Eigen::SparseMatrix<double> A = assembler.pattern().matrix();
  for(Eigen::Index p = 0; p < A.nonZeros(); ++p) A.valuePtr()[p] = M[std::size_t(p)] + tau * L[std::size_t(p)];
  Eigen::SparseMatrix<double> Lm = assembler.pattern().matrix();
  for(Eigen::Index p = 0; p < Lm.nonZeros(); ++p) Lm.valuePtr()[p] = -tau * L[std::size_t(p)];
  const AFi::Control_matrix B = Lm * X;
  AFi::Control_matrix dX = AFi::Control_matrix::Zero(X.rows(), 3);
  AFi::Block_conjugate_gradient cg(1e-8, 10000);
  clock.reset();
  const AFi::Solve_statistics sol = cg.solve(A, B, dX);
  t.solve.push_back(clock.time());
  t.iterations = sol.iterations;
}

int main(int argc, char** argv)
{
  const std::string dir = argc > 1 && argv[1][0] ? argv[1] : std::string(AF_SOURCE_DIR) + "/../shared/data";
  const int runs = argc > 2 ? std::atoi(argv[2]) : 5;
  struct Case { const char* file; int subdivisions; };
  const Case cases[] = { { "fertility.off", 2 }, { "camelhead.off", 2 }, { "bunny-closed.off", 2 } };
  std::printf("# bench_vertex_ordering: medians of %d runs, seconds\n\n", runs);
  std::printf("| mesh | numbering | compute it | bandwidth | one assembly | one CG solve (iterations) |\n|---|---|---:|---:|---:|---:|\n");
  for(const Case& c : cases)
  {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(dir + "/" + c.file, mesh)) { std::fprintf(stderr, "cannot read %s\n", c.file); continue; }
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(c.subdivisions));
    const AFi::Indexed_mesh<Mesh> im(mesh, AFi::Borders::GHOSTED);
    const AFi::Control_matrix P = im.read_points(mesh.points());
    const std::pair<const char*, std::function<AFi::Locality_ordering(const AFi::Ghost_layer&)>> numberings[] = {
      { "the user's order", identity_ordering },
      { "ours (Locality_ordering.h)", AFi::make_locality_ordering },
      { "boost::cuthill_mckee_ordering", boost_ordering } };
    for(const auto& numbering : numberings)
    {
      Timing t;
      for(int r = 0; r < runs; ++r) measure(im, P, numbering.second, t);
      std::printf("| %s Loop x%d (%zu F) | %s | %.3f | %d | %.3f | %.3f (%d) |\n", c.file, c.subdivisions, im.number_of_faces(),
                  numbering.first, median(t.order), t.bandwidth, median(t.assemble), median(t.solve), t.iterations);
      std::fflush(stdout);
    }
  }
  return 0;
}
