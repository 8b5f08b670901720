// The ghost layer that closes boundary fans (doc/Anisotropic_fairing/design/loop-fem.md section 6): ghosts are affine in the real
// vertices; boundary vertices get valence 6 (m <= 3) or m + 3; the limit points of boundary vertices
// follow the closed forms (m = 3: the cubic B-spline rule (2/3) v + (1/6)(r0 + r_m); m = 1: the corner
// is interpolated; m = 2: (5/6) v + (1/6)(r0 + r2) - (1/6) r1), checked with random 3-D control data; the
// limit surface of a single triangle is that flat triangle; bow-tie vertices are refused.

#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Boundary_constraints.h>
#include <CGAL/Anisotropic_fairing/internal/assembly/Fem_assembly.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/element/Ghosted_patch_cache.h>
#include <CGAL/Anisotropic_fairing/internal/element/Patch_cache.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Vertex_limit_masks.h>

#include "test_support/check.h"

#include <Eigen/Core>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace AFI = CGAL::Anisotropic_fairing::internal;
typedef AFI::Triangle_topology::Face Face;

AFI::Control_matrix extend(const AFI::Ghost_layer& gl, const AFI::Control_matrix& X)
{
  AFI::Control_matrix E(Eigen::Index(gl.number_of_extended_vertices()), X.cols());
  E.topRows(X.rows()) = X;
  for(std::size_t k = 0; k < gl.ghosts.size(); ++k)
  {
    E.row(Eigen::Index(gl.real_vertices + k)).setZero();
    for(const auto& w : gl.ghosts[k]) E.row(Eigen::Index(gl.real_vertices + k)) += w.second * X.row(w.first);
  }
  return E;
}

// A rows x cols grid of vertices, every quad split along the same diagonal (a regular lattice:
// interior valence 6, border vertices with m = 3, corners with m = 1 and 2).
std::vector<Face> grid_faces(int rows, int cols)
{
  std::vector<Face> f;
  for(int i = 0; i + 1 < rows; ++i)
    for(int j = 0; j + 1 < cols; ++j)
    {
      const int a = i * cols + j, b = a + 1, c = a + cols, d = c + 1;
      f.push_back({ { a, b, d } });
      f.push_back({ { a, d, c } });
    }
  return f;
}

// The real fan (v, r0, r1), ..., (v, r_{m-1}, r_m) of boundary vertex v, found independently.
std::vector<int> boundary_fan(int v, const std::vector<Face>& faces)
{
  auto has = [&](int p, int q) {
    for(const Face& t : faces)
      for(int k = 0; k < 3; ++k) if(t[k] == p && t[(k + 1) % 3] == q) return true;
    return false;
  };
  auto next_after = [&](int p, int q) {   // the third vertex of the face holding p->q
    for(const Face& t : faces)
      for(int k = 0; k < 3; ++k) if(t[k] == p && t[(k + 1) % 3] == q) return t[(k + 2) % 3];
    return -1;
  };
  std::vector<int> r;
  for(const Face& t : faces)
    for(int k = 0; k < 3; ++k)
      if(t[k] == v && !has(t[(k + 1) % 3], v)) r.push_back(t[(k + 1) % 3]);
  if(r.size() != 1) return {};
  // r0 follows v along the border edge v->r0; walk the faces (v, r_k, r_{k+1}) while v->r_k has a face
  while(r.size() < 64)
  {
    const int n = next_after(v, r.back());
    if(n < 0) break;
    r.push_back(n);
  }
  return r;
}

