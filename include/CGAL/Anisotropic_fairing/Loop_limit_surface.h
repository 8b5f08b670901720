// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_ANISOTROPIC_FAIRING_LOOP_LIMIT_SURFACE_H
#define CGAL_ANISOTROPIC_FAIRING_LOOP_LIMIT_SURFACE_H

#include <CGAL/Anisotropic_fairing/Input_error.h>
#include <CGAL/Anisotropic_fairing/Isotropic_diffusion_tensor.h>
#include <CGAL/Anisotropic_fairing/Surface_curvature.h>
#include <CGAL/Anisotropic_fairing/Vector_attribute_traits.h>
#include <CGAL/Anisotropic_fairing/named_function_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/assembly/Fem_assembly.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Indexed_mesh.h>
#include <CGAL/Anisotropic_fairing/internal/surface/Limit_resampler.h>
#include <CGAL/Anisotropic_fairing/internal/element/Ghosted_patch_cache.h>
#include <CGAL/Anisotropic_fairing/internal/element/Quadrature_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/surface/Vertex_curvature.h>
#include <CGAL/Anisotropic_fairing/internal/loop/Vertex_limit_masks.h>
#include <CGAL/Anisotropic_fairing/internal/types/Vector3.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {

/*!
\ingroup PkgAnisotropicFairingLimitSurface

The limit surface of Loop subdivision over a triangle mesh (the control mesh), closed or with borders,
and the Loop finite-element basis on it: \f$ x(\xi) = \sum_j \phi_j(\xi)\, x_j \f$ where the sum runs
over the control vertices of the face's 1-ring.

Each face is parameterised by barycentric coordinates \f$(\xi_0, \xi_1, \xi_2)\f$ with respect to
its vertices in the order of `CGAL::vertices_around_face(halfedge(f, tm), tm)`; derivatives are
taken with respect to \f$\xi_1\f$ and \f$\xi_2\f$ (\f$\xi_0 = 1 - \xi_1 - \xi_2\f$).
Faces whose three vertices have valence 6 are quartic box splines; the others are evaluated exactly
by local subdivision of the face's own 1-ring (any valences \f$\geq 3\f$, any number of
extraordinary vertices per face; the mesh is never modified or globally subdivided). Evaluation
weights are computed once per topological category of face and shared.

<b>Borders.</b> A mesh with borders is closed by a private layer of ghost vertices and triangles
beyond each border (the ghost layer of Bajaj and Xu 2003, section 4.3, with the fans of border
vertices completed): every border edge \f$p \to q\f$ of a triangle \f$(p, q, r)\f$ gets the ghost
\f$p + q - r\f$, and the fan of a border vertex \f$v\f$ with \f$m\f$ triangles is closed by
\f$\max(1, 4 - m)\f$ triangles, whose further ghosts are point reflections \f$2v - r\f$ of neighbours
\f$r\f$ through \f$v\f$. Ghosts are affine combinations of control vertices and move with them; they
carry no unknowns, and ghost triangles are neither evaluated nor integrated. So every face of the
mesh, including one whose three vertices lie on a border, is an ordinary patch; `area()`,
`mass_matrix()` and `resample()` cover exactly the faces of the mesh, and the border of the limit
surface is a limit boundary curve:
- along a stretch of border vertices with \f$m = 3\f$ triangles each and regular (valence 6) interior
  neighbours, it is the uniform cubic B-spline of the border polygon (any border vertex \f$v\f$ with
  \f$m = 3\f$ and border neighbours \f$r_0\f$, \f$r_m\f$ has the limit point
  \f$\frac{2}{3}v + \frac{1}{6}(r_0 + r_m)\f$);
- a corner with a single triangle (\f$m = 1\f$) is interpolated;
- elsewhere (\f$m = 2\f$, \f$m \geq 4\f$, extraordinary interior neighbours) it also depends on a few
  interior vertices next to the border.

The user's mesh is never modified, and sizes, indices and everything written refer to its own
vertices and faces only. A single triangle is its own (flat) limit surface.

The surface is a snapshot: positions are read at construction.

\tparam TriangleMesh a model of `FaceListGraph` (e.g. `CGAL::Surface_mesh`, `CGAL::Polyhedron_3`)
\tparam VertexPointMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
        as key and a CGAL `Point_3` as value

The mesh must be a 2-manifold made of triangles, closed or with borders, with every interior vertex
of valence at least 3; otherwise the constructor throws `Input_error`
naming the offending element. In particular a vertex whose faces form more than one fan (such as a
border vertex shared by two triangles that have no edge in common, a "bow-tie") is refused with
`Input_error::NON_MANIFOLD_VERTEX` and that vertex's index. Vertices on no face (left over in many
scans) are accepted: they lie on no surface, so their limit position (value) is their own position
(value), their normal is the zero vector, their row of `mass_matrix()` is zero, and `resample()` keeps
them as isolated vertices.
*/
template <typename TriangleMesh,
          typename VertexPointMap = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>
