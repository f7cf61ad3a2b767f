#include "mesh/off_reader.h"

#include "core/errors.h"

#include <CGAL/IO/OFF/File_scanner_OFF.h> // for CGAL::File_scanner_OFF::get_indexed_color, Geomview's colour map

#include <cerrno>  // for errno, ERANGE
#include <cmath>   // for std::isfinite, std::fabs
#include <cstdlib> // for std::strtod, std::strtol
#include <fstream> // for std::ifstream
#include <sstream> // for std::istringstream

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

} // namespace

PolygonSoup read_off_text(const std::string& path)
{
  OffLines lines(path);
  std::vector<std::string> w;
  if (!lines.next(w))
    throw InputError("has no OFF keyword and no counts");
  OffHeader h;
  std::size_t at = 0; // first unread word of w
  if (parse_keyword(w[0], h)) {
    at = 1;
  } else if (w[0].find("OFF") != std::string::npos) {
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
      if (index > 148)
        lines.fail("colour-map index " + w[first] + " is beyond Geomview's map (0-148)");
      const auto& m = CGAL::File_scanner_OFF::get_indexed_color(int(index));
      c = {float(m.red() / 255.0), float(m.green() / 255.0), float(m.blue() / 255.0)};
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
