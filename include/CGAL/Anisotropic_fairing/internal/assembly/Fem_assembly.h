// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One pass over the faces of the current surface assembles the mass matrix M_ij = (phi_i, phi_j),
// the stiffness L_ij = (D grad phi_i, grad phi_j) (integrand d phi_i^T A_q d phi_j, Bajaj & Xu eq. 25)
// and the diagnostics of the step: area, Dirichlet energy trace(X^T L X), int |H|^2, and whether the
// metric degenerated. It works on any element cache (Loop patches or P1 faces) and any diffusion
// tensor; both matrices share the fixed ring pattern, so only their values are written.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_FEM_ASSEMBLY_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_FEM_ASSEMBLY_H

#include <CGAL/Anisotropic_fairing/Quadrature_point_geometry.h>
#include <CGAL/Anisotropic_fairing/Surface_curvature.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/assembly/Face_chunks.h>
#include <CGAL/Anisotropic_fairing/internal/assembly/Local_gram.h>
#include <CGAL/Anisotropic_fairing/internal/assembly/Local_matrix_scatter.h>
#include <CGAL/Anisotropic_fairing/internal/types/Parallel_blocks.h>
#include <CGAL/Anisotropic_fairing/internal/types/Sparse_structure.h>
#include <CGAL/Anisotropic_fairing/internal/types/Stencil_row.h>
#include <CGAL/Anisotropic_fairing/internal/types/Vector3.h>
#include <CGAL/Anisotropic_fairing/internal/assembly/Sparse_pattern.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Vertex_limit_masks.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#endif

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

struct Assembly_statistics
{
  double area = 0;
  double energy = 0;       // trace(X^T L X) over the metric columns = sum_q c_q tr(A_q G_q)
  double H_integral = 0;   // int |H|^2 dA
  double bounded_H_integral = 0;   // int min(|H|, B)^2 dA, B per component (Assembly_context): sees a
                                   // blow-up over an area, not a cusp on a tiny face
  bool degenerate = false; // sqrt(det G) <= 0 or not finite somewhere
  std::size_t degenerate_face = 0;
  std::size_t degenerate_points = 0;  // quadrature points where it is
  std::size_t reversed_faces = 0;     // faces whose limit normal turns within the face by more than the angle
  std::size_t bent_faces = 0;         // ... of Assembly_context::folded_turn, and of bent_turn (Step_safety.h)
  std::vector<std::size_t> reversed_face_list;   // which faces are reversed (the cache's numbers)
  std::size_t judged_reversed_faces = std::size_t(-1);   // a distributed run's process judges the first (its own)
  std::vector<double> component_area; // per connected component (when the assembler knows them)

  void add(const Assembly_statistics& o)
  {
    area += o.area; energy += o.energy; H_integral += o.H_integral; bounded_H_integral += o.bounded_H_integral;
    degenerate_points += o.degenerate_points;
    reversed_faces += o.reversed_faces;
    bent_faces += o.bent_faces;
    reversed_face_list.insert(reversed_face_list.end(), o.reversed_face_list.begin(), o.reversed_face_list.end());
    if(o.degenerate && !degenerate) { degenerate = true; degenerate_face = o.degenerate_face; }
    if(component_area.size() < o.component_area.size()) component_area.resize(o.component_area.size(), 0.0);
    for(std::size_t c = 0; c < o.component_area.size(); ++c) component_area[c] += o.component_area[c];
  }
};