class Loop_limit_surface
{
public:
  /// \name Types
  /// @{

  /// vertex descriptor of the control mesh
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// face descriptor of the control mesh
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  /// point type of the point map
  typedef typename boost::property_traits<VertexPointMap>::value_type Point_3;
  /// kernel of the point type
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel Kernel;
  /// vector type of the kernel
  typedef typename Kernel::Vector_3 Vector_3;
  /// Barycentric coordinates of a point of a face (non-negative, summing to 1).
  typedef std::array<double, 3> Barycentric_coordinates;

  /// The limit surface and its derivatives at one parameter point.
  struct Limit_point
  {
    Point_3 position;   ///< the point of the limit surface
    Vector_3 d1;        ///< \f$\partial x/\partial \xi_1\f$
    Vector_3 d2;        ///< \f$\partial x/\partial \xi_2\f$
    Vector_3 d11;       ///< \f$\partial^2 x/\partial \xi_1^2\f$
    Vector_3 d12;       ///< \f$\partial^2 x/\partial \xi_1 \partial \xi_2\f$
    Vector_3 d22;       ///< \f$\partial^2 x/\partial \xi_2^2\f$
    Vector_3 normal;    ///< unit normal, oriented like the face
    /// true at an extraordinary (valence \f$\neq 6\f$) vertex, where the parametric derivatives of
    /// the limit surface degenerate: `d1` and `d2` then span the limit tangent plane (they are the
    /// derivatives of a regular reparameterisation, exact for valence 6) and `d11`, `d12`, `d22` are zero.
    bool at_extraordinary_vertex;
  };
  /// @}

  /// \name Creation
  /// @{

  /*!
  builds the limit surface of `tm` with the point map `vpm`.

  \cgalNamedParamsBegin
    \cgalParamNBegin{quadrature_degree}
      \cgalParamDescription{degree of the symmetric Gauss rule used on each face for `area()` and `mass_matrix()`}
      \cgalParamType{int, 4, 6 or 8}
      \cgalParamDefault{8 (16 points, exact on planar regular patches)}
    \cgalParamNEnd
    \cgalParamNBegin{quadrature_tiling_depth}
      \cgalParamDescription{0 applies the rule once per face; \f$K > 0\f$ splits faces with an extraordinary
                            vertex 1-to-4 down to level \f$K\f$ and applies the rule on every tile (adaptive
                            mode; far more accurate near extraordinary vertices, about 13-31 times more points there)}
      \cgalParamType{int in [0, 12]}
      \cgalParamDefault{0}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \throws Input_error if the mesh is not a 2-manifold triangle mesh (closed or with borders) with interior valences
          \f$\geq 3\f$, if a coordinate is not finite, or if a parameter is out of range.
  */
  template <typename NamedParameters = parameters::Default_named_parameters>
  Loop_limit_surface(const TriangleMesh& tm, VertexPointMap vpm,
                     const NamedParameters& np = parameters::default_values())
    : mesh_(tm)
  {
    init(vpm, np);
  }

