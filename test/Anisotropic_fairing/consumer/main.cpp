// Consumer of the INSTALLED package (test `consumer_find_package`): built against the headers
// and CMake package files found through find_package(Anisotropic_fairing).
// Builds a regular octahedron and prints the area of its Loop limit surface.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>

#include <cmath>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex;

int main()
{
  Mesh mesh;
  const Vertex px = mesh.add_vertex(Point( 1, 0, 0));
  const Vertex nx = mesh.add_vertex(Point(-1, 0, 0));
  const Vertex py = mesh.add_vertex(Point( 0, 1, 0));
  const Vertex ny = mesh.add_vertex(Point( 0,-1, 0));
  const Vertex pz = mesh.add_vertex(Point( 0, 0, 1));
  const Vertex nz = mesh.add_vertex(Point( 0, 0,-1));

  // Eight faces, oriented with outward normals.
  mesh.add_face(px, py, pz);
  mesh.add_face(py, nx, pz);
  mesh.add_face(nx, ny, pz);
  mesh.add_face(ny, px, pz);
  mesh.add_face(py, px, nz);
  mesh.add_face(nx, py, nz);
  mesh.add_face(ny, nx, nz);
  mesh.add_face(px, ny, nz);

  if(mesh.number_of_vertices() != 6 || mesh.number_of_faces() != 8) {
    std::cerr << "failed to build the octahedron" << std::endl;
    return 1;
  }

  CGAL::Anisotropic_fairing::Loop_limit_surface<Mesh> surface(mesh);
  const double area = surface.area();
  std::cout << "Loop limit surface area of the octahedron: " << area << std::endl;

  return (std::isfinite(area) && area > 0) ? 0 : 1;
}
