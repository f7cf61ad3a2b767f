#include "paint/png_check.h"

#include "core/errors.h"

#include <png.h> // for png_create_read_struct, png_read_info, png_read_row

#include <cerrno>   // for errno
#include <csetjmp>  // for std::jmp_buf, setjmp, std::longjmp
#include <cstdio>   // for std::FILE, std::fopen, std::snprintf
#include <cstring>  // for std::strerror
#include <sys/stat.h> // for stat

namespace meshpaint {
namespace {

// Deflate's best case: 258 bytes in 2 bits, plus a stream's framing.
constexpr std::uint64_t kMaxDeflateRatio = 1032;
constexpr std::uint64_t kFramingBytes = 1024;

//! What libpng's error handler leaves for the code after setjmp.
struct PngFailure
{
  std::jmp_buf jump;
  char message[200] = "";
};

//! libpng's error callback: keeps the message and jumps back (libpng never
//! returns from an error; exceptions must not cross its C frames).
void png_failed(png_structp png, png_const_charp message)
{
  auto* failure = static_cast<PngFailure*>(png_get_error_ptr(png));
  std::snprintf(failure->message, sizeof failure->message, "%s", message);
  std::longjmp(failure->jump, 1);
}

//! Warnings concern damage libpng reads past (an ancillary chunk's CRC):
//! VTK's reader, built on the same libpng, reads past it the same way.
void png_warned(png_structp, png_const_charp)
{
}

} // namespace

std::string png_problem(const std::string& path, std::uint64_t max_samples)
{
  struct stat st{};
  if (::stat(path.c_str(), &st) != 0)
    throw IOError("cannot open '" + path + "': " + std::strerror(errno));
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file)
    throw IOError("cannot open '" + path + "': " + std::strerror(errno));
  const std::uint64_t file_bytes = std::uint64_t(st.st_size);
  PngFailure failure;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &failure, png_failed, png_warned);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    std::fclose(file);
    throw ResourceError("out of memory starting libpng");
  }
  // Everything the error path frees lives outside the frames libpng jumps
  // out of; `row` is written once, after setjmp, hence volatile.
  png_bytep volatile row = nullptr;
  char problem[300] = "";
  if (setjmp(failure.jump) == 0) {
    png_init_io(png, file);
    png_read_info(png, info);
    png_uint_32 width = 0, height = 0;
    int depth = 0, colour = 0;
    png_get_IHDR(png, info, &width, &height, &depth, &colour, nullptr, nullptr, nullptr);
    const std::uint64_t packed_row = (std::uint64_t(width) * png_get_channels(png, info) * std::uint64_t(depth) + 7) / 8;
    if (colour == PNG_COLOR_TYPE_PALETTE)
      png_set_palette_to_rgb(png);
    if (colour == PNG_COLOR_TYPE_GRAY && depth < 8)
      png_set_expand_gray_1_2_4_to_8(png);
    if (png_get_valid(png, info, PNG_INFO_tRNS))
      png_set_tRNS_to_alpha(png);
    const int passes = png_set_interlace_handling(png);
    png_read_update_info(png, info);
    const std::uint64_t samples = std::uint64_t(width) * height * png_get_channels(png, info);
    if (samples > max_samples) {
      std::snprintf(problem, sizeof problem, "%u x %u pixels of %d channels: more than the %llu samples accepted",
                    unsigned(width), unsigned(height), int(png_get_channels(png, info)),
                    (unsigned long long)max_samples);
    } else if (height * (packed_row + 1) > kMaxDeflateRatio * file_bytes + kFramingBytes) {
      std::snprintf(problem, sizeof problem,
                    "declares %u x %u pixels, more than its %llu bytes can hold (truncated or damaged)",
                    unsigned(width), unsigned(height), (unsigned long long)file_bytes);
    } else {
      row = static_cast<png_bytep>(png_malloc(png, png_get_rowbytes(png, info)));
      for (int pass = 0; pass < passes; ++pass)
        for (png_uint_32 y = 0; y < height; ++y)
          png_read_row(png, row, nullptr);
      png_read_end(png, nullptr);
    }
  } else {
    std::snprintf(problem, sizeof problem, "damaged PNG (%s)", failure.message);
  }
  if (row)
    png_free(png, row);
  png_destroy_read_struct(&png, &info, nullptr);
  std::fclose(file);
  return problem;
}

} // namespace meshpaint
