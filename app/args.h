// Command-line arguments of one `meshpaint` command.
#pragma once

#include <map>    // for std::map
#include <set>    // for std::set
#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint::cli {

//! Positionals and --options; "--name value", "--name=value" and flags.
class Args
{
public:
  //! `flags` take no value; `options` take one. Anything else starting with
  //! "-" is an error naming the command.
  //! \throw InputError for unknown or incomplete options.
  Args(const std::string& command, const std::vector<std::string>& argv, const std::set<std::string>& flags,
       const std::set<std::string>& options);

  const std::string& command() const { return command_; }
  const std::vector<std::string>& positionals() const { return positionals_; }
  //! \throw InputError unless there are between min and max positionals.
  void expect_positionals(std::size_t min, std::size_t max, const std::string& usage) const;

  bool flag(const std::string& name) const { return flags_.count(name) > 0; }
  bool has(const std::string& name) const { return values_.count(name) > 0; }
  std::string value(const std::string& name, const std::string& fallback = "") const;
  //! Every value of an option given repeatedly, in order (value() keeps the last).
  std::vector<std::string> values(const std::string& name) const;
  //! \throw InputError when the value is not an integer in [min, max].
  int integer(const std::string& name, int fallback, int min, int max) const;

private:
  std::string command_;
  std::vector<std::string> positionals_;
  std::set<std::string> flags_;
  std::map<std::string, std::string> values_;
  std::map<std::string, std::vector<std::string>> all_values_;
};

} // namespace meshpaint::cli