/// What the assembler is told about one run, once (null members: none).
struct Assembly_context
{
  // indices reported to the tensor (Quadrature_point_geometry::face and ring) and in statistics are
  // translated through these maps when the cache works in a private numbering
  const std::vector<int>* original_vertex = nullptr;
  const std::vector<std::size_t>* original_face = nullptr;
  // vertices left out of the discrete curvature integral of an element without second derivatives: on a
  // border, (L X)_i is the conormal term of the boundary, not a mean curvature
  const std::vector<bool>* border = nullptr;
  // the connected component of each face: the statistics then carry the area per component
  const std::vector<int>* face_component = nullptr;
  std::size_t components = 0;
  // each component's length scale relative to the tensor's (Quadrature_point_geometry::component_scale)
  const std::vector<double>* component_scale = nullptr;
  // the bound B of each component's mean curvature in Assembly_statistics::bounded_H_integral
  const std::vector<double>* curvature_bound = nullptr;
  // cosines of the turning angles within a face at which it counts as reversed and as bent (Step_safety's
  // folds); -2: none counted
  double folded_turn = -2, bent_turn = -2;
};

template <typename Cache>
class Fem_assembler
{
public:
  /// Without `with_pattern` only statistics can be assembled (`with_matrices == false`). `faces`: the faces
  /// assembled, increasing (a process's part of a distributed mesh; null: all), kept by reference; the
  /// pattern, the matrices and the statistics are then those of these faces only.
  Fem_assembler(const Cache& cache, std::size_t number_of_vertices, bool with_pattern = true,
                const std::vector<std::size_t>* faces = nullptr)
    : cache_(cache), faces_(faces)
  {
    if(with_pattern)
    {
      pattern_ = ring_sparsity_pattern(cache, number_of_vertices, faces);
      sort_rings();
    }
    chunks_ = Face_chunks(assembled_faces(), number_of_vertices, [this](std::size_t i, const auto& visit) {
      for(int r = 0; r < cache_.ring_size(face(i)); ++r) visit(cache_.ring(face(i))[r]);
    }, with_pattern);
  }

  /// What the faces' numbers and components are (Assembly_context); read at every assembly.
  void set_context(const Assembly_context& context) { context_ = context; }

  /// The control points of a prefiltered surface (same rows and columns as X): its derivatives at each
  /// quadrature point are passed to the tensor (Quadrature_point_geometry::prefiltered_t1, ...); null: none.
  void set_prefiltered(const Control_matrix* Xp) { prefiltered_ = Xp; }

  /// The symmetric structure that M and L fill: value arrays index its entries.
  const Sparse_structure& pattern() const { return pattern_; }
  std::size_t number_of_nonzeros() const { return std::size_t(pattern_.nonZeros()); }

  /// Assembles M and L (value arrays over pattern()) on the surface whose control points are the
  /// first `metric_columns` columns of X. With `with_matrices == false` only the statistics are
  /// computed (when the element gives curvature at points) and M, L are left as they are. With
  /// `mass_kept`, M already holds this X's mass matrix (an assembly with matrices at the same X, with any
  /// tensor: M does not depend on it, and the same sums give the same values) and only L is assembled.
  /// Without `curvature` the statistics leave out the curvature integrals and the second derivatives are not
  /// evaluated (an assembly whose statistics nobody reads, for a tensor that reads no curvature).
  template <typename Tensor>
  Assembly_statistics assemble(const Control_matrix& X, int metric_columns, const Tensor& tensor,
                               Value_array& M, Value_array& L, bool with_matrices = true, bool mass_kept = false,
                               bool curvature = true)
  {
    const std::size_t nnz = number_of_nonzeros();
    if(!Cache::has_second_derivatives) with_matrices = true;   // the curvature integral needs them
    mass_kept = mass_kept && with_matrices && M.size() == nnz;
    if(with_matrices)
    {
      if(!mass_kept) M.resize(nnz);
      L.resize(nnz);
      parallel_blocks(nnz, [&](std::size_t first, std::size_t last) {
        if(!mass_kept) std::fill(M.begin() + std::ptrdiff_t(first), M.begin() + std::ptrdiff_t(last), 0.0);
        std::fill(L.begin() + std::ptrdiff_t(first), L.begin() + std::ptrdiff_t(last), 0.0);
      }, std::size_t(65536));
    }
    std::vector<Assembly_statistics> stats{ chunks_.size() };
    for(Assembly_statistics& st : stats) st.component_area.assign(context_.components, 0.0);
    // chunk k: its faces, writing into M and L; the chunks of a colour share no column (Face_chunks.h)
    auto run_chunk = [&](std::size_t k) {
      Workspace ws;
      ws.curvature = curvature;
      for(std::size_t i = chunks_.begin(k); i < chunks_.end(k); ++i)
      {
        ws.ring_order = ring_order_offset_.empty() ? nullptr : ring_order_.data() + ring_order_offset_[i];
        assemble_face(face(i), X, metric_columns, tensor, ws, with_matrices && !mass_kept ? M.data() : nullptr,
                      with_matrices ? L.data() : nullptr, stats[k]);
      }
    };
    for(const std::vector<int>& colour : chunks_.by_colour())
    {
#ifdef CGAL_LINKED_WITH_TBB
      if(colour.size() > 1)
      {
        tbb::parallel_for(std::size_t(0), colour.size(), [&](std::size_t c) { run_chunk(std::size_t(colour[c])); });
        continue;
      }
#endif
      for(int k : colour) run_chunk(std::size_t(k));
    }
    Assembly_statistics total;
    total.component_area.assign(context_.components, 0.0);
    for(const Assembly_statistics& s : stats) total.add(s);
    if(!Cache::has_second_derivatives)
      total.bounded_H_integral = total.H_integral = discrete_H_integral(X, metric_columns, M, L);
    return total;
  }

private:
  std::size_t assembled_faces() const { return faces_ ? faces_->size() : cache_.number_of_faces(); }

