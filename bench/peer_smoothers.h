// Smoothers the denoising benchmarks compare against (none of them is part of the library):
//  - OpenMesh's JacobiLaplaceSmootherT (Debian libopenmesh-dev), C0 (umbrella) and C1 (bi-umbrella), with
//    uniform or cotangent weights, moving vertices tangentially and normally (OpenMesh holds the border
//    vertices, and for C1 their neighbours);
//  - Taubin's lambda|mu smoothing (SIGGRAPH 1995), uniform weights, pass band k_pb = 0.1, written for
//    this comparison from the paper;
//  - bilateral normal filtering (bilateral_normal_filter.h).
// Border vertices are held by ours and by these.

#ifndef AF_BENCH_PEER_SMOOTHERS_H
#define AF_BENCH_PEER_SMOOTHERS_H

#include "bench_cases.h"
#include "bilateral_normal_filter.h"

#ifdef AF_WITH_OPENMESH
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Smoother/JacobiLaplaceSmootherT.hh>
#endif

#include <array>
#include <cmath>
#include <vector>

#ifdef AF_WITH_OPENMESH
typedef OpenMesh::TriMesh_ArrayKernelT<OpenMesh::DefaultTraitsDouble> Open_mesh;

// JacobiLaplaceSmootherT with the choice of weights: OpenMesh takes uniform weights for the component
// Tangential_and_Normal and cotangent weights for Normal, which otherwise moves the vertices the same way
// (only Tangential projects the motion; the local error check is off)
class Jacobi_smoother : public OpenMesh::Smoother::JacobiLaplaceSmootherT<Open_mesh>
{
public:
  Jacobi_smoother(Open_mesh& m, bool second_order, bool cotangent) : JacobiLaplaceSmootherT<Open_mesh>(m)
  {
    initialize(cotangent ? Normal : Tangential_and_Normal, second_order ? C1 : C0);
  }
};

// Same vertex and face order as m.
inline Open_mesh to_open_mesh(const Mesh& m)
{
  Open_mesh o;
  std::vector<Open_mesh::VertexHandle> v;
  for(Mesh::Vertex_index i : m.vertices())
  {
    const Point& p = m.point(i);
    v.push_back(o.add_vertex(Open_mesh::Point(p.x(), p.y(), p.z())));
  }
  for(Mesh::Face_index f : m.faces())
  {
    std::vector<Open_mesh::VertexHandle> face;
    for(Mesh::Vertex_index i : CGAL::vertices_around_face(m.halfedge(f), m)) face.push_back(v[i.idx()]);
    o.add_face(face);
  }
  o.request_vertex_normals();
  o.request_face_normals();
  o.update_normals();
  return o;
}

inline void copy_points(const Open_mesh& o, Mesh& m)
{
  for(Mesh::Vertex_index i : m.vertices())
  {
    const Open_mesh::Point& p = o.point(Open_mesh::VertexHandle(int(i.idx())));
    m.point(i) = Point(p[0], p[1], p[2]);
  }
}
#endif

// One-ring neighbours of each vertex (uniform weights) and whether it is on a border.
struct Vertex_rings
{
  std::vector<std::vector<std::size_t> > ring;
  std::vector<bool> border;
  explicit Vertex_rings(const Mesh& m) : ring(num_vertices(m)), border(num_vertices(m), false)
  {
    for(Mesh::Vertex_index v : m.vertices())
    {
      border[v.idx()] = m.is_border(v, false);
      for(Mesh::Vertex_index w : CGAL::vertices_around_target(m.halfedge(v), m)) ring[v.idx()].push_back(w.idx());
    }
  }
};

// `pairs` steps of lambda, then mu (uniform umbrella), on the interior vertices.
inline void taubin_smooth(Mesh& m, const Vertex_rings& r, double lambda, int pairs)
{
  const double mu = 1.0 / (0.1 - 1.0 / lambda);
  std::vector<Vector> d(num_vertices(m));
  for(int k = 0; k < 2 * pairs; ++k)
  {
    const double f = k % 2 == 0 ? lambda : mu;
    for(Mesh::Vertex_index v : m.vertices())
    {
      Vector u = CGAL::NULL_VECTOR;
      for(std::size_t w : r.ring[v.idx()]) u = u + (m.point(Mesh::Vertex_index(Mesh::size_type(w))) - m.point(v));
      d[v.idx()] = r.ring[v.idx()].empty() || r.border[v.idx()] ? CGAL::NULL_VECTOR : u / double(r.ring[v.idx()].size());
    }
    for(Mesh::Vertex_index v : m.vertices()) m.point(v) = m.point(v) + f * d[v.idx()];
  }
}

#endif // AF_BENCH_PEER_SMOOTHERS_H