void check_limit_formulas()
{
  const int rows = 6, cols = 8;
  const std::vector<Face> faces = grid_faces(rows, cols);
  const AFI::Ghost_layer gl = AFI::make_ghost_layer(std::size_t(rows * cols), faces);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  AFI::Control_matrix X(rows * cols, 3);
  for(Eigen::Index i = 0; i < X.rows(); ++i) for(int c = 0; c < 3; ++c) X(i, c) = u(rng);
  const AFI::Control_matrix Xe = extend(gl, X);
  AF_test::Max_error err[4] = { AF_test::Max_error("limit of boundary vertices with m = 1 (interpolated corner)"),
                                AF_test::Max_error("limit of boundary vertices with m = 2"),
                                AF_test::Max_error("limit of boundary vertices with m = 3 (cubic B-spline rule)"),
                                AF_test::Max_error("sum of ghost weights - 1") };
  for(const auto& row : gl.ghosts) { double s = 0; for(const auto& w : row) s += w.second; err[3].add(s, 1.0); }
  bool valence_ok = true;
  for(int v : gl.boundary_vertices)
  {
    const std::vector<int> r = boundary_fan(v, faces);
    const int m = int(r.size()) - 1;
    valence_ok = valence_ok && gl.topology->valence(v) == (m <= 3 ? 6 : m + 3);
    double got[3];
    AFI::vertex_limit_value(*gl.topology, Xe, v, got);
    for(int c = 0; c < 3; ++c)
    {
      double expected = 0;
      if(m == 1) expected = X(v, c);
      else if(m == 2) expected = 5.0 / 6 * X(v, c) + (X(r[0], c) + X(r[2], c)) / 6 - X(r[1], c) / 6;
      else if(m == 3) expected = 2.0 / 3 * X(v, c) + (X(r[0], c) + X(r[3], c)) / 6;
      if(m >= 1 && m <= 3) err[m - 1].add(got[c], expected, "vertex " + std::to_string(v));
    }
  }
  for(const auto& e : err) e.print();
  std::printf("grid %dx%d: %zu boundary vertices, %zu ghosts\n", rows, cols, gl.boundary_vertices.size(), gl.ghosts.size());
  AF_CHECK(gl.boundary_vertices.size() == std::size_t(2 * (rows + cols) - 4), "every border vertex found");
  AF_CHECK(err[0].count() > 0 && err[1].count() > 0 && err[2].count() > 0, "the grid has m = 1, 2 and 3 vertices");
  for(const auto& e : err) AF_CHECK(e.value() < 1e-14, e.label());
  AF_CHECK(valence_ok, "boundary vertices have valence 6 after the ghost layer (m <= 3)");
}

void check_single_triangle()
{
  const std::vector<Face> faces = { { { 0, 1, 2 } } };
  const AFI::Ghost_layer gl = AFI::make_ghost_layer(3, faces);
  AFI::Control_matrix X(3, 3);
  X << 0.3, -0.2, 1.1,
       2.0, 0.5, 0.7,
       0.4, 1.9, -0.3;
  const AFI::Control_matrix Xe = extend(gl, X);
  AF_test::Max_error position("single triangle: limit surface vs the flat triangle, quadrature points");
  AF_test::Max_error tangent("single triangle: tangents vs the flat triangle's edges");
  for(int tiling : { 0, 2 })
  {
    AFI::Patch_cache cache(*gl.topology, gl.real_faces);
    AFI::Quadrature_spec spec; spec.tiling_depth = tiling;
    cache.prepare_quadrature(spec);
    const int* ring = cache.ring(0);
    for(const AFI::Quadrature_point& q : cache.quadrature_points(cache.category(0)))
      for(int c = 0; c < 3; ++c)
      {
        double p = 0, d1 = 0, d2 = 0;
        for(int k = 0; k < q.stencil.m; ++k)
        {
          p += q.stencil.row(AFI::VALUE)[k] * Xe(ring[k], c);
          d1 += q.stencil.row(AFI::D1)[k] * Xe(ring[k], c);
          d2 += q.stencil.row(AFI::D2)[k] * Xe(ring[k], c);
        }
        position.add(p, (1 - q.xi1 - q.xi2) * X(0, c) + q.xi1 * X(1, c) + q.xi2 * X(2, c));
        tangent.add(d1, X(1, c) - X(0, c));
        tangent.add(d2, X(2, c) - X(0, c));
      }
  }
  AF_test::Max_error corners("single triangle: limit points of the corners");
  for(int v = 0; v < 3; ++v)
  {
    double got[3];
    AFI::vertex_limit_value(*gl.topology, Xe, v, got);
    for(int c = 0; c < 3; ++c) corners.add(got[c], X(v, c));
  }
  position.print(); tangent.print(); corners.print();
  AF_CHECK(position.value() < 1e-14 && tangent.value() < 1e-13, "the limit surface of a single triangle is the flat triangle");
  AF_CHECK(corners.value() < 1e-15, "its corners are interpolated");
}

