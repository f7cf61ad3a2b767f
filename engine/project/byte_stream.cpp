#include "project/byte_stream.h"

#include "core/errors.h"

#include <cstring> // for std::memcpy

namespace meshpaint {

void ByteWriter::u32(std::uint32_t v)
{
  for (int k = 0; k < 4; ++k)
    bytes_.push_back((unsigned char)(v >> (8 * k)));
}

void ByteWriter::u64(std::uint64_t v)
{
  for (int k = 0; k < 8; ++k)
    bytes_.push_back((unsigned char)(v >> (8 * k)));
}

void ByteWriter::f32(float v)
{
  std::uint32_t bits;
  std::memcpy(&bits, &v, 4);
  u32(bits);
}

void ByteWriter::string(const std::string& s)
{
  u32(std::uint32_t(s.size()));
  bytes_.insert(bytes_.end(), s.begin(), s.end());
}

void ByteWriter::floats(const float* v, std::size_t count)
{
  bytes_.reserve(bytes_.size() + 4 * count);
  for (std::size_t k = 0; k < count; ++k)
    f32(v[k]);
}

void ByteWriter::begin_section(const std::string& tag)
{
  bytes_.insert(bytes_.end(), tag.begin(), tag.end());
  section_length_at_ = bytes_.size();
  u64(0);
}

void ByteWriter::end_section()
{
  const std::uint64_t length = bytes_.size() - section_length_at_ - 8;
  for (int k = 0; k < 8; ++k)
    bytes_[section_length_at_ + std::size_t(k)] = (unsigned char)(length >> (8 * k));
}

void ByteReader::fail(const std::string& what) const
{
  throw InputError(where_ + ": corrupt project (" + (section_.empty() ? "" : "section " + section_ + ": ") + what + ")");
}

const unsigned char* ByteReader::take(std::size_t n)
{
  const std::size_t end = section_.empty() ? size_ : section_end_;
  if (n > end - pos_)
    fail("data ends early");
  const unsigned char* p = data_ + pos_;
  pos_ += n;
  return p;
}

std::uint32_t ByteReader::u32()
{
  const unsigned char* p = take(4);
  std::uint32_t v = 0;
  for (int k = 0; k < 4; ++k)
    v |= std::uint32_t(p[k]) << (8 * k);
  return v;
}

std::uint64_t ByteReader::u64()
{
  const unsigned char* p = take(8);
  std::uint64_t v = 0;
  for (int k = 0; k < 8; ++k)
    v |= std::uint64_t(p[k]) << (8 * k);
  return v;
}

float ByteReader::f32()
{
  const std::uint32_t bits = u32();
  float v;
  std::memcpy(&v, &bits, 4);
  return v;
}

std::string ByteReader::string()
{
  const std::size_t n = count(1);
  const unsigned char* p = take(n);
  return std::string(reinterpret_cast<const char*>(p), n);
}

std::size_t ByteReader::count(std::size_t item_bytes)
{
  const std::size_t n = u32();
  const std::size_t end = section_.empty() ? size_ : section_end_;
  if (n > (end - pos_) / item_bytes)
    fail("a count of " + std::to_string(n) + " runs past the data");
  return n;
}

std::vector<Float4> ByteReader::texels(std::size_t count)
{
  const std::size_t end = section_.empty() ? size_ : section_end_;
  if (count > (end - pos_) / 16)
    fail(std::to_string(count) + " texels run past the data");
  std::vector<Float4> t(count);
  for (Float4& v : t)
    for (float& x : v)
      x = f32();
  return t;
}

void ByteReader::begin_section(const std::string& tag)
{
  section_.clear();
  const unsigned char* p = take(4);
  if (std::string(reinterpret_cast<const char*>(p), 4) != tag)
    fail(std::string("expected section ") + tag);
  const std::uint64_t length = u64();
  if (length > size_ - pos_)
    fail(std::string("section ") + tag + " runs past the data");
  section_ = tag;
  section_end_ = pos_ + std::size_t(length);
}

void ByteReader::end_section()
{
  if (pos_ != section_end_)
    fail("unexpected bytes at its end");
  section_.clear();
}

} // namespace meshpaint
