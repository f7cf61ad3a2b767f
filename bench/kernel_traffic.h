// What each kernel family of the atlas reads and writes in a step over every
// patch, for the achieved-bandwidth columns of the benchmarks: the bytes a
// family has to move (each texel it needs once, 16 bytes a float4 texel),
// set beside its device time from a KernelClock.
#pragma once

#include "atlas/atlas_evaluator.h"
#include "atlas/atlas_topology.h"
#include "atlas/patch_layout.h"
#include "table.h"

#include <map>    // for std::map
#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint::cli {

//! One family's share of a step: its kernels (any of them may be absent
//! from a run) and the bytes it reads and writes.
struct FamilyTraffic
{
  std::string family;               //!< "subdivide edges", "limit tiles", ...
  std::vector<std::string> kernels; //!< kernel names whose times add up to the family's
  double bytes = 0;                 //!< read + written in the step(s)
};

//! The families of Catmull-Clark steps from level `from` to `to` over every
//! patch, bytes summed over the steps, as `evaluator` runs them.
std::vector<FamilyTraffic> subdivide_traffic(const AtlasTopology& topology, int from, int to,
                                             const AtlasEvaluator& evaluator);
//! The families of the limit (positions and normals) of level `level` over
//! every patch; the bounds' kernel, where it runs, reads the positions once.
std::vector<FamilyTraffic> limit_traffic(const AtlasTopology& topology, int level);

//! A family's time and bandwidth from device milliseconds per kernel
//! (KernelClock::take(), summed over `runs` runs).
struct FamilyRate
{
  std::string family;
  double ms = 0;   //!< device time per run
  double gbps = 0; //!< bytes / ms
};
std::vector<FamilyRate> family_rates(const std::vector<FamilyTraffic>& traffic,
                                     const std::map<std::string, double>& kernel_ms, int runs);

//! The rates as a table: family, device ms, GB/s, share of `copy_gbps`.
void add_family_rows(Table& table, const std::string& what, const std::vector<FamilyRate>& rates, double copy_gbps);
//! The rates as a JSON list of {"family","ms","gb_per_s"}.
std::string family_json(const std::vector<FamilyRate>& rates);

} // namespace meshpaint::cli
