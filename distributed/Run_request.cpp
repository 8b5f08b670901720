// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "Run_request.h"

#include <cctype>
#include <cstdlib>

namespace af_distributed {

namespace {

bool is_petsc_option(const std::string& a)
{
  return a.size() > 2 && a[0] == '-' && a[1] != '-' && std::isalpha(static_cast<unsigned char>(a[1]));
}

bool is_number(const std::string& a)
{
  char* end = nullptr;
  std::strtod(a.c_str(), &end);
  return !a.empty() && end == a.c_str() + a.size();
}

} // namespace

Split_arguments split_arguments(int argc, char** argv)
{
  Split_arguments s;
  s.program.push_back(argv[0]);
  s.petsc.push_back(argv[0]);
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(!is_petsc_option(a)) { s.program.push_back(a); continue; }
    s.petsc.push_back(a);
    if(i + 1 < argc && (argv[i + 1][0] != '-' || is_number(argv[i + 1]))) s.petsc.push_back(argv[++i]);
  }
  return s;
}

std::string unsupported(const af_tool::Options& o)
{
  namespace AF = CGAL::Anisotropic_fairing;
  const AF::Fairing_options& f = o.fairing;
  const std::string no = " is not supported by the distributed program";
  if(f.finite_element != AF::Finite_element::LOOP) return "--element linear" + no;
  if(f.linear_solver == AF::Linear_solver::CHOLESKY)
    return "--solver cholesky" + no + " (PETSc's options choose the solver: -ksp_type, -pc_type)";
  if(o.has_resample) return "--resample" + no;
  if(!o.snapshot.empty()) return "--snapshot" + no;
  if(f.memory_limit) return "--memory-limit" + no + " (a process's memory is not predicted yet)";
  return std::string();
}

} // namespace af_distributed
