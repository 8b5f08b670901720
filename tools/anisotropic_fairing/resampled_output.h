// --resample K: the faired limit surface at K levels of Loop refinement (4^K faces per input face),
// written instead of the faired mesh, with every property of the input.
#ifndef AF_TOOL_RESAMPLED_OUTPUT_H
#define AF_TOOL_RESAMPLED_OUTPUT_H

#include "attribute_columns.h"
#include "mesh_io.h"
#include "tool_common.h"

#include <optional>
#include <string>
#include <vector>

namespace af_tool {

// The faces --resample may write at most (a Surface_mesh of that size takes several GiB).
constexpr double resample_face_budget = 5e7;

// Fails (status invalid_parameter) if `levels` would give more faces than the budget, or (insufficient_memory)
// if they would not fit in what the process may take (`memory_limit`: --memory-limit); before the run.
void check_resample_size(const Mesh& mesh, unsigned levels, const std::optional<double>& memory_limit);

// What the run gives the resampling: the faired control points and, for the faired attribute columns,
// their control values (one vector per vertex, the columns in order).
struct Faired_controls
{
  const std::vector<Point>* points;
  const std::vector<Attribute_column>* columns;
  const std::vector<std::vector<double>>* values;
};

// Replaces `mesh` (the faired mesh as it would be written) by the limit surface of the faired control
// points at `levels` levels. Its first vertices are exactly those of `mesh`, with all their
// properties; every new vertex lies on the faired limit surface, with the limit normal (if the input has
// normals), the curvature (with --curvature), the limit of the faired attributes' control values, and,
// for any other vertex property (numeric, colour, texture coordinates), the Loop limit of the input's
// values; a new face has the properties of the input face it lies in. `input` names the file in messages.
void resample_output(Mesh& mesh, const Input_info& info, const std::string& input, unsigned levels,
                     const Faired_controls& faired, bool curvature, int quadrature_degree);

} // namespace af_tool

#endif // AF_TOOL_RESAMPLED_OUTPUT_H
