#include "mesh/off_reader.h"

#include "core/errors.h"
#include "core/format.h"

#include <CGAL/IO/OFF/File_scanner_OFF.h> // for CGAL::File_scanner_OFF::get_indexed_color, Geomview's colour map
#include <CGAL/IO/binary_file_io.h>       // for CGAL::I_Binary_read_big_endian_integer32, Geomview's byte order

#include <cctype>  // for std::isdigit
#include <cerrno>  // for errno, ERANGE
#include <cmath>   // for std::isfinite, std::fabs
#include <cstdint> // for std::int32_t
#include <cstdlib> // for std::strtod, std::strtol
#include <fstream> // for std::ifstream
#include <iterator> // for std::istreambuf_iterator
#include <sstream> // for std::istringstream
#include <type_traits> // for std::is_same_v, std::decay_t

namespace meshpaint {
namespace {

//! A file read line by line, comments cut off and blank lines skipped,
//! every line known by its number for messages.
class OffLines
{
public:
  explicit OffLines(const std::string& path) : in_(path, std::ios::binary | std::ios::ate)
  {
    if (!in_)
      throw IOError("cannot read '" + path + "'");
    size_ = long(in_.tellg());
    in_.seekg(0);
  }

  //! The next line with content, as words; false at the end of the file.
  bool next(std::vector<std::string>& words)
  {
    std::string line;
    while (std::getline(in_, line)) {
      ++number_;
      if (number_ == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0)
        line.erase(0, 3);
      const std::size_t hash = line.find('#');
      if (hash != std::string::npos)
        line.erase(hash);
      words.clear();
      std::istringstream s(line);
      for (std::string w; s >> w;)
        words.push_back(w);
      if (!words.empty())
        return true;
    }
    return false;
  }

  [[noreturn]] void fail(const std::string& what) const
  {
    throw InputError("line " + std::to_string(number_) + ": " + what);
  }

