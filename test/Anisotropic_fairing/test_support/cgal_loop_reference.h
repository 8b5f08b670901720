// Brute-force oracle: exact Loop limit-surface points at dyadic parameters,
// computed with CGAL's own Loop subdivision (CGAL::Subdivision_method_3).
//
// Method: copy the closed control mesh, apply CGAL::Subdivision_method_3::Loop_subdivision
// k times (one level at a time), tracking for every vertex its parameter as a sparse
// barycentric combination of ORIGINAL control vertices (support <= 3), then apply the
// Loop limit mask to every level-k vertex. Since the limit surface is invariant under
// subdivision, these are exact limit points (up to round-off) at the dyadic parameters.
//
// Conventions (stable, relied upon by the tests):
//   * control vertex index = position in vertices(control) iteration order;
//   * original face index  = position in faces(control) iteration order (0..F-1);
//   * in face f, (v0, v1, v2) = CGAL::vertices_around_face(halfedge(f, control), control)
//     in that order; (xi1, xi2) are the barycentric weights of v1 and v2, and
//     xi0 = 1 - xi1 - xi2 is the weight of v0.
//
// Independent of include/CGAL/Anisotropic_fairing (test oracle).

#ifndef AF_TEST_SUPPORT_CGAL_LOOP_REFERENCE_H
#define AF_TEST_SUPPORT_CGAL_LOOP_REFERENCE_H

#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/subdivision_method_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace AF_test {

// ---------------------------------------------------------------------------
// Loop weights
// ---------------------------------------------------------------------------

// Vertex-rule weight a(n) = (1/n)(5/8 - (3/8 + cos(2 pi/n)/4)^2); a(6) = 1/16.
inline double loop_vertex_weight(std::size_t n)
{
  const double pi = std::acos(-1.0);
  const double l = 3.0 / 8.0 + std::cos(2.0 * pi / double(n)) / 4.0;
  return (5.0 / 8.0 - l * l) / double(n);
}

// Limit-mask neighbour weight chi(n) = 1/(n + 3/(8 a(n))); chi(6) = 1/12,
// centre weight 1 - n chi(n) (= 1/2 for n = 6).
inline double loop_limit_weight(std::size_t n)
{
  return 1.0 / (double(n) + 3.0 / (8.0 * loop_vertex_weight(n)));
}

// ---------------------------------------------------------------------------
// Sparse barycentric parameter over original control vertices
// ---------------------------------------------------------------------------

struct Sparse_param
{
  int size = 0;                                   // 1, 2 or 3
  std::array<std::size_t, 3> vertex = {{0, 0, 0}}; // control vertex indices, strictly increasing
  std::array<double, 3> weight = {{0, 0, 0}};      // positive, sum to 1 (dyadic rationals)

  static Sparse_param single(std::size_t v)
  {
    Sparse_param p;
    p.size = 1;
    p.vertex[0] = v;
    p.weight[0] = 1.0;
    return p;
  }

  // weight of control vertex v (0 if not in the support)
  double weight_of(std::size_t v) const
  {
    for(int i = 0; i < size; ++i)
      if(vertex[i] == v) return weight[i];
    return 0.0;
  }

  bool contains(std::size_t v) const
  {
    for(int i = 0; i < size; ++i)
      if(vertex[i] == v) return true;
    return false;
  }

  bool operator==(const Sparse_param& o) const
  {
    if(size != o.size) return false;
    for(int i = 0; i < size; ++i)
      if(vertex[i] != o.vertex[i] || weight[i] != o.weight[i]) return false;
    return true;
  }
  bool operator!=(const Sparse_param& o) const { return !(*this == o); }

  std::string to_string() const
  {
    std::string s = "{";
    for(int i = 0; i < size; ++i)
      s += (i ? ", (" : "(") + std::to_string(vertex[i]) + ", " + std::to_string(weight[i]) + ")";
    return s + "}";
  }
};

