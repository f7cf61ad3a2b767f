// libFuzzer target: one mesh file format (MESHPAINT_FUZZ_EXTENSION) through
// the whole import path up to the atlas tables: census, OpenMesh's reader with
// the checks and repairs, statistics, spatial order, OpenSubdiv's first level
// and the patch tables. Input errors are expected; anything else is a finding.
#include "expect_input_errors.h"
#include "fuzz_input_file.h"

#include "atlas/atlas_topology.h"
#include "mesh/base_mesh.h"
#include "mesh/far_refiner.h"
#include "mesh/mesh_stats.h"
#include "mesh/spatial_order.h"

#include <cstddef> // for std::size_t
#include <cstdint> // for std::uint8_t

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace meshpaint;
  fuzz::InputFile file(data, size, MESHPAINT_FUZZ_EXTENSION);
  fuzz::expect_input_errors([&] {
    BaseMesh mesh = load_mesh(file.path());
    compute_stats(mesh);
    BaseMesh ordered = spatially_ordered(mesh);
    auto refiner = make_refiner(ordered);
    refine_uniform(*refiner, 1, true); // as Atlas does: the tables need level 1's edges
    build_atlas_topology(refiner->GetLevel(1));
  });
  return 0;
}