  long size() const { return size_; }

private:
  std::ifstream in_;
  long size_ = 0;
  long number_ = 0;
};

//! A word for a message: quoted text, or its length when it is not text.
std::string shown(const std::string& w)
{
  for (const char c : w)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126 || w.size() > 40)
      return "a " + std::to_string(w.size()) + "-byte word that is not text";
  return "'" + w + "'";
}

double number(const OffLines& lines, const std::string& w)
{
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(w.c_str(), &end);
  if (end == w.c_str() || *end)
    lines.fail(shown(w) + " is not a number");
  // Beyond single precision, where coordinates are kept (1e999 included).
  if ((errno == ERANGE && std::fabs(v) > 1) || (std::isfinite(v) && std::fabs(v) > 3.4e38))
    lines.fail(shown(w) + " is not a number that fits");
  if (!std::isfinite(v))
    lines.fail("non-finite coordinate " + shown(w));
  return v;
}

long integer(const OffLines& lines, const std::string& w, const char* what)
{
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(w.c_str(), &end, 10);
  if (end == w.c_str() || *end || errno == ERANGE || v < 0 || v > 2147483647L)
    lines.fail(shown(w) + " is not " + what);
  return v;
}

bool is_integer_word(const std::string& w) { return w.find_first_of(".eE") == std::string::npos; }

//! The keyword's prefixes, in Geomview's order [ST][C][N][4][n]OFF.
struct OffHeader
{
  bool texture = false, colour = false, normal = false, homogeneous = false, dimension = false;
};

//! Parses the keyword when `word` starts with one; false otherwise.
bool parse_keyword(const std::string& word, OffHeader& h)
{
  std::size_t k = 0;
  const auto take = [&](const char* p) {
    const std::size_t n = std::char_traits<char>::length(p);
    if (word.compare(k, n, p) != 0)
      return false;
    k += n;
    return true;
  };
  h.texture = take("ST");
  h.colour = take("C");
  h.normal = take("N");
  h.homogeneous = take("4");
  h.dimension = take("n");
  return take("OFF") && k == word.size();
}

//! A colour from 3 or 4 components. Face colours follow Geomview: all
//! integers are 0-255, otherwise 0-1. Vertex colours are numbers 0-1 in
//! Geomview; files that write them 0-255 are recognised by a value above 1.
Vec3 colour_of(const OffLines& lines, const std::vector<std::string>& w, std::size_t first, std::size_t n,
               bool vertex)
{
  bool integers = true, above_one = false;
  for (std::size_t k = first; k < first + n; ++k) {
    integers = integers && is_integer_word(w[k]);
    above_one = above_one || number(lines, w[k]) > 1;
  }
  if (vertex)
    integers = integers && above_one;
  Vec3 c{};
  for (std::size_t k = 0; k < 3; ++k) {
    const double v = number(lines, w[first + k]);
    const double scaled = integers ? v / 255.0 : v;
    if (scaled < 0 || scaled > 1)
      lines.fail("colour component " + shown(w[first + k]) + " is outside " + (integers ? "0-255" : "0-1"));
    c[k] = float(scaled);
  }
  if (n == 4)
    number(lines, w[first + 3]); // alpha: checked, not kept
  return c;
}

//! The last index of Geomview's colour map.
constexpr int kLastMapIndex = 148;

Vec3 map_colour(int index)
{
  const auto& m = CGAL::File_scanner_OFF::get_indexed_color(index);
  return {float(m.red() / 255.0), float(m.green() / 255.0), float(m.blue() / 255.0)};
}

//! One way to lay out a binary OFF body after the header line: 32-bit
//! integers and floats in either byte order, each face's vertex indices
//! followed by a colour count and that many floats (Geomview) or by nothing
//! (what OpenMesh writes, little-endian).
struct BinaryOffLayout
{
  bool big_endian;
  bool colour_counts;
  const char* name;
};

//! Reads `body` as `layout` lays it out into `soup`. Returns the problem,
//! empty when the body is exactly its counts, vertices and faces; `reached`
//! is how far it read before the problem.
std::string walk_binary_off(const std::string& body, const BinaryOffLayout& layout, PolygonSoup& soup,
                            std::size_t& reached)
{
  std::istringstream in(body, std::ios::binary);
  // One 32-bit integer or float in the layout's byte order.
  const auto read = [&](auto& v) {
    if (!layout.big_endian)
      in.read(reinterpret_cast<char*>(&v), 4);
    else if constexpr (std::is_same_v<std::decay_t<decltype(v)>, float>)
      CGAL::I_Binary_read_big_endian_float32(in, v);
    else
      CGAL::I_Binary_read_big_endian_integer32(in, v);
    if (in)
      reached = std::size_t(in.tellg());
    return bool(in);
  };
  std::int32_t nv = 0, nf = 0, ne = 0;
  if (!read(nv) || !read(nf) || !read(ne))
    return "the binary OFF counts are truncated";
  // 12 bytes a vertex, at least 8 a face.
  if (nv < 0 || nf < 0 || 12.0 * nv + 8.0 * nf > double(body.size()))
    return "the binary OFF declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
           " faces, more than its " + std::to_string(body.size()) + " bytes can hold";
  soup.points.resize(std::size_t(nv));
  for (std::int32_t v = 0; v < nv; ++v)
    for (float& x : soup.points[std::size_t(v)]) {
      if (!read(x))
        return "the binary OFF vertices run past the end of the file";
      if (!std::isfinite(x))
        return "binary OFF vertex " + std::to_string(v) + " has a non-finite coordinate";
    }
  const std::string face = "binary OFF face ";
  bool any_colour = false;
  std::vector<Vec3> face_colours;
  for (std::int32_t f = 0; f < nf; ++f) {
    std::int32_t n = 0;
    if (!read(n))
      return face + std::to_string(f) + " runs past the end of the file";
    if (n < 1 || n > nv)
      return face + std::to_string(f) + " has " + std::to_string(n) + " corners, but there are only " +
             std::to_string(nv) + " vertices";
    std::vector<int> corners(static_cast<std::size_t>(n));
    for (int& index : corners) {
      if (!read(index))
        return face + std::to_string(f) + " runs past the end of the file";
      if (index < 0 || index >= nv)
        return face + std::to_string(f) + " names vertex " + std::to_string(index) + ", but there are only " +
               std::to_string(nv) + " vertices";
    }
    Vec3 c{0.5f, 0.5f, 0.5f};
    std::int32_t k = 0;
    if (layout.colour_counts && !read(k))
      return face + std::to_string(f) + " runs past the end of the file";
    if (k != 0 && k != 1 && k != 3 && k != 4)
      return face + std::to_string(f) + " has a colour count of " + std::to_string(k) + " (0, 1, 3 or 4)";
    float components[4] = {};
    for (std::int32_t j = 0; j < k; ++j)
      if (!read(components[j]))
        return face + std::to_string(f) + " runs past the end of the file";
    if (k == 1) {
      const float index = components[0];
      if (!(index >= 0 && index <= kLastMapIndex && index == std::floor(index)))
        return face + std::to_string(f) + " has colour-map index " + format_number(index) +
               ", not one of Geomview's map (0-148)";
      c = map_colour(int(index));
    }
    for (std::int32_t j = 0; j < k && k > 1; ++j)
      if (!(components[j] >= 0 && components[j] <= 1))
        return face + std::to_string(f) + " has colour component " + format_number(components[j]) +
               ", outside 0-1";
    if (k > 1)
      c = {components[0], components[1], components[2]};
    any_colour = any_colour || k > 0;
    face_colours.push_back(c);
    soup.faces.push_back(std::move(corners));
  }
  if (in.peek() != std::char_traits<char>::eof())
    return "the binary OFF has " + std::to_string(body.size() - reached) + " bytes after the " +
           std::to_string(nf) + " faces its counts declare";
  if (any_colour)
    soup.face_colours = std::move(face_colours);
  return {};
}

} // namespace

