// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_ANISOTROPIC_FAIRING_INPUT_ERROR_H
#define CGAL_ANISOTROPIC_FAIRING_INPUT_ERROR_H

#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Anisotropic_fairing {

/*!
\ingroup PkgAnisotropicFairingLimitSurface

Exception thrown when an input mesh or map cannot be processed. It is thrown before anything is
written, so the user's mesh and maps are left exactly as they were.

`what()` names the problem and the offending element, e.g.
"Anisotropic_fairing: face 12 has 4 vertices; only triangle meshes are supported".
`kind()` and `element()` give the same information to programs.
*/
class Input_error : public std::invalid_argument
{
public:
  /// What is wrong with the input.
  enum Kind {
    EMPTY_MESH,            ///< the mesh has no face
    NON_TRIANGLE_FACE,     ///< a face with other than three vertices; `element()` is the face index
    DEGENERATE_FACE,       ///< a face that uses one vertex twice; `element()` is the face index
    /// the mesh has a boundary where a closed mesh is needed; `element()` is a vertex index on it. Not raised by
    /// `anisotropic_fairing()` nor `Loop_limit_surface`, which accept borders
    BORDER_EDGE,
    /// an edge used by more than two faces, or two edges joining the same vertices; `element()` is a vertex index
    NON_MANIFOLD_EDGE,
    NON_MANIFOLD_VERTEX,   ///< a vertex whose faces form more than one fan; `element()` is the vertex index
    /// a vertex without incident face where none is allowed; `element()` is the vertex index. Not raised by
    /// `anisotropic_fairing()` nor `Loop_limit_surface`, which accept such vertices and leave them as they are
    ISOLATED_VERTEX,
    LOW_VALENCE_VERTEX,    ///< a vertex of valence below 3; `element()` is the vertex index
    NON_FINITE_COORDINATE, ///< a NaN or infinite coordinate; `element()` is the vertex index
    ATTRIBUTE_DIMENSION,   ///< an attribute whose dimension differs between vertices; `element()` is the vertex index
    INVALID_PARAMETER,     ///< a parameter value outside its documented range
    /// coordinates whose size would overflow or underflow double precision in the computation (fourth powers of
    /// lengths): the mesh spans more than 1e70 or less than 1e-70, or a coordinate exceeds 1e70; `element()` is a
    /// vertex index or `no_element`
    COORDINATE_RANGE
  };

  /// Index value used by `element()` when no single element is at fault.
  static constexpr std::size_t no_element = (std::numeric_limits<std::size_t>::max)();

  Input_error(Kind kind, std::size_t element, const std::string& message)
    : std::invalid_argument("Anisotropic_fairing: " + message), kind_(kind), element_(element)
  {}

  /// The kind of problem.
  Kind kind() const { return kind_; }
  /// Index of the offending vertex or face (in the order of `vertices(tm)` / `faces(tm)`), or `no_element`.
  std::size_t element() const { return element_; }

private:
  Kind kind_;
  std::size_t element_;
};

} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INPUT_ERROR_H
