#include "LegacyPolyDataCheck.h"

#include "core/errors.h" // for meshpaint::InputError
#include "core/format.h" // for meshpaint::excerpt

#include <algorithm> // for std::count, std::find, std::transform
#include <cctype>    // for std::tolower
#include <cerrno>    // for errno, ERANGE
#include <cmath>     // for std::isfinite
#include <cstdint>   // for std::uint64_t
#include <cstdlib>   // for std::strtod, std::strtoll, std::strtoull
#include <fstream>   // for std::ifstream
#include <iterator>  // for std::istreambuf_iterator, std::begin
#include <limits>    // for std::numeric_limits
#include <map>       // for std::map
#include <utility>   // for std::pair
#include <vector>    // for std::vector

namespace meshpaint {
namespace {

//! How a value of one of the reader's array types is stored and read.
enum class Kind { Signed, Unsigned, Real, Bit, Text };

struct ArrayType
{
  const char* name; //!< as the file spells it, lower case
  Kind kind;
  int bytes; //!< in binary data (bits: packed 8 to a byte)
};

// The types VTK's legacy reader reads. vtkIdType travels as a 32-bit int.
const ArrayType kTypes[] = {
  {"bit", Kind::Bit, 0},
  {"char", Kind::Signed, 1},
  {"signed_char", Kind::Signed, 1},
  {"unsigned_char", Kind::Unsigned, 1},
  {"short", Kind::Signed, 2},
  {"unsigned_short", Kind::Unsigned, 2},
  {"int", Kind::Signed, 4},
  {"unsigned_int", Kind::Unsigned, 4},
  {"vtkidtype", Kind::Signed, 4},
  {"long", Kind::Signed, 8},
  {"unsigned_long", Kind::Unsigned, 8},
  {"vtktypeint64", Kind::Signed, 8},
  {"vtktypeuint64", Kind::Unsigned, 8},
  {"float", Kind::Real, 4},
  {"double", Kind::Real, 8},
  {"string", Kind::Text, 0},
  {"utf8_string", Kind::Text, 0},
};
const ArrayType& kInt = kTypes[6];
const ArrayType& kUnsignedChar = kTypes[3];
const ArrayType& kFloat = kTypes[13];

std::string lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

std::string upper(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::toupper(c)); });
  return s;
}

//! White space as the reader's streams skip it (the classic locale).
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }

//! Whether `w` is a decimal number as a stream reads one whole: a sign,
//! digits with at most one point, an exponent with digits.
bool is_real(const std::string& w)
{
  std::size_t k = 0;
  if (k < w.size() && (w[k] == '+' || w[k] == '-'))
    ++k;
  std::size_t digits = 0;
  while (k < w.size() && std::isdigit(static_cast<unsigned char>(w[k])))
    ++k, ++digits;
  if (k < w.size() && w[k] == '.') {
    ++k;
    while (k < w.size() && std::isdigit(static_cast<unsigned char>(w[k])))
      ++k, ++digits;
  }
  if (digits == 0)
    return false;
  if (k < w.size() && (w[k] == 'e' || w[k] == 'E')) {
    ++k;
    if (k < w.size() && (w[k] == '+' || w[k] == '-'))
      ++k;
    std::size_t exponent = 0;
    while (k < w.size() && std::isdigit(static_cast<unsigned char>(w[k])))
      ++k, ++exponent;
    if (exponent == 0)
      return false;
  }
  return k == w.size();
}

//! Whether `w` is an integer: a sign (none for unsigned types), digits.
bool is_integer(const std::string& w, bool sign)
{
  const std::size_t first = sign && !w.empty() && (w[0] == '+' || w[0] == '-') ? 1 : 0;
  return w.size() > first && w.find_first_not_of("0123456789", first) == std::string::npos;
}

class Walk
{
public:
  Walk(const std::string& path, std::string text) : path_(path), t_(std::move(text)) {}