bool read_off_binary(const std::string& path, PolygonSoup& soup)
{
  std::ifstream file(path, std::ios::binary);
  if (!file)
    throw IOError("cannot read '" + path + "'");
  std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const std::size_t eol = bytes.find('\n');
  std::string header = bytes.substr(0, eol);
  if (!header.empty() && header.back() == '\r')
    header.pop_back();
  if (eol == std::string::npos || header != "OFF BINARY")
    return false; // the census names what is wrong with the header
  const std::string body = bytes.substr(eol + 1);

  static const BinaryOffLayout layouts[] = {
    {false, false, "OpenMesh's (little-endian, nothing after each face's indices)"},
    {true, true, "Geomview's (big-endian, a colour count after each face's indices)"},
    {false, true, "Geomview's little-endian (a colour count after each face's indices)"}};
  PolygonSoup read[3];
  std::string problem[3], names;
  std::size_t reached[3] = {0, 0, 0};
  int whole = 0, best = 0;
  for (int l = 0; l < 3; ++l) {
    problem[l] = walk_binary_off(body, layouts[l], read[l], reached[l]);
    if (problem[l].empty()) {
      names += std::string(whole++ ? " and " : "") + layouts[l].name;
      best = l;
    } else if (reached[l] > reached[best] && !problem[best].empty()) {
      best = l;
    }
  }
  if (whole > 1)
    throw InputError("the binary OFF reads whole in more than one layout, " + names +
                     ": ambiguous (write it as text OFF)");
  if (best == 0)
    return false; // OpenMesh's own layout, which OpenMesh reads (and the census checks)
  if (!problem[best].empty())
    throw InputError(problem[best]);
  soup = std::move(read[best]);
  return true;
}

