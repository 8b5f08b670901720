// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The library's stages before the flow, built by the library's own functions on every process from the
// whole mesh, exactly as anisotropic_fairing() builds them (run/Fairing_driver.h, run/Fairing_core.h): the
// checked indexed mesh and its ghost layer, the locality numbering, the matrix of control values
// (coordinates, then the attributes times the attribute weight when coupled), the held vertices, the
// connected components and their mean edge lengths, and the Loop patch cache. Every process holds them
// whole (the work of a run is divided, not yet this memory: see doc/Anisotropic_fairing/Large_meshes.txt).

#ifndef AF_DISTRIBUTED_REPLICATED_SETUP_H
#define AF_DISTRIBUTED_REPLICATED_SETUP_H

#include "attribute_columns.h"
#include "tool_common.h"

#include <CGAL/Anisotropic_fairing/Fairing_options.h>
#include <CGAL/Anisotropic_fairing/Input_error.h>
#include <CGAL/Anisotropic_fairing/internal/element/Ghosted_patch_cache.h>
#include <CGAL/Anisotropic_fairing/internal/flow/Boundary_constraints.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Indexed_mesh.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Locality_ordering.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Mesh_components.h>
#include <CGAL/Anisotropic_fairing/internal/run/Caller_maps.h>
#include <CGAL/Anisotropic_fairing/internal/run/Fairing_core.h>
#include <CGAL/Anisotropic_fairing/internal/run/Fairing_parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace af_distributed {

namespace AF = CGAL::Anisotropic_fairing;
namespace AFI = CGAL::Anisotropic_fairing::internal;

struct Replicated_setup
{
  AFI::Fairing_parameters given;
  AFI::Indexed_mesh<af_tool::Mesh> im;
  AFI::Locality_ordering ordering;
  std::size_t n = 0;
  AFI::Control_matrix X;                       // run numbering: points, then attributes (times the weight when coupled)
  AFI::Control_matrix input;                   // the caller's numbering: points, then attributes as given
  std::vector<bool> constrained, border, isolated, user_held;   // run numbering; user_held: caller's numbering
  AFI::Mesh_components components;
  std::vector<double> component_edge;
  double mean_edge = 0;
  std::unique_ptr<AFI::Ghosted_patch_cache> cache;

  /// `options`: the run's (its attribute mode resolved); `attributes`: the attribute map (null: none faired).
  Replicated_setup(const af_tool::Mesh& mesh, const AF::Fairing_options& options,
                   const af_tool::Attribute_vectors* attributes)
    : given(AFI::resolve_fairing_parameters(options, attributes != nullptr)), im(mesh, AFI::Borders::GHOSTED, true),
      ordering(AFI::make_locality_ordering(im.ghost_layer())), n(im.number_of_vertices())
  {
    const AFI::Control_matrix P = im.read_points(mesh.points());
    const AFI::Control_matrix A = attributes && given.mode != AF::Attribute_mode::GEOMETRY_ONLY
                                    ? im.read_attributes(*attributes)
                                    : AFI::Control_matrix();
    const double largest = A.size() > 0 ? A.cwiseAbs().maxCoeff() : 0.0;
    if(coupled() && given.attribute_weight * largest > AFI::Indexed_mesh<af_tool::Mesh>::coordinate_limit)
      throw AF::Input_error(
        AF::Input_error::INVALID_PARAMETER, AF::Input_error::no_element,
        "the attribute weight times the largest attribute value is a coordinate beyond 1e70 in the coupled manifold");
    input.resize(P.rows(), P.cols() + A.cols());
    input.leftCols(3) = P;
    if(A.cols() > 0) input.rightCols(A.cols()) = A;
    number_rows(A.cols());
    const AFI::Ghost_layer& gl = layer();
    components = AFI::make_mesh_components(*gl.topology, n, gl.real_faces);
    mean_edge = AFI::component_mean_edges(*gl.topology, gl.real_faces, components, X, component_edge);
    cache.reset(new AFI::Ghosted_patch_cache(gl, given.quadrature));
    const std::vector<bool> boundary =
      AFI::boundary_constrained_vertices(gl, *cache, given.boundary == AF::Boundary_handling::HOLD_BOUNDARY_CURVE);
    for(std::size_t i = 0; i < n; ++i) constrained[i] = constrained[i] || boundary[i];
  }

  const AFI::Ghost_layer& layer() const { return ordering.layer; }
  bool coupled() const { return given.mode == AF::Attribute_mode::COUPLED; }
  double attribute_scale() const { return coupled() ? given.attribute_weight : 1.0; }

  /// The values written for control values Y of the run (run numbering): back in the caller's numbering and
  /// units, the vertices kept (border, isolated) at their input values.
  AFI::Control_matrix written(const AFI::Control_matrix& Y, std::vector<bool>& kept) const
  {
    AFI::Control_matrix out(Y.rows(), Y.cols());
    kept.assign(n, false);
    for(std::size_t i = 0; i < n; ++i)
    {
      const int old = ordering.old_of_new_vertex[i];
      out.row(old) = Y.row(Eigen::Index(i));
      if(Y.cols() > 3) out.row(old).tail(Y.cols() - 3) /= attribute_scale();
      kept[std::size_t(old)] = border[i] || isolated[i] || user_held[std::size_t(old)];
    }
    return out;
  }

private:
  // the run's numbering (Fairing_core::number_rows)
  void number_rows(Eigen::Index d)
  {
    X.resize(Eigen::Index(n), 3 + d);
    constrained.assign(n, false);
    border.assign(n, false);
    isolated.assign(n, false);
    user_held.assign(n, false);
    for(std::size_t i = 0; i < n; ++i)
    {
      const Eigen::Index old = ordering.old_of_new_vertex[i];
      X.row(Eigen::Index(i)).head(3) = input.row(old).head(3);
      if(d > 0) X.row(Eigen::Index(i)).tail(d) = attribute_scale() * input.row(old).tail(d);
    }
    for(int v : layer().boundary_vertices) border[std::size_t(v)] = true;
    for(int v : layer().isolated_vertices) isolated[std::size_t(v)] = constrained[std::size_t(v)] = true;
  }
};

} // namespace af_distributed

#endif // AF_DISTRIBUTED_REPLICATED_SETUP_H