  // Each assembled face's ring in increasing vertex order, once (a sort per face and assembly otherwise);
  // positions fit 16 bits unless a ring is longer, which is then sorted at each assembly.
  void sort_rings()
  {
    const std::size_t nf = assembled_faces();
    ring_order_offset_.assign(nf + 1, 0);
    for(std::size_t i = 0; i < nf; ++i)
    {
      const int m = cache_.ring_size(face(i));
      if(m > 65535) { ring_order_offset_.clear(); return; }
      ring_order_offset_[i + 1] = ring_order_offset_[i] + std::size_t(m);
    }
    ring_order_.resize(ring_order_offset_[nf]);
    parallel_blocks(nf, [&](std::size_t first, std::size_t last) {
      for(std::size_t i = first; i < last; ++i)
        sorted_ring_order(cache_.ring(face(i)), cache_.ring_size(face(i)), ring_order_.data() + ring_order_offset_[i]);
    });
  }
  // the i-th face assembled
  std::size_t face(std::size_t i) const { return faces_ ? (*faces_)[i] : i; }

  // Per-face buffers with compile-time sizes where known (ring size M, points NQ, coordinates K),
  // so the common faces run unrolled, allocation-free products; Dynamic covers every other face.
  template <int M, int NQ, int K>
  struct Face_buffers
  {
    static constexpr bool fixed = M != Eigen::Dynamic && NQ != Eigen::Dynamic && K != Eigen::Dynamic;
    static constexpr int NQ2 = NQ == Eigen::Dynamic ? Eigen::Dynamic : 2 * NQ;
    typedef Eigen::Matrix<double, NQ, M, Eigen::RowMajor> Stencil_rows;
    Eigen::Matrix<double, M, K, (K == 1 ? Eigen::ColMajor : Eigen::RowMajor)> Xr;
    Eigen::Matrix<double, NQ, K, (K == 1 ? Eigen::ColMajor : Eigen::RowMajor)> T[5];
    Eigen::Matrix<double, NQ, K, (K == 1 ? Eigen::ColMajor : Eigen::RowMajor)> P[5];   // of the prefiltered surface
    Eigen::Matrix<double, M, K, (K == 1 ? Eigen::ColMajor : Eigen::RowMajor)> Pr;
    Eigen::Matrix<double, NQ, M, Eigen::RowMajor> Bm;
    Eigen::Matrix<double, NQ2, M, Eigen::RowMajor> Bl;
    Eigen::Matrix<double, M, M> localM, localL;
  };
  typedef Face_buffers<12, 16, 3> Regular_loop_buffers;   // valence-6 patch, degree-8 rule, geometry
  typedef Face_buffers<3, 3, 3> Linear_buffers;           // P1 face, geometry
  typedef Face_buffers<Eigen::Dynamic, Eigen::Dynamic, Eigen::Dynamic> Any_buffers;

