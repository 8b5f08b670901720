// How close a result of bench_denoising is to the noise-free Original of its pair:
//   angle  mean angle in degrees between corresponding face normals of the result and of Original
//   dist   mean distance of the result's vertices to the Original surface (AABB tree), divided by
//          the bounding-box diagonal of Original
// Faces and vertices correspond by index (a result is a copy of Noisy, read in file order like Original).

#ifndef AF_BENCH_DENOISING_QUALITY_H
#define AF_BENCH_DENOISING_QUALITY_H

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include "bench_cases.h"
#include "loop_limit.h"

#include <cmath>
#include <limits>
#include <vector>

struct Quality
{
  double angle = std::numeric_limits<double>::quiet_NaN();
  double dist = std::numeric_limits<double>::quiet_NaN();
  bool ok() const { return std::isfinite(angle) && std::isfinite(dist); }
};

// Original, with what the measures need: its face normals, its AABB tree and its bounding-box diagonal.
struct Reference
{
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;

  explicit Reference(const Mesh& m)
    : mesh(m), tree(faces(m).first, faces(m).second, m), diagonal(bbox_diagonal(m)), normals(face_normals(m))
  {
    tree.accelerate_distance_queries();
  }
  const Mesh& mesh;
  Tree tree;
  double diagonal = 0;
  std::vector<Vector> normals;
};

// Both measures; both NaN if a position is not finite.
Quality evaluate(const Mesh& m, const Reference& ref)
{
  Quality q;
  if(!finite_points(m)) return q;
  double dist = 0;
  for(Mesh::Vertex_index v : m.vertices()) dist += std::sqrt(ref.tree.squared_distance(m.point(v)));
  q.angle = normal_error(m, ref.normals);
  q.dist = dist / double(num_vertices(m)) / ref.diagonal;
  return q;
}

// The measures of the Loop limit surface of the control mesh `m`.
Quality limit_quality(const Mesh& m, const Reference& ref) { return evaluate(limit_mesh(m), ref); }

// The angle (degrees) of each face's normal to that of Original.
std::vector<double> face_angles(const Mesh& m, const Reference& ref)
{
  std::vector<double> a;
  std::size_t i = 0;
  for(Mesh::Face_index f : m.faces()) a.push_back(normal_angle(face_normal(m, f), ref.normals[i++]) * 180.0 / pi);
  return a;
}

#endif // AF_BENCH_DENOISING_QUALITY_H
