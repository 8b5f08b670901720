// anisotropic_fairing tool: reading a mesh file without trusting it.
//
// CGAL 5.5's readers index with the file's numbers before checking them (a PLY face index equal to the
// vertex count loops forever in Euler::add_face, a larger one crashes; OBJ index 0 reads before the
// array) and allocate what a header claims (a 48-byte OFF whose face claims 2e8 vertices took 1.6 GB).
// So every file is first read here into a polygon soup: counts are checked against the bytes the file
// has before anything is allocated for them, every index against the vertex count, every coordinate for
// being a finite number, and the message names the line (ASCII) or the element (binary). Only a file
// that passes reaches CGAL's readers, which keep the vertex properties. The soup also serves the
// formats CGAL's Surface_mesh readers do not take: PLY triangle strips and STL.

#ifndef AF_TOOL_MESH_FILE_CHECK_H
#define AF_TOOL_MESH_FILE_CHECK_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace af_tool {

/// A file that cannot be a mesh; `what()` names the line or element.
struct File_problem : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

enum class Mesh_format { OFF, OBJ, PLY, STL };

/// The points and faces of a file as it holds them, and where each face is in it.
struct Polygon_soup
{
  std::string path;
  std::vector<std::array<double, 3> > points;
  std::vector<std::vector<std::size_t> > faces;
  std::vector<std::string> face_place;   // "line 12" (text), "face 7", "triangle 3 of strip 0" (binary) ...
  bool ply_strips = false;                // the faces came from a PLY "tristrips" element
  bool positions_and_faces_only = false;  // PLY: nothing else that CGAL's reader keeps, positions as it reads them
  std::size_t merged_points = 0;          // STL: corners merged into a point they coincide with
  std::vector<std::string> warnings;      // what the file holds that will not be kept
  // NaN or infinite values of the properties of an ASCII PLY file that are not coordinates: carried
  // through as they are, though CGAL's ASCII reader cannot read them (mesh_io.cpp reads them so)
  struct Nonfinite_value
  {
    std::size_t offset, length;   // of the token in the file
    bool vertex;                  // of a vertex, else of a face
    std::size_t index;
    std::string property;
    double value;
  };
  std::vector<Nonfinite_value> nonfinite;
};

/// Reads `path` as `format` into a soup, checking it as described above; throws File_problem.
Polygon_soup read_checked_soup(const std::string& path, Mesh_format format);

/// Checks that the faces form an oriented 2-manifold (no face repeating a vertex, no edge in more than
/// two faces or twice in one direction, no vertex whose faces form separate fans); throws File_problem
/// naming the element.
void check_oriented_manifold(const Polygon_soup& soup);

} // namespace af_tool

#endif // AF_TOOL_MESH_FILE_CHECK_H