  std::string run()
  {
    header();
    dataset();
    if (removed_.empty())
      return std::move(t_); // large scans: no second copy
    std::string out;
    out.reserve(t_.size());
    std::size_t from = 0;
    for (const auto& [start, end] : removed_) {
      out.append(t_, from, start - from);
      from = end;
    }
    out.append(t_, from, std::string::npos);
    return out;
  }

private:
  struct Word
  {
    std::string text;
    std::size_t at = 0;
  };

  //! The line holding byte `at`, from 1.
  long line_of(std::size_t at) const
  {
    return 1 + long(std::count(t_.begin(), t_.begin() + std::ptrdiff_t(std::min(at, t_.size())), '\n'));
  }

  [[noreturn]] void refuse(std::size_t at, const std::string& why) const
  {
    throw InputError("'" + path_ + "': line " + std::to_string(line_of(at)) + ": " + why);
  }

  //! The next word as the reader's `>>` takes it; false at the end.
  bool next(Word& w)
  {
    while (at_ < t_.size() && is_space(t_[at_]))
      ++at_;
    if (at_ == t_.size())
      return false;
    const std::size_t start = at_;
    while (at_ < t_.size() && !is_space(t_[at_]))
      ++at_;
    w.text.assign(t_, start, at_ - start);
    w.at = start;
    // The reader takes words of at most 255 bytes and the rest as the next.
    if (w.text.size() > 255)
      refuse(start, "a word of more than 255 bytes ('" + excerpt(w.text, 30) + "')");
    return true;
  }

  Word expect(const std::string& what)
  {
    Word w;
    if (!next(w))
      refuse(t_.size(), "the file ends where " + what + " should follow");
    return w;
  }

  //! A count: digits only, at most `most`.
  long long count(const std::string& what, long long most = std::numeric_limits<int>::max())
  {
    const Word w = expect(what);
    if (!is_integer(w.text, false))
      refuse(w.at, what + " is '" + excerpt(w.text, 30) + "', not a count");
    errno = 0;
    const unsigned long long n = std::strtoull(w.text.c_str(), nullptr, 10);
    if (errno == ERANGE || n > static_cast<unsigned long long>(most))
      refuse(w.at, what + " " + excerpt(w.text, 30) + " is more than the file can hold");
    return static_cast<long long>(n);
  }

  const ArrayType& type(const Word& w, const std::string& what, bool text_allowed)
  {
    const std::string name = lower(w.text);
    for (const ArrayType& t : kTypes)
      if (name == t.name) {
        if (t.kind == Kind::Text && binary_)
          refuse(w.at, what + " is a binary string array, which VTK's reader cannot read safely (write the file "
                              "as ASCII or .vtp)");
        if (t.kind == Kind::Text && !text_allowed)
          refuse(w.at, what + " has the type '" + excerpt(w.text, 30) + "', where numbers are needed");
        return t;
      }
    refuse(w.at, what + " has the type '" + excerpt(w.text, 30) + "', which VTK's reader does not read");
  }

  void header()
  {
    const std::size_t end = t_.find('\n');
    std::string first = t_.substr(0, end);
    if (!first.empty() && first.back() == '\r')
      first.pop_back();
    static const std::string prefix = "# vtk DataFile Version";
    std::size_t k = prefix.size();
    const auto digits = [&] {
      const std::size_t from = k;
      while (k < first.size() && k - from < 5 && std::isdigit(static_cast<unsigned char>(first[k])))
        ++k;
      return k - from;
    };
    bool ok = first.compare(0, prefix.size(), prefix) == 0;
    while (ok && k < first.size() && first[k] == ' ')
      ++k;
    const std::size_t major_at = k;
    const std::size_t major_digits = ok ? digits() : 0;
    ok = ok && major_digits >= 1 && major_digits <= 4 && k < first.size() && first[k] == '.';
    if (ok) {
      major_ = std::atoi(first.c_str() + major_at);
      ++k;
      const std::size_t minor = digits();
      while (k < first.size() && is_space(first[k]))
        ++k;
      ok = minor >= 1 && minor <= 4 && k == first.size();
    }
    if (!ok || end == std::string::npos)
      refuse(0, "not a legacy VTK file (its first line must be '# vtk DataFile Version M.N')");
    // The title: the reader takes the whole of the second line.
    const std::size_t title_end = t_.find('\n', end + 1);
    if (title_end == std::string::npos)
      refuse(t_.size(), "the file ends in its title");
    at_ = title_end + 1;
    const Word form = expect("ASCII or BINARY");
    const std::string f = lower(form.text);
    if (f != "ascii" && f != "binary")
      refuse(form.at, "'" + excerpt(form.text, 30) + "' where ASCII or BINARY should be");
    binary_ = f == "binary";
  }

