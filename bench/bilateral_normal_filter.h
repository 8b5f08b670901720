// Bilateral normal filtering (Zheng, Fu, Au and Tai, TVCG 2011, the local iterative scheme), a peer of the
// denoising benchmarks (bench_peers): face normals filtered with a spatial Gaussian of the centroid distance
// (sigma_c: the mean distance between the centroids of faces sharing an edge) and a range Gaussian of the
// normal difference (sigma_s), over the faces sharing a vertex, weighted by area; then the vertices are
// fitted to the filtered normals (Sun et al. 2007), 20 iterations, border vertices held. Written for this
// comparison from the papers; not part of the library.

#ifndef AF_BENCH_BILATERAL_NORMAL_FILTER_H
#define AF_BENCH_BILATERAL_NORMAL_FILTER_H

#include <CGAL/boost/graph/helpers.h>

#include "bench_cases.h"

#include <algorithm>
#include <cmath>
#include <vector>

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

  void run(Mesh& m, const std::vector<bool>& border, double sigma_s, int iterations) const
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
        d[v.idx()] = count == 0 || border[v.idx()] ? CGAL::NULL_VECTOR : u / double(count);
      }
      for(Mesh::Vertex_index v : m.vertices()) m.point(v) = m.point(v) + d[v.idx()];
    }
  }
};

#endif // AF_BENCH_BILATERAL_NORMAL_FILTER_H