  /*!
  builds the limit surface of `tm` with the point map given by the named parameter
  `vertex_point_map` (default: `get(CGAL::vertex_point, tm)`). Other named parameters as above.
  */
  template <typename NamedParameters = parameters::Default_named_parameters>
  explicit Loop_limit_surface(const TriangleMesh& tm,
                              const NamedParameters& np = parameters::default_values())
    : mesh_(tm)
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    init(choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                          get_const_property_map(CGAL::vertex_point, tm)), np);
  }
  /// @}

  /// \name Size
  /// @{

  /// number of control vertices
  std::size_t number_of_vertices() const { return indexed_->number_of_vertices(); }
  /// number of control faces (one limit-surface patch each)
  std::size_t number_of_faces() const { return indexed_->number_of_faces(); }
  /// Number of distinct topological categories of face patches; evaluation weights are computed once per category.
  std::size_t number_of_patch_categories() const { return patches().number_of_categories(); }
  /// Index of `v` in the order of `vertices(tm)`: the row of `v` in `mass_matrix()`.
  std::size_t vertex_index(vertex_descriptor v) const { return indexed_->index(v); }
  /// @}

  /// \name Evaluation
  /// @{

  /// Curvature of the limit surface at a point (see `curvature()`).
  struct Curvature
  {
    Vector_3 mean_curvature_vector;   ///< \f$H = \frac12\Delta_M x\f$ (for the unit sphere, \f$-x\f$)
    /// principal curvatures, \f$k_1 \leq k_2\f$ , w.r.t. the oriented normal (negative on a convex surface oriented
    /// outward)
    double k1 = 0, k2 = 0;
    Vector_3 d1, d2;                  ///< unit principal directions
  };

  /*!
  the curvature of the limit surface at the point of face `f` with barycentric coordinates `b`, with
  respect to the normal oriented like the face. At an extraordinary vertex itself (barycentric
  coordinates (1,0,0) etc. at a vertex of valence other than 6) the Loop limit surface has no finite
  curvature in general; evaluate next to it instead, or use `vertex_curvatures()`.
  \throws Input_error as `evaluate()`.
  */
  Curvature curvature(face_descriptor f, const Barycentric_coordinates& b) const
  {
    const std::size_t fi = indexed_->index(f);
    check_barycentric(fi, b);
    return curvature_at(fi, b[1] / (b[0] + b[1] + b[2]), b[2] / (b[0] + b[1] + b[2]));
  }

  /*!
  evaluates the limit surface at the point of face `f` with barycentric coordinates `b`.
  \throws Input_error if `b` has a negative or non-finite entry or does not sum to 1 (to 1e-12).
  */
  Limit_point evaluate(face_descriptor f, const Barycentric_coordinates& b) const
  {
    const std::size_t fi = indexed_->index(f);
    internal::Stencil s;
    stencil_at(fi, b, s);
    double v[6][3];
    jet(fi, s, v);
    double n[3];
    internal::unit_cross(v[1], v[2], n);
    Limit_point p;
    p.position = Point_3(v[0][0], v[0][1], v[0][2]);
    p.d1 = Vector_3(v[1][0], v[1][1], v[1][2]);
    p.d2 = Vector_3(v[2][0], v[2][1], v[2][2]);
    p.d11 = Vector_3(v[3][0], v[3][1], v[3][2]);
    p.d12 = Vector_3(v[4][0], v[4][1], v[4][2]);
    p.d22 = Vector_3(v[5][0], v[5][1], v[5][2]);
    p.normal = Vector_3(n[0], n[1], n[2]);
    p.at_extraordinary_vertex = s.singular;
    return p;
  }

  /*!
  evaluates the limit of a per-vertex attribute (a function on the surface, e.g. colours or texture
  coordinates) at the point of face `f` with barycentric coordinates `b`: the same Loop basis
  functions applied to the attribute values.
  \tparam AttributeMap a `ReadablePropertyMap` with `vertex_descriptor` as key whose value type has a
  `Vector_attribute_traits`
  */
  template <typename AttributeMap>
  typename boost::property_traits<AttributeMap>::value_type
  evaluate_attribute(face_descriptor f, const Barycentric_coordinates& b, AttributeMap attributes) const
  {
    typedef typename boost::property_traits<AttributeMap>::value_type Value;
    const internal::Control_matrix A = extended_attributes(attributes);
    const std::size_t fi = indexed_->index(f);
    internal::Stencil s;
    stencil_at(fi, b, s);
    const int* ring = patches().ring(fi);
    std::vector<double> a(std::size_t(A.cols()), 0.0);
    for(Eigen::Index c = 0; c < A.cols(); ++c)
      for(int k = 0; k < s.m; ++k) a[std::size_t(c)] += s.row(internal::VALUE)[k] * A(ring[k], c);
    const int corner = int(std::max_element(b.begin(), b.end()) - b.begin());
    const Value& prototype = get(attributes, indexed_->vertex(std::size_t(indexed_->topology().face(fi)[corner])));
    return Vector_attribute_traits<Value>::make(prototype, a.data());
  }

  /// writes the limit position of every control vertex (closed-form limit mask) into `out`,
  /// a `WritablePropertyMap` with `vertex_descriptor` key and `Point_3` value. A border vertex gets its
  /// point of the limit boundary curve.
  template <typename PointOutputMap>
  void limit_positions(PointOutputMap out) const
  {
    write_vertex_masks<Point_3>(out, &internal::vertex_limit_value);
  }

  /// writes the unit normal of the limit surface at every control vertex (closed-form tangent masks)
  /// into `out`, a `WritablePropertyMap` with `vertex_descriptor` key and `Vector_3` value (on a border,
  /// the normal of the limit surface at its boundary point).
  template <typename VectorOutputMap>
  void limit_normals(VectorOutputMap out) const
  {
    write_vertex_masks<Vector_3>(out, &internal::vertex_limit_normal);
  }

  /*!
  writes the curvature of the limit surface at every control vertex into `out`, a
  `WritablePropertyMap` with `vertex_descriptor` key and `Curvature` value.

  The Loop limit surface has no finite curvature at an extraordinary vertex in general (it is
  unbounded for valence > 6, and for valence 3 to 5 its limit depends on the direction of approach),
  so every vertex gets the same kind of value: the average of the shape operator
  \f$S = k_1 e_1 e_1^T + k_2 e_2 e_2^T\f$ over the limit patches of its incident faces, weighted by
  the vertex's hat function \f$\xi_v\f$ (its barycentric coordinate in each face),
  \f[ S_v = \frac{\int \xi_v\, S\, dA}{\int \xi_v\, dA}, \f]
  restricted to the limit tangent plane at the vertex (the normal of `limit_normals()`) and
  diagonalised there: `k1` \f$\leq\f$ `k2` with unit tangent directions `d1`, `d2` (\f$d_1\times d_2\f$
  is the limit normal), and `mean_curvature_vector` \f$= \frac12(k_1 + k_2)\f$ times the limit normal.
  Regular vertices get the average too, rather than the pointwise value of `curvature()` there: on an
  interpolating icosphere the pointwise curvature at valence-6 vertices is off by about 0.2 (relative)
  at every refinement, the average by 0.05. The integrals use the quadrature chosen at construction;
  on a smooth surface sampled by a regular mesh the average is a second-order approximation of the
  curvature at the vertex (the star is symmetric to first order). A border vertex averages over its
  half star; a vertex on no face gets zero curvature and zero vectors.
  */
  template <typename CurvatureMap>
  void vertex_curvatures(CurvatureMap out) const
  {
    const std::vector<internal::Vertex_curvature_value> c = vertex_curvature_values();
    for(std::size_t i = 0; i < number_of_vertices(); ++i) put(out, indexed_->vertex(i), to_curvature(c[i]));
  }

  /// writes the limit value of an attribute at every control vertex into `out` (same key and value type as `in`).
  template <typename AttributeMap, typename AttributeOutputMap>
  void limit_values(AttributeMap in, AttributeOutputMap out) const
  {
    typedef typename boost::property_traits<AttributeMap>::value_type Value;
    const internal::Control_matrix A = extended_attributes(in);
    std::vector<double> a(std::size_t(A.cols()));
    std::vector<Value> result;
    result.reserve(number_of_vertices());
    for(std::size_t i = 0; i < number_of_vertices(); ++i)
    {
      internal::vertex_limit_value(indexed_->topology(), A, int(i), a.data());
      result.push_back(Vector_attribute_traits<Value>::make(get(in, indexed_->vertex(i)), a.data()));
    }
    for(std::size_t i = 0; i < number_of_vertices(); ++i) put(out, indexed_->vertex(i), result[i]);  // in may be out
  }
  /// @}

  /// \name Integration
  /// @{

  /// the area of the limit surface (the patches of the mesh's faces), by the quadrature chosen at construction.
  double area() const { return area_; }

  /*!
  the mass matrix \f$ M_{ij} = \int \phi_i \phi_j \, dA \f$ over the limit surface, with rows and
  columns in the order of `vertices(tm)`. It is symmetric positive definite (but for the zero rows and
  columns of vertices on no face), has one row per control
  vertex with non-zeros for the vertices of its 3-ring (37 on a regular mesh), and its entries sum to `area()`.
  Next to a border, \f$\phi_i\f$ includes the share of vertex \f$i\f$ in the ghosts' basis functions
  (\f$M = E^T M_{ext} E\f$ with \f$E\f$ the affine map from control vertices to ghosts), so a row also
  holds the vertices that define the ghosts of its 3-ring.
  */
  Eigen::SparseMatrix<double> mass_matrix() const
  {
    // assembled on the control vertices: the faces next to a border have the ghosts' affine rows
    // folded into their stencils (Ghosted_patch_cache.h), so E^T M_ext E is never formed
    const std::size_t n = number_of_vertices();
    internal::Fem_assembler<internal::Ghosted_patch_cache> assembler(*cache_, n);
    internal::Value_array m, l;
    assembler.assemble(X_.topRows(Eigen::Index(n)), int(X_.cols()), Isotropic_diffusion_tensor(), m, l);
    return assembler.pattern().matrix(m);
  }
  /// @}

  /// \name Resampling
  /// @{

  /*!
  writes into the empty mesh `out` a triangulation of the limit surface at \f$2^{levels}\f$ times the
  resolution of the control mesh: the connectivity of `levels` steps of Loop subdivision, with every
  vertex placed exactly on the limit surface (vertices of the control mesh first, in their order,
  then the points inside edges, then those inside faces). Its faces come \f$4^{levels}\f$ per face of
  the mesh, in the order of `faces(tm)`, so face properties carry over. It covers exactly the faces of
  the mesh, so it has the same borders; their vertices lie on the limit boundary curve.

  \tparam OutputMesh a model of `MutableFaceGraph`
  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{the point map of `out`}
      \cgalParamDefault{`get(CGAL::vertex_point, out)`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_normal_map}
      \cgalParamDescription{if given, receives the unit normal of the limit surface at each new vertex}
      \cgalParamDefault{unused}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_curvature_map}
      \cgalParamDescription{if given, a `WritablePropertyMap` with `out`'s vertex descriptor as key and
        `Curvature` as value that receives the curvature of the limit surface at each new vertex: at the
        vertices of the control mesh the value of `vertex_curvatures()`, at the others (inside edges
        and faces, where the limit surface is smooth) the exact value of `curvature()`}
      \cgalParamDefault{unused}
    \cgalParamNEnd
  \cgalNamedParamsEnd
  \throws Input_error if `out` is not empty or `levels` exceeds 10.
  */
  template <typename OutputMesh, typename NamedParameters = parameters::Default_named_parameters>
  void resample(unsigned levels, OutputMesh& out, const NamedParameters& np = parameters::default_values()) const
  {
    const internal::Resampled_surface r = resampled(levels, out, nullptr);
    write_resampled(r, out, np, [](std::size_t, typename boost::graph_traits<OutputMesh>::vertex_descriptor) {});
  }

  /*!
  as above, and also writes the limit values of the attribute `in` (keyed by this mesh's vertices)
  into `out_attributes` (keyed by `out`'s vertices, same value type).
  */
  template <typename OutputMesh, typename AttributeMap, typename AttributeOutputMap,
            typename NamedParameters = parameters::Default_named_parameters>
  void resample(unsigned levels, OutputMesh& out, AttributeMap in, AttributeOutputMap out_attributes,
                const NamedParameters& np = parameters::default_values()) const
  {
    typedef typename boost::property_traits<AttributeMap>::value_type Value;
    const internal::Control_matrix A = extended_attributes(in);
    const internal::Resampled_surface r = resampled(levels, out, &A);
    write_resampled(r, out, np,
      [&](std::size_t i, typename boost::graph_traits<OutputMesh>::vertex_descriptor v) {
        const Value& prototype = get(in, indexed_->vertex(r.prototype[i]));
        put(out_attributes, v, Vector_attribute_traits<Value>::make(prototype,
                                                                    r.attributes.row(Eigen::Index(i)).data()));
      });
  }
  /// @}