  void dataset()
  {
    const Word d = expect("DATASET POLYDATA");
    if (lower(d.text) != "dataset")
      refuse(d.at, "'" + excerpt(d.text, 30) + "' where DATASET POLYDATA should be");
    const Word kind = expect("the dataset's type");
    if (lower(kind.text) != "polydata")
      refuse(kind.at, "a dataset of type '" + excerpt(kind.text, 30) + "' (only POLYDATA has polygons)");
    std::map<std::string, std::size_t> seen; //!< where each section starts
    Word w;
    while (next(w)) {
      const std::string key = lower(w.text);
      if (key == "field") {
        field(-1);
      } else if (key == "points" || key == "vertices" || key == "lines" || key == "polygons" ||
                 key == "triangle_strips") {
        if (seen.count(key))
          refuse(w.at, upper(key) + " repeats the section of line " + std::to_string(line_of(seen[key])));
        seen[key] = w.at;
        if (key == "points")
          points();
        else
          cells(upper(key));
      } else if (key == "point_data" || key == "cell_data") {
        attributes(w);
        return;
      } else {
        refuse(w.at, "'" + excerpt(w.text, 30) + "' is not a section of polygon data");
      }
    }
  }

  void points()
  {
    points_ = count("the number of points");
    const Word t = expect("the type of the points");
    const ArrayType& type = this->type(t, "POINTS", false);
    if (type.kind == Kind::Bit)
      refuse(t.at, "POINTS of type bit");
    block(type, points_, 3, "POINTS " + std::to_string(points_) + " " + excerpt(t.text, 30), nullptr, Block::Array);
  }

  //! A cell section: version 5's offsets and connectivity, or before it a
  //! list of each cell's count followed by its point ids.
  void cells(const std::string& key)
  {
    if (major_ >= 5) {
      const long long offsets = count("the number of offsets of " + key);
      const long long ids = count("the number of point ids of " + key);
      if (offsets < 1) { // the reader reads nothing more for it
        if (ids != 0)
          refuse(at_, key + " states no offsets but " + std::to_string(ids) + " point ids");
        return;
      }
      std::vector<long long> off;
      typed_block(key, "OFFSETS", offsets, &off);
      typed_block(key, "CONNECTIVITY", ids, nullptr);
      for (std::size_t k = 0; k < off.size(); ++k)
        if ((k == 0 && off[k] != 0) || (k > 0 && off[k] < off[k - 1]) || off[k] > ids)
          refuse(at_, key + ": offset " + std::to_string(k) + " is " + std::to_string(off[k]) +
                        " (offsets start at 0, never decrease and end at the " + std::to_string(ids) +
                        " point ids)");
      if (off.back() != ids)
        refuse(at_, key + ": the last offset is " + std::to_string(off.back()) + ", not the " + std::to_string(ids) +
                      " point ids");
      cells_ += offsets - 1;
      return;
    }
    const long long cells = count("the number of cells of " + key);
    const long long size = count("the list size of " + key);
    const std::size_t after = at_;
    Word peek;
    if (next(peek) && (lower(peek.text) == "offsets" || lower(peek.text) == "connectivity"))
      refuse(peek.at, "cells in the layout of version 5 (OFFSETS, CONNECTIVITY) under a header of version " +
                        std::to_string(major_) + ".x");
    at_ = after;
    std::vector<long long> list;
    block(kInt, size, 1, key, &list, Block::Cells);
    // Each cell is its count, then that many point ids; the reader takes
    // them until the list ends, wherever the counts point.
    std::size_t at = 0;
    long long found = 0;
    while (at < list.size()) {
      const long long n = list[at];
      if (n < 0 || static_cast<unsigned long long>(n) >= list.size() - at)
        refuse(at_, "a cell of the " + lower(key) + " (entry " + std::to_string(at) + ") counts " + std::to_string(n) +
                      " points, more than its list of " + std::to_string(size) + " entries holds");
      at += 1 + std::size_t(n);
      ++found;
    }
    if (found != cells)
      refuse(at_, key + " states " + std::to_string(cells) + " cells, but its list holds " + std::to_string(found));
    cells_ += cells;
  }

