// Types and the failure contract shared by the files of the program anisotropic_fairing.
//
// Failure policy: on any failure the program prints ONE line starting with "anisotropic_fairing: " on
// stderr, exits non-zero (2 for usage errors, 1 otherwise) and creates no OUTPUT. Every part throws a
// Failure; main() turns it into that line, the exit code and the report's status.
#ifndef AF_TOOL_TOOL_COMMON_H
#define AF_TOOL_TOOL_COMMON_H

#include "message_text.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstring>
#include <string>

namespace CGAL {
namespace Anisotropic_fairing {
}
} // namespace CGAL

namespace af_tool {

namespace AF = CGAL::Anisotropic_fairing;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef K::Point_2 Texcoord;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef Mesh::Face_index Face_index;
typedef Mesh::Property_map<Vertex_index, Vector> Normal_map;
typedef Mesh::Property_map<Vertex_index, Texcoord> Texcoord_map;   // "v:texcoord", as CGAL's OFF reader makes it

enum class Format { OFF, OBJ, PLY, STL };   // in the order of af_tool::Mesh_format

// Thrown to end the program: the one-line message, the exit code and the report's status.
struct Failure
{
  int exit_code;
  std::string status;
  std::string message;
};

[[noreturn]] inline void usage_error(const std::string& message)
{
  throw Failure{ 2, "usage_error", message + " (see --help)" };
}
[[noreturn]] inline void fail(const std::string& status, const std::string& message)
{
  throw Failure{ 1, status, message };
}

// seconds since the program started (the report's wall_seconds)
double elapsed_seconds();

} // namespace af_tool

#endif // AF_TOOL_TOOL_COMMON_H
