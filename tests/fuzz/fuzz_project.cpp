// libFuzzer target: the project loader (header, version, checksums, the
// shape of every section). Input errors are expected; anything else is a
// finding. Inputs are mostly refused at a checksum; the seeds are valid
// projects, so that the mutations that keep the checksums (and those of
// the header alone) reach the sections.
#include "fuzz_input_file.h"

#include "core/errors.h"
#include "project/project.h"

#include <cstddef> // for std::size_t
#include <cstdint> // for std::uint8_t
#include <cstdio>  // for std::fprintf
#include <cstdlib> // for std::abort

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace meshpaint;
  fuzz::InputFile file(data, size, ".meshpaint");
  try {
    load_project(file.path());
  } catch (const InputError&) {
  } catch (const IOError&) {
  } catch (const std::exception& e) { // any other exception is a finding: say which
    std::fprintf(stderr, "unexpected exception: %s\n", e.what());
    std::abort();
  }
  return 0;
}
