// The stiffness matrix L_ij = (grad phi_i, grad phi_j) assembled with the mass matrix in one pass:
// symmetric, L 1 = 0, positive semi-definite with the constants as kernel, the energy identity
// trace(X^T L X) = 2 Area for D = I in any dimension kappa (doc/Anisotropic_fairing/design/loop-fem-flow.md section 11d), the same M as
// the mass-only assembly; and the linear (P1) element against the closed forms of Clarenz et al.:
// consistent mass area/12 (1 + delta_ij) and cotangent stiffness, computed here independently.
// The uniform tensor: with P1 the graph Laplacian (valence, -1 per edge) over sqrt(3), with Loop a
// stiffness that does not depend on the embedding (the same for a perturbed copy), L 1 = 0.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/Uniform_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/internal/assembly/Fem_assembly.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Indexed_mesh.h>
#include <CGAL/Anisotropic_fairing/internal/element/Linear_element_cache.h>
#include <CGAL/Anisotropic_fairing/internal/element/Patch_cache.h>

#include "test_support/check.h"
#include "test_support/interpolating_sphere.h"
#include "test_support/mesh_generators.h"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace AF = CGAL::Anisotropic_fairing;
namespace AFI = CGAL::Anisotropic_fairing::internal;

Eigen::SparseMatrix<double> with_values(const CGAL::Anisotropic_fairing::internal::Sparse_structure& pattern, const AFI::Value_array& v)
{
  return pattern.matrix(v);
}

// Checks the identities of (M, L) assembled on X (n x kappa), with `cache` any element cache.
template <class Cache>
void check_operator(const Cache& cache, const AFI::Control_matrix& X, const std::string& name, bool dense_checks)
{
  AFI::Fem_assembler<Cache> as(cache, std::size_t(X.rows()));
  AFI::Value_array mv, lv;
  const AFI::Assembly_statistics st = as.assemble(X, int(X.cols()), AF::Isotropic_diffusion_tensor(), mv, lv);
  const Eigen::SparseMatrix<double> M = with_values(as.pattern(), mv), L = with_values(as.pattern(), lv);
  const Eigen::MatrixXd Xd = X;
  const double energy = (Xd.transpose() * (L * Xd)).trace();
  std::printf("%s: area %.15g, trace(X^T L X) %.15g, 2 area %.15g, stats energy %.15g\n", name.c_str(), st.area, energy,
              2 * st.area, st.energy);
  AF_CHECK(!st.degenerate, "metric is regular, " + name);
  AF_CHECK_REL(energy, 2 * st.area, 1e-12, "trace(X^T L X) = 2 area, " + name);
  AF_CHECK_REL(st.energy, energy, 1e-12, "reported energy = trace(X^T L X), " + name);
  AF_CHECK_REL(M.sum(), st.area, 1e-13, "sum of M = area, " + name);
  const double lnorm = L.cwiseAbs().sum() / double(L.rows());
  const Eigen::VectorXd L1 = L * Eigen::VectorXd::Ones(L.rows());
  std::printf("  max |L 1| / (mean |L| row sum) = %.3g\n", L1.cwiseAbs().maxCoeff() / lnorm);
  AF_CHECK(L1.cwiseAbs().maxCoeff() <= 1e-13 * lnorm, "L 1 = 0, " + name);
  const Eigen::SparseMatrix<double> Lt = L.transpose(), Mt = M.transpose();
  AF_CHECK((L - Lt).norm() == 0.0 && (M - Mt).norm() == 0.0, "L and M exactly symmetric, " + name);
  // positive definite once one vertex is held (the kernel of L is the constants only)
  Eigen::SparseMatrix<double> Lh = L.bottomRightCorner(L.rows() - 1, L.cols() - 1);
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt(Lh);
  AF_CHECK(llt.info() == Eigen::Success, "L with one vertex held is positive definite, " + name);
  if(dense_checks)
  {
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Eigen::MatrixXd(L), Eigen::EigenvaluesOnly);
    const Eigen::VectorXd ev = es.eigenvalues();
    std::printf("  eigenvalues of L: %.3g, %.3g, ..., %.3g\n", ev[0], ev[1], ev[ev.size() - 1]);
    AF_CHECK(std::abs(ev[0]) <= 1e-12 * ev[ev.size() - 1] && ev[1] > 1e-8 * ev[ev.size() - 1],
             "L is positive semi-definite with a one-dimensional kernel, " + name);
  }
}

template <class Mesh>
AFI::Control_matrix points_of(const Mesh& m)
{
  AFI::Indexed_mesh<Mesh> im(m);
  return im.read_points(get(CGAL::vertex_point, m));
}

