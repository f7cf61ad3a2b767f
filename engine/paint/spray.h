// Droplet positions of spray paint: reproducible from a seed.
#pragma once

#include <array>   // for std::array
#include <cstdint> // for std::uint64_t
#include <vector>  // for std::vector

namespace meshpaint {

//! `drops` points uniformly distributed in the disc of `radius` around the
//! origin, the same for the same seed and dab on every machine (the raw
//! output of std::mt19937, which the standard fixes, made into floats here).
std::vector<std::array<float, 2>> spray_offsets(unsigned seed, std::uint64_t dab, int drops, float radius);

} // namespace meshpaint
