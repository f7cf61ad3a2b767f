// An exclusive lock on a file that is replaced by renames, as every saved
// file is: concurrent continuations of one project take turns.
#pragma once

#include <functional> // for std::function
#include <string>     // for std::string

namespace meshpaint {

//! Holds an exclusive advisory lock (flock) on the file at `path` while it
//! lives. A file replaced while waiting (a rename over it) is locked anew,
//! so the holder always has the file now at `path`. Nothing is locked when
//! `path` does not exist. Processes that end release their locks, however
//! they end.
class FileLock
{
public:
  //! Waits for the lock; calls `waiting` once if another process holds it.
  //! \throw IOError when the file exists but cannot be opened or locked.
  FileLock(const std::string& path, const std::function<void()>& waiting);
  ~FileLock();
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

  //! Whether a file was there to lock.
  bool held() const { return fd_ >= 0; }

private:
  int fd_ = -1;
};

} // namespace meshpaint