  //! `OFFSETS TYPE` or `CONNECTIVITY TYPE` and its values.
  void typed_block(const std::string& key, const std::string& name, long long n, std::vector<long long>* keep)
  {
    const Word w = expect(name + " of " + key);
    if (lower(w.text) != lower(name))
      refuse(w.at, "'" + excerpt(w.text, 30) + "' where " + name + " of " + key + " should follow");
    const Word t = expect("the type of the " + name + " of " + key);
    const ArrayType& type = this->type(t, key + " " + name, false);
    if (type.kind != Kind::Signed && type.kind != Kind::Unsigned)
      refuse(t.at, key + " " + name + " of type " + excerpt(t.text, 30) + " (integers are needed)");
    block(type, n, 1, key + " " + name, keep, Block::Array);
  }

  //! The point or cell data, each once, with their counts.
  void attributes(Word w)
  {
    std::map<std::string, bool> seen;
    for (;;) {
      const std::string key = lower(w.text);
      if (seen[key])
        refuse(w.at, upper(key) + " repeats");
      seen[key] = true;
      const bool on_points = key == "point_data";
      const long long n = count("the count of " + upper(key));
      const long long expected = on_points ? std::max(points_, 0LL) : cells_;
      if (n != expected)
        refuse(w.at, upper(key) + " " + std::to_string(n) + " for " + std::to_string(expected) +
                       (on_points ? " points" : " cells"));
      for (;;) {
        if (!next(w))
          return;
        const std::string k = lower(w.text);
        if (k == "point_data" || k == "cell_data")
          break;
        attribute(k, w, n, on_points);
      }
    }
  }

