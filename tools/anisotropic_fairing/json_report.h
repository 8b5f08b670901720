// The JSON report of anisotropic_fairing (--report): what was asked, what the run chose and did,
// and the statistics of every step; written on success and on failure (with status and message).
// Numbers are written in the shortest form that reads back to the same double; unknown or non-finite
// values are null. The keys and their meaning are a public interface: the --help text lists them
// (report_keys), the manual's page on the program describes each, and the test cli_option_docs checks
// that page against a report.
#ifndef AF_TOOL_JSON_REPORT_H
#define AF_TOOL_JSON_REPORT_H

#include "options.h"

#include <CGAL/Anisotropic_fairing/Fairing_report.h>

#include <cstddef>
#include <string>
#include <vector>

namespace af_tool {

// What the program did, for the report: filled as the run goes.
struct Run_record
{
  std::string status = "success";
  std::string message;
  bool mesh_read = false;
  std::size_t vertices = 0, faces = 0;
  std::vector<std::string> input_changes;   // what was changed in the input for the run
  std::size_t split_vertices = 0;           // non-manifold vertices split for the run
  std::size_t triangulated_faces = 0;       // faces of the input that were not triangles
  bool fairing_ran = false;
  AF::Fairing_report report;
  std::string normals = "none";
  bool curvature = false;   // k1, k2, mean_curvature were added to the output
  std::size_t held_vertices = 0;   // held by --hold
  std::size_t resampled_vertices = 0, resampled_faces = 0;   // --resample: what was written
  bool output_written = false;
  double read_seconds = 0;    // the input file read and checked
  double write_seconds = 0;   // after the fairing: normals, curvature, resampling, the output file written
};

std::string report_json(const Options& o, const Run_record& r, double wall_seconds);

/// The report's keys of the deviation bounds (absolute_maximum_deviation ... clamped_vertices) as a JSON
/// object: what the distributed program reports of them.
std::string deviations_json(const Options& o, const Run_record& r);

/// The report's keys in the order written, nested ones in braces ("initial {area, ...}"), from a report
/// of a run that took a step: the list --help prints.
std::string report_keys();

} // namespace af_tool

#endif // AF_TOOL_JSON_REPORT_H
