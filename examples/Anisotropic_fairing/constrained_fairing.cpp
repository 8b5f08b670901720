// Fairs a noisy mesh while holding chosen vertices exactly where they are (vertex_is_constrained_map),
// and follows the run step by step through a progress callback (which could also end it early by
// returning false). Here the held vertices are those on one side of a plane: a part of the model that
// must not move, e.g. where it meets another part.
//
// usage: constrained_fairing INPUT [OUTPUT.off]   (e.g. data/bumpy.off)
// Exits 1 unless every held vertex kept its position to the last bit and the others moved.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include <cstdio>
#include <iostream>
#include <random>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace AF = CGAL::Anisotropic_fairing;

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " INPUT [OUTPUT.off]\n";
    return 2;
  }
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh))
  {
    std::cerr << "cannot read " << argv[1] << "\n";
    return 1;
  }
  // some noise to remove
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0, 0.002 * (box.xmax() - box.xmin()));
  for(Vertex v : mesh.vertices()) mesh.point(v) = mesh.point(v) + K::Vector_3(noise(rng), noise(rng), noise(rng));

  // hold the vertices below the middle of the bounding box in z
  const double cut = 0.5 * (box.zmin() + box.zmax());
  auto held = mesh.add_property_map<Vertex, bool>("v:held", false).first;
  for(Vertex v : mesh.vertices()) held[v] = mesh.point(v).z() < cut;
  const std::vector<K::Point_3> before(mesh.points().begin(), mesh.points().end());

  auto progress = [](const AF::Fairing_step& s) {
    std::printf("step %zu: time %.4g, area %.6g, largest displacement %.4g, %d solver iterations\n", s.step, s.time, s.area,
                s.max_displacement, s.solver_iterations);
    return true;   // false would end the run here (successfully)
  };
  const AF::Fairing_report report = AF::anisotropic_fairing(mesh, AF::parameters::vertex_is_constrained_map(held).callback(progress));
  if(!report.succeeded())
  {
    std::cerr << "fairing failed (" << AF::to_string(report.status) << "): " << report.message << "\n";
    return 1;
  }
  std::size_t kept = 0, moved = 0, held_count = 0;
  for(Vertex v : mesh.vertices())
  {
    const bool same = mesh.point(v) == before[std::size_t(v)];
    if(held[v]) { ++held_count; kept += same ? 1 : 0; }
    else moved += same ? 0 : 1;
  }
  std::cout << report.steps.size() << " steps (stopped: " << AF::to_string(report.stop_reason) << "); " << kept << " of "
            << held_count << " held vertices unchanged, " << moved << " of " << mesh.number_of_vertices() - held_count << " others moved\n";
  if(argc > 2) CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(17));
  return kept == held_count && moved > 0 ? 0 : 1;
}
