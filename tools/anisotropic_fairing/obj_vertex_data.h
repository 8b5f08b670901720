// anisotropic_fairing tool: what CGAL's OBJ reader leaves out of an OBJ file (mesh_io.cpp keeps it).

#ifndef AF_TOOL_OBJ_VERTEX_DATA_H
#define AF_TOOL_OBJ_VERTEX_DATA_H

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace af_tool {

// The texture coordinates of an OBJ file (CGAL's OBJ reader skips vt and the /vt of the faces).
// They are kept only when they are one per vertex: every face corner of a vertex refers to the same
// value (`f a/a` with as many vt as v is the usual case); a texture seam (a vertex with two values)
// or a corner without vt makes them unmatched.
struct Obj_texcoords
{
  bool present = false;   // the file has vt lines
  bool matched = false;   // one value per vertex: `uv` is filled
  std::string problem;    // why not
  bool dropped_w = false; // some vt had a non-zero third component (not kept)
  std::vector<std::array<double, 2>> uv;
};

/// The texture coordinates of the OBJ file `path`, whose mesh has `mesh_vertices` vertices.
Obj_texcoords read_obj_texcoords(const std::string& path, std::size_t mesh_vertices);

/// What CGAL's OBJ reader drops (it reads only v and f): whether the file has vn, vt and per-vertex colours.
void scan_obj(const std::string& path, bool& normals, bool& textures, bool& colors);

} // namespace af_tool

#endif // AF_TOOL_OBJ_VERTEX_DATA_H
