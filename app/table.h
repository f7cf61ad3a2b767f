// Aligned text tables for command output.
#pragma once

#include <ostream> // for std::ostream
#include <string>  // for std::string
#include <vector>  // for std::vector

namespace meshpaint::cli {

class Table
{
public:
  explicit Table(std::vector<std::string> header) : rows_{std::move(header)} {}
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  //! First column left-aligned, the others right-aligned, a rule under the header.
  void print(std::ostream& os) const;

private:
  std::vector<std::vector<std::string>> rows_;
};

//! 1234567 -> "1,234,567".
std::string grouped(unsigned long long n);

} // namespace meshpaint::cli