// (p + q) / 2; throws std::runtime_error if the support would exceed 3 vertices.
inline Sparse_param average(const Sparse_param& p, const Sparse_param& q)
{
  Sparse_param r;
  int i = 0, j = 0;
  while(i < p.size || j < q.size)
  {
    if(r.size == 3)
      throw std::runtime_error("AF_test::average: parameter support exceeds 3 control vertices");
    if(j >= q.size || (i < p.size && p.vertex[i] < q.vertex[j]))
    { r.vertex[r.size] = p.vertex[i]; r.weight[r.size] = 0.5 * p.weight[i]; ++i; }
    else if(i >= p.size || q.vertex[j] < p.vertex[i])
    { r.vertex[r.size] = q.vertex[j]; r.weight[r.size] = 0.5 * q.weight[j]; ++j; }
    else
    { r.vertex[r.size] = p.vertex[i]; r.weight[r.size] = 0.5 * (p.weight[i] + q.weight[j]); ++i; ++j; }
    ++r.size;
  }
  return r;
}

// ---------------------------------------------------------------------------
// Output
// ---------------------------------------------------------------------------

struct Limit_sample
{
  std::size_t face;                // original face index (faces(control) order)
  double xi1, xi2;                 // barycentric weights of v1, v2 of that face
  std::array<double, 3> limit;     // exact limit point (or limit value of the data)
  std::size_t refined_vertex;      // index into Loop_reference::refined_vertices
};

template <class Mesh>
struct Loop_reference
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;

  int level = 0;
  std::size_t num_control_vertices = 0;
  // per original face: control indices of (v0, v1, v2)
  std::vector<std::array<std::size_t, 3> > control_faces;

  Mesh refined;                                     // level-k mesh produced by CGAL
  std::vector<vertex_descriptor> refined_vertices;  // vertices(refined) order
  std::vector<Sparse_param> params;                 // per refined vertex
  std::vector<std::array<double, 3> > limits;       // per refined vertex
  // one sample per (refined vertex, original face whose closure contains it),
  // ordered by refined vertex, then by face index
  std::vector<Limit_sample> samples;
};

