// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A normal-field stage for mesh denoising: the face normals filtered once with guidance (Zhang, Deng, Zhang,
// Bouaziz, Liu, "Guided Mesh Normal Filtering", Pacific Graphics 2015), then the vertices fitted to the filtered
// normals by the iterative update of Sun, Rosin, Martin, Langbein ("Fast and effective feature-preserving mesh
// denoising", IEEE TVCG 2007). The control mesh's vertices move directly: no limit surface is involved.
//
// Neighbourhoods: N(f) is the faces sharing a vertex with f (f included); each j in N(f) offers the patch
// P(j) = N(j) as a candidate guide for f. Zhang et al. measure how consistent a patch's normals are by
// H(P) = D(P) R(P): D the largest normal difference in P, R = max_e s(e) / (sum_e s(e) + 1e-9) the relative
// total variation of the saliencies s(e) = |n_a - n_b| of P's interior edges. A noisy flat patch has a small D
// spread over all its edges (low H); a patch across a feature has a large D carried by few edges (high H). Both
// factors count: D / sum_e s(e) alone is blind to the noise's amplitude (it is the same for a patch with tiny
// noise and one across a cube's corner, which then rounds off pass after pass). The guidance normal is the mean
// normal of the consistent patches, and the filtered normal a bilateral mean whose range kernel reads the
// guidance, not the noisy normals, so that faces on two sides of a feature do not mix.
//
// Every per-face and per-vertex value is gathered by one thread in a fixed order, so a pass gives the same
// bytes whatever the number of threads.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NORMAL_FIELD_FILTER_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NORMAL_FIELD_FILTER_H

#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/types/Parallel_blocks.h>
#include <CGAL/Anisotropic_fairing/internal/types/Vector3.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

struct Normal_field_settings
{
  double range = 0.35;                  // sigma_r of the range kernel on normal differences (GMNF's published default)
  std::size_t vertex_iterations = 10;   // iterations of the vertex update per pass
};

class Normal_field_filter
{
public:
  /// topo: the mesh; only its first `real_faces` faces are the surface (later faces are a ghost layer, ignored
  /// entirely). moves[i]: vertex i may move (false: border or held vertex, never changed). X: the input
  /// positions (n rows, geometry in the first 3 columns; further columns, attribute values, are left unchanged).
  /// The spatial scale (sigma_s) and the face neighbourhoods are fixed here, from X.
  Normal_field_filter(const Triangle_topology& topo, std::size_t real_faces, const std::vector<bool>& moves,
                      const Control_matrix& X, const Normal_field_settings& settings = Normal_field_settings())
    : settings_(settings)
  {
    CGAL_precondition(real_faces <= topo.number_of_faces());
    CGAL_precondition(std::size_t(X.rows()) >= topo.number_of_vertices() && X.cols() >= 3);
    const std::size_t n = topo.number_of_vertices();
    corners_.assign(topo.faces().begin(), topo.faces().begin() + std::ptrdiff_t(real_faces));
    moves_.assign(n, 0);
    for(std::size_t i = 0; i < n && i < moves.size(); ++i) moves_[i] = moves[i] ? 1 : 0;
    build_vertex_faces(n);
    build_neighbourhoods();
    build_patch_edges(build_edges(topo));
    sigma_s_ = spatial_scale(X);
    // "zero area" relative to the mesh's scale: below it a face's normal is rounding noise
    degenerate_ = 1e-12 * sigma_s_ * sigma_s_;
  }

  /// The face normals of a mesh with its faces' areas (0: degenerate, no normal) and centroids: the state of a
  /// filter that iterates on the normals alone, the geometry staying that of the mesh they came from.
  struct Face_field
  {
    std::vector<double> area;                // 0: degenerate (no normal)
    std::vector<Eigen::Vector3d> normal;     // unit, or 0 where degenerate
    std::vector<Eigen::Vector3d> centroid;
  };

