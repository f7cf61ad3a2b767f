// Human-readable numbers for messages and tables.
#pragma once

#include <cstddef> // for std::size_t
#include <string>  // for std::string
#include <vector>  // for std::vector

namespace meshpaint {

//! "1.5 GiB", "320 MiB", "12 KiB", "512 B".
std::string format_bytes(std::size_t bytes);

//! Fixed-point with `digits` decimals.
std::string format_fixed(double value, int digits);

//! ".obj" for "Mesh.OBJ": the extension, lower case, with its dot.
std::string lower_extension(const std::string& path);

//! `s` as a JSON string literal, quotes included.
std::string json_string(const std::string& s);

//! Index of `name` in `names`.
//! \throw InputError "`what` must be one of a, b, c, not 'name'".
int index_of_name(const std::vector<std::string>& names, const std::string& name, const std::string& what);

} // namespace meshpaint
