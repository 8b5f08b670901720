// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The caller's maps around a run: the attributes read into columns and written back, and the maps
// whose types only the caller knows (held vertices, control values, the callback) behind functions,
// so that the run is compiled once per mesh, point map and attribute map, whatever else is passed.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_CALLER_MAPS_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_CALLER_MAPS_H

#include <CGAL/Anisotropic_fairing/Fairing_report.h>
#include <CGAL/Anisotropic_fairing/Fairing_settings.h>
#include <CGAL/Anisotropic_fairing/Vector_attribute_traits.h>
#include <CGAL/Anisotropic_fairing/named_function_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Indexed_mesh.h>
#include <CGAL/Anisotropic_fairing/internal/run/Fairing_parameters.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <functional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// Stands for "no attribute map" (geometry-only fairing).
struct No_attributes {};

/// What a run is given besides its options and its maps of points and attributes.
template <typename Vertex>
struct Caller_hooks
{
  std::function<bool(Vertex)> constrained;                        // vertex_is_constrained_map (empty: none)
  std::function<void(Vertex, const double*)> control_point;       // control_point_map: x, y, z (empty: none)
  std::function<void(Vertex, const double*)> attribute_control;   // attribute_control_map: the columns (empty: none)
  std::function<bool(const Fairing_step&)> callback;
  Direct_solver_factory direct_solver;                            // sparse_linear_solver (empty: the package's)
};

/// The hooks of a run on a mesh of type TriangleMesh.
template <typename TriangleMesh>
using Mesh_hooks = Caller_hooks<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>;

/// The hooks of the named parameters `np` for a run on `attributes`.
template <typename TriangleMesh, typename AttributeMap, typename NamedParameters>
Mesh_hooks<TriangleMesh> caller_hooks(AttributeMap attributes, const NamedParameters& np)
{
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor Vertex;
  Caller_hooks<Vertex> hooks;
  hooks.direct_solver = direct_solver_of(get_parameter(np, CGAL::internal_np::sparse_linear_solver));
  if constexpr(!is_default_parameter<NamedParameters, CGAL::internal_np::vertex_is_constrained_t>::value)
  {
    const auto map = get_parameter(np, CGAL::internal_np::vertex_is_constrained);
    hooks.constrained = [map](Vertex v) { return bool(get(map, v)); };
  }
  if constexpr(!is_default_parameter<NamedParameters, internal_np::control_point_map_t>::value)
  {
    const auto map = get_parameter(np, internal_np::control_point_map);
    hooks.control_point = [map](Vertex v, const double* x) {
      typedef typename boost::property_traits<std::decay_t<decltype(map)>>::value_type Point;
      put(map, v, Point(x[0], x[1], x[2]));
    };
  }
  if constexpr(!is_default_parameter<NamedParameters, internal_np::attribute_control_map_t>::value &&
               !std::is_same<AttributeMap, No_attributes>::value)
  {
    const auto map = get_parameter(np, internal_np::attribute_control_map);
    hooks.attribute_control = [map, attributes](Vertex v, const double* x) {
      typedef typename boost::property_traits<std::decay_t<decltype(map)>>::value_type Value;
      put(map, v, Vector_attribute_traits<Value>::make(get(attributes, v), x));
    };
  }
  if constexpr(!is_default_parameter<NamedParameters, CGAL::internal_np::callback_t>::value)
    hooks.callback = get_parameter(np, CGAL::internal_np::callback);
  else
    hooks.callback = [](const Fairing_step&) { return true; };
  return hooks;
}

template <typename Mesh>
Control_matrix read_attribute_columns(const Indexed_mesh<Mesh>&, No_attributes) { return Control_matrix(); }
template <typename Mesh, typename AttributeMap>
Control_matrix read_attribute_columns(const Indexed_mesh<Mesh>& im, AttributeMap map)
{
  return im.read_attributes(map);
}

template <typename Mesh>
void write_attribute_columns(const Indexed_mesh<Mesh>&, No_attributes, const Control_matrix&, Eigen::Index,
                             const std::vector<bool>&)
{}
template <typename Mesh, typename AttributeMap>
void write_attribute_columns(const Indexed_mesh<Mesh>& im, AttributeMap map, const Control_matrix& X,
                             Eigen::Index first, const std::vector<bool>& keep)
{
  typedef typename boost::property_traits<AttributeMap>::value_type Value;
  std::vector<Value> values;
  values.reserve(im.number_of_vertices());
  for(std::size_t i = 0; i < im.number_of_vertices(); ++i)
  {
    const double* row = X.row(Eigen::Index(i)).data() + first;
    values.push_back(Vector_attribute_traits<Value>::make(get(map, im.vertex(i)), row));
  }
  for(std::size_t i = 0; i < im.number_of_vertices(); ++i)
    if(!keep[i]) put(map, im.vertex(i), values[i]);
}

/// Writes the result X (rows in the order of vertices(tm)) into the caller's maps: the points (unless only
/// attributes were faired) and the attribute columns, from column 3; not the rows `kept`.
template <typename Mesh, typename VertexPointMap, typename AttributeMap>
void write_back(const Indexed_mesh<Mesh>& im, const Control_matrix& X, Attribute_mode mode,
                const std::vector<bool>& kept, VertexPointMap vpm, AttributeMap attributes)
{
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  for(std::size_t i = 0; i < im.number_of_vertices(); ++i)
  {
    const Eigen::Index r = Eigen::Index(i);
    if(!kept[i] && mode != Attribute_mode::ATTRIBUTES_ONLY) put(vpm, im.vertex(i), Point(X(r, 0), X(r, 1), X(r, 2)));
  }
  if(X.cols() > 3) write_attribute_columns(im, attributes, X, 3, kept);
}

/// Hands the control values Z (rows in the order of vertices(tm)) to the caller's map through `put`, every
/// vertex (the held ones at their input), from column `first`; nothing without a map.
template <typename Mesh, typename Put>
void write_control_values(const Indexed_mesh<Mesh>& im, const Put& put, const Control_matrix& Z, Eigen::Index first)
{
  if(!put) return;
  for(Eigen::Index i = 0; i < Z.rows(); ++i) put(im.vertex(std::size_t(i)), Z.row(i).data() + first);
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_CALLER_MAPS_H