void check_high_valence_boundary_vertex()
{
  // vertex 0 on the border with a fan of m = 5 real triangles
  std::vector<Face> faces;
  for(int k = 1; k <= 5; ++k) faces.push_back({ { 0, k, k + 1 } });
  const AFI::Ghost_layer gl = AFI::make_ghost_layer(7, faces);
  std::printf("boundary vertex with m = 5: extended valence %d\n", gl.topology->valence(0));
  AF_CHECK(gl.topology->valence(0) == 8, "a boundary vertex with m >= 4 gets valence m + 3");
}

void check_bow_tie()
{
  // two triangles sharing only vertex 2
  const std::vector<Face> faces = { { { 0, 1, 2 } }, { { 2, 3, 4 } } };
  bool refused = false;
  try { AFI::make_ghost_layer(5, faces); }
  catch(const CGAL::Anisotropic_fairing::Input_error& e)
  {
    refused = e.kind() == CGAL::Anisotropic_fairing::Input_error::NON_MANIFOLD_VERTEX && e.element() == 2;
    std::printf("bow-tie: %s\n", e.what());
  }
  AF_CHECK(refused, "a bow-tie boundary vertex is refused, naming the vertex");
}

Eigen::MatrixXd dense(const CGAL::Anisotropic_fairing::internal::Sparse_structure& pattern, const CGAL::Anisotropic_fairing::internal::Value_array& values)
{
  return Eigen::MatrixXd(pattern.matrix(values));
}

// Assembly over the real vertices with ghosts substituted (Ghosted_patch_cache) equals
// E^T M_ext E and E^T L_ext E from the extended mesh; on a planar regular grid the limit surface is
// the grid itself, so the area is exact.
void check_ghosted_assembly()
{
  const int rows = 6, cols = 8, n = rows * cols;
  const std::vector<Face> faces = grid_faces(rows, cols);
  const AFI::Ghost_layer gl = AFI::make_ghost_layer(std::size_t(n), faces);
  AFI::Control_matrix flat(n, 3), wavy(n, 3);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for(int i = 0; i < rows; ++i)
    for(int j = 0; j < cols; ++j)
    {
      flat.row(i * cols + j) << j, i, 0;
      wavy.row(i * cols + j) << j + u(rng), i + u(rng), 0.4 * std::sin(0.7 * j) * std::cos(0.5 * i) + u(rng);
    }
  const AFI::Ghosted_patch_cache cache(gl, AFI::Quadrature_spec());
  AFI::Fem_assembler<AFI::Ghosted_patch_cache> real(cache, std::size_t(n));
  AFI::Fem_assembler<AFI::Patch_cache> extended(cache.extended(), gl.number_of_extended_vertices());
  AFI::Value_array m, l, me, le;
  const AFI::Assembly_statistics flat_stats = real.assemble(flat, 3, CGAL::Anisotropic_fairing::Isotropic_diffusion_tensor(), m, l);
  std::printf("planar %dx%d grid with ghosts: limit area %.15g (grid %d), %zu of %zu faces see ghosts\n", rows, cols,
              flat_stats.area, (rows - 1) * (cols - 1), cache.number_of_ghosted_faces(), faces.size());
  AF_CHECK_REL(flat_stats.area, double((rows - 1) * (cols - 1)), 1e-14, "the limit surface of a planar regular grid is the grid");
  real.assemble(wavy, 3, CGAL::Anisotropic_fairing::Isotropic_diffusion_tensor(), m, l);
  extended.assemble(extend(gl, wavy), 3, CGAL::Anisotropic_fairing::Isotropic_diffusion_tensor(), me, le);
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(Eigen::Index(gl.number_of_extended_vertices()), n);
  for(int i = 0; i < n; ++i) E(i, i) = 1;
  for(std::size_t k = 0; k < gl.ghosts.size(); ++k)
    for(const auto& w : gl.ghosts[k]) E(Eigen::Index(std::size_t(n) + k), w.first) += w.second;
  const Eigen::MatrixXd M = dense(real.pattern(), m), L = dense(real.pattern(), l);
  const Eigen::MatrixXd Mref = E.transpose() * dense(extended.pattern(), me) * E;
  const Eigen::MatrixXd Lref = E.transpose() * dense(extended.pattern(), le) * E;
  const double em = (M - Mref).cwiseAbs().maxCoeff() / Mref.cwiseAbs().maxCoeff();
  const double el = (L - Lref).cwiseAbs().maxCoeff() / Lref.cwiseAbs().maxCoeff();
  std::printf("wavy grid: |M - E^T M_ext E| %.3g, |L - E^T L_ext E| %.3g (relative to the largest entry)\n", em, el);
  AF_CHECK(em < 1e-14 && el < 1e-14, "ghost substitution in the stencils = E^T (extended matrix) E");
  AF_CHECK((M - M.transpose()).norm() == 0 && (L - L.transpose()).norm() == 0, "and the matrices stay exactly symmetric");
  AF_CHECK((L * Eigen::VectorXd::Ones(n)).cwiseAbs().maxCoeff() < 1e-14 * L.cwiseAbs().maxCoeff(), "L 1 = 0 with ghosts");
}