  /// The face field of Y (same shape as X).
  Face_field field_of(const Control_matrix& Y) const
  {
    CGAL_precondition(std::size_t(Y.rows()) + 1 >= vertex_first_.size() && Y.cols() >= 3);
    Face_field field;
    measure_faces(Y, field);
    return field;
  }

  /// The normals of `field` filtered once with guidance (its areas and centroids kept).
  void filter(Face_field& field) const
  {
    std::vector<double> consistency;
    std::vector<Eigen::Vector3d> patch_normal;
    measure_patches(field, edge_saliency(field), consistency, patch_normal);
    field.normal = filtered_normals(field, guidance(consistency, patch_normal));
  }

  /// Y's movable vertices fitted to the normals of `field` by `vertex_iterations` iterations of the vertex update.
  void fit(Control_matrix& Y, const Face_field& field) const { fit_vertices(Y, field.normal); }

  /// One pass on Y: its face normals filtered once, then its vertices fitted to them. The state is Y alone.
  void pass(Control_matrix& Y) const
  {
    Face_field field = field_of(Y);
    filter(field);
    fit(Y, field);
  }

  /// sigma_s: the mean distance between the centroids of edge-adjacent real faces of X
  double spatial_scale() const { return sigma_s_; }

private:
  typedef Triangle_topology::Face Face;


  // the per-face loops do ~100 vector operations a face: worth threads from a few thousand faces on
  static constexpr std::size_t grain_ = 1024, serial_up_to_ = 4096;

  static Eigen::Vector3d position(const Control_matrix& Y, int v)
  {
    return Eigen::Vector3d(Y(v, 0), Y(v, 1), Y(v, 2));
  }

  static Eigen::Vector3d unit_or_zero(const Eigen::Vector3d& v)
  {
    const double l = v.norm();
    return l > 0 && std::isfinite(l) ? Eigen::Vector3d(v / l) : Eigen::Vector3d::Zero();
  }

  Eigen::Vector3d centroid(const Control_matrix& Y, std::size_t f) const
  {
    const Face& t = corners_[f];
    return (position(Y, t[0]) + position(Y, t[1]) + position(Y, t[2])) / 3.0;
  }

  template <typename Body>
  static void over(std::size_t n, const Body& body)
  {
    parallel_blocks(n, body, grain_, serial_up_to_);
  }

  // each vertex's real faces, in increasing order (CSR)
  void build_vertex_faces(std::size_t n)
  {
    vertex_first_.assign(n + 1, 0);
    for(const Face& t : corners_)
      for(int v : t) ++vertex_first_[std::size_t(v) + 1];
    for(std::size_t i = 0; i < n; ++i) vertex_first_[i + 1] += vertex_first_[i];
    vertex_faces_.resize(vertex_first_[n]);
    std::vector<std::size_t> fill(vertex_first_.begin(), vertex_first_.end() - 1);
    for(std::size_t f = 0; f < corners_.size(); ++f)
      for(int v : corners_[f]) vertex_faces_[fill[std::size_t(v)]++] = int(f);
  }

  // N(f): the real faces sharing a vertex with f, in increasing order (CSR); also the patch P(f)
  void build_neighbourhoods()
  {
    ring_first_.assign(1, 0);
    ring_.clear();
    std::vector<int> ring;
    for(const Face& t : corners_)
    {
      ring.clear();
      for(int v : t)
        ring.insert(ring.end(), vertex_faces_.begin() + std::ptrdiff_t(vertex_first_[std::size_t(v)]),
                    vertex_faces_.begin() + std::ptrdiff_t(vertex_first_[std::size_t(v) + 1]));
      std::sort(ring.begin(), ring.end());
      ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
      ring_.insert(ring_.end(), ring.begin(), ring.end());
      ring_first_.push_back(ring_.size());
    }
  }

