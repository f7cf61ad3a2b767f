#include "core/format.h"

#include "core/errors.h"

#include <cctype>     // for std::tolower, std::isdigit
#include <cerrno>     // for errno, ERANGE
#include <cstdlib>    // for std::strtoull
#include <cstdint>    // for std::uint32_t
#include <cstdio>     // for std::snprintf
#include <filesystem> // for std::filesystem::path

namespace meshpaint {

std::string format_bytes(std::size_t bytes)
{
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
  double v = double(bytes);
  int u = 0;
  while (v >= 1024.0 && u < 4) {
    v /= 1024.0;
    ++u;
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : "%.1f %s", v, units[u]);
  return buf;
}

std::string format_grouped(unsigned long long n)
{
  std::string s = std::to_string(n);
  for (int i = int(s.size()) - 3; i > 0; i -= 3)
    s.insert(std::size_t(i), ",");
  return s;
}

std::string counted(unsigned long long n, const std::string& one, const std::string& many, bool grouped)
{
  return (grouped ? format_grouped(n) : std::to_string(n)) + " " + (n == 1 ? one : many);
}

std::string format_fixed(double value, int digits)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, value);
  return buf;
}

std::string lower_extension(const std::string& path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string format_number(double value)
{
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", value);
  return buf;
}

std::string json_string(const std::string& s)
{
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

bool is_utf8(const std::string& s)
{
  std::size_t k = 0;
  while (k < s.size()) {
    const auto c = static_cast<unsigned char>(s[k]);
    const int more = c < 0x80 ? 0 : (c & 0xE0) == 0xC0 ? 1 : (c & 0xF0) == 0xE0 ? 2 : (c & 0xF8) == 0xF0 ? 3 : -1;
    if (more < 0 || s.size() - k <= std::size_t(more))
      return false;
    std::uint32_t code = more == 0 ? c : c & (0x3F >> more);
    for (int m = 1; m <= more; ++m) {
      const auto b = static_cast<unsigned char>(s[k + std::size_t(m)]);
      if ((b & 0xC0) != 0x80)
        return false;
      code = (code << 6) | (b & 0x3F);
    }
    static const std::uint32_t smallest[] = {0, 0x80, 0x800, 0x10000};
    if (code < smallest[more] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF))
      return false;
    k += std::size_t(more) + 1;
  }
  return true;
}

std::string excerpt(const std::string& s, std::size_t limit)
{
  const bool utf8 = is_utf8(s); // else every byte beyond ASCII is shown as \xNN
  std::size_t cut = s.size();
  if (cut > limit) {
    cut = limit;
    while (utf8 && cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80)
      --cut; // not inside a UTF-8 sequence
  }
  std::string out;
  for (std::size_t k = 0; k < cut; ++k) {
    const auto c = static_cast<unsigned char>(s[k]);
    if (c < 0x20 || c == 0x7f || (c >= 0x80 && !utf8)) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else {
      out += char(c);
    }
  }
  if (cut < s.size())
    out += "... (" + std::to_string(s.size()) + " bytes)";
  return out;
}

int index_of_name(const std::vector<std::string>& names, const std::string& name, const std::string& what)
{
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name)
      return int(k);
  std::string all;
  for (const std::string& n : names)
    all += (all.empty() ? "" : ", ") + n;
  throw InputError(what + " must be one of " + all + ", not '" + excerpt(name) + "'");
}

std::uint64_t parse_memory_size(const std::string& variable, const std::string& text)
{
  const std::string problem = variable + " must be a size such as 512M or 2G, not '" + text + "'";
  // strtoull would take a sign ("-1" as the largest number) or blanks.
  if (text.empty() || !std::isdigit(static_cast<unsigned char>(text[0])))
    throw InputError(problem);
  char* end = nullptr;
  errno = 0;
  const unsigned long long n = std::strtoull(text.c_str(), &end, 10);
  int shift = 0;
  if (*end && !end[1])
    shift = *end == 'K' ? 10 : *end == 'M' ? 20 : *end == 'G' ? 30 : -1;
  else if (*end)
    shift = -1;
  if (shift < 0 || n == 0 || errno == ERANGE || n > (~0ull >> shift))
    throw InputError(problem);
  return std::uint64_t(n) << shift;
}

} // namespace meshpaint
