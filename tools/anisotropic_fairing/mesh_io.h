// Reading and writing the meshes of anisotropic_fairing: every file is checked first
// (mesh_file_check.h), then read by CGAL's readers, with work-arounds for what CGAL 5.5's readers and
// writers get wrong or drop (STOFF without colours, PLY alpha, OBJ vt and vn, STL, PLY strips).
// The mesh is written with full double precision, the vertices in their input order and every
// vertex property of the input that the output format can hold.
#ifndef AF_TOOL_MESH_IO_H
#define AF_TOOL_MESH_IO_H

#include "tool_common.h"
#include "vertex_split.h"

#include <boost/cstdint.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace af_tool {

struct Input_info
{
  Format format = Format::OFF;
  bool ply_binary = false;
  std::string ply_comments;
  bool has_normals = false;       // the input carries vertex normals (v:normal exists)
  bool normals_read = false;      // ... and their values were read (not for OBJ: CGAL's reader skips vn)
  bool vertex_alpha = false;      // PLY: the vertex alpha was folded into v:color (selectable as "alpha")
  bool face_alpha = false;        // PLY: the face alpha was folded into f:color
  std::string uv_problem;         // OBJ: why its vt could not be kept (empty: none, or kept as v:texcoord)
  std::vector<std::string> warnings;
  std::vector<std::string> notes;   // what was done to read the file (STL corners merged, strips split)
  std::vector<std::string> input_changes;   // what was changed for the run (split, triangulated, --repair's changes)
  Vertex_split split;             // the non-manifold vertices split for the run, merged on writing
  std::size_t triangulated_faces = 0;   // faces that were not triangles
};

// Reads INPUT (checked first). Faces that are not an oriented 2-manifold are made one for the run
// (vertex_split.h), polygons are triangulated; with `repair`, also as --repair says. Throws Failure.
void read_input(const std::string& path, Mesh& mesh, Input_info& info, bool repair);

// The numeric types a PLY property can have (CGAL's reader makes a v:<name> map of that type).
template <typename F>
bool for_numeric_type(F&& f)
{
  return f(boost::int8_t()) || f(boost::uint8_t()) || f(boost::int16_t()) || f(boost::uint16_t()) ||
         f(boost::int32_t()) || f(boost::uint32_t()) || f(boost::int64_t()) || f(boost::uint64_t()) ||
         f(float()) || f(double());
}

template <typename Index>
bool is_numeric_property(const Mesh& mesh, const std::string& property)
{
  return for_numeric_type([&](auto zero) {
    return mesh.property_map<Index, decltype(zero)>(property).second;
  });
}

// The properties of the mesh that a file of format `f` does not hold (warned about, not an error).
std::vector<std::string> dropped_properties(const Mesh& mesh, Format f);

// Writes the mesh in format `f`: PLY binary if the input was a binary PLY, STL binary; as text if `text`.
// Throws Failure, naming the path and the system's reason.
void write_mesh(const std::string& path, Format f, const Mesh& mesh, const Input_info& info, bool with_normals,
                bool text);

// A temporary file next to `path`, renamed to it once everything succeeded.
std::filesystem::path temporary_next_to(const std::string& path);
// Removes the temporary file `written` that `f` failed to write, then fails naming `shown` (the user's path)
// with f's reason.
[[noreturn]] void fail_writing(const Failure& f, const std::filesystem::path& written, const std::string& shown);
// Writes `text` to `path` through a temporary file next to it (removed on failure); returns the system's
// reason why it could not ("No space left on device", ...), empty when written.
std::string write_file_atomically(const std::string& path, const std::string& text);

} // namespace af_tool

#endif // AF_TOOL_MESH_IO_H