  void attribute(const std::string& key, const Word& w, long long n, bool on_points)
  {
    const std::string what = upper(key);
    static const char* const known[] = {"field",   "lookup_table", "color_scalars", "texture_coordinates",
                                        "scalars", "vectors",      "normals",       "tensors",
                                        "tensors6", "global_ids",  "pedigree_ids",  "edge_flags"};
    if (std::find(std::begin(known), std::end(known), key) == std::end(known) || (key == "edge_flags" && !on_points))
      refuse(w.at, "'" + excerpt(w.text, 30) + "' is not an attribute of " + (on_points ? "points" : "cells"));
    if (key == "field") {
      field(n);
      return;
    }
    if (key == "lookup_table") {
      expect("the name of a lookup table");
      const long long size = count("the size of the lookup table");
      block(binary_ ? kUnsignedChar : kFloat, size, 4, "LOOKUP_TABLE", nullptr, Block::Table);
      return;
    }
    const Word name = expect("the name of a " + what);
    const std::string called = what + " " + excerpt(name.text, 30);
    if (key == "color_scalars") {
      const long long components = count("the number of components of " + called, 4096);
      if (components < 1)
        refuse(name.at, called + " with no components");
      block(binary_ ? kUnsignedChar : kFloat, n, components, called, nullptr, Block::Colours);
      return;
    }
    long long components = 0;
    if (key == "texture_coordinates") {
      components = count("the dimension of " + called, 3);
      if (components < 1)
        refuse(name.at, called + " of dimension 0");
    }
    const Word t = expect("the type of " + called);
    const bool ids = key == "pedigree_ids";
    const ArrayType& type = this->type(t, called, ids);
    if (key == "scalars") {
      Word k = expect("LOOKUP_TABLE after " + called);
      components = 1;
      if (lower(k.text) != "lookup_table") {
        if (!is_integer(k.text, false) || k.text.size() > 4 || std::atoi(k.text.c_str()) < 1 ||
            std::atoi(k.text.c_str()) > 4096)
          refuse(k.at, called + "'s components are '" + excerpt(k.text, 30) + "', not 1 to 4096");
        components = std::atoi(k.text.c_str());
        k = expect("LOOKUP_TABLE after " + called);
        if (lower(k.text) != "lookup_table")
          refuse(k.at, "'" + excerpt(k.text, 30) + "' where LOOKUP_TABLE should follow " + called);
      }
      expect("the name of a lookup table");
    } else if (key == "vectors" || key == "normals") {
      components = 3;
    } else if (key == "tensors") {
      components = 9;
    } else if (key == "tensors6") {
      components = 6;
    } else if (key != "texture_coordinates") {
      components = 1; // global ids, pedigree ids, edge flags
    }
    block(type, n, components, called, nullptr, Block::Array);
  }

  //! `FIELD NAME ARRAYS` and its arrays, `NAME COMPONENTS TUPLES TYPE` each
  //! (or NULL_ARRAY); in point or cell data each of `tuples` tuples.
  void field(long long tuples)
  {
    expect("the name of a FIELD");
    const long long arrays = count("the number of arrays of the FIELD");
    if (static_cast<unsigned long long>(arrays) > t_.size() - at_)
      refuse(at_, "FIELD with " + std::to_string(arrays) + " arrays is more than the file can hold");
    for (long long a = 0; a < arrays; ++a) {
      const Word name = expect("FIELD array " + std::to_string(a + 1) + " of " + std::to_string(arrays));
      if (name.text == "NULL_ARRAY")
        continue;
      const std::string called = "the FIELD array " + excerpt(name.text, 30);
      const long long components = count("the number of components of " + called);
      const long long n = count("the number of tuples of " + called, std::numeric_limits<long long>::max() / 2);
      if (components < 1)
        refuse(name.at, called + " with no components");
      if (tuples >= 0 && n != tuples)
        refuse(name.at, called + " has " + std::to_string(n) + " tuples for " + std::to_string(tuples));
      const Word t = expect("the type of " + called);
      block(this->type(t, called, true), n, components, called, nullptr, Block::Array);
    }
  }

  //! What a block of values is, for the reader's ways with each.
  enum class Block
  {
    Array,   //!< read as an array: METADATA may follow
    Cells,   //!< a cell list before version 5: its header line is read even when empty
    Table,   //!< a lookup table: likewise, colours from 0 to 1 in ASCII
    Colours, //!< colour scalars: an array of colours from 0 to 1 in ASCII
  };

  //! `n` tuples of `components` values of `type` from here; `keep` takes
  //! integer values.
  void block(const ArrayType& type, long long n, long long components, const std::string& what,
             std::vector<long long>* keep, Block kind)
  {
    // Bounds the product; what the values take is checked below (bits: 8 to a byte).
    const unsigned long long most = 8ULL * (t_.size() - at_ + 1);
    if (static_cast<unsigned long long>(n) > most || static_cast<unsigned long long>(components) > most)
      refuse(at_, what + ": " + std::to_string(n) + " tuples are more than the file can hold");
    const unsigned long long values = static_cast<unsigned long long>(n) * static_cast<unsigned long long>(components);
    if (binary_)
      binary_block(type, values, what, keep, kind);
    else if (type.kind == Kind::Text)
      text_lines(values, what);
    else
      ascii_block(type, values, what, keep, kind);
    if (kind == Block::Array || kind == Block::Colours)
      metadata(components);
  }