  // the edges between two real faces (one entry each); returns each real halfedge's edge, or -1 (a border,
  // or a ghost face across)
  std::vector<int> build_edges(const Triangle_topology& topo)
  {
    const std::size_t nh = 3 * corners_.size();
    std::vector<int> edge_of(nh, -1);
    edge_faces_.clear();
    for(std::size_t h = 0; h < nh; ++h)
    {
      const int o = topo.opposite(int(h));
      if(o < 0 || std::size_t(o) >= nh) continue;
      if(std::size_t(o) > h)
      {
        edge_of[h] = int(edge_faces_.size());
        edge_faces_.push_back(std::make_pair(int(h / 3), o / 3));
      }
      else edge_of[h] = edge_of[std::size_t(o)];
    }
    return edge_of;
  }

  // each patch's interior edges (both faces in the patch): they depend on the connectivity only
  void build_patch_edges(const std::vector<int>& edge_of)
  {
    patch_edge_first_.assign(1, 0);
    patch_edges_.clear();
    for(std::size_t j = 0; j < corners_.size(); ++j)
    {
      const auto first = ring_.begin() + std::ptrdiff_t(ring_first_[j]);
      const auto last = ring_.begin() + std::ptrdiff_t(ring_first_[j + 1]);
      for(auto a = first; a != last; ++a)
        for(int c = 0; c < 3; ++c)
        {
          const int e = edge_of[3 * std::size_t(*a) + std::size_t(c)];
          if(e < 0) continue;
          const std::pair<int, int>& ab = edge_faces_[std::size_t(e)];
          const int b = ab.first == *a ? ab.second : ab.first;
          if(*a < b && std::binary_search(first, last, b)) patch_edges_.push_back(e);
        }
      patch_edge_first_.push_back(patch_edges_.size());
    }
  }

  // sigma_s: the mean distance between the centroids of edge-adjacent real faces of X (else the mean edge
  // length, else 1: a mesh without a length has nothing to filter)
  double spatial_scale(const Control_matrix& X) const
  {
    double sum = 0;
    for(const std::pair<int, int>& ab : edge_faces_)
      sum += (centroid(X, std::size_t(ab.first)) - centroid(X, std::size_t(ab.second))).norm();
    if(!edge_faces_.empty() && sum > 0 && std::isfinite(sum)) return sum / double(edge_faces_.size());
    double edges = 0;
    for(const Face& t : corners_)
      for(std::size_t c = 0; c < 3; ++c) edges += (position(X, t[(c + 1) % 3]) - position(X, t[c])).norm();
    return edges > 0 && std::isfinite(edges) ? edges / double(3 * corners_.size()) : 1.0;
  }

  void measure_faces(const Control_matrix& Y, Face_field& field) const
  {
    const std::size_t nf = corners_.size();
    field.area.assign(nf, 0.0);
    field.normal.assign(nf, Eigen::Vector3d::Zero());
    field.centroid.assign(nf, Eigen::Vector3d::Zero());
    over(nf, [&](std::size_t first, std::size_t last) {
      for(std::size_t f = first; f < last; ++f)
      {
        const Face& t = corners_[f];
        const Eigen::Vector3d p0 = position(Y, t[0]);
        const Eigen::Vector3d cross = (position(Y, t[1]) - p0).cross(position(Y, t[2]) - p0);
        const double twice_area = cross.norm();
        field.centroid[f] = centroid(Y, f);
        if(!(twice_area > degenerate_) || !std::isfinite(twice_area)) continue;
        field.area[f] = 0.5 * twice_area;
        field.normal[f] = cross / twice_area;
      }
    });
  }

  // |n_a - n_b| at each edge between real faces (0 next to a degenerate face: it has no normal)
  std::vector<double> edge_saliency(const Face_field& field) const
  {
    std::vector<double> saliency(edge_faces_.size(), 0.0);
    over(edge_faces_.size(), [&](std::size_t first, std::size_t last) {
      for(std::size_t e = first; e < last; ++e)
      {
        const std::size_t a = std::size_t(edge_faces_[e].first), b = std::size_t(edge_faces_[e].second);
        if(field.area[a] > 0 && field.area[b] > 0) saliency[e] = (field.normal[a] - field.normal[b]).norm();
      }
    });
    return saliency;
  }

