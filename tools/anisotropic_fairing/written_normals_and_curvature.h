// The normals and the curvature written with the faired mesh. Input normals (NOFF, PLY nx/ny/nz, OBJ vn)
// are replaced by those of the faired surface, never left stale:
//  - Loop element with `--output limit`: the library writes the limit points (held within the bounds)
//    and gives the faired control points through its control_point_map; a Loop_limit_surface built on
//    those gives the exact normals of the faired limit surface at the points written.
//  - `--output control` or the linear element: the written mesh is the surface itself (control
//    polygon or P1 surface), so the normals are CGAL::Polygon_mesh_processing::compute_vertex_normals.
// Curvature (`--curvature`, PLY output): Loop_limit_surface::vertex_curvatures() of the limit surface of
// the faired control mesh, written as the double vertex properties k1, k2 and mean_curvature.
// With `--mode attributes` the geometry is not faired: positions and the input's normals are written
// unchanged (OBJ vn, which CGAL's reader does not read, are recomputed as for `--output control`).
#ifndef AF_TOOL_WRITTEN_NORMALS_AND_CURVATURE_H
#define AF_TOOL_WRITTEN_NORMALS_AND_CURVATURE_H

#include "json_report.h"
#include "mesh_io.h"
#include "options.h"

#include <vector>

namespace af_tool {

// The vertex properties --curvature adds; an input that has one already is refused, never overwritten.
inline constexpr const char* curvature_properties[3] = { "v:k1", "v:k2", "v:mean_curvature" };

// Fails (input_error) if --curvature would overwrite a vertex property of the input.
void check_curvature_properties_free(const Options& o, const Mesh& mesh);

// Whether the normals written are those of the faired limit surface at the limit points written.
bool writes_exact_limit_normals(const Options& o, const Input_info& info, bool fair_geometry);

// Adds the curvature (--curvature) and sets the normals of `mesh`, the faired mesh whose faired control
// points are `control_points`; records in `r` what was written.
void write_normals_and_curvature(const Options& o, const Input_info& info, bool fair_geometry,
                                 const std::vector<Point>& control_points, Mesh& mesh, Run_record& r);

} // namespace af_tool

#endif // AF_TOOL_WRITTEN_NORMALS_AND_CURVATURE_H
