// Geometry and mesh helpers of test_limit_surface_borders.cpp, computed without the library: distances,
// barycentric combinations, the mass matrix's invariants, border loops and border neighbours.

#ifndef AF_TEST_SUPPORT_BORDER_MESH_HELPERS_H
#define AF_TEST_SUPPORT_BORDER_MESH_HELPERS_H

#include "check.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <string>

namespace AF_border_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index V;
typedef Mesh::Face_index F;

inline double distance(const Point& a, const Point& b) { return std::sqrt(CGAL::squared_distance(a, b)); }
inline double norm(const Vector& v) { return std::sqrt(v.squared_length()); }

// The face's vertices in the order that defines evaluate()'s barycentric coordinates.
template <typename TM>
std::array<typename boost::graph_traits<TM>::vertex_descriptor, 3> corners(typename boost::graph_traits<TM>::face_descriptor f, const TM& tm)
{
  std::array<typename boost::graph_traits<TM>::vertex_descriptor, 3> c;
  int k = 0;
  for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) c[std::size_t(k++)] = v;
  return c;
}

inline Point combination(const std::array<Point, 3>& p, const std::array<double, 3>& b)
{
  return Point(b[0] * p[0].x() + b[1] * p[1].x() + b[2] * p[2].x(), b[0] * p[0].y() + b[1] * p[1].y() + b[2] * p[2].y(),
               b[0] * p[0].z() + b[1] * p[1].z() + b[2] * p[2].z());
}

inline std::array<double, 3> random_barycentric(std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(0, 1);
  double a = u(rng), b = u(rng);
  if(a + b > 1) { a = 1 - a; b = 1 - b; }
  return { 1 - a - b, a, b };
}

// Exact symmetry, entries summing to area (relative 1e-14), and a successful Cholesky factorisation.
inline void check_mass_matrix(const Eigen::SparseMatrix<double>& M, double area, std::size_t n, const std::string& what)
{
  const Eigen::SparseMatrix<double> Mt = M.transpose();
  const double asymmetry = (M - Mt).norm();
  const double sum = Eigen::VectorXd::Ones(M.rows()).dot(M * Eigen::VectorXd::Ones(M.cols()));
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt(M);
  std::printf("%s: mass matrix %ldx%ld, |M - M^T| = %.3g, sum %.17g vs area %.17g (rel %.3g), Cholesky %s\n", what.c_str(),
              long(M.rows()), long(M.cols()), asymmetry, sum, area, std::abs(sum - area) / area,
              llt.info() == Eigen::Success ? "succeeds" : "fails");
  AF_CHECK(std::size_t(M.rows()) == n && std::size_t(M.cols()) == n, what + ": mass matrix is n x n over the control vertices");
  AF_CHECK(asymmetry == 0, what + ": mass matrix exactly symmetric");
  AF_CHECK_REL(sum, area, 1e-14, what + ": mass matrix entries sum to area()");
  AF_CHECK(llt.info() == Eigen::Success, what + ": mass matrix positive definite");
}

// Border halfedges of tm grouped into cycles: the number of boundary loops.
template <typename TM>
std::size_t boundary_loops(const TM& tm)
{
  std::set<typename boost::graph_traits<TM>::halfedge_descriptor> seen;
  std::size_t loops = 0;
  for(auto h : halfedges(tm))
  {
    if(!CGAL::is_border(h, tm) || seen.count(h)) continue;
    ++loops;
    for(auto g = h; seen.insert(g).second; g = next(g, tm)) {}
  }
  return loops;
}

// Number of faces around a vertex (m for a border vertex).
inline std::size_t face_count(V v, const Mesh& m)
{
  std::size_t k = 0;
  for(F f : CGAL::faces_around_target(halfedge(v, m), m)) if(f != Mesh::null_face()) ++k;
  return k;
}

// The two border neighbours of a border vertex: before (the source of its incoming border halfedge
// of the hole) and after.
inline std::array<V, 2> border_neighbours(V v, const Mesh& m)
{
  for(auto h : CGAL::halfedges_around_target(v, m))
    if(CGAL::is_border(h, m)) return { source(h, m), target(next(h, m), m) };
  return { Mesh::null_vertex(), Mesh::null_vertex() };
}

} // namespace AF_border_test

#endif // AF_TEST_SUPPORT_BORDER_MESH_HELPERS_H