  // per patch P(j), once a pass: H(P(j)) and the area-weighted mean normal m(P(j)) (0: no face with a normal);
  // each face then reads the values of its candidates instead of recomputing ~13 patches of ~13 faces
  void measure_patches(const Face_field& field, const std::vector<double>& saliency,
                       std::vector<double>& consistency, std::vector<Eigen::Vector3d>& patch_normal) const
  {
    const std::size_t nf = corners_.size();
    consistency.assign(nf, 0.0);
    patch_normal.assign(nf, Eigen::Vector3d::Zero());
    over(nf, [&](std::size_t first, std::size_t last) {
      for(std::size_t j = first; j < last; ++j)
      {
        const int* P = ring_.data() + ring_first_[j];
        const std::size_t k = ring_first_[j + 1] - ring_first_[j];
        double largest2 = 0;
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for(std::size_t a = 0; a < k; ++a)
        {
          const std::size_t fa = std::size_t(P[a]);
          if(field.area[fa] == 0) continue;
          sum += field.area[fa] * field.normal[fa];
          for(std::size_t b = a + 1; b < k; ++b)
            if(field.area[std::size_t(P[b])] > 0)
              largest2 = (std::max)(largest2, (field.normal[fa] - field.normal[std::size_t(P[b])]).squaredNorm());
        }
        double total = 0, largest = 0;
        for(std::size_t e = patch_edge_first_[j]; e < patch_edge_first_[j + 1]; ++e)
        {
          total += saliency[std::size_t(patch_edges_[e])];
          largest = (std::max)(largest, saliency[std::size_t(patch_edges_[e])]);
        }
        consistency[j] = std::sqrt(largest2) * largest / (total + 1e-9);
        patch_normal[j] = unit_or_zero(sum);
      }
    });
  }

  // The guidance normal g_f. Zhang et al. take the one patch of lowest H among f's candidates; that choice
  // jumps when two patches trade places, and the filter must be a smooth function of the positions (a risk
  // estimate takes finite differences of it with tiny perturbations). So we take a soft minimum: patch P gets
  // the weight exp(-(H(P) - H_min) / H_min), 1 at the minimum, e^-1 at twice it, which keeps the choice of the
  // paper where one patch is clearly the most consistent. With H_min below 1e-12 (a noise-free patch) the
  // scale is 1e-12 instead: only patches within about that of H_min count, and the weight stays continuous.
  std::vector<Eigen::Vector3d> guidance(const std::vector<double>& consistency,
                                        const std::vector<Eigen::Vector3d>& patch_normal) const
  {
    const std::size_t nf = corners_.size();
    std::vector<Eigen::Vector3d> guide(nf, Eigen::Vector3d::Zero());
    over(nf, [&](std::size_t first, std::size_t last) {
      for(std::size_t f = first; f < last; ++f)
      {
        double h_min = std::numeric_limits<double>::infinity();
        for(std::size_t k = ring_first_[f]; k < ring_first_[f + 1]; ++k)
        {
          const std::size_t j = std::size_t(ring_[k]);
          if(patch_normal[j].squaredNorm() > 0) h_min = (std::min)(h_min, consistency[j]);
        }
        if(!std::isfinite(h_min)) continue;   // no candidate with a normal
        const double scale = (std::max)(h_min, 1e-12);
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for(std::size_t k = ring_first_[f]; k < ring_first_[f + 1]; ++k)
        {
          const std::size_t j = std::size_t(ring_[k]);
          if(patch_normal[j].squaredNorm() > 0) sum += std::exp(-(consistency[j] - h_min) / scale) * patch_normal[j];
        }
        guide[f] = unit_or_zero(sum);
      }
    });
    return guide;
  }

