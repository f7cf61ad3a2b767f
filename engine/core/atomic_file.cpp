#include "core/atomic_file.h"

#include "core/errors.h"

#include <algorithm>  // for std::min
#include <array>      // for std::array
#include <atomic>     // for std::atomic
#include <cerrno>     // for errno, ENOSPC, EDQUOT, EIO
#include <csignal>    // for sigaction, raise
#include <cstring>    // for std::strerror, std::strncpy
#include <fcntl.h>    // for open, O_WRONLY
#include <filesystem> // for std::filesystem
#include <memory>     // for std::make_shared
#include <signal.h>   // for kill
#include <sys/statvfs.h> // for statvfs
#include <unistd.h>   // for getpid, write, fsync, close, unlink

namespace meshpaint {
namespace {

namespace fs = std::filesystem;

//! The extensions meshpaint writes: only temporaries of these are ever
//! taken for stale ones of ours.
bool written_extension(const std::string& ext)
{
  for (const char* known : {".obj", ".mtl", ".ply", ".vtp", ".png", ".meshpaint", ".json", ".gltf", ".glb"})
    if (ext == known)
      return true;
  return false;
}

//! Temporaries being written, for the signal handler: fixed slots, since a
//! handler may not allocate or lock.
constexpr int kSlots = 32; // a batched export holds about 15 at once
struct Slot
{
  std::atomic<bool> used{false};
  char path[4096] = {};
};
std::array<Slot, kSlots> g_slots;

//! Holds a temporary's slot while it is written.
class InFlight
{
public:
  explicit InFlight(const std::string& path)
  {
    if (path.size() >= sizeof(Slot::path))
      return;
    for (int k = 0; k < kSlots; ++k) {
      bool expected = false;
      if (g_slots[k].used.load() || !g_slots[k].used.compare_exchange_strong(expected, true))
        continue;
      std::strncpy(g_slots[k].path, path.c_str(), sizeof(Slot::path) - 1);
      slot_ = k;
      return;
    }
  }
  ~InFlight()
  {
    if (slot_ >= 0) {
      g_slots[slot_].path[0] = '\0';
      g_slots[slot_].used.store(false);
    }
  }
  InFlight(const InFlight&) = delete;
  InFlight& operator=(const InFlight&) = delete;

private:
  int slot_ = -1;
};

void remove_in_flight(int sig)
{
  for (Slot& s : g_slots)
    if (s.used.load() && s.path[0] != '\0')
      ::unlink(s.path);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

//! Errors that mean the file system, not the request, failed.
bool storage_failure(int error)
{
  return error == ENOSPC || error == EDQUOT || error == EIO || error == EFBIG;
}

[[noreturn]] void fail(const std::string& path, int error)
{
  const std::string what = "cannot write '" + path + "': " + std::strerror(error);
  if (storage_failure(error))
    throw StorageError(what + "; the previous file is unchanged");
  throw IOError(what);
}

fs::path folder_of(const std::string& path)
{
  const fs::path target(path);
  return target.has_parent_path() ? target.parent_path() : fs::path(".");
}

void check_folder(const std::string& path)
{
  std::error_code ec;
  const fs::path dir = folder_of(path);
  if (!fs::is_directory(dir, ec))
    throw IOError("cannot write '" + path + "': no directory '" + dir.string() + "'");
}

//! Makes the rename itself durable.
void sync_folder(const std::string& path)
{
  const int fd = ::open(folder_of(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0)
    return; // the file is in place; only its durability across a crash is unknown
  const bool ok = ::fsync(fd) == 0 || errno == EINVAL; // some file systems do not sync folders
  const int error = errno;
  ::close(fd);
  if (!ok)
    fail(path, error);
}

//! fsync of a written file; the error code, or 0.
int sync_file(const std::string& tmp)
{
  const int fd = ::open(tmp.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0)
    return errno;
  const int error = ::fsync(fd) == 0 ? 0 : errno;
  ::close(fd);
  return error;
}

void rename_over(const std::string& tmp, const std::string& path)
{
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec)
    throw IOError("cannot write '" + path + "': " + ec.message());
  sync_folder(path);
}

thread_local AtomicWriteBatch* g_batch = nullptr;

} // namespace

AtomicWriteBatch::AtomicWriteBatch() : outer_(g_batch)
{
  if (!outer_)
    g_batch = this;
}

AtomicWriteBatch::~AtomicWriteBatch()
{
  if (outer_)
    return;
  g_batch = nullptr;
  if (committed_)
    return;
  for (const Staged& s : staged_)
    ::unlink(s.tmp.c_str());
  for (const std::string& dir : made_) {
    std::error_code ec;
    fs::remove(dir, ec); // only when empty
  }
}

void AtomicWriteBatch::made_directory(const std::string& dir)
{
  (outer_ ? *g_batch : *this).made_.push_back(dir);
}

AtomicWriteBatch* AtomicWriteBatch::current() { return g_batch; }

void AtomicWriteBatch::stage(const std::string& tmp, const std::string& path, std::shared_ptr<void> slot)
{
  AtomicWriteBatch& outermost = outer_ ? *g_batch : *this;
  for (const Staged& s : outermost.staged_)
    if (s.tmp == tmp)
      return; // the same file written again: its temporary holds the last bytes
  outermost.staged_.push_back({tmp, path, std::move(slot)});
}

std::vector<std::string> AtomicWriteBatch::temporaries() const
{
  std::vector<std::string> out;
  for (const Staged& s : (outer_ ? *g_batch : *this).staged_)
    out.push_back(s.tmp);
  return out;
}

void AtomicWriteBatch::commit()
{
  if (outer_ || committed_)
    return;
  for (std::size_t k = 0; k < staged_.size(); ++k) {
    std::error_code ec;
    fs::rename(staged_[k].tmp, staged_[k].path, ec);
    if (ec) {
      for (std::size_t j = k; j < staged_.size(); ++j)
        ::unlink(staged_[j].tmp.c_str());
      committed_ = true;
      throw IOError("cannot write '" + staged_[k].path + "': " + ec.message());
    }
  }
  committed_ = true;
  for (const Staged& s : staged_)
    sync_folder(s.path);
}

std::string temporary_path(const std::string& path)
{
  const fs::path target(path);
  return (folder_of(path) /
          ("." + target.stem().string() + ".tmp-" + std::to_string(::getpid()) + target.extension().string()))
    .string();
}

int remove_stale_temporaries(const std::string& path)
{
  std::error_code ec;
  int removed = 0;
  for (fs::directory_iterator it(folder_of(path), ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string(), ext = it->path().extension().string();
    const std::size_t mark = name.rfind(".tmp-");
    if (name.size() < 2 || name[0] != '.' || mark == std::string::npos || mark == 0 || !written_extension(ext))
      continue;
    const std::string digits = name.substr(mark + 5, name.size() - ext.size() - mark - 5);
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
      continue;
    const pid_t pid = pid_t(std::stol(digits));
    if (pid == ::getpid() || ::kill(pid, 0) == 0 || errno != ESRCH)
      continue; // ours, or a process still running (or one we may not signal)
    std::error_code rm;
    if (fs::remove(it->path(), rm))
      ++removed;
  }
  return removed;
}

namespace {

//! Puts a written and synced temporary in place of `path`, or stages it
//! in the batch open on this thread; the temporary goes if that fails.
void publish(const std::string& tmp, const std::string& path, const std::shared_ptr<InFlight>& in_flight)
{
  try {
    if (AtomicWriteBatch* batch = AtomicWriteBatch::current())
      batch->stage(tmp, path, in_flight);
    else
      rename_over(tmp, path);
  } catch (...) {
    ::unlink(tmp.c_str());
    throw;
  }
}

} // namespace

void write_bytes_atomically(const std::string& path, const std::vector<std::string_view>& parts)
{
  check_folder(path);
  remove_stale_temporaries(path);
  const std::string tmp = temporary_path(path);
  auto in_flight = std::make_shared<InFlight>(tmp);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0)
    fail(path, errno);
  int error = 0;
  for (const std::string_view& part : parts) {
    std::size_t done = 0;
    while (error == 0 && done < part.size()) {
      const ssize_t n = ::write(fd, part.data() + done, std::min<std::size_t>(part.size() - done, 1u << 30));
      if (n < 0 && errno == EINTR)
        continue;
      if (n <= 0)
        error = n < 0 ? errno : ENOSPC;
      else
        done += std::size_t(n);
    }
  }
  if (error == 0 && ::fsync(fd) != 0)
    error = errno;
  if (::close(fd) != 0 && error == 0)
    error = errno;
  if (error != 0) {
    ::unlink(tmp.c_str());
    fail(path, error);
  }
  publish(tmp, path, in_flight);
}

void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write)
{
  check_folder(path);
  remove_stale_temporaries(path);
  const std::string tmp = temporary_path(path);
  auto in_flight = std::make_shared<InFlight>(tmp);
  try {
    try {
      write(tmp);
    } catch (const IOError&) {
      // A library's writer rarely says why; a full file system is the usual reason.
      struct statvfs fs_info;
      if (::statvfs(folder_of(path).c_str(), &fs_info) == 0 && fs_info.f_bavail == 0)
        fail(path, ENOSPC);
      throw;
    }
    std::error_code ec;
    if (!fs::exists(tmp, ec))
      throw IOError("cannot write '" + path + "'");
    if (const int error = sync_file(tmp))
      fail(path, error);
    publish(tmp, path, in_flight);
  } catch (...) {
    ::unlink(tmp.c_str());
    throw;
  }
}

void remove_temporaries_on_signals()
{
  struct sigaction action = {};
  action.sa_handler = remove_in_flight;
  sigemptyset(&action.sa_mask);
  for (const int sig : {SIGINT, SIGTERM, SIGHUP})
    sigaction(sig, &action, nullptr);
}

} // namespace meshpaint