// Independent P1 reference: consistent mass and cotangent stiffness, face by face.
void check_linear_element(const Mesh& mesh, const std::string& name)
{
  AFI::Indexed_mesh<Mesh> im(mesh);
  const AFI::Control_matrix X = im.read_points(mesh.points());
  AFI::Linear_element_cache cache(im.topology());
  AFI::Fem_assembler<AFI::Linear_element_cache> as(cache, im.number_of_vertices());
  AFI::Value_array mv, lv;
  as.assemble(X, 3, AF::Isotropic_diffusion_tensor(), mv, lv);
  const Eigen::MatrixXd M = Eigen::MatrixXd(with_values(as.pattern(), mv)), L = Eigen::MatrixXd(with_values(as.pattern(), lv));
  const Eigen::Index n = Eigen::Index(im.number_of_vertices());
  Eigen::MatrixXd Mref = Eigen::MatrixXd::Zero(n, n), Lref = Eigen::MatrixXd::Zero(n, n);
  for(std::size_t f = 0; f < im.number_of_faces(); ++f)
  {
    const auto& t = im.topology().face(f);
    const Eigen::Vector3d p[3] = { X.row(t[0]).transpose(), X.row(t[1]).transpose(), X.row(t[2]).transpose() };
    const double area = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
    for(int a = 0; a < 3; ++a)
    {
      for(int b = 0; b < 3; ++b) Mref(t[a], t[b]) += area / 12.0 * (a == b ? 2.0 : 1.0);
      // the angle at corner a is opposite the edge (b, c): contributes cot/2 to L_bc
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      const Eigen::Vector3d u = p[b] - p[a], v = p[c] - p[a];
      const double cot = u.dot(v) / u.cross(v).norm();
      Lref(t[b], t[c]) -= 0.5 * cot; Lref(t[c], t[b]) -= 0.5 * cot;
      Lref(t[b], t[b]) += 0.5 * cot; Lref(t[c], t[c]) += 0.5 * cot;
    }
  }
  const double merr = (M - Mref).cwiseAbs().maxCoeff() / Mref.cwiseAbs().maxCoeff();
  const double lerr = (L - Lref).cwiseAbs().maxCoeff() / Lref.cwiseAbs().maxCoeff();
  std::printf("%s, P1: max relative |M - area/12 (1 + delta)| %.3g, |L - cotan| %.3g, nnz/row %.2f\n", name.c_str(), merr,
              lerr, double(as.number_of_nonzeros()) / double(n));
  AF_CHECK(merr < 1e-14, "P1 mass = consistent mass area/12 (1 + delta_ij), " + name);
  AF_CHECK(lerr < 1e-13, "P1 stiffness = cotangent Laplacian, " + name);
}

// The uniform tensor's stiffness: P1 against the graph Laplacian / sqrt(3) (each edge: -1/(2 sqrt 3) from
// each of its two faces, the cotangent weight of 60 degrees), Loop the same for two embeddings of one mesh.
void check_uniform_tensor(const Mesh& mesh, const std::string& name)
{
  AFI::Indexed_mesh<Mesh> im(mesh);
  const AFI::Control_matrix X = im.read_points(mesh.points());
  AFI::Control_matrix Y = X;   // another embedding: perturbed by a third of the bounding box's size
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const double size = (X.colwise().maxCoeff() - X.colwise().minCoeff()).norm();
  for(Eigen::Index i = 0; i < Y.rows(); ++i)
    for(int c = 0; c < 3; ++c) Y(i, c) += 0.01 * size * u(rng);
  const Eigen::Index n = Eigen::Index(im.number_of_vertices());
  AFI::Value_array mv, lv;
  {
    AFI::Linear_element_cache cache(im.topology());
    AFI::Fem_assembler<AFI::Linear_element_cache> as(cache, im.number_of_vertices());
    as.assemble(X, 3, AF::Uniform_diffusion_tensor(), mv, lv);
    const Eigen::MatrixXd L = Eigen::MatrixXd(with_values(as.pattern(), lv));
    Eigen::MatrixXd Lref = Eigen::MatrixXd::Zero(n, n);
    for(std::size_t f = 0; f < im.number_of_faces(); ++f)
      for(int a = 0; a < 3; ++a)
      {
        const int i = im.topology().face(f)[a], j = im.topology().face(f)[(a + 1) % 3];
        const double w = 0.5 / std::sqrt(3.0);
        Lref(i, j) -= w; Lref(j, i) -= w; Lref(i, i) += w; Lref(j, j) += w;
      }
    const double err = (L - Lref).cwiseAbs().maxCoeff() / Lref.cwiseAbs().maxCoeff();
    std::printf("%s, P1, uniform tensor: max relative |L - graph Laplacian / sqrt 3| %.3g\n", name.c_str(), err);
    AF_CHECK(err < 1e-13, "P1 uniform stiffness = graph Laplacian / sqrt(3), " + name);
  }
  AFI::Patch_cache cache(im.topology());
  cache.prepare_quadrature(AFI::Quadrature_spec());
  AFI::Fem_assembler<AFI::Patch_cache> as(cache, im.number_of_vertices());
  AFI::Value_array lx, ly;
  as.assemble(X, 3, AF::Uniform_diffusion_tensor(), mv, lx);
  as.assemble(Y, 3, AF::Uniform_diffusion_tensor(), mv, ly);
  const Eigen::SparseMatrix<double> Lx = with_values(as.pattern(), lx), Ly = with_values(as.pattern(), ly);
  const double scale = Eigen::MatrixXd(Lx).cwiseAbs().maxCoeff();
  const double err = Eigen::MatrixXd(Lx - Ly).cwiseAbs().maxCoeff() / scale;
  const Eigen::VectorXd L1 = Lx * Eigen::VectorXd::Ones(n);
  const double asym = Eigen::MatrixXd(Lx - Eigen::SparseMatrix<double>(Lx.transpose())).cwiseAbs().maxCoeff() / scale;
  std::printf("%s, Loop, uniform tensor: max relative |L(X) - L(perturbed X)| %.3g, |L 1| %.3g, asymmetry %.3g\n", name.c_str(), err,
              L1.cwiseAbs().maxCoeff() / scale, asym);
  AF_CHECK(err < 1e-13, "Loop uniform stiffness does not depend on the embedding, " + name);
  AF_CHECK(L1.cwiseAbs().maxCoeff() < 1e-13 * scale, "Loop uniform stiffness: L 1 = 0, " + name);
  AF_CHECK(asym < 1e-15, "Loop uniform stiffness is symmetric, " + name);
}