  void binary_block(const ArrayType& type, unsigned long long values, const std::string& what,
                    std::vector<long long>* keep, Block kind)
  {
    if (values == 0 && (kind == Block::Array || kind == Block::Colours))
      return; // the reader reads nothing, not even the end of the line
    // The reader takes the rest of the header line, then the bytes.
    std::size_t p = at_;
    while (p < t_.size() && t_[p] != '\n') {
      if (t_[p] != ' ' && t_[p] != '\t' && t_[p] != '\r')
        refuse(p, "'" + excerpt(t_.substr(p, 20), 20) + "' after " + what + " (its binary data starts on the next line)");
      ++p;
    }
    if (p - at_ >= 255)
      refuse(p, "a line of more than 255 bytes before the binary data of " + what);
    if (p == t_.size())
      refuse(p, "the file ends before the binary data of " + what);
    const std::size_t start = p + 1;
    const unsigned long long bytes = type.kind == Kind::Bit ? (values + 7) / 8 : values * unsigned(type.bytes);
    if (bytes > t_.size() - start)
      refuse(start, what + " is more than the file can hold (" + std::to_string(bytes) + " bytes of binary data, " +
                      std::to_string(t_.size() - start) + " left)");
    if (keep) {
      keep->reserve(values);
      for (unsigned long long v = 0; v < values; ++v) {
        std::uint64_t u = 0;
        for (int b = 0; b < type.bytes; ++b)
          u = (u << 8) | static_cast<unsigned char>(t_[start + v * unsigned(type.bytes) + unsigned(b)]);
        long long value = 0;
        if (type.kind == Kind::Signed) {
          const int shift = 64 - 8 * type.bytes; // sign-extend
          value = static_cast<long long>(u << shift) >> shift;
        } else if (u > std::uint64_t(std::numeric_limits<long long>::max())) {
          refuse(start, what + ": value " + std::to_string(v + 1) + " is out of range");
        } else {
          value = static_cast<long long>(u);
        }
        keep->push_back(value);
      }
    }
    at_ = start + bytes;
  }

  void ascii_block(const ArrayType& type, unsigned long long values, const std::string& what,
                   std::vector<long long>* keep, Block kind)
  {
    // Each value takes at least a byte and a space.
    if (values > 0 && 2 * values - 1 > t_.size() - at_)
      refuse(at_, what + " is more than the file can hold (" + std::to_string(values) + " values)");
    if (keep)
      keep->reserve(values);
    const bool unit = kind == Block::Table || kind == Block::Colours;
    Word w;
    for (unsigned long long v = 0; v < values; ++v) {
      if (!next(w))
        refuse(t_.size(), what + ": the file ends after " + std::to_string(v) + " of its " + std::to_string(values) +
                            " values");
      const auto bad = [&](const std::string& why) {
        refuse(w.at, what + ": value " + std::to_string(v + 1) + " is '" + excerpt(w.text, 30) + "', " + why);
      };
      if (type.kind == Kind::Real) {
        if (!is_real(w.text))
          bad(std::string("not a ") + type.name);
        const double x = std::strtod(w.text.c_str(), nullptr);
        const double most = type.bytes == 4 ? double(std::numeric_limits<float>::max())
                                             : std::numeric_limits<double>::max();
        if (!std::isfinite(x) || std::fabs(x) > most)
          bad(std::string("beyond the range of ") + type.name);
        // The reader scales colours to bytes without clamping.
        if (unit && !(x >= 0 && x <= 1))
          bad("not a colour value from 0 to 1");
      } else {
        if (!is_integer(w.text, type.kind != Kind::Unsigned))
          bad(std::string("not an integer of type ") + type.name);
        errno = 0;
        long long value = 0;
        if (type.kind == Kind::Unsigned) {
          const unsigned long long u = std::strtoull(w.text.c_str(), nullptr, 10);
          const unsigned long long most = type.bytes == 8 ? ~0ULL : (1ULL << (8 * type.bytes)) - 1;
          if (errno == ERANGE || u > most)
            bad(std::string("beyond the range of ") + type.name);
          if (keep && u > static_cast<unsigned long long>(std::numeric_limits<long long>::max()))
            bad("out of range");
          value = static_cast<long long>(u);
        } else {
          value = std::strtoll(w.text.c_str(), nullptr, 10);
          const long long most = type.kind == Kind::Bit ? 1 : type.bytes == 8 ? std::numeric_limits<long long>::max()
                                                                              : (1LL << (8 * type.bytes - 1)) - 1;
          const long long least = type.kind == Kind::Bit ? 0 : -most - 1;
          if (errno == ERANGE || value < least || value > most)
            bad(std::string("beyond the range of ") + type.name);
        }
        if (keep)
          keep->push_back(value);
      }
    }
  }

