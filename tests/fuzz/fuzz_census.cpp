// libFuzzer target: the file census alone, the first byte choosing the format
// it reads the rest as (the census runs before OpenMesh and must survive any
// bytes, including lines and headers that claim huge counts).
#include "fuzz_input_file.h"

#include "mesh/base_mesh.h"
#include "mesh/file_census.h"

#include <cstddef> // for std::size_t
#include <cstdint> // for std::uint8_t

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace meshpaint;
  if (size == 0)
    return 0;
  const auto& extensions = readable_mesh_extensions();
  const std::string& extension = extensions[data[0] % extensions.size()];
  fuzz::InputFile file(data + 1, size - 1, extension);
  take_census(file.path(), extension);
  return 0;
}
