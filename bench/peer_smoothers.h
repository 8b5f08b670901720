// Smoothers the denoising benchmarks compare against (none of them is part of the library):
//  - OpenMesh's JacobiLaplaceSmootherT (Debian libopenmesh-dev), C0 (umbrella) and C1 (bi-umbrella), with
//    uniform or cotangent weights, moving vertices tangentially and normally (OpenMesh holds the border
//    vertices, and for C1 their neighbours);
//  - Taubin's lambda|mu smoothing (SIGGRAPH 1995), uniform weights, pass band k_pb = 0.1;
//  - bilateral normal filtering (Zheng, Fu, Au and Tai, TVCG 2011, the local iterative scheme): face
//    normals filtered with a spatial Gaussian of the centroid distance (sigma_c: the mean distance between
//    the centroids of faces sharing an edge) and a range Gaussian of the normal difference (sigma_s), over
//    the faces sharing a vertex, weighted by area; then the vertices are fitted to the filtered normals
//    (Sun et al. 2007), 20 iterations. Written for this comparison from the papers.
// Border vertices are held by ours and by these.

#ifndef AF_BENCH_PEER_SMOOTHERS_H
#define AF_BENCH_PEER_SMOOTHERS_H

#include "bench_cases.h"

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

// Bilateral normal filtering: `iterations` normal-filtering passes, then the vertex update.
struct Bilateral_normal_filter
{
  std::vector<std::vector<std::size_t> > neighbours;   // faces sharing a vertex with each face
  double sigma_c = 0;

  explicit Bilateral_normal_filter(const Mesh& m) : neighbours(num_faces(m))
  {
    double sum = 0;
    std::size_t count = 0;
    for(Mesh::Face_index f : m.faces())
    {
      std::vector<std::size_t>& n = neighbours[f.idx()];
      for(Mesh::Vertex_index v : CGAL::vertices_around_face(m.halfedge(f), m))
        for(Mesh::Face_index g : CGAL::faces_around_target(m.halfedge(v), m))
          if(g != Mesh::null_face() && g != f && std::find(n.begin(), n.end(), g.idx()) == n.end()) n.push_back(g.idx());
      for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(m.halfedge(f), m))
        if(!m.is_border(m.opposite(h)))
        {
          sum += std::sqrt(CGAL::squared_distance(centroid(m, f), centroid(m, m.face(m.opposite(h)))));
          ++count;
        }
    }
    sigma_c = count ? sum / double(count) : 1.0;
  }

  static Point centroid(const Mesh& m, Mesh::Face_index f)
  {
    const Mesh::Halfedge_index h = m.halfedge(f);
    return CGAL::centroid(m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h))));
  }

  void run(Mesh& m, const Vertex_rings& r, double sigma_s, int iterations) const
  {
    const std::size_t nf = num_faces(m);
    std::vector<Vector> n(nf), filtered(nf);
    std::vector<Point> c(nf);
    std::vector<double> area(nf);
    for(Mesh::Face_index f : m.faces())
    {
      const Vector a = face_normal(m, f);
      area[f.idx()] = std::sqrt(a.squared_length()) / 2;
      n[f.idx()] = area[f.idx()] > 0 ? a / (2 * area[f.idx()]) : CGAL::NULL_VECTOR;
      c[f.idx()] = centroid(m, f);
    }
    for(int k = 0; k < iterations; ++k)
    {
      for(std::size_t i = 0; i < nf; ++i)
      {
        Vector s = area[i] * n[i];
        for(std::size_t j : neighbours[i])
        {
          const double wc = std::exp(-CGAL::squared_distance(c[i], c[j]) / (2 * sigma_c * sigma_c));
          const double ws = std::exp(-(n[i] - n[j]).squared_length() / (2 * sigma_s * sigma_s));
          s = s + area[j] * wc * ws * n[j];
        }
        const double l = std::sqrt(s.squared_length());
        filtered[i] = l > 0 ? s / l : n[i];
      }
      n.swap(filtered);
    }
    // vertices fitted to the filtered normals: each moves toward the planes of its faces
    std::vector<Vector> d(num_vertices(m));
    for(int k = 0; k < 20; ++k)
    {
      for(Mesh::Face_index f : m.faces()) c[f.idx()] = centroid(m, f);
      for(Mesh::Vertex_index v : m.vertices())
      {
        Vector u = CGAL::NULL_VECTOR;
        int count = 0;
        for(Mesh::Face_index f : CGAL::faces_around_target(m.halfedge(v), m))
          if(f != Mesh::null_face()) { u = u + n[f.idx()] * (n[f.idx()] * (c[f.idx()] - m.point(v))); ++count; }
        d[v.idx()] = count == 0 || r.border[v.idx()] ? CGAL::NULL_VECTOR : u / double(count);
      }
      for(Mesh::Vertex_index v : m.vertices()) m.point(v) = m.point(v) + d[v.idx()];
    }
  }
};

#endif // AF_BENCH_PEER_SMOOTHERS_H
