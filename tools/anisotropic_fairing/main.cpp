// anisotropic_fairing -- the command-line program of the Anisotropic_fairing package.
//
//   anisotropic_fairing INPUT OUTPUT [options]        (anisotropic_fairing --help for the options)
//
// Reads a triangle mesh (OFF, OBJ or PLY; closed or with borders), fairs it with CGAL::Anisotropic_fairing::
// anisotropic_fairing() and writes the result (OFF, OBJ or PLY, chosen by OUTPUT's extension) with
// full double precision, the vertices in their input order and every vertex property of the input
// that the output format can hold. Optionally writes a JSON report with the statistics of every step.
//
// The parts: options.{h,cpp} (the option table, the help text), mesh_io.{h,cpp} (checked reading and
// writing, with the CGAL 5.5 work-arounds), attribute_columns.{h,cpp} (--attributes), json_report.{h,cpp}
// (--report), fairing_run.{h,cpp} (the run: fairing, normals, curvature, the writes) and this file
// (the failure contract of tool_common.h: one line on stderr, exit 1 or 2, a report on failure too).

#include "fairing_run.h"
#include "huge_pages.h"
#include "json_report.h"
#include "mesh_io.h"
#include "options.h"
#include "tool_common.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <new>
#include <string>

namespace {
const std::chrono::steady_clock::time_point program_start = std::chrono::steady_clock::now();
}

double af_tool::elapsed_seconds()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - program_start).count();
}

int main(int argc, char** argv)
{
  using namespace af_tool;
  start_with_huge_pages(argv);
  Options o;
  Run_record r;
  int exit_code = 1;
  try
  {
    parse_arguments(argc, argv, o);
    if(o.help)
    {
      std::fputs(help_text().c_str(), stdout);
      return 0;
    }
    if(o.version)
    {
      std::fputs(version_text().c_str(), stdout);
      return 0;
    }
    return run(o, r);
  }
  catch(const Failure& f)
  {
    r.status = f.status;
    r.message = one_line(f.message);
    exit_code = f.exit_code;
  }
  catch(const std::bad_alloc&)
  {
    r.status = "error";
    r.message = "out of memory";
  }
  catch(const std::exception& e)
  {
    r.status = "error";
    r.message = one_line(e.what());
  }
  int code = exit_code;
  std::string line = "anisotropic_fairing: " + r.message;
  const bool report_failed = r.status == "write_error" && r.message.rfind("cannot write the report ", 0) == 0;
  const std::string refused = report_refused_on_failure(o);
  if(!o.report.empty() && !o.report_refused && !refused.empty())
    line += " (the report " + one_line(o.report) + " is not written: " + refused + ")";
  else if(!o.report.empty() && refused.empty() && !report_failed)
  {
    const std::string why = write_file_atomically(o.report, report_json(o, r, elapsed_seconds()));
    if(!why.empty()) line += " (and cannot write the report " + one_line(o.report) + ": " + why + ")";
  }
  std::fprintf(stderr, "%s\n", line.c_str());
  return code;
}