  struct Workspace
  {
    Regular_loop_buffers regular;
    Linear_buffers linear;
    Any_buffers any;
    std::vector<int> order, original_ring;
    const std::uint16_t* ring_order = nullptr;   // the face's ring sorted (sort_rings), or null: sort it here
    bool curvature = true;                       // second derivatives and the curvature statistics
    std::vector<double> zeros, mean_curvature;   // kappa values, for any kappa
  };

  template <typename Tensor>
  void assemble_face(std::size_t f, const Control_matrix& X, int kappa, const Tensor& tensor, Workspace& ws,
                     double* mv, double* lv, Assembly_statistics& stats) const
  {
    const int m = cache_.ring_size(f);
    const Eigen::Index nq = cache_.quadrature_weights(cache_.category(f)).size();
    if(kappa == 3 && m == 12 && nq == 16) assemble_face_with(ws.regular, f, X, kappa, tensor, ws, mv, lv, stats);
    else if(kappa == 3 && m == 3 && nq == 3) assemble_face_with(ws.linear, f, X, kappa, tensor, ws, mv, lv, stats);
    else assemble_face_with(ws.any, f, X, kappa, tensor, ws, mv, lv, stats);
  }

  // What one face sums over its quadrature points, before it is added to the statistics: fewer roundings
  // in the totals (a planar regular grid's area comes out exact)
  struct Face_sums
  {
    double area = 0, energy = 0, H = 0, bounded_H = 0;
    double first_normal[3] = { 0, 0, 0 };
    double lowest_dot = 1;   // of the normals at the points with the first one's: a fold inside the face
    double bound = std::numeric_limits<double>::infinity();   // of the mean curvature (Assembly_context)
  };

  // lv == nullptr: statistics only; mv == nullptr (and lv given): L only, M is kept
  template <typename Buffers, typename Tensor>
  void assemble_face_with(Buffers& b, std::size_t f, const Control_matrix& X, int kappa, const Tensor& tensor,
                          Workspace& ws, double* mv, double* lv, Assembly_statistics& stats) const
  {
    const int m = cache_.ring_size(f);
    const int* ring = cache_.ring(f);
    const Eigen::Index nq = cache_.quadrature_weights(cache_.category(f)).size();
    const bool prefiltered = load_face(b, f, X, kappa, ws.curvature);
    b.Bm.resize(nq, m);
    b.Bl.resize(2 * nq, m);
    if(ws.zeros.size() != std::size_t(kappa)) { ws.zeros.assign(std::size_t(kappa),
                                                                0.0); ws.mean_curvature.resize(std::size_t(kappa)); }

    Quadrature_point_geometry g;
    const Assembly_context& x = context_;
    g.face = x.original_face ? (*x.original_face)[f] : f;
    const int component = x.face_component ? (*x.face_component)[f] : -1;
    if(component >= 0 && x.component_scale) g.component_scale = (*x.component_scale)[std::size_t(component)];
    g.dimension = kappa; g.ring = ring; g.ring_size = m;
    if(x.original_vertex)
    {
      ws.original_ring.resize(std::size_t(m));
      for(int k = 0; k < m; ++k) ws.original_ring[std::size_t(k)] = (*x.original_vertex)[std::size_t(ring[k])];
      g.ring = ws.original_ring.data();
    }
    Face_sums sums;
    if(component >= 0 && x.curvature_bound) sums.bound = (*x.curvature_bound)[std::size_t(component)];
    for(Eigen::Index q = 0; q < nq; ++q) assemble_point(b, f, q, prefiltered, tensor, g, ws, lv != nullptr, sums,
                                                        stats);
    stats.area += sums.area;
    if(component >= 0) stats.component_area[std::size_t(component)] += sums.area;
    if(sums.lowest_dot < x.folded_turn) { ++stats.reversed_faces; stats.reversed_face_list.push_back(f); }
    if(sums.lowest_dot < x.bent_turn) ++stats.bent_faces;
    stats.energy += sums.energy;
    stats.H_integral += sums.H;
    stats.bounded_H_integral += sums.bounded_H;
    if(lv) add_local_matrices(b, ring, m, ws, mv, lv);
  }

