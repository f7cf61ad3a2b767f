#include "core/input_file.h"

#include "core/errors.h"
#include "core/format.h" // for meshpaint::format_bytes

#include <cerrno>     // for errno
#include <cstring>    // for std::strerror
#include <fcntl.h>    // for open, O_NONBLOCK
#include <sys/stat.h> // for fstat, S_ISREG
#include <unistd.h>   // for read, close

namespace meshpaint {

std::string read_input_file(const std::string& path, std::uint64_t max_bytes, const std::string& what)
{
  // Non-blocking, so that opening a FIFO returns at once; the kind is then
  // taken from the open descriptor, which a rename cannot swap afterwards.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0)
    throw IOError("cannot open " + what + " '" + path + "': " + std::strerror(errno));
  struct Closer
  {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st{};
  if (::fstat(fd, &st) != 0)
    throw IOError("cannot read " + what + " '" + path + "': " + std::strerror(errno));
  if (!S_ISREG(st.st_mode))
    throw InputError(what + " '" + path + "' is not a regular file");
  if (std::uint64_t(st.st_size) > max_bytes)
    throw InputError(what + " '" + path + "' has " + format_bytes(std::size_t(st.st_size)) + ", more than the " +
                     format_bytes(std::size_t(max_bytes)) + " accepted");
  // One byte more than stated, to notice a file growing while it is read.
  std::string text(std::size_t(st.st_size) + 1, '\0');
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::read(fd, &text[done], text.size() - done);
    if (n < 0 && errno == EINTR)
      continue;
    if (n < 0)
      throw IOError("cannot read " + what + " '" + path + "': " + std::strerror(errno));
    if (n == 0)
      break;
    done += std::size_t(n);
  }
  if (done > std::size_t(st.st_size))
    throw InputError(what + " '" + path + "' changed while it was read");
  text.resize(done);
  return text;
}

} // namespace meshpaint
