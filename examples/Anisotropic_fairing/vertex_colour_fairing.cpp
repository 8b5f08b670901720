// Fairs noisy vertex colours (CGAL::IO::Color, the "v:color" property that CGAL's OFF and PLY
// readers fill) on a scanned surface, geometry fixed (Bajaj & Xu's case c). The colours are a smooth
// pattern plus Gaussian noise; results are rounded and clamped to 0..255 by the attribute traits.
//
// usage: vertex_colour_fairing INPUT [OUTPUT.off]
// Prints the RMS colour error before and after; exits 1 if it did not halve.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include <algorithm>
#include <array>
#include <cmath>
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
  // a smooth pattern over the bounding box, and its noisy version
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  const double size = std::max({ box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin() });
  std::vector<std::array<double, 3>> clean(mesh.number_of_vertices());
  auto colour = mesh.add_property_map<Vertex, CGAL::IO::Color>("v:color").first;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0, 25);
  for(Vertex v : mesh.vertices())
  {
    const K::Point_3& p = mesh.point(v);
    const double x = (p.x() - box.xmin()) / size, y = (p.y() - box.ymin()) / size, z = (p.z() - box.zmin()) / size;
    clean[std::size_t(v)] = { { 128 + 90 * std::sin(6 * x), 128 + 90 * std::cos(5 * y), 128 + 90 * std::sin(4 * (x + z)) } };
    auto channel = [&](double c) { return (unsigned char)std::lround(std::min(255.0, std::max(0.0, c + noise(rng)))); };
    const auto& c = clean[std::size_t(v)];
    colour[v] = CGAL::IO::Color(channel(c[0]), channel(c[1]), channel(c[2]));
  }
  auto rms_error = [&] {
    double s = 0;
    for(Vertex v : mesh.vertices())
      for(int k = 0; k < 3; ++k) s += std::pow(double(colour[v][k]) - clean[std::size_t(v)][std::size_t(k)], 2);
    return std::sqrt(s / double(3 * mesh.number_of_vertices()));
  };
  const double before = rms_error();

  const AF::Fairing_report report = AF::anisotropic_fairing(mesh, mesh.points(), colour,
      AF::parameters::attribute_mode(AF::Attribute_mode::ATTRIBUTES_ONLY).relative_time_step(1e-4).number_of_iterations(3));
  if(!report.succeeded())
  {
    std::cerr << "fairing failed: " << report.message << "\n";
    return 1;
  }
  const double after = rms_error();
  std::cout << argv[1] << ": " << mesh.number_of_vertices() << " vertices, RMS colour error " << before << " -> " << after
            << " after " << report.steps.size() << " steps (stopped: " << AF::to_string(report.stop_reason) << ", "
            << report.total_seconds << " s)\n";
  if(argc > 2) CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(17));
  return 2 * after <= before ? 0 : 1;
}
