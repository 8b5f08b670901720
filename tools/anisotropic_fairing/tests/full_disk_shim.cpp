// A full file system for the test tool_full_disk (tests/full_disk_test.py), loaded with LD_PRELOAD: every
// write() and writev() to a file under the directory AF_FULL_DISK_PREFIX fails with ENOSPC, as on a disk
// that has filled up; every other file (and the terminal) is written as usual.
#include <dlfcn.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

bool full(int fd)
{
  const char* prefix = std::getenv("AF_FULL_DISK_PREFIX");
  if(!prefix || fd <= 2) return false;
  char link[64], target[4096];
  std::snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
  const ssize_t n = ::readlink(link, target, sizeof target - 1);
  if(n <= 0) return false;
  target[n] = 0;
  return std::strncmp(target, prefix, std::strlen(prefix)) == 0;
}

template <typename F>
F real(const char* name)
{
  return reinterpret_cast<F>(::dlsym(RTLD_NEXT, name));
}

} // namespace

extern "C" ssize_t write(int fd, const void* buffer, size_t count)
{
  static const auto next = real<ssize_t (*)(int, const void*, size_t)>("write");
  if(full(fd)) { errno = ENOSPC; return -1; }
  return next(fd, buffer, count);
}

extern "C" ssize_t writev(int fd, const struct iovec* vector, int count)
{
  static const auto next = real<ssize_t (*)(int, const struct iovec*, int)>("writev");
  if(full(fd)) { errno = ENOSPC; return -1; }
  return next(fd, vector, count);
}