  // The ring's control points of face f (b.Xr) and their derivatives at the quadrature points (b.T), and
  // those of the prefiltered surface (b.Pr, b.P) when there is one; returns whether there is
  template <typename Buffers>
  bool load_face(Buffers& b, std::size_t f, const Control_matrix& X, int kappa, bool curvature) const
  {
    typedef Eigen::Map<const typename Buffers::Stencil_rows> Rows;
    const int m = cache_.ring_size(f);
    const int* ring = cache_.ring(f);
    const int cat = cache_.category(f);
    const Eigen::Index nq = cache_.quadrature_weights(cat).size();
    b.Xr.resize(m, kappa);
    for(int k = 0; k < m; ++k)
      for(int c = 0; c < kappa; ++c) b.Xr(k, c) = X(ring[k], c);
    const int derivative_rows = Cache::has_second_derivatives && curvature ? 5 : 2;
    for(int r = 0; r < derivative_rows; ++r)
      b.T[r].noalias() = Rows(cache_.quadrature_rows(cat, D1 + r).data(), nq, m).lazyProduct(b.Xr);
    const bool prefiltered = prefiltered_ && Cache::has_second_derivatives;
    if(prefiltered)
    {
      b.Pr.resize(m, kappa);
      for(int k = 0; k < m; ++k)
        for(int c = 0; c < kappa; ++c) b.Pr(k, c) = (*prefiltered_)(ring[k], c);
      for(int r = 0; r < 5; ++r)
        b.P[r].noalias() = Rows(cache_.quadrature_rows(cat, D1 + r).data(), nq, m).lazyProduct(b.Pr);
    }
    return prefiltered;
  }

