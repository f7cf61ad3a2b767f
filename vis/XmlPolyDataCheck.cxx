#include "XmlPolyDataCheck.h"

#include "core/errors.h" // for meshpaint::InputError
#include "core/format.h" // for meshpaint::excerpt

#include <vtkBase64Utilities.h>     // for vtkBase64Utilities::DecodeSafely
#include <vtkDataCompressor.h>      // for vtkDataCompressor
#include <vtkLZ4DataCompressor.h>   // for vtkLZ4DataCompressor
#include <vtkLZMADataCompressor.h>  // for vtkLZMADataCompressor
#include <vtkSmartPointer.h>        // for vtkSmartPointer
#include <vtkXMLDataElement.h>      // for vtkXMLDataElement
#include <vtkXMLDataParser.h>       // for vtkXMLDataParser
#include <vtkZLibDataCompressor.h>  // for vtkZLibDataCompressor

#include <algorithm>  // for std::min, std::reverse
#include <cmath>      // for std::floor
#include <cstdint>    // for std::uint64_t, std::int64_t
#include <cstdio>     // for std::snprintf
#include <cstring>    // for std::memcpy, std::strcmp
#include <filesystem> // for std::filesystem::file_size
#include <fstream>    // for std::ifstream
#include <map>        // for std::map
#include <optional>   // for std::optional
#include <vector>     // for std::vector

namespace meshpaint {
namespace {

//! A compressor VTK's XML files name, and what it can pack into one byte at
//! best: deflate 1032, LZ4 255; LZMA packs long runs far tighter (6500 to 1
//! for 16 MiB of zeros), so it gets a wider bound. Each block may add its
//! framing on top.
struct Packing
{
  vtkSmartPointer<vtkDataCompressor> compressor;
  const char* name;
  double ratio;
};
constexpr double kBlockFramingBytes = 64;

std::optional<Packing> packing_of(const std::string& compressor)
{
  if (compressor == "vtkZLibDataCompressor")
    return Packing{vtkSmartPointer<vtkZLibDataCompressor>::New(), "zlib", 1032};
  if (compressor == "vtkLZ4DataCompressor")
    return Packing{vtkSmartPointer<vtkLZ4DataCompressor>::New(), "LZ4", 256};
  if (compressor == "vtkLZMADataCompressor")
    return Packing{vtkSmartPointer<vtkLZMADataCompressor>::New(), "LZMA", 16384};
  return std::nullopt;
}

//! The file, read where asked (a .vtp may be too large to hold twice).
class FileBytes
{
public:
  explicit FileBytes(const std::string& path) : in_(path, std::ios::binary)
  {
    std::error_code ec;
    size_ = std::filesystem::file_size(path, ec);
  }
  std::uint64_t size() const { return size_; }

  //! Bytes [at, at + n), fewer where the file ends.
  std::string read(std::uint64_t at, std::uint64_t n)
  {
    if (at >= size_)
      return {};
    std::string bytes(std::size_t(std::min(n, size_ - at)), '\0');
    in_.clear();
    in_.seekg(std::streamoff(at));
    in_.read(&bytes[0], std::streamsize(bytes.size()));
    bytes.resize(std::size_t(in_.gcount()));
    return bytes;
  }

  //! Where the run of characters `keep` accepts, from `at`, ends.
  template <class Keep> std::uint64_t run_end(std::uint64_t at, Keep keep)
  {
    for (int c; (c = byte(at)) >= 0 && keep(char(c));)
      ++at;
    return at;
  }

private:
  //! The byte at `at`, -1 past the end; scans read through a window.
  int byte(std::uint64_t at)
  {
    if (at >= size_)
      return -1;
    if (at < window_at_ || at - window_at_ >= window_.size()) {
      window_ = read(at, 1 << 16);
      window_at_ = at;
      if (window_.empty())
        return -1;
    }
    return static_cast<unsigned char>(window_[std::size_t(at - window_at_)]);
  }

