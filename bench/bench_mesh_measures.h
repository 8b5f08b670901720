// Measures of a Surface_mesh shared by the benchmarks.

#ifndef AF_BENCH_MESH_MEASURES_H
#define AF_BENCH_MESH_MEASURES_H

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/squared_distance_3.h>

#include <cmath>
#include <cstddef>

// the library's definition (Fairing_report::mean_edge_length): every face's three edges, averaged
template <class Point>
double mean_edge_length(const CGAL::Surface_mesh<Point>& m)
{
  double sum = 0;
  std::size_t count = 0;
  for(auto f : m.faces())
    for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m))
    {
      sum += std::sqrt(CGAL::squared_distance(m.point(m.source(h)), m.point(m.target(h))));
      ++count;
    }
  return count ? sum / double(count) : 0.0;
}

#endif // AF_BENCH_MESH_MEASURES_H