namespace detail {

template <class Mesh>
std::array<double, 3> point_as_array(const Mesh& mesh, typename boost::graph_traits<Mesh>::vertex_descriptor v)
{
  const auto& p = get(get(CGAL::vertex_point, mesh), v);
  return {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
}

// Limit-mask position of vertex v of a closed mesh.
template <class Mesh>
std::array<double, 3> limit_mask_at(const Mesh& mesh, typename boost::graph_traits<Mesh>::vertex_descriptor v)
{
  std::array<double, 3> sum = {{0, 0, 0}};
  std::size_t n = 0;
  for(auto h : CGAL::halfedges_around_target(halfedge(v, mesh), mesh))
  {
    if(is_border(h, mesh) || is_border(opposite(h, mesh), mesh))
      throw std::invalid_argument("AF_test: limit mask needs a closed mesh");
    const std::array<double, 3> q = point_as_array(mesh, source(h, mesh));
    for(int d = 0; d < 3; ++d) sum[d] += q[d];
    ++n;
  }
  const double chi = loop_limit_weight(n);
  const double centre = 1.0 - double(n) * chi;
  const std::array<double, 3> x = point_as_array(mesh, v);
  return {{centre * x[0] + chi * sum[0], centre * x[1] + chi * sum[1], centre * x[2] + chi * sum[2]}};
}

template <class Mesh>
Loop_reference<Mesh> loop_reference_impl(const Mesh& control, int k,
                                         const std::vector<std::array<double, 3> >* values)
{
  typedef boost::graph_traits<Mesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename boost::property_map<Mesh, CGAL::vertex_point_t>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point;

  if(k < 1)
    throw std::invalid_argument("AF_test::cgal_loop_reference: level must be >= 1");
  if(!CGAL::is_closed(control) || !CGAL::is_triangle_mesh(control))
    throw std::invalid_argument("AF_test::cgal_loop_reference: control mesh must be a closed triangle mesh");

  Loop_reference<Mesh> ref;
  ref.level = k;

  // control indexing
  std::unordered_map<vertex_descriptor, std::size_t> control_index;
  std::vector<vertex_descriptor> control_vertices;
  for(vertex_descriptor v : vertices(control))
  {
    control_index.emplace(v, control_vertices.size());
    control_vertices.push_back(v);
  }
  const std::size_t nv = control_vertices.size();
  ref.num_control_vertices = nv;
  if(values && values->size() != nv)
    throw std::invalid_argument("AF_test::cgal_loop_reference: values.size() != number of control vertices");

  std::vector<std::vector<std::size_t> > incident_faces(nv);
  for(auto f : faces(control))
  {
    std::array<std::size_t, 3> t;
    int c = 0;
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, control), control))
    {
      if(c == 3) throw std::invalid_argument("AF_test::cgal_loop_reference: non-triangular face");
      t[c++] = control_index.at(v);
    }
    for(int i = 0; i < 3; ++i) incident_faces[t[i]].push_back(ref.control_faces.size());
    ref.control_faces.push_back(t);
  }

  // copy, with an explicit control -> copy vertex correspondence
  Mesh& p = ref.refined;
  std::vector<std::pair<vertex_descriptor, vertex_descriptor> > v2v;
  CGAL::copy_face_graph(control, p, CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(v2v)));
  if(v2v.size() != nv || num_vertices(p) != nv || num_faces(p) != num_faces(control))
    throw std::runtime_error("AF_test::cgal_loop_reference: copy_face_graph produced an unexpected copy");

  // vertex of the working mesh -> index into `par`
  std::unordered_map<vertex_descriptor, std::size_t> index;
  std::vector<Sparse_param> par(nv);
  for(const auto& vv : v2v)
  {
    const std::size_t i = control_index.at(vv.first);
    index.emplace(vv.second, i);
    par[i] = Sparse_param::single(i);
  }
  if(index.size() != nv)
    throw std::runtime_error("AF_test::cgal_loop_reference: copy vertex map is not a bijection");

  if(values)
  {
    VPM vpm = get(CGAL::vertex_point, p);
    for(const auto& vv : v2v)
    {
      const auto& x = (*values)[control_index.at(vv.first)];
      put(vpm, vv.second, Point(x[0], x[1], x[2]));
    }
  }

  for(int level = 1; level <= k; ++level)
  {
    // PTQ_1step inserts one vertex per edge, in edges(p) order, after the old ones.
    std::vector<std::pair<vertex_descriptor, vertex_descriptor> > edge_ends;
    edge_ends.reserve(num_edges(p));
    for(auto e : edges(p))
      edge_ends.emplace_back(source(e, p), target(e, p));
    const std::size_t old_nv = num_vertices(p);

    CGAL::Subdivision_method_3::Loop_subdivision(p, CGAL::parameters::number_of_iterations(1));

    if(num_vertices(p) != old_nv + edge_ends.size())
      throw std::runtime_error("AF_test::cgal_loop_reference: unexpected vertex count after Loop_subdivision");
    std::size_t j = 0;
    for(vertex_descriptor w : vertices(p))
    {
      if(index.count(w)) continue;
      if(j >= edge_ends.size())
        throw std::runtime_error("AF_test::cgal_loop_reference: more new vertices than edges");
      const vertex_descriptor s = edge_ends[j].first, t = edge_ends[j].second;
      ++j;
      // verify the assumed correspondence: w must split edge (s,t)
      if(!halfedge(w, s, p).second || !halfedge(w, t, p).second)
        throw std::runtime_error("AF_test::cgal_loop_reference: new vertex #" + std::to_string(j - 1) +
                                 " at level " + std::to_string(level) +
                                 " is not adjacent to the endpoints of the corresponding edge "
                                 "(vertex iteration order assumption broken)");
      index.emplace(w, par.size());
      par.push_back(average(par[index.at(s)], par[index.at(t)]));
    }
    if(j != edge_ends.size())
      throw std::runtime_error("AF_test::cgal_loop_reference: fewer new vertices than edges");
  }

  // outputs in vertices(refined) order
  const std::size_t nr = num_vertices(p);
  ref.refined_vertices.reserve(nr);
  ref.params.reserve(nr);
  ref.limits.reserve(nr);
  for(vertex_descriptor v : vertices(p))
  {
    const std::size_t r = ref.refined_vertices.size();
    ref.refined_vertices.push_back(v);
    const Sparse_param& sp = par[index.at(v)];
    ref.params.push_back(sp);
    ref.limits.push_back(limit_mask_at(p, v));

    std::size_t found = 0;
    for(std::size_t f : incident_faces[sp.vertex[0]])
    {
      const std::array<std::size_t, 3>& t = ref.control_faces[f];
      bool all = true;
      for(int i = 0; i < sp.size; ++i)
        if(sp.vertex[i] != t[0] && sp.vertex[i] != t[1] && sp.vertex[i] != t[2]) all = false;
      if(!all) continue;
      ++found;
      Limit_sample smp;
      smp.face = f;
      smp.xi1 = sp.weight_of(t[1]);
      smp.xi2 = sp.weight_of(t[2]);
      smp.limit = ref.limits.back();
      smp.refined_vertex = r;
      ref.samples.push_back(smp);
    }
    if(found == 0)
      throw std::runtime_error("AF_test::cgal_loop_reference: parameter " + sp.to_string() +
                               " lies in no original face");
  }
  return ref;
}

} // namespace detail

