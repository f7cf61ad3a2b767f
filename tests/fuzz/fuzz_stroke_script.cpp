// libFuzzer target: the stroke-script parser, then the dab positions of every
// stroke it accepts, and the round trip through stroke_script_json(): what
// was accepted is written, read back and written again to the same text.
// Input errors are expected; anything else is a finding.
#include "expect_input_errors.h"

#include "paint/stroke.h"

#include <cstddef> // for std::size_t
#include <cstdint> // for std::uint8_t
#include <cstdio>  // for std::fprintf
#include <cstdlib> // for std::abort
#include <string>  // for std::string

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace meshpaint;
  fuzz::expect_input_errors([&] {
    StrokeScript script = parse_stroke_script(std::string(reinterpret_cast<const char*>(data), size));
    for (const Stroke& stroke : script.strokes)
      stroke_samples(stroke);
    const std::string written = stroke_script_json(script);
    if (stroke_script_json(parse_stroke_script(written)) != written) {
      std::fprintf(stderr, "the script does not read back as written:\n%s\n", written.c_str());
      std::abort();
    }
  });
  return 0;
}