private:
  // puts Value(mask(v)) for every control vertex v: a closed-form limit mask of X_ at v
  template <typename Value, typename OutputMap, typename Mask>
  void write_vertex_masks(OutputMap out, const Mask& mask) const
  {
    double m[3];
    for(std::size_t i = 0; i < number_of_vertices(); ++i)
    {
      mask(indexed_->topology(), X_, int(i), m);
      put(out, indexed_->vertex(i), Value(m[0], m[1], m[2]));
    }
  }

  template <typename PointMap, typename NamedParameters>
  void init(PointMap vpm, const NamedParameters& np)
  {
    indexed_.reset(new internal::Indexed_mesh<TriangleMesh>(mesh_, internal::Borders::GHOSTED, true));
    indexed_->index_faces();
    // rows of the ghosts appended, so patches next to a border evaluate like any other
    const internal::Ghost_layer& gl = indexed_->ghost_layer();
    X_ = gl.extend(indexed_->read_points(vpm));
    // ghost faces get no patch
    cache_.reset(new internal::Ghosted_patch_cache(gl, internal::read_quadrature_spec(np)));
    internal::Fem_assembler<internal::Patch_cache> statistics(patches(), gl.number_of_extended_vertices(), false);
    internal::Value_array unused;
    area_ = statistics.assemble(X_, int(X_.cols()), Isotropic_diffusion_tensor(), unused, unused, false).area;
  }

  // Attributes of the control vertices with the ghosts' rows appended (the same affine map as positions).
  template <typename AttributeMap>
  internal::Control_matrix extended_attributes(AttributeMap map) const
  {
    const internal::Ghost_layer& gl = indexed_->ghost_layer();
    internal::Control_matrix A = indexed_->read_attributes(map);
    return gl.has_boundary() ? gl.extend(A) : A;
  }

  // the Loop patches over the control vertices and ghosts (evaluation, area, resampling)
  const internal::Patch_cache& patches() const { return cache_->extended(); }

  static void check_barycentric(std::size_t fi, const Barycentric_coordinates& b)
  {
    const double sum = b[0] + b[1] + b[2];
    if(!(b[0] >= 0 && b[1] >= 0 && b[2] >= 0) || !(std::abs(sum - 1.0) <= 1e-12))
      throw Input_error(Input_error::INVALID_PARAMETER, fi,
                        "barycentric coordinates must be non-negative and sum to 1");
  }

  void stencil_at(std::size_t fi, const Barycentric_coordinates& b, internal::Stencil& s) const
  {
    check_barycentric(fi, b);
    const double sum = b[0] + b[1] + b[2];
    patches().root_patch(patches().category(fi)).stencil(b[1] / sum, b[2] / sum, s);
  }

  // position and derivatives (the stencil's rows VALUE, D1, D2, D11, D12, D22) at a point of face fi
  void jet(std::size_t fi, const internal::Stencil& s, double (&v)[6][3]) const
  {
    const int* ring = patches().ring(fi);
    for(int r = 0; r < 6; ++r)
      for(int c = 0; c < 3; ++c)
      {
        double sum = 0;
        for(int k = 0; k < s.m; ++k) sum += s.row(r)[k] * X_(ring[k], c);
        v[r][c] = sum;
      }
  }

  // the curvature at parameters (xi1, xi2) of face fi (internal index)
  Curvature curvature_at(std::size_t fi, double xi1, double xi2) const
  {
    internal::Stencil s;
    patches().root_patch(patches().category(fi)).stencil(xi1, xi2, s);
    double v[6][3];
    jet(fi, s, v);
    const double (*t)[3] = v + 1;   // the derivative rows
    const Quadrature_point_geometry q = internal::point_geometry_3(t, fi, -1);
    double H[3];
    mean_curvature_vector(q, H);
    const Principal_curvatures pc = principal_curvatures(q);
    auto direction = [&](const std::array<double, 2>& c) {
      const Vector_3 e(c[0] * t[0][0] + c[1] * t[1][0], c[0] * t[0][1] + c[1] * t[1][1],
                       c[0] * t[0][2] + c[1] * t[1][2]);
      const double l = std::sqrt(e * e);
      return l > 0 ? e / l : e;
    };
    return Curvature{ Vector_3(H[0], H[1], H[2]), pc.k1, pc.k2, direction(pc.c1), direction(pc.c2) };
  }

  std::vector<internal::Vertex_curvature_value> vertex_curvature_values() const
  {
    return internal::averaged_vertex_curvatures(indexed_->topology(), patches(), number_of_vertices(), X_);
  }

  Curvature to_curvature(const internal::Vertex_curvature_value& c) const
  {
    return Curvature{ Vector_3(c.H[0], c.H[1], c.H[2]), c.k1, c.k2,
                      Vector_3(c.d1[0], c.d1[1], c.d1[2]), Vector_3(c.d2[0], c.d2[1], c.d2[2]) };
  }

  template <typename OutputMesh>
  internal::Resampled_surface resampled(unsigned levels, const OutputMesh& out, const internal::Control_matrix* A) const
  {
    if(levels > 10)
      throw Input_error(Input_error::INVALID_PARAMETER, Input_error::no_element,
                        "resampling levels must not exceed 10");
    if(num_vertices(out) != 0 || num_faces(out) != 0)
      throw Input_error(Input_error::INVALID_PARAMETER, Input_error::no_element,
                        "the output mesh of resample() must be empty");
    return internal::resample_limit_surface(indexed_->topology(), patches(), number_of_vertices(), X_, A, levels);
  }

  template <typename OutputMesh, typename NamedParameters, typename AttributeWriter>
  void write_resampled(const internal::Resampled_surface& r, OutputMesh& out, const NamedParameters& np,
                       AttributeWriter write_attribute) const
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    using parameters::is_default_parameter;
    typedef typename boost::graph_traits<OutputMesh>::vertex_descriptor out_vertex;
    typedef typename CGAL::GetVertexPointMap<OutputMesh, NamedParameters>::type Out_vpm;
    typedef typename boost::property_traits<Out_vpm>::value_type Out_point;
    typedef typename CGAL::Kernel_traits<Out_point>::Kernel::Vector_3 Out_vector;
    Out_vpm ovpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, out));
    auto onm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_normal_map),
                                CGAL::Constant_property_map<out_vertex, Out_vector>(Out_vector(0, 0, 0)));
    const bool with_normals = !is_default_parameter<NamedParameters, CGAL::internal_np::vertex_normal_map_t>::value;
    auto ocm = choose_parameter(get_parameter(np, internal_np::vertex_curvature_map),
                                CGAL::Constant_property_map<out_vertex, Curvature>(Curvature()));
    const bool with_curvatures = !is_default_parameter<NamedParameters, internal_np::vertex_curvature_map_t>::value;
    std::vector<internal::Vertex_curvature_value> at_vertices;
    if(with_curvatures) at_vertices = vertex_curvature_values();

    std::vector<out_vertex> created;
    created.reserve(std::size_t(r.positions.rows()));
    for(Eigen::Index i = 0; i < r.positions.rows(); ++i)
    {
      out_vertex v = add_vertex(out);
      put(ovpm, v, Out_point(r.positions(i, 0), r.positions(i, 1), r.positions(i, 2)));
      if(with_normals) put(onm, v, Out_vector(r.normals(i, 0), r.normals(i, 1), r.normals(i, 2)));
      if(with_curvatures)
      {
        if(std::size_t(i) < number_of_vertices()) put(ocm, v, to_curvature(at_vertices[std::size_t(i)]));
        else put(ocm, v, curvature_at(r.face[std::size_t(i)], r.parameter[std::size_t(i)][0],
                                      r.parameter[std::size_t(i)][1]));
      }
      write_attribute(std::size_t(i), v);
      created.push_back(v);
    }
    for(const auto& t : r.faces)
    {
      const std::array<out_vertex, 3> tri = { created[t[0]], created[t[1]], created[t[2]] };
      if(CGAL::Euler::add_face(tri, out) == boost::graph_traits<OutputMesh>::null_face())
        throw std::logic_error("Loop_limit_surface::resample: could not add a face");
    }
  }

  const TriangleMesh& mesh_;
  std::unique_ptr<internal::Indexed_mesh<TriangleMesh>> indexed_;
  std::unique_ptr<internal::Ghosted_patch_cache> cache_;   // its extended() cache: patches()
  internal::Control_matrix X_;   // control points, then ghosts (E X)
  double area_ = 0;
};

} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_LOOP_LIMIT_SURFACE_H
