// --hold: the vertices the program holds where they are (vertex_is_constrained_map), read from a vertex
// property of the input (held where it is not 0) or from a text file of vertex indices.
#ifndef AF_TOOL_HELD_VERTICES_H
#define AF_TOOL_HELD_VERTICES_H

#include "tool_common.h"

#include <functional>
#include <string>
#include <vector>

namespace af_tool {

// `spec`: the name of a numeric vertex property of `mesh` (PLY: e.g. "quality", or one of the input's own),
// or the path of a text file with one 0-based vertex index per line (blank lines and lines starting with
// '#' skipped). held[i] is set to 1 for each vertex held; returns how many. A bad line, an index out of
// range or a spec that is neither fails naming it.
std::size_t read_held_vertices(const Mesh& mesh, const std::string& spec, std::vector<unsigned char>& held);

// The indices of the text file `spec` (as above), each below `vertices`, given to `held` in the file's order; a bad
// line or an index out of range fails naming it. False, having read nothing, where `spec` cannot be opened.
bool read_vertex_index_file(const std::string& spec, std::size_t vertices,
                            const std::function<void(std::size_t)>& held);

} // namespace af_tool

#endif // AF_TOOL_HELD_VERTICES_H
