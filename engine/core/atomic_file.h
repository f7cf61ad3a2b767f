// Saving without ever leaving a half-written file where the user's was.
#pragma once

#include <functional>  // for std::function
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

//! Makes SIGINT, SIGTERM and SIGHUP remove the temporaries being written
//! before the process ends as the signal would end it. For programs (the
//! command line), not for libraries loaded into someone else's process.
void remove_temporaries_on_signals();

} // namespace meshpaint