  // Quadrature point q of face f: the metric, the tensor, the point's share of the sums and, `with_matrices`,
  // its rows of B_M and B_L (M = B_M^T B_M, L = B_L^T B_L); a degenerate metric gives zero rows
  template <typename Buffers, typename Tensor>
  void assemble_point(Buffers& b, std::size_t f, Eigen::Index q, bool prefiltered, const Tensor& tensor,
                      Quadrature_point_geometry& g,
                      Workspace& ws, bool with_matrices, Face_sums& sums, Assembly_statistics& stats) const
  {
    typedef Eigen::Map<const typename Buffers::Stencil_rows> Rows;
    const int m = cache_.ring_size(f);
    const int cat = cache_.category(f);
    const Eigen::VectorXd& w = cache_.quadrature_weights(cat);
    const Eigen::Index nq = w.size();
    const double* t1 = b.T[0].row(q).data();
    const double* t2 = b.T[1].row(q).data();
    double g11 = 0, g12 = 0, g22 = 0;
    for(int c = 0; c < g.dimension; ++c) { g11 += t1[c] * t1[c]; g12 += t1[c] * t2[c]; g22 += t2[c] * t2[c]; }
    const double det = g11 * g22 - g12 * g12;
    if(!(det > 0) || !std::isfinite(det))
    {
      ++stats.degenerate_points;
      if(!stats.degenerate) { stats.degenerate = true; stats.degenerate_face = g.face; }
      b.Bm.row(q).setZero(); b.Bl.row(2 * q).setZero(); b.Bl.row(2 * q + 1).setZero();
      return;
    }
    const double c = w[q] * std::sqrt(det);
    {
      // a fold inside the face: the normal (of the geometry's 3 coordinates) turns by more than 120
      // degrees between the first point and this one
      double n[3];
      unit_cross(t1, t2, n);
      double* first = sums.first_normal;
      if(first[0] == 0 && first[1] == 0 && first[2] == 0) { first[0] = n[0]; first[1] = n[1]; first[2] = n[2]; }
      else sums.lowest_dot = std::min(sums.lowest_dot, n[0] * first[0] + n[1] * first[1] + n[2] * first[2]);
    }
    const double* no_second = ws.zeros.data();
    const bool second = Cache::has_second_derivatives && ws.curvature;
    g.point = int(q); g.t1 = t1; g.t2 = t2;
    g.t11 = second ? b.T[2].row(q).data() : no_second;
    g.t12 = second ? b.T[3].row(q).data() : no_second;
    g.t22 = second ? b.T[4].row(q).data() : no_second;
    g.g11 = g11; g.g12 = g12; g.g22 = g22; g.det = det;
    const Rows S0(cache_.quadrature_rows(cat, VALUE).data(), nq, m);
    g.basis = S0.row(q).data();
    g.prefiltered_t1 = prefiltered ? b.P[0].row(q).data() : nullptr;
    g.prefiltered_t2 = prefiltered ? b.P[1].row(q).data() : nullptr;
    g.prefiltered_t11 = prefiltered ? b.P[2].row(q).data() : nullptr;
    g.prefiltered_t12 = prefiltered ? b.P[3].row(q).data() : nullptr;
    g.prefiltered_t22 = prefiltered ? b.P[4].row(q).data() : nullptr;
    const Parametric_tensor A = tensor(g);

    sums.area += c;
    sums.energy += c * (A.a11 * g11 + 2 * A.a12 * g12 + A.a22 * g22);
    if(second)
    {
      const double H2 = mean_curvature_squared(g, ws.mean_curvature.data());
      sums.H += c * H2;
      sums.bounded_H += c * std::min(H2, sums.bound * sums.bound);
    }
    if(!with_matrices) return;
    const Rows S1(cache_.quadrature_rows(cat, D1).data(), nq, m);
    const Rows S2(cache_.quadrature_rows(cat, D2).data(), nq, m);
    b.Bm.row(q) = std::sqrt(c) * S0.row(q);
    // c A = R R^T (2x2 Cholesky; A is positive semi-definite), then d phi^T (cA) d phi = |R^T d phi|^2
    const double b11 = c * A.a11, b12 = c * A.a12, b22 = c * A.a22;
    const double r11 = b11 > 0 ? std::sqrt(b11) : 0.0;
    const double r21 = r11 > 0 ? b12 / r11 : 0.0;
    const double r22 = std::sqrt(std::max(0.0, b22 - r21 * r21));
    b.Bl.row(2 * q) = r11 * S1.row(q) + r21 * S2.row(q);
    b.Bl.row(2 * q + 1) = r22 * S2.row(q);
  }

  // The face's local matrices B^T B (their lower triangles: all the scatter reads, so symmetry is exact),
  // added into the value arrays mv (null: M kept) and lv
  template <typename Buffers>
  void add_local_matrices(Buffers& b, const int* ring, int m, Workspace& ws, double* mv, double* lv) const
  {
    if constexpr(Buffers::fixed)
    {
      if(mv) lower_gram(b.Bm, b.localM);
      lower_gram(b.Bl, b.localL);
    }
    else
    {
      if(mv)
      {
        b.localM.setZero(m, m);
        b.localM.template selfadjointView<Eigen::Lower>().rankUpdate(b.Bm.transpose());
      }
      b.localL.setZero(m, m);
      b.localL.template selfadjointView<Eigen::Lower>().rankUpdate(b.Bl.transpose());
    }
    if(ws.ring_order) scatter(b, ring, m, ws, ws.ring_order, mv, lv);
    else
    {
      ws.order.resize(std::size_t(m));
      sorted_ring_order(ring, m, ws.order.data());
      scatter(b, ring, m, ws, ws.order.data(), mv, lv);
    }
  }

