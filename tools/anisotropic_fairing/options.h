// The command line of anisotropic_fairing: the options, their table (which also makes the help text)
// and the checks between them.
#ifndef AF_TOOL_OPTIONS_H
#define AF_TOOL_OPTIONS_H

#include "tool_common.h"

#include <CGAL/Anisotropic_fairing/Fairing_options.h>

#include <optional>
#include <string>
#include <vector>

namespace af_tool {

struct Options
{
  std::string input, output, report;
  // what the library is asked for, in its own terms (CGAL::Anisotropic_fairing::Fairing_options): the
  // options below that name a named parameter set it directly; the tensor's words are put into it last
  AF::Fairing_options fairing;
  std::string stop = "auto";   // auto, noise, paper, off: the word given to --stop (fairing.stopping_criteria)
  // --tensor, --lambda, --epsilon, --tangential-motion as given, in any order: fairing.diffusion_tensor
  std::string tensor;          // empty: not given
  bool has_lambda = false, has_epsilon = false, has_tangential_motion = false;
  double lambda = 2.0, epsilon = 1e-3;
  bool normal_motion_only = true;
  bool has_attribute_weight = false;   // (a warning without --mode coupled)
  std::vector<std::string> attributes;   // the names given to --attributes, in their order
  bool curvature = false;   // --curvature: k1, k2, mean_curvature written as PLY vertex properties
  bool quiet = false;
  double progress_interval = 2;   // seconds of silence before a line says what the program is doing (0: never)
  bool has_progress_interval = false;
  bool repair = false;           // --repair: also stitch borders and remove lone vertices
  bool text_output = false;      // --ascii: STL and PLY written as text
  std::vector<std::string> deprecations;   // the deprecated spellings used, each with what to write instead
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

// --mode, or its default: separate with --attributes, geometry without
AF::Attribute_mode effective_mode(const Options& o);
const char* mode_name(AF::Attribute_mode m);

// The format named by the file's extension (case-insensitive); false if none.
bool format_of(const std::string& path, Format& f);

} // namespace af_tool

#endif // AF_TOOL_OPTIONS_H
