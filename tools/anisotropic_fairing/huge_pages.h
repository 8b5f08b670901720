// anisotropic_fairing tool: transparent huge pages for the program's large arrays.
//
// On a mesh of millions of triangles, reading and set-up touch gigabytes of fresh memory, and a page
// fault per 4 kB page then costs as much as the work (measured here, 2.3M triangles: reading 5.3 s, of
// which most in the kernel). glibc's allocator asks the kernel for transparent huge pages (2 MB) only when
// the tunable glibc.malloc.hugetlb says so, and reads its tunables once, at start-up; where the kernel's
// mode is "madvise" (Debian's) nothing else gives them. So the program starts itself again once with
// that tunable added, unless GLIBC_TUNABLES sets it already (glibc.malloc.hugetlb=0 keeps it off, and keeps
// the program from starting again, e.g. under valgrind). Numbers are unchanged: only the pages differ.

#ifndef AF_TOOL_HUGE_PAGES_H
#define AF_TOOL_HUGE_PAGES_H

#include <cstdlib>
#include <string>

#if defined(__linux__) && defined(__GLIBC__)
#include <unistd.h>
#endif

namespace af_tool {

/// Returns only when the program runs with the tunable set (or cannot be started again).
inline void start_with_huge_pages(char** argv)
{
#if defined(__linux__) && defined(__GLIBC__)
  const char* set = std::getenv("GLIBC_TUNABLES");
  std::string tunables = set ? set : "";
  if(tunables.find("glibc.malloc.hugetlb") != std::string::npos) return;
  tunables += (tunables.empty() ? "" : ":") + std::string("glibc.malloc.hugetlb=1");
  if(setenv("GLIBC_TUNABLES", tunables.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);   // returns only if it failed: then on as it is
#else
  (void)argv;
#endif
}

} // namespace af_tool

#endif // AF_TOOL_HUGE_PAGES_H
