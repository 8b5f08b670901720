// The command line of anisotropic_fairing: the options, their table (which also makes the help text)
// and the checks between them.
#ifndef AF_TOOL_OPTIONS_H
#define AF_TOOL_OPTIONS_H

#include "tool_common.h"

#include <CGAL/Anisotropic_fairing/Fairing_settings.h>

#include <string>
#include <vector>

namespace af_tool {

struct Options
{
  std::string input, output, report;
  bool has_time_step = false, has_relative_time_step = false;
  double time_step = 0, relative_time_step = 0;
  unsigned int steps = 10;
  int order = 2;                   // --order: of the flow (2 or 4)
  bool has_order = false;
  bool has_steps = false;
  std::string stop = "auto";   // auto, noise, paper, off
  bool has_fidelity = false, has_relative_fidelity = false;
  double fidelity = 0, relative_fidelity = 0;
  bool has_bound = false, has_relative_bound = false, has_attribute_bound = false;   // --maximum-deviation ...
  double bound = 0, relative_bound = 0, attribute_bound = 0;
  AF::Finite_element element = AF::Finite_element::LOOP;
  AF::Output_positions output_positions = AF::Output_positions::LIMIT_SURFACE;
  AF::Linear_solver solver = AF::Linear_solver::AUTOMATIC;
  AF::Boundary_handling boundary = AF::Boundary_handling::HOLD_BOUNDARY_CURVE;
  int quadrature_degree = 8;
  bool anisotropic = false, uniform = false, has_tensor = false, has_lambda = false, has_epsilon = false;
  bool normal_motion_only = true, has_tangential_motion = false;   // --tangential-motion remove|keep
  double lambda = 2.0, epsilon = 1e-3;
  std::vector<std::string> attributes;   // the names given to --attributes, in their order
  bool has_mode = false;
  AF::Attribute_mode mode = AF::Attribute_mode::GEOMETRY_ONLY;
  bool has_attribute_weight = false;
  double attribute_weight = 1;
  bool curvature = false;   // --curvature: k1, k2, mean_curvature written as PLY vertex properties
  bool quiet = false;
  double progress_interval = 2;   // seconds of silence before a line says what the program is doing (0: never)
  bool has_progress_interval = false;
  bool repair = false;           // --repair: make a non-manifold or inconsistently oriented input usable
  bool report_refused = false;   // the report's path collides with the input or the output: never written
  std::vector<std::string> positional;   // the arguments that are not options, as given (even after a usage error)
  std::string hold;            // --hold: a vertex property or a file of vertex indices
  unsigned int resample = 0;   // --resample K: levels of Loop refinement of the written surface
  bool has_resample = false;
  std::string snapshot;        // --snapshot FILE.png: input and result side by side
  bool help = false;
  bool version = false;
};

// Reads the options; throws Failure (exit 2) on a usage error. `o.report` is set as soon as it is
// seen, so that a later usage error can still be written into the report.
void parse_arguments(int argc, char** argv, Options& o);

// The text of --help, its option list made from the option table.
std::string help_text();
// The text of --version: the program's version and those of the libraries it was built with.
std::string version_text();

// Why a failed run must not write its report to `o.report` (empty: it may). A failure may write only
// where it cannot destroy anything: not over any path on the command line (INPUT, OUTPUT, a stray
// argument, --hold's file, --snapshot), and not over an existing file that is not a report of this
// program.
std::string report_refused_on_failure(const Options& o);

bool automatic_parameters(const Options& o);
// the anisotropic tensor whose threshold and prefilter are chosen from the mesh
bool automatic_tensor(const Options& o);
// --mode, or its default: separate with --attributes, geometry without
AF::Attribute_mode effective_mode(const Options& o);
const char* mode_name(AF::Attribute_mode m);

// The format named by the file's extension (case-insensitive); false if none.
bool format_of(const std::string& path, Format& f);

} // namespace af_tool

#endif // AF_TOOL_OPTIONS_H
