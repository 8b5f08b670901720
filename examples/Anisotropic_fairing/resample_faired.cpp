// Fairs a noisy mesh and resamples the smooth result at a higher resolution: the faired surface is the
// Loop limit surface of the faired control points, which control_point_map gives back next to the
// limit points written into the mesh, and Loop_limit_surface::resample() puts 4^levels triangles on it
// per input triangle, with the exact normals of the limit surface (Bajaj & Xu's "new attributed meshes
// at a higher resolution").
//
// usage: resample_faired INPUT [LEVELS=2] [OUTPUT.off]   (e.g. data/bumpy.off, to which it adds noise)
// Exits 1 unless the finer mesh has 4^levels times the faces and its vertices at the input's vertices
// are the faired limit points written.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>
#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <cstdlib>
#include <random>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace AF = CGAL::Anisotropic_fairing;

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " INPUT [LEVELS=2] [OUTPUT.off]\n";
    return 2;
  }
  const unsigned levels = argc > 2 ? unsigned(std::atoi(argv[2])) : 2u;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh))
  {
    std::cerr << "cannot read " << argv[1] << "\n";
    return 1;
  }
  // some noise to remove
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0, 0.002 * (box.xmax() - box.xmin()));
  for(Vertex v : mesh.vertices()) mesh.point(v) = mesh.point(v) + K::Vector_3(noise(rng), noise(rng), noise(rng));

  // the faired limit points go into the mesh, the control points they come from into `control`
  std::vector<K::Point_3> control(mesh.number_of_vertices());
  const AF::Fairing_report report = AF::anisotropic_fairing(mesh, AF::parameters::control_point_map(CGAL::make_property_map(control)));
  if(!report.succeeded())
  {
    std::cerr << "fairing failed (" << AF::to_string(report.status) << "): " << report.message << "\n";
    return 1;
  }
  Mesh control_mesh = mesh;
  for(Vertex v : control_mesh.vertices()) control_mesh.point(v) = control[std::size_t(v)];

  const AF::Loop_limit_surface<Mesh> surface(control_mesh);
  Mesh fine;
  auto normals = fine.add_property_map<Vertex, K::Vector_3>("v:normal").first;
  surface.resample(levels, fine, AF::parameters::vertex_normal_map(normals));
  std::cout << argv[1] << ": faired in " << report.steps.size() << " steps (" << report.selected_tensor << " kept), resampled to "
            << fine.number_of_vertices() << " vertices and " << fine.number_of_faces() << " faces\n";
  if(argc > 3 && !CGAL::IO::write_polygon_mesh(argv[3], fine, CGAL::parameters::stream_precision(17).vertex_normal_map(normals)))
  {
    std::cerr << "cannot write " << argv[3] << "\n";
    return 1;
  }
  // the finer mesh starts with the input's vertices, at the faired limit points (unless the run stopped
  // before its first step part of the way to them: Fairing_report::limit_weight)
  if(report.limit_weight < 1) return 0;
  double largest = 0;
  for(Vertex v : mesh.vertices())
    largest = std::max(largest, std::sqrt(CGAL::squared_distance(fine.point(v), mesh.point(v))));
  const bool faces = fine.number_of_faces() == mesh.number_of_faces() << (2 * levels);
  std::cout << "largest distance from a coarse vertex of the finer mesh to the faired point written: " << largest << "\n";
  return faces && largest < 1e-12 ? 0 : 1;
}
