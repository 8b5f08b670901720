// The interpolating icosphere of doc/Anisotropic_fairing/design/loop-fem-flow.md section 11: control points X = Lambda^-1 P whose Loop
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

// The limit-mask matrix Lambda of a closed mesh (row i: the Loop limit point of vertex i), built
// from the test's own Loop weights, independently of the package.
template <class Mesh>
Eigen::SparseMatrix<double> limit_mask_matrix(const Mesh& mesh)
{
  const std::size_t n = num_vertices(mesh);
  std::vector<Eigen::Triplet<double>> t;
  for(auto v : vertices(mesh))
  {
    const std::size_t i = std::size_t(v);
    const std::size_t val = CGAL::halfedges_around_target(v, mesh).size();
    const double chi = loop_limit_weight(val);
    t.emplace_back(i, i, 1 - double(val) * chi);
    for(auto w : CGAL::vertices_around_target(v, mesh)) t.emplace_back(i, std::size_t(w), chi);
  }
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(t.begin(), t.end());
  return L;
}

// Lambda^-1 B: the control values whose limit values at the vertices are the rows of B.
template <class Mesh>
Eigen::MatrixXd interpolating_control_values(const Mesh& mesh, const Eigen::MatrixXd& B)
{
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(limit_mask_matrix(mesh));
  return lu.solve(B);
}

// Replaces the points of a closed mesh by the control points whose limit points are the old points.
template <class Mesh>
void make_interpolating(Mesh& mesh)
{
  Eigen::MatrixXd P(num_vertices(mesh), 3);
  for(auto v : vertices(mesh))
  {
    const auto& p = mesh.point(v);
    P.row(std::size_t(v)) << p.x(), p.y(), p.z();
  }
  const Eigen::MatrixXd X = interpolating_control_values(mesh, P);
  for(auto v : vertices(mesh))
    mesh.point(v) = typename Mesh::Point(X(std::size_t(v), 0), X(std::size_t(v), 1), X(std::size_t(v), 2));
}

// Control points whose limit surface interpolates the unit-sphere vertices: X = Lambda^-1 P.
template <class Mesh>
void make_interpolating_icosphere(Mesh& mesh, int levels)
{
  make_icosphere(mesh, levels);
  make_interpolating(mesh);
}

} // namespace AF_test

#endif // AF_TEST_INTERPOLATING_SPHERE_H
