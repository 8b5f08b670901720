// A denoising pair (a noisy mesh and the noise-free one, the same connectivity) read in file order, and the
// denoising benchmark's measure of a result: the mean angle between corresponding face normals.
#ifndef AF_TEST_SUPPORT_DENOISING_PAIR_H
#define AF_TEST_SUPPORT_DENOISING_PAIR_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <string>
#include <vector>

namespace AF_test {

typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Pair_mesh;

// in file order (read_polygon_mesh may reorder), so faces correspond between the two files of the pair
inline bool read_obj_in_order(const std::string& path, Pair_mesh& mesh)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<Pair_mesh::Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if(!CGAL::IO::read_OBJ(path, points, polygons) || !PMP::is_polygon_soup_a_polygon_mesh(polygons)) return false;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return num_vertices(mesh) == points.size() && num_faces(mesh) == polygons.size();
}

inline CGAL::Epick::Vector_3 face_normal(const Pair_mesh& m, Pair_mesh::Face_index f)
{
  const auto h = m.halfedge(f);
  const auto &a = m.point(m.source(h)), &b = m.point(m.target(h)), &c = m.point(m.target(m.next(h)));
  return CGAL::cross_product(b - a, c - a);
}

// mean angle in degrees between corresponding face normals
inline double mean_normal_angle(const Pair_mesh& m, const Pair_mesh& reference)
{
  double sum = 0;
  auto r = reference.faces().begin();
  for(Pair_mesh::Face_index f : m.faces())
  {
    const CGAL::Epick::Vector_3 n = face_normal(m, f), t = face_normal(reference, *r++);
    sum += std::atan2(std::sqrt(CGAL::cross_product(n, t).squared_length()), n * t);
  }
  return sum / double(num_faces(m)) * 180 / 3.14159265358979323846;
}

} // namespace AF_test

#endif // AF_TEST_SUPPORT_DENOISING_PAIR_H