  // m_f = normalize(sum_{j in N(f)} A_j W_s W_r n_j), W_s on the centroids' distance, W_r on the guidance
  // normals' difference; 0 for a degenerate face (the vertex update skips it)
  std::vector<Eigen::Vector3d> filtered_normals(const Face_field& field,
                                                const std::vector<Eigen::Vector3d>& guide) const
  {
    const std::size_t nf = corners_.size();
    const double spatial = 1.0 / (2.0 * sigma_s_ * sigma_s_);
    const double range = 1.0 / (2.0 * settings_.range * settings_.range);
    std::vector<Eigen::Vector3d> filtered(nf, Eigen::Vector3d::Zero());
    over(nf, [&](std::size_t first, std::size_t last) {
      for(std::size_t f = first; f < last; ++f)
      {
        if(field.area[f] == 0) continue;
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for(std::size_t k = ring_first_[f]; k < ring_first_[f + 1]; ++k)
        {
          const std::size_t j = std::size_t(ring_[k]);
          if(field.area[j] == 0) continue;
          const double w = std::exp(-(field.centroid[f] - field.centroid[j]).squaredNorm() * spatial -
                                    (guide[f] - guide[j]).squaredNorm() * range);
          sum += field.area[j] * w * field.normal[j];
        }
        filtered[f] = unit_or_zero(sum);
      }
    });
    return filtered;
  }

  // Sun et al.'s update in Jacobi form: x_i += (1/|F_i|) sum_{f in F_i} m_f (m_f . (c_f - x_i)), every vertex
  // reading the positions of the start of the iteration (deterministic, and independent of the vertex order).
  // It moves x_i onto the planes through the centroids with the filtered normals, so tangentially not at all.
  void fit_vertices(Control_matrix& Y, const std::vector<Eigen::Vector3d>& filtered) const
  {
    const std::size_t nf = corners_.size(), n = vertex_first_.size() - 1;
    std::vector<Eigen::Vector3d> centroids(nf), next(n);
    for(std::size_t iteration = 0; iteration < settings_.vertex_iterations; ++iteration)
    {
      over(nf, [&](std::size_t first, std::size_t last) {
        for(std::size_t f = first; f < last; ++f) centroids[f] = centroid(Y, f);
      });
      over(n, [&](std::size_t first, std::size_t last) {
        for(std::size_t i = first; i < last; ++i)
        {
          if(!moves_[i]) continue;
          const Eigen::Vector3d x = position(Y, int(i));
          Eigen::Vector3d sum = Eigen::Vector3d::Zero();
          std::size_t count = 0;
          for(std::size_t k = vertex_first_[i]; k < vertex_first_[i + 1]; ++k)
          {
            const Eigen::Vector3d& m = filtered[std::size_t(vertex_faces_[k])];
            if(m.squaredNorm() == 0) continue;
            sum += m * m.dot(centroids[std::size_t(vertex_faces_[k])] - x);
            ++count;
          }
          next[i] = count > 0 ? Eigen::Vector3d(x + sum / double(count)) : x;
        }
      });
      over(n, [&](std::size_t first, std::size_t last) {
        for(std::size_t i = first; i < last; ++i)
          if(moves_[i])
            for(int a = 0; a < 3; ++a) Y(Eigen::Index(i), a) = next[i][a];
      });
    }
  }

  Normal_field_settings settings_;
  std::vector<Face> corners_;                 // the real faces
  std::vector<char> moves_;                   // (not vector<bool>: read from several threads)
  std::vector<std::size_t> vertex_first_;     // CSR: vertex -> its real faces
  std::vector<int> vertex_faces_;
  std::vector<std::size_t> ring_first_;       // CSR: face f -> N(f), which is also the patch P(f)
  std::vector<int> ring_;
  std::vector<std::pair<int, int>> edge_faces_;   // the two faces of each edge between real faces
  std::vector<std::size_t> patch_edge_first_;     // CSR: patch P(j) -> its interior edges
  std::vector<int> patch_edges_;
  double sigma_s_ = 1, degenerate_ = 0;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_FLOW_NORMAL_FIELD_FILTER_H