int main(int argc, char** argv)
{
  const std::string data = argc > 1 ? argv[1] : "data";
  Mesh bumpy, bunny, sphere, mixed;
  AF_CHECK(CGAL::IO::read_polygon_mesh(data + "/bumpy.off", bumpy), "read bumpy.off");
  AF_CHECK(CGAL::IO::read_polygon_mesh(data + "/bunny.off", bunny), "read bunny.off");
  AF_test::make_interpolating_icosphere(sphere, 2);
  AF_test::make_mixed_valence_mesh(mixed);
  AF_test::perturb_vertices(mixed, 0.05, 7);

  for(int degree : { 8, 4 })
  {
    AFI::Indexed_mesh<Mesh> im(bumpy);
    AFI::Patch_cache cache(im.topology());
    AFI::Quadrature_spec spec; spec.degree = degree;
    cache.prepare_quadrature(spec);
    check_operator(cache, points_of(bumpy), "bumpy, Loop, degree " + std::to_string(degree), false);
  }
  {
    AFI::Indexed_mesh<Mesh> im(sphere);
    AFI::Patch_cache cache(im.topology());
    AFI::Quadrature_spec spec; spec.tiling_depth = 2;
    cache.prepare_quadrature(spec);
    check_operator(cache, points_of(sphere), "interpolating icosphere(2), Loop, tiled K=2", true);
    // kappa = 5: the sphere plus two noisy function columns, a 2-manifold in R^5
    AFI::Control_matrix X5(points_of(sphere).rows(), 5);
    X5.leftCols(3) = points_of(sphere);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-0.3, 0.3);
    for(Eigen::Index i = 0; i < X5.rows(); ++i) { X5(i, 3) = u(rng); X5(i, 4) = X5(i, 0) * X5(i, 1) + u(rng); }
    check_operator(cache, X5, "icosphere(2) with 2 function columns (kappa = 5), Loop", true);
  }
  {
    AFI::Indexed_mesh<Mesh> im(mixed);
    AFI::Patch_cache cache(im.topology());
    cache.prepare_quadrature(AFI::Quadrature_spec());
    check_operator(cache, points_of(mixed), "perturbed valence 3-9 mesh, Loop", true);
  }
  {
    AFI::Indexed_mesh<Mesh> im(bunny);
    AFI::Patch_cache cache(im.topology());
    cache.prepare_quadrature(AFI::Quadrature_spec());
    check_operator(cache, points_of(bunny), "bunny, Loop", false);
    AFI::Linear_element_cache p1(im.topology());
    check_operator(p1, points_of(bunny), "bunny, P1", false);
  }
  check_linear_element(bumpy, "bumpy");
  check_linear_element(mixed, "perturbed valence 3-9 mesh");
  check_uniform_tensor(bumpy, "bumpy");
  check_uniform_tensor(mixed, "perturbed valence 3-9 mesh");
  return AF_test::report();
}
