// libFuzzer target: the PNG check that runs before VTK's reader decodes a
// pattern or stamp (libpng's header, the size budget, every row, the chunks
// to IEND). A verdict either way is fine; a crash, a sanitizer report, a
// leak or more memory than the budget is a finding.
#include "expect_input_errors.h"
#include "fuzz_input_file.h"

#include "paint/png_check.h"
#include "paint/raster.h"

#include <cstddef> // for std::size_t
#include <cstdint> // for std::uint8_t

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace meshpaint;
  fuzz::InputFile file(data, size, ".png");
  fuzz::expect_input_errors([&] { (void)png_problem(file.path(), kMaxRasterSamples); });
  return 0;
}
