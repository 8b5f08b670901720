// anisotropic_fairing tool: `--repair`, what CGAL's Polygon_mesh_processing already offers for meshes that
// are not oriented 2-manifolds, applied only on request and reported change by change.

#ifndef AF_TOOL_MESH_REPAIR_H
#define AF_TOOL_MESH_REPAIR_H

#include "mesh_file_check.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <string>
#include <vector>

namespace af_tool {

typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Repair_mesh;

/// Makes the soup an oriented 2-manifold: drops faces that repeat a vertex, then orients the faces
/// consistently and splits non-manifold vertices and edges by duplicating their points (new vertices
/// come after the file's; CGAL::Polygon_mesh_processing::orient_polygon_soup). Returns one line per kind
/// of change made (none for a soup that needed none).
std::vector<std::string> repair_soup(Polygon_soup& soup);

/// Stitches borders that coincide (CGAL::Polygon_mesh_processing::stitch_borders) and removes the
/// vertices that then belong to no face (the later vertices move up); returns one line per change.
std::vector<std::string> repair_mesh(Repair_mesh& mesh);

} // namespace af_tool

#endif // AF_TOOL_MESH_REPAIR_H
