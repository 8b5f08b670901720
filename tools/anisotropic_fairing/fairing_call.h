// The call of CGAL::Anisotropic_fairing::anisotropic_fairing() that the program's options ask for: the
// one place that hands Options to the library, shared by the program and the Python module so
// that both give the same result for the same settings.
#ifndef AF_TOOL_FAIRING_CALL_H
#define AF_TOOL_FAIRING_CALL_H

#include "attribute_columns.h"
#include "options.h"
#include "tool_common.h"

#include <CGAL/Anisotropic_fairing/Fairing_report.h>

#include <functional>
#include <vector>

namespace af_tool {

typedef std::function<bool(const AF::Fairing_step&)> Step_callback;

// Fairs `mesh` in place as `o` says, with the attribute mode `mode` (GEOMETRY_ONLY when no attribute is
// faired). Gives back the faired control points and the attributes' control values (one entry per vertex;
// `attribute_controls` sized like the attribute vectors); `held[v]` != 0 holds vertex v. Throws
// AF::Input_error as the library does.
AF::Fairing_report fair_with_options(Mesh& mesh, const Options& o, AF::Attribute_mode mode,
                                     const Attribute_vectors& attributes,
                                     std::vector<std::vector<double>>& attribute_controls,
                                     std::vector<Point>& control_points, std::vector<unsigned char>& held,
                                     const Step_callback& callback);

} // namespace af_tool

#endif // AF_TOOL_FAIRING_CALL_H