// Exact limit points of the Loop surface of `control` at all dyadic parameters of level k >= 1.
// Throws std::invalid_argument for a bad input, std::runtime_error if CGAL's vertex
// ordering does not match the assumed one (checked by adjacency).
template <class Mesh>
Loop_reference<Mesh> cgal_loop_reference(const Mesh& control, int k)
{
  return detail::loop_reference_impl(control, k, nullptr);
}

// Same, but subdivides the data `values` (one 3-vector per control vertex, vertices(control)
// order) instead of the geometry: Loop subdivision is linear and topology-only, so this gives
// the exact limit values of vector-valued data. refined's positions then hold the data.
template <class Mesh>
Loop_reference<Mesh> cgal_loop_reference(const Mesh& control, int k,
                                         const std::vector<std::array<double, 3> >& values)
{
  return detail::loop_reference_impl(control, k, &values);
}

// Limit positions of the control vertices (level 0), vertices(mesh) order.
template <class Mesh>
std::vector<std::array<double, 3> > limit_mask_positions(const Mesh& mesh)
{
  std::vector<std::array<double, 3> > r;
  r.reserve(num_vertices(mesh));
  for(auto v : vertices(mesh))
    r.push_back(detail::limit_mask_at(mesh, v));
  return r;
}

// The neighbours of v in counter-clockwise order (as seen from the side the face
// orientation points to), starting at source(halfedge(v, mesh)).
template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>
ccw_neighbours(const Mesh& mesh, typename boost::graph_traits<Mesh>::vertex_descriptor v)
{
  // halfedges_around_target visits h, opposite(next(h)), ...: their sources go clockwise.
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> nb;
  for(auto h : CGAL::halfedges_around_target(halfedge(v, mesh), mesh))
    nb.push_back(source(h, mesh));
  if(nb.size() > 1) std::reverse(nb.begin() + 1, nb.end());
  return nb;
}

// Unit limit normals from the Loop tangent masks, vertices(mesh) order:
// t_u = sum_j cos(2 pi j/n) x_j, t_v = sum_j sin(2 pi j/n) x_j over the CCW neighbours,
// normal = (t_u x t_v) / |t_u x t_v| (outward for an outward-oriented mesh).
template <class Mesh>
std::vector<std::array<double, 3> > tangent_mask_normals(const Mesh& mesh)
{
  const double pi = std::acos(-1.0);
  std::vector<std::array<double, 3> > r;
  r.reserve(num_vertices(mesh));
  for(auto v : vertices(mesh))
  {
    const auto nb = ccw_neighbours(mesh, v);
    const std::size_t n = nb.size();
    std::array<double, 3> tu = {{0, 0, 0}}, tv = {{0, 0, 0}};
    for(std::size_t j = 0; j < n; ++j)
    {
      const std::array<double, 3> x = detail::point_as_array(mesh, nb[j]);
      const double c = std::cos(2 * pi * double(j) / double(n)), s = std::sin(2 * pi * double(j) / double(n));
      for(int d = 0; d < 3; ++d) { tu[d] += c * x[d]; tv[d] += s * x[d]; }
    }
    std::array<double, 3> nr = {{tu[1] * tv[2] - tu[2] * tv[1], tu[2] * tv[0] - tu[0] * tv[2], tu[0] * tv[1] - tu[1] * tv[0]}};
    const double l = std::sqrt(nr[0] * nr[0] + nr[1] * nr[1] + nr[2] * nr[2]);
    for(int d = 0; d < 3; ++d) nr[d] /= l;
    r.push_back(nr);
  }
  return r;
}

} // namespace AF_test

#endif // AF_TEST_SUPPORT_CGAL_LOOP_REFERENCE_H