// The patch test (loop-fem.md section 6): on a planar regular grid a linear function is a steady state
// iff no free basis function touches the limit boundary curve. Holding the boundary vertices only
// fails next to the m = 2 corners; holding the influence set too passes.
void check_patch_test()
{
  const int rows = 6, cols = 8, n = rows * cols;
  const AFI::Ghost_layer gl = AFI::make_ghost_layer(std::size_t(n), grid_faces(rows, cols));
  const AFI::Ghosted_patch_cache cache(gl, AFI::Quadrature_spec());
  AFI::Control_matrix X(n, 3);
  for(int i = 0; i < rows; ++i)
    for(int j = 0; j < cols; ++j) X.row(i * cols + j) << j, i, 0.3 * j - 0.2 * i + 0.1;   // a tilted plane
  AFI::Fem_assembler<AFI::Ghosted_patch_cache> as(cache, std::size_t(n));
  AFI::Value_array m, l;
  as.assemble(X, 3, CGAL::Anisotropic_fairing::Isotropic_diffusion_tensor(), m, l);
  const Eigen::MatrixXd L = dense(as.pattern(), l);
  const Eigen::MatrixXd LX = L * Eigen::MatrixXd(X);
  for(bool influence : { false, true })
  {
    const std::vector<bool> fixed = AFI::boundary_constrained_vertices(gl, cache, influence);
    double residual = 0;
    std::size_t held = 0;
    for(int i = 0; i < n; ++i)
      if(fixed[std::size_t(i)]) ++held;
      else residual = std::max(residual, LX.row(i).norm() / L.cwiseAbs().maxCoeff());
    std::printf("patch test, %s: %zu vertices held (%zu on the border), largest free residual |(L X)_i| %.3g\n",
                influence ? "border + influence set" : "border only", held, gl.boundary_vertices.size(), residual);
    if(influence)
    {
      AF_CHECK(held == gl.boundary_vertices.size() + 2, "the influence set of the regular grid: the 2 vertices next to the m = 2 corners");
      AF_CHECK(residual < 1e-14, "patch test passes with the influence set held");
    }
    else AF_CHECK(residual > 1e-3, "patch test fails with the border vertices only (the paper's choice)");
  }
}

int main()
{
  check_patch_test();
  check_ghosted_assembly();
  check_limit_formulas();
  check_single_triangle();
  check_high_valence_boundary_vertex();
  check_bow_tie();
  return AF_test::report();
}