PolygonSoup read_off_text(const std::string& path)
{
  OffLines lines(path);
  std::vector<std::string> w;
  if (!lines.next(w))
    throw InputError("has no OFF keyword and no counts");
  OffHeader h;
  std::size_t at = 0; // first unread word of w
  const std::size_t off = w[0].find("OFF");
  if (parse_keyword(w[0], h)) {
    at = 1;
  } else if (off != std::string::npos && off + 3 < w[0].size() && std::isdigit(static_cast<unsigned char>(w[0][off + 3])) &&
             parse_keyword(w[0].substr(0, off + 3), h)) {
    // ModelNet's files run the first count into the keyword: "OFF490 518 0".
    w.insert(w.begin() + 1, w[0].substr(off + 3));
    at = 1;
  } else if (off != std::string::npos) {
    lines.fail(shown(w[0]) + " is not an OFF keyword ([ST][C][N][4][n]OFF)");
  } // Geomview's keyword is optional: the counts may come first.
  if (at < w.size() && w[at] == "BINARY")
    lines.fail("binary OFF with prefixes is not read; only plain 'OFF BINARY'");
  const auto ensure_words = [&]() {
    if (at == w.size()) {
      if (!lines.next(w))
        throw InputError("ends before the OFF counts (vertices faces edges)");
      at = 0;
    }
  };
  int dim = 3;
  if (h.dimension) {
    ensure_words();
    const long d = integer(lines, w[at++], "a dimension");
    if (d != 2 && d != 3)
      lines.fail("nOFF of dimension " + std::to_string(d) + " is not a surface in 3D (2 or 3 work)");
    dim = int(d);
  }
  ensure_words();
  const long nv = integer(lines, w[at++], "a vertex count");
  ensure_words();
  const long nf = integer(lines, w[at++], "a face count");
  if (at < w.size())
    integer(lines, w[at++], "an edge count");
  if (at < w.size())
    lines.fail(shown(w[at]) + " after the vertex, face and edge counts");
  // "0 0 0" is the shortest vertex line, "3 0 1 2" the shortest face.
  if (nv > lines.size() / 6 + 1 || nf > lines.size() / 8 + 1)
    throw InputError("declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                     " faces, more than its " + std::to_string(lines.size()) + " bytes can hold");

  const std::size_t coords = std::size_t(dim + (h.homogeneous ? 1 : 0));
  const std::size_t fixed = coords + (h.normal ? std::size_t(dim) : 0) + (h.texture ? 2 : 0);
  PolygonSoup soup;
  soup.points.reserve(std::size_t(nv));
  if (h.colour)
    soup.colours.reserve(std::size_t(nv));
  for (long v = 0; v < nv; ++v) {
    if (!lines.next(w))
      throw InputError("declares " + std::to_string(nv) + " vertices, but the file ends after " +
                       std::to_string(v) + " (truncated?)");
    const std::size_t colour = h.colour ? w.size() - std::min(w.size(), fixed) : 0;
    if (w.size() < fixed || (h.colour && colour != 3 && colour != 4) || (!h.colour && w.size() != fixed))
      lines.fail("a vertex of " + std::to_string(w.size()) + " numbers, but this OFF variant has " +
                 (h.colour ? std::to_string(fixed + 3) + " or " + std::to_string(fixed + 4)
                           : std::to_string(fixed)));
    Vec3 p{};
    for (std::size_t a = 0; a < std::size_t(dim); ++a)
      p[a] = float(number(lines, w[a]));
    if (h.homogeneous) {
      const double hw = number(lines, w[std::size_t(dim)]);
      if (hw == 0)
        lines.fail("a vertex at infinity (homogeneous coordinate 0)");
      for (float& x : p) {
        x = float(x / hw);
        if (!std::isfinite(x))
          lines.fail("a vertex beyond single precision once divided by its homogeneous coordinate");
      }
    }
    for (std::size_t k = coords; k < fixed; ++k)
      number(lines, w[k]); // normals and texture coordinates: checked, not kept
    if (h.colour)
      soup.colours.push_back(colour_of(lines, w, coords + (h.normal ? std::size_t(dim) : 0), colour, true));
    soup.points.push_back(p);
  }

  soup.faces.reserve(std::size_t(nf));
  bool any_colour = false;
  std::vector<Vec3> face_colours;
  std::vector<bool> coloured;
  for (long f = 0; f < nf; ++f) {
    if (!lines.next(w))
      throw InputError("declares " + std::to_string(nf) + " faces, but the file ends after " + std::to_string(f) +
                       " (truncated?)");
    const long n = integer(lines, w[0], "a corner count");
    if (n < 1 || n > nv)
      lines.fail("a face of " + w[0] + " corners, but there are only " + std::to_string(nv) + " vertices");
    if (long(w.size()) < n + 1)
      lines.fail("a face of " + w[0] + " corners names " + std::to_string(w.size() - 1) + " vertices");
    std::vector<int> face(static_cast<std::size_t>(n));
    for (long k = 0; k < n; ++k) {
      const std::string& word = w[std::size_t(k + 1)];
      char* end = nullptr;
      errno = 0;
      const long index = std::strtol(word.c_str(), &end, 10);
      if (end == word.c_str() || *end || errno == ERANGE)
        lines.fail(shown(word) + " is not a vertex index");
      if (index < 0 || index >= nv)
        lines.fail("face " + std::to_string(f) + " names vertex " + word + ", but there are only " +
                   std::to_string(nv) + " vertices");
      face[std::size_t(k)] = int(index);
    }
    const std::size_t extra = w.size() - std::size_t(n + 1), first = std::size_t(n + 1);
    Vec3 c{0.5f, 0.5f, 0.5f};
    if (extra == 1) {
      const long index = integer(lines, w[first], "a colour-map index");
      if (index > kLastMapIndex)
        lines.fail("colour-map index " + w[first] + " is beyond Geomview's map (0-148)");
      c = map_colour(int(index));
    } else if (extra == 3 || extra == 4) {
      c = colour_of(lines, w, first, extra, false);
    } else if (extra != 0) {
      lines.fail("a face of " + w[0] + " corners with " + std::to_string(extra) +
                 " more numbers: a face colour is 1 (a colour-map index), 3 or 4 numbers");
    }
    any_colour = any_colour || extra > 0;
    face_colours.push_back(c);
    soup.faces.push_back(std::move(face));
  }
  if (lines.next(w))
    lines.fail("more content after the " + std::to_string(nf) + " faces the counts declare");
  if (any_colour)
    soup.face_colours = std::move(face_colours);
  return soup;
}

} // namespace meshpaint
