// Saving without ever leaving a half-written file where the user's was.
#pragma once

#include <functional> // for std::function
#include <string>     // for std::string

namespace meshpaint {

//! Calls `write` with a temporary path in the destination's directory (same
//! extension, so format detection by extension works), then renames it over
//! `path`. On any failure the temporary is removed and `path` is untouched.
//! \throw IOError when the directory is not writable or the rename fails.
void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write);

} // namespace meshpaint
