// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The bridge from a user's FaceGraph to the index world: vertices and faces numbered in iteration
// order, the validated Triangle_topology (closed, or closed by a ghost layer), and property maps
// read into dense matrices (with the checks that keep bad input from reaching the numerics).

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_INDEXED_MESH_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_INDEXED_MESH_H

#include <CGAL/Anisotropic_fairing/Input_error.h>
#include <CGAL/Anisotropic_fairing/Vector_attribute_traits.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Ghost_layer.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Triangle_topology.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// What a mesh with borders gets: an error (operations defined on closed meshes only), or a ghost layer.
enum class Borders { REFUSED, GHOSTED };

template <typename TriangleMesh>
class Indexed_mesh
{
public:
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;
  typedef typename Graph_traits::face_descriptor face_descriptor;
  typedef typename Graph_traits::halfedge_descriptor halfedge_descriptor;

  /// Numbers the elements and validates the topology (throws Input_error, naming elements by
  /// their position in vertices(tm) / faces(tm)). With Borders::GHOSTED, topology() is the
  /// extended topology of the ghost layer: real vertices and faces first, with their indices.
  /// With `allow_isolated`, vertices without a face are accepted (listed in ghost_layer()) rather than refused.
  explicit Indexed_mesh(const TriangleMesh& tm, Borders borders = Borders::REFUSED, bool allow_isolated = false)
  {
    std::unordered_map<vertex_descriptor, std::size_t> vertex_index;
    for(vertex_descriptor v : vertices(tm))
    {
      vertex_index.emplace(v, vertices_.size());
      vertices_.push_back(v);
    }
    std::vector<Triangle_topology::Face> tris;
    for(face_descriptor f : faces(tm))
    {
      const std::size_t fi = faces_.size();
      faces_.push_back(f);
      Triangle_topology::Face t{ { -1, -1, -1 } };
      std::size_t degree = 0;
      for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, tm), tm))
      {
        if(degree < 3) t[degree] = int(vertex_index.at(v));
        ++degree;
      }
      if(degree != 3)
        throw Input_error(Input_error::NON_TRIANGLE_FACE, fi,
                          "face " + std::to_string(fi) + " has " + std::to_string(degree) +
                          " vertices; only triangle meshes are supported");
      tris.push_back(t);
    }
    if(borders == Borders::GHOSTED)
    {
      if(tris.empty()) throw Input_error(Input_error::EMPTY_MESH, Input_error::no_element, "the mesh has no face");
      ghost_layer_ = make_ghost_layer(vertices_.size(), tris, allow_isolated);
    }
    else
    {
      ghost_layer_.real_vertices = vertices_.size();
      ghost_layer_.real_faces = tris.size();
      ghost_layer_.topology.reset(new Triangle_topology(vertices_.size(), std::move(tris),
                                                        (std::numeric_limits<std::size_t>::max)(), allow_isolated));
      for(std::size_t v = 0; v < vertices_.size(); ++v)
        if(ghost_layer_.topology->outgoing(int(v)) < 0) ghost_layer_.isolated_vertices.push_back(int(v));
    }
  }

  const Triangle_topology& topology() const { return *ghost_layer_.topology; }
  /// The ghost layer (without ghosts for a closed mesh, or when built with Borders::REFUSED).
  const Ghost_layer& ghost_layer() const { return ghost_layer_; }
  std::size_t number_of_vertices() const { return vertices_.size(); }
  std::size_t number_of_faces() const { return faces_.size(); }
  vertex_descriptor vertex(std::size_t i) const { return vertices_[i]; }
  face_descriptor face(std::size_t i) const { return faces_[i]; }
  /// Frees the topology and the ghost layer once nothing reads them (a fairing, after its own numbering
  /// is made: 30 bytes a face); topology() and ghost_layer() are then empty.
  void release_ghost_layer() { ghost_layer_ = Ghost_layer(); }
  /// Makes index(f) available (a hash map of the faces: 40 bytes a face, which a fairing does not need).
  void index_faces()
  {
    face_index_.reserve(faces_.size());
    for(std::size_t i = 0; i < faces_.size(); ++i) face_index_.emplace(faces_[i], i);
  }
  /// The index of f; after index_faces().
  std::size_t index(face_descriptor f) const { return face_index_.at(f); }

  /// The largest coordinate, and the inverse of the smallest span, the fairing's arithmetic can hold.
  static constexpr double coordinate_limit = 1e70;

  static std::string to_text(double x)
  {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", x);
    return text;
  }

  /// Reads a point map into an n x 3 matrix; throws on a non-finite coordinate or one out of range.
  template <typename PointMap>
  Control_matrix read_points(PointMap vpm) const
  {
    Control_matrix X(Eigen::Index(vertices_.size()), 3);
    for(std::size_t i = 0; i < vertices_.size(); ++i)
    {
      const auto& p = get(vpm, vertices_[i]);
      for(int c = 0; c < 3; ++c)
      {
        const double x = CGAL::to_double(p[c]);
        if(!std::isfinite(x))
          throw Input_error(Input_error::NON_FINITE_COORDINATE, i,
                            "vertex " + std::to_string(i) + " has a non-finite coordinate");
        if(std::abs(x) > coordinate_limit)
          throw Input_error(Input_error::COORDINATE_RANGE, i,
                            "vertex " + std::to_string(i) + " has a coordinate of " + to_text(x) +
                              ": the fairing computes fourth powers of lengths, which overflow double precision beyond "
                              "1e70; scale the mesh down");
        X(Eigen::Index(i), c) = x;
      }
    }
    // the metric's determinant is a length to the fourth power: it underflows for a mesh of ~1e-77
    // not squared: 1e-170 must not vanish
    const double span = X.rows() > 0 ? (X.colwise().maxCoeff() - X.colwise().minCoeff()).maxCoeff() : 0.0;
    if(span > 0 && span < 1 / coordinate_limit)
      throw Input_error(Input_error::COORDINATE_RANGE, Input_error::no_element,
                        "the mesh spans only " + to_text(span) +
                          ": the fairing computes fourth powers of lengths, which underflow double precision below "
                          "1e-70; scale the mesh up");
    return X;
  }

  /// Reads an attribute map into an n x d matrix; throws if the dimension varies or a value is not finite.
  template <typename AttributeMap>
  Control_matrix read_attributes(AttributeMap map) const
  {
    typedef typename boost::property_traits<AttributeMap>::value_type Value;
    typedef Vector_attribute_traits<Value> Traits;
    if(vertices_.empty()) return Control_matrix();
    const std::size_t d = Traits::dimension(get(map, vertices_[0]));
    Control_matrix A(Eigen::Index(vertices_.size()), Eigen::Index(d));
    for(std::size_t i = 0; i < vertices_.size(); ++i)
    {
      const Value& value = get(map, vertices_[i]);
      if(Traits::dimension(value) != d)
        throw Input_error(Input_error::ATTRIBUTE_DIMENSION, i,
                          "the attribute of vertex " + std::to_string(i) + " has dimension " +
                          std::to_string(Traits::dimension(value)) + " but vertex 0's has " + std::to_string(d));
      for(std::size_t c = 0; c < d; ++c)
      {
        const double x = Traits::get(value, c);
        if(!std::isfinite(x))
          throw Input_error(Input_error::NON_FINITE_COORDINATE, i,
                            "the attribute of vertex " + std::to_string(i) + " is not finite");
        A(Eigen::Index(i), Eigen::Index(c)) = x;
      }
    }
    return A;
  }

private:
  std::vector<vertex_descriptor> vertices_;
  std::vector<face_descriptor> faces_;
  // a hash map rather than CGAL's dynamic property map: on a const Surface_mesh those (CGAL 5.5) are a
  // vector of num_vertices() entries indexed by idx(), out of range on a mesh with removed elements, and
  // on a mutable one they add a property to the user's mesh for as long as a Loop_limit_surface lives
  std::unordered_map<face_descriptor, std::size_t> face_index_;
  Ghost_layer ghost_layer_;
};

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_INDEXED_MESH_H
