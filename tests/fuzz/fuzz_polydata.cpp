// libFuzzer target: transfer's VTK reading of a scan or mesh given as VTK
// polydata (MESHPAINT_FUZZ_EXTENSION .vtp or .vtk): the size checks against
// the file's length, VTK's XML or legacy reader with its messages kept, the
// checks of its output, then the import steps. Built only where VTK is found;
// input errors are expected, anything else is a finding.
#include "expect_input_errors.h"
#include "fuzz_input_file.h"

#include "PolyDataFiles.h"

#include <cstddef> // for std::size_t
#include <cstdint> // for std::uint8_t

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace meshpaint;
  fuzz::InputFile file(data, size, MESHPAINT_FUZZ_EXTENSION);
  fuzz::expect_input_errors([&] { load_polydata_mesh(file.path()); });
  return 0;
}
