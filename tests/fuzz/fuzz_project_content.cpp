// libFuzzer target: a project's content past its checksums. The input is a
// decompressed payload (the sections of docs/project-format.md); the target
// compresses it and writes the header with correct sizes and CRC-32s, so
// every input reaches the section reader and the content checks (finite
// values in range, the base mesh, the labels) that fuzz_project's mutations
// rarely get past the checksums to. Input errors are expected; anything
// else is a finding.
#include "expect_input_errors.h"
#include "fuzz_input_file.h"

#include "project/project.h"

#include <zlib.h> // for compress2, compressBound, crc32

#include <cstddef> // for std::size_t
#include <cstdint> // for std::uint8_t, std::uint32_t, std::uint64_t
#include <string>  // for std::string
#include <vector>  // for std::vector

namespace {

void put(std::string& out, std::uint64_t v, int bytes)
{
  for (int k = 0; k < bytes; ++k)
    out += char((v >> (8 * k)) & 0xff);
}

std::uint32_t crc_of(const void* data, std::size_t size)
{
  return std::uint32_t(crc32(crc32(0L, Z_NULL, 0), static_cast<const Bytef*>(data), uInt(size)));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace meshpaint;
  std::vector<Bytef> packed(compressBound(uLong(size)));
  uLongf packed_size = uLongf(packed.size());
  if (compress2(packed.data(), &packed_size, data, uLong(size), 1) != Z_OK)
    return 0;
  std::string file_bytes("\x89MPROJ\r\n", 8);
  put(file_bytes, kProjectVersion, 4);
  put(file_bytes, 40, 4);
  put(file_bytes, packed_size, 8);
  put(file_bytes, size, 8);
  put(file_bytes, crc_of(packed.data(), packed_size), 4);
  put(file_bytes, crc_of(file_bytes.data(), file_bytes.size()), 4);
  file_bytes.append(reinterpret_cast<const char*>(packed.data()), packed_size);
  fuzz::InputFile file(reinterpret_cast<const std::uint8_t*>(file_bytes.data()), file_bytes.size(), ".meshpaint");
  fuzz::expect_input_errors([&] { load_project(file.path()); });
  return 0;
}
