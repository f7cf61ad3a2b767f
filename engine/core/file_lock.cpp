#include "core/file_lock.h"

#include "core/errors.h"

#include <cerrno>     // for errno
#include <cstring>    // for std::strerror
#include <fcntl.h>    // for open
#include <sys/file.h> // for flock
#include <sys/stat.h> // for stat, fstat
#include <unistd.h>   // for close

namespace meshpaint {

FileLock::FileLock(const std::string& path, const std::function<void()>& waiting)
{
  bool told = false;
  for (;;) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
      if (errno == ENOENT)
        return;
      throw IOError("cannot lock '" + path + "': " + std::strerror(errno));
    }
    int got = ::flock(fd, LOCK_EX | LOCK_NB);
    if (got != 0 && errno == EWOULDBLOCK) {
      if (!told && waiting)
        waiting();
      told = true;
      do
        got = ::flock(fd, LOCK_EX);
      while (got != 0 && errno == EINTR);
    }
    if (got != 0) {
      const int error = errno;
      ::close(fd);
      throw IOError("cannot lock '" + path + "': " + std::strerror(error));
    }
    // The holder before us may have renamed a new file over `path`: that
    // one is the project now, and the one to lock.
    struct stat locked = {}, now = {};
    if (::fstat(fd, &locked) == 0 && ::stat(path.c_str(), &now) == 0 && locked.st_dev == now.st_dev &&
        locked.st_ino == now.st_ino) {
      fd_ = fd;
      return;
    }
    ::close(fd);
  }
}

FileLock::~FileLock()
{
  if (fd_ >= 0)
    ::close(fd_);
}

} // namespace meshpaint
