// The run of anisotropic_fairing: read, fair, write (see fairing_run.cpp).
#ifndef AF_TOOL_FAIRING_RUN_H
#define AF_TOOL_FAIRING_RUN_H

#include "json_report.h"
#include "options.h"

namespace af_tool {

// Reads o.input, fairs it and writes o.output (and the report) as the options say; returns the exit
// code (0). Throws Failure; `r` then holds what the report says about the part that ran.
int run(const Options& o, Run_record& r);

} // namespace af_tool

#endif // AF_TOOL_FAIRING_RUN_H
