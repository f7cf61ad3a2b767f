// libFuzzer target: the project loader (header, version, checksums, the
// shape of every section). Input errors are expected; anything else is a
// finding. Inputs are mostly refused at a checksum; the seeds are valid
// projects, so that the mutations that keep the checksums (and those of
// the header alone) reach the sections.
#include "expect_input_errors.h"
#include "fuzz_input_file.h"

#include "project/project.h"

#include <cstddef> // for std::size_t
#include <cstdint> // for std::uint8_t

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace meshpaint;
  fuzz::InputFile file(data, size, ".meshpaint");
  fuzz::expect_input_errors([&] { load_project(file.path()); });
  return 0;
}
