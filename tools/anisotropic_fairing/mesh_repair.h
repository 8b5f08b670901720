// anisotropic_fairing tool: what CGAL's Polygon_mesh_processing offers for meshes that are not oriented
// 2-manifolds of triangles, reported change by change. The split and the triangulation are made on
// every such input (the fairing needs them; the vertices are written back as the input had them,
// vertex_split.h); stitching borders and removing lone vertices only with --repair.

#ifndef AF_TOOL_MESH_REPAIR_H
#define AF_TOOL_MESH_REPAIR_H

#include "mesh_file_check.h"
#include "tool_common.h"

#include <string>
#include <vector>

namespace af_tool {

/// What made a soup an oriented 2-manifold.
struct Soup_repair
{
  std::vector<std::string> changes;   // one line per kind of change made (none for a soup that needed none)
  std::vector<std::size_t> copy_of;   // point `n + i` (n: the soup's points before) duplicates point copy_of[i]
  std::size_t split_vertices = 0;     // distinct points of the file that got copies
};

/// Makes the soup an oriented 2-manifold: drops faces that repeat a vertex, then orients the faces
/// consistently and splits non-manifold vertices and edges by duplicating their points (the copies come
/// after the file's points; CGAL::Polygon_mesh_processing::orient_polygon_soup).
Soup_repair repair_soup(Polygon_soup& soup);

/// Stitches borders that coincide (CGAL::Polygon_mesh_processing::stitch_borders) and removes the
/// vertices that then belong to no face (the later vertices move up); returns one line per change.
std::vector<std::string> repair_mesh(Mesh& mesh);

/// Triangulates the faces that are not triangles (CGAL::Polygon_mesh_processing::triangulate_faces); the
/// new triangles keep the face properties of the polygon they come from. Returns the number of polygons.
std::size_t triangulate_polygons(Mesh& mesh);

} // namespace af_tool

#endif // AF_TOOL_MESH_REPAIR_H
