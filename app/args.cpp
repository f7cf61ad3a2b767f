#include "args.h"

#include "core/errors.h"

#include <cerrno>  // for errno
#include <cstdlib> // for std::strtol

namespace meshpaint::cli {

Args::Args(const std::string& command, const std::vector<std::string>& argv, const std::set<std::string>& flags,
           const std::set<std::string>& options)
  : command_(command)
{
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string& a = argv[i];
    if (a.size() < 2 || a[0] != '-') {
      positionals_.push_back(a);
      continue;
    }
    const std::size_t eq = a.find('=');
    const std::string name = a.substr(0, eq);
    if (flags.count(name) && eq == std::string::npos) {
      flags_.insert(name);
    } else if (options.count(name)) {
      if (eq != std::string::npos)
        values_[name] = a.substr(eq + 1);
      else if (i + 1 < argv.size())
        values_[name] = argv[++i];
      else
        throw InputError(name + " needs a value");
      all_values_[name].push_back(values_[name]);
    } else {
      throw InputError("unknown option " + name + " for 'meshpaint " + command_ +
                       "' (see meshpaint help)");
    }
  }
}

void Args::expect_positionals(std::size_t min, std::size_t max, const std::string& usage) const
{
  if (positionals_.size() < min || positionals_.size() > max)
    throw InputError("usage: meshpaint " + command_ + " " + usage);
}

std::vector<std::string> Args::values(const std::string& name) const
{
  const auto it = all_values_.find(name);
  return it == all_values_.end() ? std::vector<std::string>() : it->second;
}

std::string Args::value(const std::string& name, const std::string& fallback) const
{
  const auto it = values_.find(name);
  return it == values_.end() ? fallback : it->second;
}

int Args::integer(const std::string& name, int fallback, int min, int max) const
{
  const auto it = values_.find(name);
  if (it == values_.end())
    return fallback;
  const char* s = it->second.c_str();
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(s, &end, 10);
  if (end == s || *end != '\0' || errno != 0 || v < min || v > max)
    throw InputError(name + " must be an integer from " + std::to_string(min) + " to " +
                     std::to_string(max) + ", not '" + it->second + "'");
  return int(v);
}

} // namespace meshpaint::cli
