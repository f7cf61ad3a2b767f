#include "table.h"

#include "core/format.h"

#include <algorithm> // for std::max

namespace meshpaint::cli {

void Table::print(std::ostream& os) const
{
  std::vector<std::size_t> width;
  for (const auto& row : rows_)
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (width.size() <= c)
        width.push_back(0);
      width[c] = std::max(width[c], row[c].size());
    }
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    std::string line;
    for (std::size_t c = 0; c < rows_[r].size(); ++c) {
      const std::string& cell = rows_[r][c];
      const std::string pad(width[c] - cell.size(), ' ');
      line += (c == 0 ? cell + pad : "  " + pad + cell);
    }
    os << "  " << line << "\n";
    if (r == 0) {
      std::size_t total = 0;
      for (std::size_t w : width)
        total += w + 2;
      os << "  " << std::string(total - 2, '-') << "\n";
    }
  }
}

std::string grouped(unsigned long long n)
{
  return format_grouped(n);
}

} // namespace meshpaint::cli
