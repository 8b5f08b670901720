// The output, the snapshot and the report written all or nothing (see output_commit.h).
#include "output_commit.h"

#include "snapshot.h"

#include <CGAL/Anisotropic_fairing/Fairing_report.h>

#include <cstdio>
#include <filesystem>

#include <unistd.h>

namespace af_tool {
namespace fs = std::filesystem;

namespace {

// `what` names the file in the message ("the report "), empty for the output.
void check_writable(const std::string& path, const std::string& what)
{
  const fs::path out(path);
  const fs::path dir = out.has_parent_path() ? out.parent_path() : fs::path(".");
  std::error_code ec;
  if(!fs::is_directory(dir, ec)) fail("write_error", "cannot write " + what + path + ": no directory " + dir.string());
  if(::access(dir.c_str(), W_OK) != 0)
    fail("write_error", "cannot write " + what + path + ": directory " + dir.string() + " is not writable");
  if(fs::is_directory(out, ec)) fail("write_error", "cannot write " + what + path + ": it is a directory");
  if(fs::exists(out, ec) && ::access(out.c_str(), W_OK) != 0)
    fail("write_error", "cannot write " + what + path + ": it is not writable");
}

// The temporary files, removed when a later write fails.
struct Temporaries
{
  fs::path output, snapshot;   // snapshot: empty without --snapshot
  void remove() const
  {
    std::error_code ec;
    fs::remove(output, ec);
    if(!snapshot.empty()) fs::remove(snapshot, ec);
  }
};

void write_mesh_next_to(const Options& o, const Mesh& mesh, const Input_info& info, Format format, const fs::path& tmp)
{
  try
  {
    write_mesh(tmp.string(), format, mesh, info, info.has_normals, o.text_output);
    // resampled: a new mesh, copies and all
    if(!o.has_resample) merge_copies_in_file(tmp.string(), format, info.split);
  }
  catch(const Failure& f)
  {
    fail_writing(f, tmp, o.output);
  }
}

void render_snapshot_next_to(const Options& o, const std::string& renderer, const Temporaries& tmp,
                             Progress_heartbeat& heartbeat, const Run_record& r)
{
  char result_title[200];
  std::snprintf(result_title, sizeof result_title, "faired: %s, %zu steps, %s",
                r.report.selected_tensor.empty() ? "" : r.report.selected_tensor.c_str(), r.report.steps.size(),
                AF::to_string(r.report.stop_reason));
  heartbeat.phase("rendering the snapshot " + o.snapshot);
  try
  {
    render_snapshot(renderer, o.input, tmp.output.string(), "input: " + fs::path(o.input).filename().string(),
                    result_title, tmp.snapshot.string(), o.snapshot);
  }
  catch(const Failure&)
  {
    tmp.remove();
    throw;
  }
}

// Renames the output and the snapshot into place; if either fails nothing stays, the report included
// (it described an output that does not exist).
void rename_into_place(const Options& o, const Temporaries& tmp, Run_record& r)
{
  std::error_code ec;
  fs::rename(tmp.output, o.output, ec);
  const bool output_moved = !ec;
  if(output_moved && !o.snapshot.empty()) fs::rename(tmp.snapshot, o.snapshot, ec);
  if(!ec) return;
  std::error_code ec2;
  tmp.remove();
  if(output_moved) fs::remove(o.output, ec2);
  r.output_written = false;
  if(!o.report.empty()) fs::remove(o.report, ec2);
  fail("write_error", "cannot write " + (output_moved ? o.snapshot : o.output) + ": " + ec.message());
}

} // namespace

std::string check_outputs_writable(const Options& o)
{
  check_writable(o.output, "");
  if(!o.report.empty()) check_writable(o.report, "the report ");
  if(!o.snapshot.empty()) check_writable(o.snapshot, "the snapshot ");
  const std::string renderer = o.snapshot.empty() ? std::string() : render_script();
  if(!o.snapshot.empty() && renderer.empty())
    fail("snapshot_error", "--snapshot: the renderer render_mesh.py was not found (installed next to the program, "
                           "or set AF_RENDER_SCRIPT)");
  return renderer;
}

void commit_outputs(const Options& o, const std::string& renderer, const Mesh& mesh, const Input_info& info,
                    Format format, double write_from, Progress_heartbeat& heartbeat, Run_record& r)
{
  Temporaries tmp;
  tmp.output = temporary_next_to(o.output);
  heartbeat.phase("writing " + o.output);
  write_mesh_next_to(o, mesh, info, format, tmp.output);
  if(!o.snapshot.empty())
  {
    tmp.snapshot = temporary_next_to(o.snapshot);
    render_snapshot_next_to(o, renderer, tmp, heartbeat, r);
  }
  r.output_written = true;  // as far as the report is concerned
  r.write_seconds = elapsed_seconds() - write_from;
  // wall time up to here; the rename is negligible
  const std::string why =
    o.report.empty() ? std::string() : write_file_atomically(o.report, report_json(o, r, elapsed_seconds()));
  if(!why.empty())
  {
    tmp.remove();
    r.output_written = false;
    throw Failure{1, "write_error", "cannot write the report " + o.report + ": " + why};
  }
  rename_into_place(o, tmp, r);
}

} // namespace af_tool
