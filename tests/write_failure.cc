// Failure injection for the tests, loaded with LD_PRELOAD into penny:
//   PENNY_TEST_DISK_BYTES=N      write() to regular files (not stdout or stderr)
//                                fails with ENOSPC once N bytes are written:
//                                a full disk, where no small tmpfs can be mounted;
//   PENNY_TEST_KILL_AT_RENAME=before|after
//                                the process sends itself SIGKILL just before or
//                                just after its first renameat2: a run killed
//                                with its results staged, or with the results
//                                swapped in but the previous ones not yet removed.
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <sys/stat.h>
#include <unistd.h>

namespace
{
  template <typename Function> Function next(const char *name)
  {
    return reinterpret_cast<Function>(dlsym(RTLD_NEXT, name));
  }

  long long written = 0;
} // namespace

extern "C" ssize_t write(const int descriptor, const void *buffer, const size_t count)
{
  static const auto  real  = next<ssize_t (*)(int, const void *, size_t)>("write");
  static const char *limit = std::getenv("PENNY_TEST_DISK_BYTES");
  struct stat        status;
  if (limit && descriptor > STDERR_FILENO && fstat(descriptor, &status) == 0 && S_ISREG(status.st_mode))
    {
      const long long room = std::atoll(limit) - written;
      if (room <= 0)
        {
          errno = ENOSPC;
          return -1;
        }
      const ssize_t n = real(descriptor, buffer, count < size_t(room) ? count : size_t(room));
      if (n > 0)
        written += n;
      return n;
    }
  return real(descriptor, buffer, count);
}

extern "C" int renameat2(const int from_folder, const char *from, const int to_folder, const char *to,
                         const unsigned int flags)
{
  static const auto real = next<int (*)(int, const char *, int, const char *, unsigned int)>("renameat2");
  const char       *kill = std::getenv("PENNY_TEST_KILL_AT_RENAME");
  if (kill && std::strcmp(kill, "before") == 0)
    raise(SIGKILL);
  const int result = real(from_folder, from, to_folder, to, flags);
  if (kill && std::strcmp(kill, "after") == 0)
    raise(SIGKILL);
  return result;
}
