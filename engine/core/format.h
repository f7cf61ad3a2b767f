// Human-readable numbers for messages and tables.
#pragma once

#include <cstddef> // for std::size_t
#include <cstdint> // for std::uint64_t
#include <string>  // for std::string
#include <vector>  // for std::vector

namespace meshpaint {

//! "1.5 GiB", "320 MiB", "12 KiB", "512 B".
std::string format_bytes(std::size_t bytes);

//! A number as printf's %g writes it: "3e+38", "0.5", "nan".
std::string format_number(double value);

//! "1,234,567": the digits in groups of three.
std::string format_grouped(unsigned long long n);

//! "1 face", "2 faces": the count and its noun in agreement (`one` for 1,
//! `many` otherwise); with `grouped`, the digits as format_grouped() writes
//! them.
std::string counted(unsigned long long n, const std::string& one, const std::string& many, bool grouped = false);

//! Fixed-point with `digits` decimals.
std::string format_fixed(double value, int digits);

//! ".obj" for "Mesh.OBJ": the extension, lower case, with its dot.
std::string lower_extension(const std::string& path);

//! Length of a parser's whole message kept by excerpt().
constexpr std::size_t kMessageChars = 300;

//! `s` as a JSON string literal, quotes included.
std::string json_string(const std::string& s);

//! Whether `s` is well-formed UTF-8 (no overlong forms, surrogates or
//! code points beyond U+10FFFF).
bool is_utf8(const std::string& s);

//! `s` for quoting in a one-line message: control bytes (and, when `s` is
//! not UTF-8, every byte beyond ASCII) as \xNN, and
//! cut after about `limit` bytes (on a UTF-8 boundary) with
//! "... (N bytes)" when longer, so a huge name cannot flood the terminal.
std::string excerpt(const std::string& s, std::size_t limit = 60);

//! Index of `name` in `names`.
//! \throw InputError "`what` must be one of a, b, c, not 'name'".
int index_of_name(const std::vector<std::string>& names, const std::string& name, const std::string& what);

//! A memory size in bytes as the environment gives it: a number, optionally
//! followed by K, M or G (binary units), more than 0.
//! \throw InputError "`variable` must be a size such as 512M or 2G, not 'text'".
std::uint64_t parse_memory_size(const std::string& variable, const std::string& text);

} // namespace meshpaint
