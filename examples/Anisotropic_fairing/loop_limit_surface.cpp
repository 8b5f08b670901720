// Evaluates the Loop limit surface of a triangle mesh and writes a denser triangulation whose vertices
// lie exactly on it (with the limit normals), at full double precision. Also reads the curvature of the
// limit surface into property maps: at the control vertices (vertex_curvatures()) and at every vertex
// of the denser mesh (resample()'s vertex_curvature_map), and prints its range.
//
// usage: loop_limit_surface INPUT OUTPUT [LEVELS=2]
//   INPUT, OUTPUT: OFF, OBJ, PLY, STL, ... (by extension); OUTPUT gets 4^LEVELS times as many faces.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace AF = CGAL::Anisotropic_fairing;

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " INPUT OUTPUT [LEVELS=2]\n";
    return 2;
  }
  const std::string input = argv[1], output = argv[2];
  const int levels = argc > 3 ? std::atoi(argv[3]) : 2;

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh))
  {
    std::cerr << "error: cannot read a polygon mesh from " << input << "\n";
    return 1;
  }
  try
  {
    AF::Loop_limit_surface<Mesh> surface(mesh);
    std::cout << input << ": " << surface.number_of_vertices() << " vertices, " << surface.number_of_faces()
              << " faces, " << surface.number_of_patch_categories() << " patch categories\n"
              << "area of the control mesh: " << CGAL::Polygon_mesh_processing::area(mesh)
              << ", of the limit surface: " << surface.area() << "\n";

    typedef AF::Loop_limit_surface<Mesh>::Curvature Curvature;
    auto curvature = mesh.add_property_map<Mesh::Vertex_index, Curvature>("v:curvature").first;
    surface.vertex_curvatures(curvature);
    double lowest = 0, highest = 0;
    for(Mesh::Vertex_index v : vertices(mesh))
    {
      lowest = (std::min)(lowest, curvature[v].k1);
      highest = (std::max)(highest, curvature[v].k2);
    }
    std::cout << "principal curvatures at the control vertices in [" << lowest << ", " << highest << "]\n";

    Mesh fine;
    auto normals = fine.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:normal").first;
    auto fine_curvature = fine.add_property_map<Mesh::Vertex_index, Curvature>("v:curvature").first;
    surface.resample(unsigned(levels < 0 ? 0 : levels), fine,
                     AF::parameters::vertex_normal_map(normals).vertex_curvature_map(fine_curvature));
    double largest_mean = 0;
    for(Mesh::Vertex_index v : vertices(fine))
      largest_mean = (std::max)(largest_mean, std::sqrt(fine_curvature[v].mean_curvature_vector.squared_length()));
    std::cout << "largest |H| at the vertices of the denser mesh: " << largest_mean << "\n";
    if(!CGAL::IO::write_polygon_mesh(output, fine, CGAL::parameters::stream_precision(17).vertex_normal_map(normals)))
    {
      std::cerr << "error: cannot write " << output << "\n";
      return 1;
    }
    std::cout << "wrote " << output << ": " << fine.number_of_vertices() << " vertices, " << fine.number_of_faces()
              << " faces on the limit surface (" << levels << " levels)\n";
  }
  catch(const AF::Input_error& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