  std::ifstream in_;
  std::uint64_t size_ = 0;
  std::string window_;
  std::uint64_t window_at_ = 0;
};

bool is_base64(char c)
{
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' || c == '/' ||
         c == '=';
}

bool is_space(char c)
{
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

//! An array's binary bytes as VTK's input streams see them: raw from a file
//! position, or base64 from one (each 4 characters 3 bytes, a stream of its
//! own starting at each header and at the compressed data).
class Stream
{
public:
  Stream(FileBytes& file, std::uint64_t start, bool base64, std::uint64_t end)
    : file_(&file), start_(start), base64_(base64), end_(std::max(start, end))
  {
  }

  //! The bytes the file holds from the start on.
  std::uint64_t size()
  {
    if (!base64_)
      return end_ - start_;
    const std::uint64_t quads = (end_ - start_) / 4;
    if (quads == 0)
      return 0;
    const std::string last = file_->read(start_ + (quads - 1) * 4, 4);
    const std::uint64_t pads = (last.size() > 3 && last[3] == '=') + (last.size() > 2 && last[2] == '=');
    return quads * 3 - pads;
  }

  //! Bytes [from, from + n) of the stream, fewer where it ends.
  std::string bytes(std::uint64_t from, std::uint64_t n)
  {
    if (!base64_)
      return file_->read(start_ + from, std::min(n, from < size() ? size() - from : 0));
    const std::uint64_t first = from / 3, after = (from + n + 2) / 3;
    const std::uint64_t chars_end = std::min(end_, start_ + after * 4);
    if (start_ + first * 4 >= chars_end)
      return {};
    const std::string text = file_->read(start_ + first * 4, chars_end - (start_ + first * 4));
    std::string decoded(text.size(), '\0');
    const std::size_t got = vtkBase64Utilities::DecodeSafely(reinterpret_cast<const unsigned char*>(text.data()),
                                                             text.size(), reinterpret_cast<unsigned char*>(&decoded[0]),
                                                             decoded.size());
    decoded.resize(got);
    const std::uint64_t skip = from - first * 3;
    return skip >= decoded.size() ? std::string() : decoded.substr(std::size_t(skip), std::size_t(n));
  }

  //! The stream that starts after `n` bytes of this one, as VTK starts one
  //! after a compression header.
  Stream after(std::uint64_t n) const
  {
    return Stream(*file_, start_ + (base64_ ? (n + 2) / 3 * 4 : n), base64_, end_);
  }

private:
  FileBytes* file_;
  std::uint64_t start_;
  bool base64_;
  std::uint64_t end_;
};

//! Bytes of VTK's word types; 0 for types whose bytes are no fixed count
//! per value (String, Bit) or that VTK's reader refuses itself.
int word_bytes(const std::string& type)
{
  static const std::map<std::string, int> sizes{
    {"Int8", 1},  {"UInt8", 1},  {"Char", 1},   {"Int16", 2},   {"UInt16", 2},  {"Int32", 4},
    {"UInt32", 4}, {"Int64", 8}, {"UInt64", 8}, {"Float32", 4}, {"Float64", 8}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

//! A value of `type` from its bytes in the file's byte order.
double value_of(std::string bytes, const std::string& type, bool big_endian)
{
  if (big_endian)
    std::reverse(bytes.begin(), bytes.end());
  auto as = [&](auto v) {
    std::memcpy(&v, bytes.data(), sizeof v);
    return double(v);
  };
  if (type == "Int8" || type == "Char")
    return as(std::int8_t());
  if (type == "UInt8")
    return as(std::uint8_t());
  if (type == "Int16")
    return as(std::int16_t());
  if (type == "UInt16")
    return as(std::uint16_t());
  if (type == "Int32")
    return as(std::int32_t());
  if (type == "UInt32")
    return as(std::uint32_t());
  if (type == "Int64")
    return as(std::int64_t());
  if (type == "UInt64")
    return as(std::uint64_t());
  if (type == "Float32")
    return as(float());
  return as(double());
}

std::string number_text(double v)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string attribute(vtkXMLDataElement* e, const char* name)
{
  const char* v = e->GetAttribute(name);
  return v ? v : "";
}

//! What the file says about all its arrays.
struct FileLayout
{
  std::string where; //!< "'path': "
  FileBytes file;
  bool big_endian = false;
  std::uint64_t header_bytes = 4;
  std::optional<Packing> packing;
  double budget = 0;
  bool has_appended = false;
  bool appended_raw = false;
  std::uint64_t appended_at = 0, appended_end = 0;

  explicit FileLayout(const std::string& path) : where("'" + path + "': "), file(path) {}
};

//! One array as VTK's reader would read it.
class ArrayCheck
{
public:
  ArrayCheck(FileLayout& f, vtkXMLDataElement* e, const std::string& label)
    : f_(f), e_(e), type_(attribute(e, "type")), word_(word_bytes(type_))
  {
    const std::string name = attribute(e, "Name");
    label_ = label + (name.empty() ? std::string(" array") : " array '" + excerpt(name, 40) + "'");
  }

  //! Checks that the array holds `expected` values, as `why` says (e.g. "64
  //! polys"; unknown: only what the file and the budget allow); with
  //! `last`, returns its last value.
  std::optional<double> check(std::optional<std::uint64_t> expected, const std::string& why, bool last = false)
  {
    why_ = why;
    // No fixed bytes per value: VTK still allocates every value first, so
    // a string needs a byte (its end) at least, a bit an eighth.
    std::optional<std::uint64_t> at_least;
    if (word_ == 0 && expected && (type_ == "String" || type_ == "Bit"))
      at_least = type_ == "String" ? *expected : (*expected + 7) / 8;
    if (word_ == 0)
      expected.reset();
    const std::string format = attribute(e_, "format");
    if (format == "ascii")
      return ascii(expected, last, type_ == "String" ? at_least : std::nullopt);
    if (format != "binary" && format != "appended")
      fail("has format '" + excerpt(format, 20) + "', not ascii, binary or appended");
    Stream s = stream(format == "appended");
    Located bytes = f_.packing ? compressed(s, expected) : plain(s, expected);
    if (at_least && bytes.total < *at_least)
      fail("holds " + std::to_string(bytes.total) + " bytes, but " + why_ + " of type " + type_ + " need " +
           std::to_string(*at_least) + " at least");
    if (!last || word_ == 0 || bytes.total < std::uint64_t(word_))
      return std::nullopt;
    return value_of(read_at(bytes, bytes.total - std::uint64_t(word_)), type_, f_.big_endian);
  }

private:
  //! Where the array's bytes are: its stream, and the blocks or the plain
  //! data in it.
  struct Located
  {
    Stream data;
    std::uint64_t total = 0;                 //!< uncompressed bytes
    std::uint64_t block = 0, last_block = 0; //!< compressed: block sizes
    std::vector<std::uint64_t> packed;       //!< compressed: each block's bytes
  };

  [[noreturn]] void fail(const std::string& what) const
  {
    throw InputError(f_.where + label_ + " " + what);
  }

  std::string declared(std::uint64_t values) const
  {
    return why_ + ", " + std::to_string(word_) + "-byte values, need " + std::to_string(values * std::uint64_t(word_));
  }

  //! The inline data start as VTK's parser finds it: after the first '>'
  //! from the element's tag, and the spaces after that.
  std::uint64_t inline_start()
  {
    const std::uint64_t tag = std::uint64_t(std::max<vtkTypeInt64>(0, e_->GetXMLByteIndex()));
    const std::uint64_t close = f_.file.run_end(tag, [](char c) { return c != '>'; });
    return f_.file.run_end(close + 1, is_space);
  }

  Stream stream(bool appended)
  {
    if (!appended) {
      const std::uint64_t start = inline_start();
      return Stream(f_.file, start, true, f_.file.run_end(start, is_base64));
    }
    if (!f_.has_appended)
      fail("is appended, but the file has no AppendedData");
    const std::string offset = attribute(e_, "offset");
    char* end = nullptr;
    const unsigned long long at = std::strtoull(offset.c_str(), &end, 10);
    while (*end && is_space(*end))
      ++end;
    if (offset.empty() || offset.find('-') != std::string::npos || *end != '\0' || at > f_.file.size())
      fail("has offset '" + excerpt(offset, 20) + "', not a position in the file's appended data");
    return Stream(f_.file, f_.appended_at + at, !f_.appended_raw, f_.appended_raw ? f_.file.size() : f_.appended_end);
  }

  std::uint64_t header_word(const std::string& bytes, std::size_t k) const
  {
    std::string w = bytes.substr(k * f_.header_bytes, f_.header_bytes);
    if (f_.big_endian)
      std::reverse(w.begin(), w.end());
    std::uint64_t v = 0;
    if (f_.header_bytes == 4) {
      std::uint32_t v32 = 0;
      std::memcpy(&v32, w.data(), 4);
      v = v32;
    } else {
      std::memcpy(&v, w.data(), 8);
    }
    return v;
  }

  void check_total(std::uint64_t total, std::optional<std::uint64_t> expected, const std::string& stated)
  {
    if (expected && total != *expected * std::uint64_t(word_))
      fail(stated + " " + std::to_string(total) + " bytes, but " + declared(*expected));
    if (double(total) > f_.budget)
      fail(stated + " " + std::to_string(total) + " bytes, more than a file of this size can describe");
  }

  Located plain(Stream& s, std::optional<std::uint64_t> expected)
  {
    const std::string header = s.bytes(0, f_.header_bytes);
    if (header.size() < f_.header_bytes)
      fail("ends before its header");
    const std::uint64_t total = header_word(header, 0);
    check_total(total, expected, "states");
    const std::uint64_t held = s.size() - f_.header_bytes;
    if (total > held)
      fail("states " + std::to_string(total) + " bytes, but the file holds only " + std::to_string(held));
    return Located{s, total, 0, 0, {}};
  }

  Located compressed(Stream& s, std::optional<std::uint64_t> expected)
  {
    const std::uint64_t hb = f_.header_bytes;
    const std::string head = s.bytes(0, 3 * hb);
    if (head.size() < 3 * hb)
      fail("ends before its compression header");
    const std::uint64_t blocks = header_word(head, 0), block = header_word(head, 1), last = header_word(head, 2);
    const std::uint64_t held = s.size();
    if (blocks > (held - 3 * hb) / hb)
      fail("lists " + std::to_string(blocks) + " compressed blocks, more than the file holds");
    if (double(block) > f_.budget)
      fail("has compressed blocks of " + std::to_string(block) + " bytes, more than a file of this size can describe");
    if (last > block)
      fail("has a last block of " + std::to_string(last) + " bytes in blocks of " + std::to_string(block));
    if (blocks > 0 && block == 0)
      fail("lists " + std::to_string(blocks) + " compressed blocks of 0 bytes");
    if (blocks > 1 && blocks - 1 > std::uint64_t(f_.budget / double(block)))
      fail("lists " + std::to_string(blocks) + " blocks of " + std::to_string(block) +
           " bytes, more than a file of this size can describe");
    const std::uint64_t total = blocks == 0 ? 0 : (blocks - 1) * block + (last ? last : block);
    const std::string sizes = s.bytes(3 * hb, blocks * hb);
    if (sizes.size() < blocks * hb)
      fail("ends inside its compression header");
    Located at{s.after((3 + blocks) * hb), total, block, last ? last : block, {}};
    const std::uint64_t data = at.data.size();
    std::uint64_t sum = 0;
    for (std::uint64_t k = 0; k < blocks; ++k) {
      const std::uint64_t packed = header_word(sizes, std::size_t(k));
      const std::uint64_t unpacked = k + 1 == blocks ? at.last_block : block;
      if (double(unpacked) > f_.packing->ratio * double(packed) + kBlockFramingBytes)
        fail("states " + std::to_string(unpacked) + " bytes for block " + std::to_string(k) + " of " +
             std::to_string(packed) + " compressed bytes, more than " + f_.packing->name + " can pack into them");
      if (packed > data - sum)
        fail("has compressed blocks beyond the " + std::to_string(data) + " bytes the file holds for them");
      sum += packed;
      at.packed.push_back(packed);
    }
    check_total(total, expected, "decompresses to");
    return at;
  }

  //! The word at byte `at` of the uncompressed data.
  std::string read_at(Located& a, std::uint64_t at)
  {
    const std::uint64_t w = std::uint64_t(word_);
    std::string bytes;
    if (!f_.packing) {
      bytes = a.data.bytes(f_.header_bytes + at, w);
    } else {
      const std::size_t k = std::size_t(at / a.block);
      std::uint64_t from = 0;
      for (std::size_t j = 0; j < k; ++j)
        from += a.packed[j];
      const std::string packed = a.data.bytes(from, a.packed[k]);
      const std::uint64_t size = k + 1 == a.packed.size() ? a.last_block : a.block;
      std::string unpacked(std::size_t(size), '\0');
      const std::size_t got = packed.size() < a.packed[k] ? 0
        : f_.packing->compressor->Uncompress(reinterpret_cast<const unsigned char*>(packed.data()),
                                             packed.size(), reinterpret_cast<unsigned char*>(&unpacked[0]),
                                             unpacked.size());
      if (got != size)
        fail("has a block " + std::to_string(k) + " that does not decompress to its " + std::to_string(size) +
             " bytes");
      bytes = unpacked.substr(std::size_t(at - std::uint64_t(k) * a.block), std::size_t(w));
    }
    if (bytes.size() < w)
      fail("ends before its last value");
    return bytes;
  }

  std::optional<double> ascii(std::optional<std::uint64_t> expected, bool last, std::optional<std::uint64_t> at_least)
  {
    // Values up to the next tag, as VTK's parser reads them.
    std::uint64_t at = inline_start(), values = 0;
    std::uint64_t last_start = at, last_end = at;
    for (;;) {
      const std::uint64_t end = f_.file.run_end(at, [](char c) { return c != '<' && !is_space(c); });
      if (end == at)
        break;
      ++values;
      last_start = at;
      last_end = end;
      at = f_.file.run_end(end, is_space);
    }
    if (expected && values != *expected)
      fail("holds " + std::to_string(values) + " ascii values, but " + why_ + " need " + std::to_string(*expected));
    if (at_least && values < *at_least)
      fail("holds " + std::to_string(values) + " ascii values, but " + why_ + " of type " + type_ + " need " +
           std::to_string(*at_least) + " at least");
    if (!last || values == 0)
      return std::nullopt;
    const std::string text = f_.file.read(last_start, std::min<std::uint64_t>(last_end - last_start, 64));
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0')
      fail("ends with '" + excerpt(text, 20) + "', not a number");
    return v;
  }

  FileLayout& f_;
  vtkXMLDataElement* e_;
  std::string type_;
  int word_;
  std::string label_;
  std::string why_;
};

//! A count attribute of the piece (missing: 0).
std::uint64_t count_of(FileLayout& f, vtkXMLDataElement* piece, const char* name)
{
  const std::string text = attribute(piece, name);
  if (text.empty())
    return 0;
  char* end = nullptr;
  const double n = std::strtod(text.c_str(), &end);
  while (*end && is_space(*end))
    ++end;
  if (end == text.c_str() || *end != '\0' || !(n >= 0) || n != std::floor(n) || n > f.budget)
    throw InputError(f.where + "Piece attribute " + name + "=\"" + excerpt(text, 20) + "\" is not a count");
  return std::uint64_t(n);
}

std::optional<std::uint64_t> tuples_attribute(FileLayout& f, vtkXMLDataElement* e, const std::string& label)
{
  if (!e->GetAttribute("NumberOfTuples"))
    return std::nullopt;
  const std::string text = attribute(e, "NumberOfTuples");
  char* end = nullptr;
  const double n = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !(n >= 0) || n != std::floor(n) || n > f.budget)
    throw InputError(f.where + label + " array: NumberOfTuples=\"" + excerpt(text, 20) + "\" is not a count");
  return std::uint64_t(n);
}

std::uint64_t components_of(FileLayout& f, vtkXMLDataElement* e, const std::string& label)
{
  const std::string text = attribute(e, "NumberOfComponents");
  if (text.empty())
    return 1;
  char* end = nullptr;
  const long n = std::strtol(text.c_str(), &end, 10);
  if (end == text.c_str() || *end != '\0' || n < 1 || n > 4096)
    throw InputError(f.where + label + " array: NumberOfComponents=\"" + excerpt(text, 20) +
                     "\" is not 1 to 4096");
  return std::uint64_t(n);
}

bool is_array(vtkXMLDataElement* e)
{
  return std::strcmp(e->GetName(), "DataArray") == 0 || std::strcmp(e->GetName(), "Array") == 0;
}

//! The arrays of a point, cell or field data element, each with `tuples`
//! tuples, the piece's `what` (unknown: NumberOfTuples where given).
void check_data_arrays(FileLayout& f, vtkXMLDataElement* data, std::optional<std::uint64_t> tuples,
                       const std::string& what = "")
{
  const std::string label = data->GetName();
  for (int k = 0; k < data->GetNumberOfNestedElements(); ++k) {
    vtkXMLDataElement* e = data->GetNestedElement(k);
    if (!is_array(e))
      continue;
    const std::uint64_t components = components_of(f, e, label);
    std::optional<std::uint64_t> n = tuples_attribute(f, e, label);
    if (tuples && n && *n != *tuples)
      throw InputError(f.where + label + " array '" + excerpt(attribute(e, "Name"), 40) + "' states NumberOfTuples=" +
                       std::to_string(*n) + ", but its piece has " + std::to_string(*tuples));
    const std::string why = tuples ? std::to_string(*tuples) + " " + what : "NumberOfTuples=" + std::to_string(n ? *n : 0);
    if (tuples)
      n = tuples;
    ArrayCheck(f, e, label)
      .check(n ? std::optional<std::uint64_t>(*n * components) : std::nullopt,
             why + " x " + std::to_string(components) + " components");
  }
}

vtkXMLDataElement* array_named(vtkXMLDataElement* cells, const char* name)
{
  for (int k = 0; k < cells->GetNumberOfNestedElements(); ++k) {
    vtkXMLDataElement* e = cells->GetNestedElement(k);
    if (is_array(e) && attribute(e, "Name") == name)
      return e;
  }
  return nullptr;
}

//! Verts, Lines, Strips or Polys of `count` cells: as many offsets, and the
//! connectivity as long as the last offset says (VTK allocates that).
void check_cells(FileLayout& f, vtkXMLDataElement* cells, std::uint64_t count)
{
  if (count == 0)
    return; // VTK's reader does not read them
  const std::string label = cells->GetName();
  // VTK's reader reads the offsets before it looks for the connectivity
  // (a fuzz finding: damaged offsets beside a missing connectivity).
  vtkXMLDataElement* offsets = array_named(cells, "offsets");
  if (!offsets)
    return; // VTK's reader says it is missing
  const std::optional<double> last =
    ArrayCheck(f, offsets, label).check(count, "NumberOf" + label + "=" + std::to_string(count), true);
  vtkXMLDataElement* connectivity = array_named(cells, "connectivity");
  if (!last || !connectivity)
    return; // no fixed word size or no connectivity: VTK's reader refuses them
  if (!(*last >= 0) || *last != std::floor(*last) || *last > f.budget)
    throw InputError(f.where + label + " array 'offsets' ends with " + number_text(*last) +
                     ", not a connectivity length a file of this size can hold");
  ArrayCheck(f, connectivity, label).check(std::uint64_t(*last), "the last offset (" + number_text(*last) + ")");
}

void check_piece(FileLayout& f, vtkXMLDataElement* piece)
{
  const char* kinds[] = {"Verts", "Lines", "Strips", "Polys"};
  const std::uint64_t points = count_of(f, piece, "NumberOfPoints");
  std::uint64_t cells[4], all_cells = 0;
  for (int k = 0; k < 4; ++k)
    all_cells += cells[k] = count_of(f, piece, (std::string("NumberOf") + kinds[k]).c_str());
  for (int k = 0; k < piece->GetNumberOfNestedElements(); ++k) {
    vtkXMLDataElement* e = piece->GetNestedElement(k);
    const std::string name = e->GetName();
    if (name == "PointData" || name == "Points")
      check_data_arrays(f, e, points, "points");
    else if (name == "CellData")
      check_data_arrays(f, e, all_cells, "cells");
    else if (name == "FieldData")
      check_data_arrays(f, e, std::nullopt);
    for (int c = 0; c < 4; ++c)
      if (name == kinds[c])
        check_cells(f, e, cells[c]);
  }
}

} // namespace

void check_xml_polydata_arrays(const std::string& path, double budget_bytes)
{
  std::ifstream in(path, std::ios::binary);
  auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
  parser->SetStream(&in);
  if (!parser->Parse())
    return; // VTK's reader parses it again and says why it cannot
  // VTK's reader takes the PolyData element whatever the root's name and
  // type say (a fuzz finding), and so does this check.
  vtkXMLDataElement* root = parser->GetRootElement();
  if (!root)
    return;
  FileLayout f(path);
  f.budget = budget_bytes;
  f.big_endian = attribute(root, "byte_order") == "BigEndian";
  const std::string header = attribute(root, "header_type");
  if (header == "UInt64")
    f.header_bytes = 8;
  else if (!header.empty() && header != "UInt32")
    throw InputError(f.where + "header_type=\"" + excerpt(header, 20) + "\" is neither UInt32 nor UInt64");
  if (root->GetAttribute("compressor")) {
    f.packing = packing_of(attribute(root, "compressor"));
    if (!f.packing)
      throw InputError(f.where + "compressor=\"" + excerpt(attribute(root, "compressor"), 40) +
                       "\" is not one VTK reads (vtkZLibDataCompressor, vtkLZ4DataCompressor, vtkLZMADataCompressor)");
  }
  if (vtkXMLDataElement* appended = root->FindNestedElementWithName("AppendedData")) {
    f.has_appended = true;
    f.appended_at = std::uint64_t(parser->GetAppendedDataPosition());
    f.appended_raw = attribute(appended, "encoding") == "raw";
    if (!f.appended_raw)
      f.appended_end = f.file.run_end(f.appended_at, is_base64);
  }
  vtkXMLDataElement* polydata = root->FindNestedElementWithName("PolyData");
  if (!polydata)
    return; // VTK's reader says it is missing
  for (int k = 0; k < polydata->GetNumberOfNestedElements(); ++k) {
    vtkXMLDataElement* e = polydata->GetNestedElement(k);
    if (std::strcmp(e->GetName(), "Piece") == 0)
      check_piece(f, e);
    else if (std::strcmp(e->GetName(), "FieldData") == 0)
      check_data_arrays(f, e, std::nullopt);
  }
}

} // namespace meshpaint
