#include "paint/spray.h"

#include <algorithm> // for std::max
#include <cmath>  // for std::sqrt, std::cos, std::sin
#include <random> // for std::mt19937, std::seed_seq

namespace meshpaint {

std::vector<std::array<float, 2>> spray_offsets(unsigned seed, std::uint64_t dab, int drops, float radius)
{
  std::seed_seq seq{seed, unsigned(dab), unsigned(dab >> 32)};
  std::mt19937 random(seq);
  const auto unit = [&] { return double(random() >> 8) * (1.0 / 16777216.0); }; // [0, 1), 24 bits
  std::vector<std::array<float, 2>> out(std::size_t(std::max(drops, 0)));
  for (auto& o : out) {
    const double r = radius * std::sqrt(unit()), a = 2.0 * M_PI * unit();
    o = {float(r * std::cos(a)), float(r * std::sin(a))};
  }
  return out;
}

} // namespace meshpaint
