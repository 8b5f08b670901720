// Fairs the geometry and the vertex colours of a CGAL::Polyhedron_3 together: both are noisy, and the
// colours are faired on the surface as it is faired (Attribute_mode::SEPARATE, Bajaj & Xu's case b).
// The colours live in a std::map keyed by the vertex handles (any readable and writable property map
// will do); their value type, std::array<double, 3>, has Vector_attribute_traits.
//
// usage: polyhedron_geometry_and_colours INPUT [OUTPUT.off]   (e.g. data/bumpy.off)
// Exits 1 unless the colour noise (root mean square) fell by a third and the face normals came closer to
// those before noise.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <random>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef boost::graph_traits<Polyhedron>::vertex_descriptor Vertex;
typedef std::array<double, 3> Colour;   // red, green, blue in 0..1
namespace AF = CGAL::Anisotropic_fairing;

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " INPUT [OUTPUT.off]\n";
    return 2;
  }
  Polyhedron mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh))
  {
    std::cerr << "cannot read " << argv[1] << "\n";
    return 1;
  }
  // clean colours from the position, then noise on both
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double size = box.xmax() - box.xmin();
  std::map<Vertex, Colour> clean_colour, colour_values;
  const Polyhedron clean = mesh;
  std::mt19937 rng(11);
  std::normal_distribution<double> colour_noise(0, 0.1), point_noise(0, 0.003 * size);
  for(Vertex v : vertices(mesh))
  {
    const K::Point_3 p = v->point();
    clean_colour[v] = { { 0.5 + 0.4 * std::sin(3 * p.x() / size), 0.5 + 0.4 * std::cos(2 * p.y() / size), 0.5 } };
    colour_values[v] = { { clean_colour[v][0] + colour_noise(rng), clean_colour[v][1] + colour_noise(rng), 0.5 + colour_noise(rng) } };
    v->point() = p + K::Vector_3(point_noise(rng), point_noise(rng), point_noise(rng));
  }
  boost::associative_property_map<std::map<Vertex, Colour>> colours(colour_values);
  // the squared colour error, and the mean angle (degrees) between the face normals and those before noise
  auto errors = [&](double& colour_error, double& normal_error) {
    colour_error = normal_error = 0;
    for(Vertex v : vertices(mesh))
      for(int k = 0; k < 3; ++k) colour_error += std::pow(colour_values[v][std::size_t(k)] - clean_colour[v][std::size_t(k)], 2);
    auto f = faces(mesh).begin();
    for(auto g : faces(clean))
    {
      const double c = CGAL::Polygon_mesh_processing::compute_face_normal(*f++, mesh) * CGAL::Polygon_mesh_processing::compute_face_normal(g, clean);
      normal_error += std::acos(std::max(-1.0, std::min(1.0, c))) * 180 / CGAL_PI / double(num_faces(mesh));
    }
  };
  double colour_before, normal_before;
  errors(colour_before, normal_before);

  // the default run: parameters chosen from the mesh's noise; the colours go with the geometry
  const AF::Fairing_report report = AF::anisotropic_fairing(mesh, colours, AF::parameters::attribute_mode(AF::Attribute_mode::SEPARATE));
  if(!report.succeeded())
  {
    std::cerr << "fairing failed (" << AF::to_string(report.status) << "): " << report.message << "\n";
    return 1;
  }
  double colour_after, normal_after;
  errors(colour_after, normal_after);
  std::cout << argv[1] << ": " << report.steps.size() << " steps (" << report.selected_tensor << " kept); squared colour error "
            << colour_before << " -> " << colour_after << ", face-normal error " << normal_before << " -> " << normal_after << " degrees\n";
  if(argc > 2) CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(17));
  return 9 * colour_after <= 4 * colour_before && normal_after < normal_before ? 0 : 1;
}
