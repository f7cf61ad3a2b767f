#include "core/format.h"

#include "core/errors.h"

#include <cctype>     // for std::tolower
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

int index_of_name(const std::vector<std::string>& names, const std::string& name, const std::string& what)
{
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name)
      return int(k);
  std::string all;
  for (const std::string& n : names)
    all += (all.empty() ? "" : ", ") + n;
  throw InputError(what + " must be one of " + all + ", not '" + name + "'");
}

} // namespace meshpaint
