// Little-endian binary writing and bounds-checked reading, for project files.
#pragma once

#include "core/vec.h"

#include <cstdint> // for std::uint32_t, std::uint64_t
#include <string>  // for std::string
#include <utility> // for std::move
#include <vector>  // for std::vector

namespace meshpaint {

//! Appends values to a byte vector, little-endian whatever the host.
class ByteWriter
{
public:
  void u32(std::uint32_t v);
  void u64(std::uint64_t v);
  void i32(std::int32_t v) { u32(std::uint32_t(v)); }
  void f32(float v);
  //! Length (u32) and bytes.
  void string(const std::string& s);
  void floats(const float* v, std::size_t count);
  void texels(const std::vector<Float4>& t) { floats(t.empty() ? nullptr : t.front().data(), 4 * t.size()); }
  //! Starts a section: its 4-character tag and a length filled in by end_section().
  void begin_section(const std::string& tag);
  void end_section();

  std::vector<unsigned char>& bytes() { return bytes_; }

private:
  std::vector<unsigned char> bytes_;
  std::size_t section_length_at_ = 0;
};

//! Reads what ByteWriter wrote. Every read is checked against the end of
//! the data and throws InputError("WHERE: corrupt project (...)") past it.
class ByteReader
{
public:
  ByteReader(const unsigned char* data, std::size_t size, std::string where)
    : data_(data), size_(size), where_(std::move(where))
  {
  }

  std::uint32_t u32();
  std::uint64_t u64();
  std::int32_t i32() { return std::int32_t(u32()); }
  float f32();
  std::string string();
  //! A count of items of `item_bytes` each that must still fit in the data.
  std::size_t count(std::size_t item_bytes);
  std::vector<Float4> texels(std::size_t count);
  //! Enters a section with this tag; end_section() checks it was read exactly.
  void begin_section(const std::string& tag);
  void end_section();
  bool at_end() const { return pos_ == size_; }

  [[noreturn]] void fail(const std::string& what) const;

private:
  const unsigned char* take(std::size_t n);

  const unsigned char* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
  std::size_t section_end_ = 0;
  std::string section_;
  std::string where_;
};

} // namespace meshpaint