  template <typename Buffers, typename Index>
  void scatter(Buffers& b, const int* ring, int m, Workspace& ws, const Index* order, double* mv, double* lv) const
  {
    typedef typename std::remove_reference<decltype(b.localM)>::type Local;
    const int* outer = pattern_.outerIndexPtr();
    const int* rows = pattern_.innerIndexPtr();
    if(!mv)
    {
      const Local* const locals[1] = { &b.localL };
      double* const values[1] = { lv };
      scatter_local_matrices<1>(locals, ring, m, order, outer, rows, values);
      return;
    }
    const Local* const locals[2] = { &b.localM, &b.localL };
    double* const values[2] = { mv, lv };
    scatter_local_matrices<2>(locals, ring, m, order, outer, rows, values);
  }

  // |H|^2, H the mean-curvature vector (Surface_curvature.h), written into h
  static double mean_curvature_squared(const Quadrature_point_geometry& g, double* h)
  {
    mean_curvature_vector(g, h);
    double s = 0;
    for(int c = 0; c < g.dimension; ++c) s += h[c] * h[c];
    return s;
  }

  // Without second derivatives (P1): the discrete mean-curvature vector at vertex i is
  // H_i = -(L X)_i / (2 A_i) with A_i = sum_j M_ij, so int |H|^2 ~ sum_i |(L X)_i|^2 / (4 A_i).
  double discrete_H_integral(const Control_matrix& X, int kappa, const Value_array& M, const Value_array& L) const
  {
    const Eigen::Index n = pattern_.cols();
    const int* outer = pattern_.outerIndexPtr();
    const int* rows = pattern_.innerIndexPtr();
    Eigen::MatrixXd LX = Eigen::MatrixXd::Zero(n, kappa);
    Eigen::VectorXd area = Eigen::VectorXd::Zero(n);
    for(Eigen::Index j = 0; j < n; ++j)
      for(int p = outer[j]; p < outer[j + 1]; ++p)
      {
        area[rows[p]] += M[std::size_t(p)];
        LX.row(rows[p]) += L[std::size_t(p)] * X.row(j).head(kappa);
      }
    double s = 0;
    for(Eigen::Index i = 0; i < n; ++i)
      if(area[i] > 0 && !(context_.border && (*context_.border)[std::size_t(i)]))
        s += LX.row(i).squaredNorm() / (4 * area[i]);
    return s;
  }

  const Cache& cache_;
  const std::vector<std::size_t>* faces_ = nullptr;   // the faces assembled (null: all)
  Sparse_structure pattern_;
  Face_chunks chunks_;
  std::vector<std::size_t> ring_order_offset_;   // per assembled face (sort_rings; empty: none)
  std::vector<std::uint16_t> ring_order_;
  Assembly_context context_;
  const Control_matrix* prefiltered_ = nullptr;
};

/// trace(F^T L F) over all columns of F: the Dirichlet energy of F.
inline double dirichlet_energy(const Sparse_structure& pattern, const Value_array& L, const Control_matrix& F)
{
  double e = 0;
  for(Eigen::Index i = 0; i < pattern.cols(); ++i)
    for(int p = pattern.outerIndexPtr()[i]; p < pattern.outerIndexPtr()[i + 1]; ++p)
      e += L[std::size_t(p)] * F.row(i).dot(F.row(pattern.innerIndexPtr()[p]));
  return e;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_ASSEMBLY_FEM_ASSEMBLY_H
