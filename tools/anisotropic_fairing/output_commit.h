// The output, the snapshot and the report written all or nothing: each is checked to be writable before
// the fairing (a long run should not end on a directory that does not exist), written to a temporary file
// next to it and renamed into place only once every one was written.
#ifndef AF_TOOL_OUTPUT_COMMIT_H
#define AF_TOOL_OUTPUT_COMMIT_H

#include "json_report.h"
#include "mesh_io.h"
#include "options.h"
#include "progress_heartbeat.h"

#include <string>

namespace af_tool {

// Fails (write_error, snapshot_error) if the output, the report or the snapshot cannot be created; returns
// the snapshot's renderer (empty without --snapshot).
std::string check_outputs_writable(const Options& o);

// Writes o.output in `format`, the snapshot (rendered by `renderer`) and the report, then renames them into
// place; on failure removes them all and throws Failure. `r.write_seconds` counts from `write_from`.
void commit_outputs(const Options& o, const std::string& renderer, const Mesh& mesh, const Input_info& info,
                    Format format, double write_from, Progress_heartbeat& heartbeat, Run_record& r);

} // namespace af_tool

#endif // AF_TOOL_OUTPUT_COMMIT_H
