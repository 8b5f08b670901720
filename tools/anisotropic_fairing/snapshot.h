// --snapshot FILE.png: the input and the result rendered side by side by the package's renderer
// (scripts/figures/render_mesh.py: VTK from Debian's python3-vtk9, under xvfb-run when there is no
// display), the same that makes the manual's figures.
#ifndef AF_TOOL_SNAPSHOT_H
#define AF_TOOL_SNAPSHOT_H

#include <string>

namespace af_tool {

// The renderer: $AF_RENDER_SCRIPT, else share/anisotropic_fairing/render_mesh.py next to the installed
// program, else the source tree's; empty if none exists.
std::string render_script();

// Renders `input` and `result` (titled as given) into `png`, which messages call `name`, with the renderer
// `script` (render_script(), found); throws Failure (status snapshot_error) with the
// renderer's last message line if it fails. The interpreter is $AF_PYTHON, else /usr/bin/python3 (Debian's,
// where python3-vtk9 installs), else python3 from PATH.
void render_snapshot(const std::string& script, const std::string& input, const std::string& result,
                     const std::string& input_title, const std::string& result_title, const std::string& png,
                     const std::string& name);

} // namespace af_tool

#endif // AF_TOOL_SNAPSHOT_H
