// anisotropic_fairing tool: the non-manifold vertices of an input, split for the run and written back
// once. A vertex where separate fans of faces meet (a bow-tie), or at the end of an edge of three or
// more faces, is given one copy per fan so that the mesh is a 2-manifold the fairing can take
// (mesh_repair.h: repair_soup); the copies come after the file's vertices. Once faired, each such
// vertex is written once, in its place, at the mean of its copies, and the faces refer to it again:
// the output has the input's vertices, in their order and number.
#ifndef AF_TOOL_VERTEX_SPLIT_H
#define AF_TOOL_VERTEX_SPLIT_H

#include "tool_common.h"

#include <cstddef>
#include <string>
#include <vector>

namespace af_tool {

struct Vertex_split
{
  std::size_t file_vertices = 0;      // the vertices of the file, numbered as there
  std::vector<std::size_t> copy_of;   // vertex file_vertices + i is a copy of vertex copy_of[i]
  std::size_t split_vertices = 0;     // distinct vertices of the file that have copies
  bool empty() const { return copy_of.empty(); }
  std::size_t original(std::size_t v) const { return v < file_vertices ? v : copy_of[v - file_vertices]; }
};

/// Gives every copy the vertex properties of its original (attributes, held marks, colours ...).
void copy_properties_to_copies(Mesh& mesh, const Vertex_split& split);

/// Each split vertex and its copies set to their mean: the position and every floating-point vertex
/// property (vectors, texture coordinates; "v:normal" normalised again).
void merge_copies(Mesh& mesh, const Vertex_split& split);

/// The same for per-vertex values (the faired attributes, before they are written into their properties).
void merge_copies(std::vector<std::vector<double> >& values, const Vertex_split& split);

/// Rewrites the file the mesh was written to (OFF, OBJ or PLY, text or binary, as write_mesh() writes
/// them) without the copies: the vertices after the file's are dropped and the faces refer to their
/// originals. Throws Failure.
void merge_copies_in_file(const std::string& path, Format format, const Vertex_split& split);

} // namespace af_tool

#endif // AF_TOOL_VERTEX_SPLIT_H
