// Saving without ever leaving a half-written file where the user's was.
#pragma once

#include <functional>  // for std::function
#include <memory>      // for std::shared_ptr
#include <string>      // for std::string
#include <string_view> // for std::string_view
#include <vector>      // for std::vector

namespace meshpaint {

//! Writes `parts`, one after another, to `path` atomically and durably: into
//! a temporary `.STEM.tmp-PID.EXT` in the target's folder, every byte checked,
//! `fsync`ed, renamed over `path`, and the folder `fsync`ed. On any failure
//! the temporary is removed and `path` is untouched. Temporaries that runs
//! killed in that folder left behind are removed first
//! (remove_stale_temporaries()).
//! \throw StorageError when the file system is full or fails (no space,
//! quota, I/O error); IOError when the folder is missing or not writable.
void write_bytes_atomically(const std::string& path, const std::vector<std::string_view>& parts);

//! For writers that can only write to a path: calls `write` with the
//! temporary's path, then syncs and renames it as write_bytes_atomically()
//! does. A writer that throws or leaves no file leaves `path` untouched;
//! when it fails on a full file system the error becomes a StorageError.
//! Prefer write_bytes_atomically(): a library writing to a path may not
//! report a short write.
//! \throw StorageError, IOError as write_bytes_atomically().
void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write);

//! The temporary write_bytes_atomically() uses for `path` in this process.
std::string temporary_path(const std::string& path);

//! Removes, in the folder of `path`, the temporaries of write_bytes_atomically()
//! (`.NAME.tmp-PID.EXT`) whose process no longer runs on this machine; returns
//! how many it removed. Errors are ignored: a temporary it cannot remove stays.
int remove_stale_temporaries(const std::string& path);

//! Makes the atomic writes of one piece of work (an export of several
//! files) land together or not at all: while a batch lives on this thread,
//! write_bytes_atomically() and write_atomically() leave their temporaries
//! written and synced but not renamed. commit() renames them all into place;
//! a batch that ends without commit() (an error, a cancelled export) removes
//! them, so the previous files stay whole and no new one appears. A batch
//! made while another lives on the thread joins it: the outermost commits.
class AtomicWriteBatch
{
public:
  AtomicWriteBatch();
  ~AtomicWriteBatch();
  AtomicWriteBatch(const AtomicWriteBatch&) = delete;
  AtomicWriteBatch& operator=(const AtomicWriteBatch&) = delete;
  //! Renames the temporaries over their paths (the outermost batch only).
  //! \throw IOError when a rename fails (the temporaries not yet renamed
  //! are removed).
  void commit();
  //! `dir`, made for this batch's files, goes again when the batch ends
  //! without commit() (if nothing else was put in it meanwhile).
  void made_directory(const std::string& dir);
  //! The temporaries written and not yet renamed.
  std::vector<std::string> temporaries() const;

  //! Keeps `tmp`, written for `path`, until commit() (the outermost batch);
  //! `slot` holds it for the signal handler meanwhile.
  void stage(const std::string& tmp, const std::string& path, std::shared_ptr<void> slot);
  //! The batch writes join on this thread now, null for none.
  static AtomicWriteBatch* current();

private:
  struct Staged
  {
    std::string tmp, path;
    std::shared_ptr<void> slot;
  };
  AtomicWriteBatch* outer_;
  std::vector<Staged> staged_;
  std::vector<std::string> made_; // deepest first
  bool committed_ = false;
};

//! Makes SIGINT, SIGTERM and SIGHUP remove the temporaries being written
//! before the process ends as the signal would end it. For programs (the
//! command line), not for libraries loaded into someone else's process.
void remove_temporaries_on_signals();

} // namespace meshpaint
