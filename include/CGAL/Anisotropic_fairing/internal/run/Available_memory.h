// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How much more memory this process may take now, and what limits it: the tightest of the cgroup's memory
// limit (a container's, a batch job's), the address-space and data limits (ulimit -v, ulimit -d) and the
// memory the system has available. Read before the work, so that a run that cannot fit is refused up
// front (Memory_estimate.h) instead of failing with "out of memory" after its set-up. Linux reads all
// four; elsewhere only the POSIX limits without the process's use of them, i.e. nothing is known.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_AVAILABLE_MEMORY_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_AVAILABLE_MEMORY_H

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/sysinfo.h>
#include <unistd.h>
#endif

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// What the process may still take, in bytes (infinite when nothing is known), and what sets it.
struct Available_memory
{
  double bytes = std::numeric_limits<double>::infinity();
  std::string source;   // e.g. "the address-space limit (ulimit -v)"; empty when nothing is known
  double in_use = 0;    // the process's resident memory when read (0 when unknown)

  void take(double headroom, const char* why)
  {
    if(!(headroom < bytes)) return;
    bytes = std::max(0.0, headroom);
    source = why;
  }
};

#if defined(__linux__)
namespace memory_files {

inline std::string contents(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return in ? s.str() : std::string();
}

/// The number a file holds (a cgroup's "max" or a missing file: infinity).
inline double number_in(const std::string& path)
{
  const std::string text = contents(path);
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  return end != text.c_str() ? v : std::numeric_limits<double>::infinity();
}

/// The value of `key` in a "key value" file (memory.stat), 0 when absent.
inline double keyed(const std::string& path, const std::string& key)
{
  std::istringstream in(contents(path));
  std::string line, k;
  while(std::getline(in, line))
  {
    std::istringstream words(line);
    double v;
    if(words >> k >> v && k == key) return v;
  }
  return 0;
}

/// The cgroup path of the memory controller in /proc/self/cgroup ("0::/a/b" for v2, "4:memory:/a/b" for v1).
inline std::string cgroup_path(bool v2)
{
  std::istringstream in(contents("/proc/self/cgroup"));
  std::string line;
  while(std::getline(in, line))
  {
    const std::size_t a = line.find(':'), b = line.find(':', a + 1);
    if(a == std::string::npos || b == std::string::npos) continue;
    const std::string controllers = "," + line.substr(a + 1, b - a - 1) + ",";
    if(v2 ? line.compare(0, a, "0") == 0 && b == a + 1 : controllers.find(",memory,") != std::string::npos)
      return line.substr(b + 1);
  }
  return std::string();
}

/// The headroom of the cgroup `path` under `root` and of each of its ancestors up to the mount (a container
/// sees its own cgroup as the mount's root): the limit less what is charged, page cache that would be
/// reclaimed first not counted.
inline void take_cgroup(Available_memory& a, const std::string& root, std::string path, bool v2)
{
  const char* limit = v2 ? "/memory.max" : "/memory.limit_in_bytes";
  const char* usage = v2 ? "/memory.current" : "/memory.usage_in_bytes";
  const char* cache = v2 ? "inactive_file" : "total_inactive_file";
  for(;;)
  {
    const std::string dir = root + path;
    const double max = number_in(dir + limit);
    // v1 writes "no limit" as a huge page-aligned number
    if(std::isfinite(max) && max < 1e18)
    {
      const double used = number_in(dir + usage) - keyed(dir + "/memory.stat", cache);
      if(std::isfinite(used)) a.take(max - std::max(0.0, used), "the cgroup's memory limit");
    }
    if(path.empty() || path == "/") break;
    path.erase(path.find_last_of('/'));
  }
}

} // namespace memory_files

/// The memory this process may take now (see the top of this file).
inline Available_memory available_memory()
{
  using namespace memory_files;
  Available_memory a;
  const double page = double(sysconf(_SC_PAGESIZE));
  std::istringstream statm(contents("/proc/self/statm"));
  double size = 0, resident = 0, shared = 0, text = 0, lib = 0, data = 0;
  statm >> size >> resident >> shared >> text >> lib >> data;
  a.in_use = resident * page;

  rlimit r;
  if(getrlimit(RLIMIT_AS, &r) == 0 && r.rlim_cur != RLIM_INFINITY)
    a.take(double(r.rlim_cur) - size * page, "the address-space limit (ulimit -v)");
  if(getrlimit(RLIMIT_DATA, &r) == 0 && r.rlim_cur != RLIM_INFINITY)
    a.take(double(r.rlim_cur) - data * page, "the data-segment limit (ulimit -d)");

  const std::string v2 = cgroup_path(true), v1 = cgroup_path(false);
  if(!v2.empty() && std::ifstream("/sys/fs/cgroup/cgroup.controllers").good())   // the unified hierarchy
    take_cgroup(a, "/sys/fs/cgroup", v2 == "/" ? std::string() : v2, true);
  if(!v1.empty())
  {
    // a container mounts its own cgroup as the root: then the path from /proc is not under the mount
    const std::string root = "/sys/fs/cgroup/memory";
    const bool nested = !contents(root + v1 + "/memory.limit_in_bytes").empty();
    take_cgroup(a, root, nested && v1 != "/" ? v1 : std::string(), false);
  }

  const double meminfo = keyed("/proc/meminfo", "MemAvailable:");
  if(meminfo > 0) a.take(meminfo * 1024.0, "the memory the system has available");
  else
  {
    struct sysinfo s;
    if(sysinfo(&s) == 0)
      a.take((double(s.freeram) + double(s.bufferram)) * double(s.mem_unit), "the memory the system has available");
  }
  return a;
}
#else
inline Available_memory available_memory() { return Available_memory(); }
#endif

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_RUN_AVAILABLE_MEMORY_H