  //! An ASCII string array: the reader takes the rest of the header line,
  //! then a line per value.
  void text_lines(unsigned long long values, const std::string& what)
  {
    for (unsigned long long v = 0; v <= values; ++v) {
      const std::size_t end = t_.find('\n', at_);
      if (end == std::string::npos) {
        if (v == values) {
          at_ = t_.size();
          return;
        }
        refuse(t_.size(), what + ": the file ends after " + std::to_string(v == 0 ? 0 : v - 1) + " of its " +
                            std::to_string(values) + " strings");
      }
      at_ = end + 1;
    }
  }

  //! After an array the reader drops lines of spaces, then reads a METADATA
  //! block (up to an empty line) if the next 8 bytes spell it in any case.
  //! Those blocks are left out of what the reader gets; a run of 256 spaces
  //! without an end of line there makes the reader spin for ever.
  void metadata(long long components)
  {
    for (;;) {
      std::size_t pos = at_;
      for (;;) {
        std::size_t p = pos;
        while (p < t_.size() && p - pos < 256 && (t_[p] == ' ' || t_[p] == '\r'))
          ++p;
        if (p - pos == 256)
          refuse(pos, "a run of 256 spaces or more (VTK's reader would never finish reading it)");
        if (p < t_.size() && t_[p] == '\n') {
          pos = p + 1;
          continue;
        }
        break;
      }
      if (pos + 8 > t_.size() || lower(t_.substr(pos, 8)) != "metadata")
        return;
      std::size_t end = line_end(pos); // past the METADATA line
      while (end < t_.size()) {
        const std::size_t next_line = line_end(end);
        std::string line = t_.substr(end, next_line - end);
        if (!line.empty() && line.back() == '\n')
          line.pop_back();
        line = line.substr(0, line.find('\0'));
        if (!line.empty() && line.back() == '\r')
          line.pop_back();
        end = next_line;
        if (line.empty())
          break;
        // Component names may be empty lines: one line each.
        if (lower(line).rfind("component_names", 0) == 0)
          for (long long c = 0; c < components && end < t_.size(); ++c)
            end = line_end(end);
      }
      removed_.emplace_back(pos, end);
      at_ = end;
    }
  }

  //! Just past the end of the line starting at `from`.
  std::size_t line_end(std::size_t from) const
  {
    const std::size_t end = t_.find('\n', from);
    return end == std::string::npos ? t_.size() : end + 1;
  }

  const std::string& path_;
  std::string t_; //!< the file's bytes, unchanged until run() hands them back
  std::size_t at_ = 0;
  bool binary_ = false;
  int major_ = 0;
  long long points_ = -1; //!< none read yet
  long long cells_ = 0;
  std::vector<std::pair<std::size_t, std::size_t>> removed_; //!< METADATA blocks, in order
};

} // namespace

std::string checked_legacy_polydata(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return Walk(path, std::move(text)).run();
}

} // namespace meshpaint
