// The interpolating icosphere of loop-fem.md section 11: control points X = Lambda^-1 P whose Loop
// limit surface passes through the unit-sphere vertices P (Lambda is the limit-mask matrix, built
// here from the test's own Loop weights, independently of the package).

#ifndef AF_TEST_INTERPOLATING_SPHERE_H
#define AF_TEST_INTERPOLATING_SPHERE_H

#include "cgal_loop_reference.h"
#include "mesh_generators.h"

#include <CGAL/boost/graph/iterator.h>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <vector>

namespace AF_test {

// Control points whose limit surface interpolates the unit-sphere vertices: X = Lambda^-1 P with
// Lambda the limit-mask matrix (built here independently from the CGAL oracle's weights).
template <class Mesh>
void make_interpolating_icosphere(Mesh& mesh, int levels)
{
  make_icosphere(mesh, levels);
  const std::size_t n = num_vertices(mesh);
  std::vector<Eigen::Triplet<double>> t;
  Eigen::MatrixXd P(n, 3);
  for(auto v : vertices(mesh))
  {
    const std::size_t i = std::size_t(v);
    const std::size_t val = CGAL::halfedges_around_target(v, mesh).size();
    const double chi = loop_limit_weight(val);
    t.emplace_back(i, i, 1 - double(val) * chi);
    for(auto w : CGAL::vertices_around_target(v, mesh)) t.emplace_back(i, std::size_t(w), chi);
    const auto& p = mesh.point(v);
    P.row(i) << p.x(), p.y(), p.z();
  }
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(t.begin(), t.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(L);
  const Eigen::MatrixXd X = lu.solve(P);
  for(auto v : vertices(mesh))
    mesh.point(v) = typename Mesh::Point(X(std::size_t(v), 0), X(std::size_t(v), 1), X(std::size_t(v), 2));
}

} // namespace AF_test

#endif // AF_TEST_INTERPOLATING_SPHERE_H
