#include "mesh/file_census.h"

#include "core/format.h" // for meshpaint::excerpt

#include <algorithm> // for std::max, std::all_of, std::none_of
#include <cctype>    // for std::tolower, std::isprint, std::isspace
#include <cerrno>    // for errno, ERANGE
#include <cmath>     // for std::isfinite, std::fabs
#include <cstdint>   // for std::int32_t, std::uint32_t
#include <cstdlib>   // for std::strtol, std::strtod
#include <cstring>   // for std::memcpy
#include <fstream>   // for std::ifstream
#include <set>       // for std::set
#include <sstream>   // for std::istringstream
#include <vector>    // for std::vector

namespace meshpaint {
namespace {

bool nonfinite_word(std::string w)
{
  if (!w.empty() && (w[0] == '+' || w[0] == '-'))
    w.erase(0, 1);
  for (char& c : w)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return w.rfind("nan", 0) == 0 || w.rfind("inf", 0) == 0;
}

//! A word from the file for a message: quoted when it is short text,
//! described otherwise (binary garbage is not echoed).
std::string shown(const std::string& word)
{
  const bool text = word.size() <= 40 && std::all_of(word.begin(), word.end(), [](char ch) {
                      return std::isprint(static_cast<unsigned char>(ch)) != 0;
                    });
  return text ? "'" + word + "'" : "a " + std::to_string(word.size()) + "-byte word that is not text";
}

//! Records the first non-finite number among the words of a coordinate line.
void check_numbers(const std::string& line, long number, FileCensus& c)
{
  if (c.nonfinite_line >= 0)
    return;
  std::istringstream words(line);
  std::string w;
  while (words >> w)
    if (nonfinite_word(w)) {
      c.nonfinite_line = number;
      c.nonfinite_token = w;
      return;
    }
}

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

//! An OBJ face needs at least one corner, and each corner a vertex index
//! (OpenMesh asserts on a face without one).
void check_obj_face(std::istringstream& words, long number, FileCensus& c)
{
  std::string corner;
  int corners = 0;
  while (words >> corner) {
    ++corners;
    const char* text = corner.c_str();
    char* end = nullptr;
    errno = 0;
    const long index = std::strtol(text, &end, 10);
    if (end == text || index == 0 || errno == ERANGE || (end != text + corner.size() && *end != '/')) {
      c.problem = "line " + std::to_string(number) + ": face corner " + shown(corner) + " has no vertex index";
      return;
    }
  }
  if (corners == 0)
    c.problem = "line " + std::to_string(number) + ": a face without vertices";
}

bool is_ply_type(const std::string& t)
{
  static const std::set<std::string> types = {"char",  "uchar",   "short",  "ushort", "int",   "uint",
                                               "float", "double",  "int8",   "uint8",  "int16", "uint16",
                                               "int32", "uint32",  "float32", "float64"};
  return types.count(t) > 0;
}

//! One PLY header line, as words, checked against the grammar (OpenMesh's
//! reader crashes on some malformed headers). Returns true at end_header.
bool check_ply_header_line(const std::vector<std::string>& w, long number, bool in_element, FileCensus& c)
{
  const std::string& k = w[0];
  bool ok = false;
  if (number == 1)
    ok = w.size() == 1 && k == "ply";
  else if (k == "format")
    ok = w.size() == 3 && (w[1] == "ascii" || w[1] == "binary_little_endian" || w[1] == "binary_big_endian") &&
         w[2] == "1.0";
  else if (k == "comment")
    ok = true;
  else if (k == "obj_info") // OpenMesh reads on in it for keywords: "element" there loops, "property" crashes
    ok = std::none_of(w.begin() + 1, w.end(), [](const std::string& word) {
      return word == "ply" || word == "format" || word == "comment" || word == "obj_info" || word == "element" ||
             word == "property" || word == "end_header";
    });
  else if (k == "element")
    ok = w.size() == 3 && w[2].find_first_not_of("0123456789") == std::string::npos && w[2].size() < 10;
  else if (k == "property") // OpenMesh leaks on a property outside an element
    ok = in_element && ((w.size() == 3 && is_ply_type(w[1])) ||
         (w.size() == 5 && w[1] == "list" && is_ply_type(w[2]) && is_ply_type(w[3])));
  else if (k == "end_header")
    ok = w.size() == 1;
  if (!ok)
    c.problem = "line " + std::to_string(number) + ": not a PLY header line";
  return ok && k == "end_header";
}

//! Whether a word is one whole number of magnitude at most `limit` (or a
//! nan/inf, which the census reports on its own). OpenMesh's text readers
//! read numbers: "0-3" would be two, and one too large for its type stops
//! the stream, so that everything after it is read out of step.
bool is_number(const std::string& w, double limit)
{
  char* end = nullptr;
  const double v = std::strtod(w.c_str(), &end);
  // The whole word: a NUL inside it ends strtod's number but not OpenMesh's word.
  return end != w.c_str() && end == w.c_str() + w.size() && (!std::isfinite(v) || std::fabs(v) <= limit);
}

//! A number OpenMesh reads as a float, and as an int.
constexpr double kFloatWord = 3.4e38, kIntWord = 2147483647.0;

//! The words of a line, each a number within `limit` (see is_number); at
//! least one.
std::vector<std::string> numeric_words(const std::string& line, long number, double limit, FileCensus& c)
{
  std::istringstream words(line);
  std::vector<std::string> out;
  for (std::string w; words >> w;) {
    if (!is_number(w, limit)) {
      c.problem = "line " + std::to_string(number) + ": " + shown(w) + " is not a number that fits";
      return out;
    }
    out.push_back(w);
  }
  if (out.empty())
    c.problem = "line " + std::to_string(number) + ": an empty line";
  return out;
}

struct PlyElement
{
  std::string name;
  long count = 0;
  std::vector<bool> lists;              //!< per property: a list (count, then items)
  std::vector<std::string> names;       //!< per property
  std::vector<std::string> types;       //!< per property: its type, a list's item type
  std::vector<std::string> count_types; //!< per property: a list's count type, else empty
};

//! Whether a word is one number from 0 to 1.
bool unit_number(const std::string& w)
{
  char* end = nullptr;
  const double v = std::strtod(w.c_str(), &end);
  return end != w.c_str() && end == w.c_str() + w.size() && v >= 0 && v <= 1;
}

//! An OBJ line's colour words from `first` on, each 0-1 (OpenMesh scales
//! them by 255 into a byte), else the census's problem.
void check_colour_words(const std::vector<std::string>& w, std::size_t first, long number, FileCensus& c)
{
  for (std::size_t k = first; c.problem.empty() && k < w.size(); ++k)
    if (!unit_number(w[k]))
      c.problem = "line " + std::to_string(number) + ": colour " + shown(w[k]) + " is outside 0-1";
}

//! Whether a PLY type is a float or a double.
bool is_real_type(const std::string& t) { return t == "float" || t == "float32" || t == "double" || t == "float64"; }

//! A colour property stored as a real number: OpenMesh scales it by 255
//! into a byte, which is only defined for 0-1.
bool is_real_colour(const std::string& name, const std::string& type)
{
  const bool colour = name == "red" || name == "green" || name == "blue" || name == "alpha" ||
                      name == "diffuse_red" || name == "diffuse_green" || name == "diffuse_blue";
  return colour && is_real_type(type);
}

//! Bytes of a PLY scalar type.
int ply_size(const std::string& t)
{
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8")
    return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16")
    return 2;
  if (t == "double" || t == "float64")
    return 8;
  return 4;
}

//! How one property of a binary PLY element is laid out, resolved from
//! the header's words once, not per element.
struct PlyField
{
  bool list = false;
  int bytes = 4;       //!< a scalar's, a list item's
  int count_bytes = 0; //!< a list's count
  bool count_signed = false;
  bool real = false;   //!< float or double
  bool coordinate = false;      //!< x, y or z of a vertex, stored as a real
  bool colour_in_unit = false;  //!< a vertex colour stored as a real: 0-1
};

bool is_signed_type(const std::string& t)
{
  return t == "char" || t == "int8" || t == "short" || t == "int16" || t == "int" || t == "int32";
}

std::vector<PlyField> ply_fields(const PlyElement& e)
{
  std::vector<PlyField> fields(e.types.size());
  for (std::size_t p = 0; p < fields.size(); ++p) {
    PlyField& f = fields[p];
    f.list = e.lists[p];
    f.bytes = ply_size(e.types[p]);
    f.real = is_real_type(e.types[p]);
    if (f.list) {
      f.count_bytes = ply_size(e.count_types[p]);
      f.count_signed = is_signed_type(e.count_types[p]);
    }
    const std::string& name = e.names[p];
    f.coordinate = !f.list && f.real && e.name == "vertex" && (name == "x" || name == "y" || name == "z");
    f.colour_in_unit = !f.list && e.name == "vertex" && is_real_colour(name, e.types[p]);
  }
  return fields;
}

//! A binary PLY integer of `n` bytes as a signed value.
long long ply_integer(const unsigned char* b, int n, bool is_signed, bool big_endian)
{
  unsigned long long u = 0;
  for (int k = 0; k < n; ++k)
    u |= (unsigned long long)b[big_endian ? n - 1 - k : k] << (8 * k);
  if (is_signed && n < 8 && (u >> (8 * n - 1)) & 1)
    return (long long)u - (1LL << (8 * n));
  return (long long)u;
}

//! A binary PLY float (`n` 4) or double (8) as a double.
double ply_real(const unsigned char* b, int n, bool big_endian)
{
  unsigned char le[8];
  for (int k = 0; k < n; ++k)
    le[k] = b[big_endian ? n - 1 - k : k];
  if (n == 4) {
    float f;
    std::memcpy(&f, le, 4);
    return f;
  }
  double d;
  std::memcpy(&d, le, 8);
  return d;
}

//! Walks a binary PLY body as the header lays it out, before OpenMesh
//! allocates what its counts say: every list fits the file and names at
//! most the vertex count, every vertex coordinate is finite, and the body
//! ends where the file does.
void check_ply_binary_body(std::istream& in, const std::vector<PlyElement>& elements, long nv, long size,
                           bool big_endian, FileCensus& c)
{
  const std::streamoff start = in.tellg();
  std::string body(std::size_t(size - start), '\0');
  in.read(&body[0], std::streamsize(body.size()));
  const auto* b = reinterpret_cast<const unsigned char*>(body.data());
  const std::size_t n = body.size();
  std::size_t at = 0;
  for (const PlyElement& e : elements) {
    const std::vector<PlyField> fields = ply_fields(e);
    const auto where = [&](long k) { return e.name + " " + std::to_string(k); };
    for (long k = 0; k < e.count; ++k)
      for (std::size_t p = 0; p < fields.size(); ++p) {
        const PlyField& f = fields[p];
        if (!f.list) {
          if (at + std::size_t(f.bytes) > n) {
            c.problem = "the binary PLY body ends inside " + where(k) + " (truncated?)";
            return;
          }
          if (f.coordinate && !std::isfinite(ply_real(b + at, f.bytes, big_endian))) {
            c.problem = "vertex " + std::to_string(k) + " has a non-finite coordinate " + e.names[p];
            return;
          }
          if (f.colour_in_unit) {
            const double v = ply_real(b + at, f.bytes, big_endian);
            if (!(v >= 0 && v <= 1)) {
              c.problem = "vertex " + std::to_string(k) + " has a colour " + e.names[p] + " outside 0-1";
              return;
            }
          }
          at += std::size_t(f.bytes);
          continue;
        }
        if (at + std::size_t(f.count_bytes) > n) {
          c.problem = "the binary PLY body ends inside " + where(k) + " (truncated?)";
          return;
        }
        const long long items = ply_integer(b + at, f.count_bytes, f.count_signed, big_endian);
        at += std::size_t(f.count_bytes);
        if (items < 0 || items > nv || at + std::size_t(items) * std::size_t(f.bytes) > n) {
          c.problem = where(k) + " has a list of " + std::to_string(items) + " items, but there are " +
                      std::to_string(nv) + " vertices and " + std::to_string(n - at) + " bytes left";
          return;
        }
        at += std::size_t(items) * std::size_t(f.bytes);
      }
  }
  if (at != n)
    c.problem = "the binary PLY body has " + std::to_string(n - at) + " bytes after the elements its header declares";
}

//! Every triangle of a binary STL (`in` after the 84-byte header): finite
//! normal and corners.
void check_binary_stl_numbers(std::istream& in, long triangles, FileCensus& c)
{
  char record[50];
  for (long t = 0; t < triangles; ++t) {
    in.read(record, 50);
    float values[12];
    std::memcpy(values, record, sizeof values);
    for (int k = 3; k < 12; ++k)
      if (!std::isfinite(values[k])) {
        c.problem = "binary STL triangle " + std::to_string(t) + " has a non-finite coordinate";
        return;
      }
  }
}

//! ASCII STL, line by line: facets of exactly three vertices of three
//! numbers each, and the closing endsolid (a file without it is cut short).
void check_ascii_stl(std::istream& in, FileCensus& c)
{
  std::string line;
  long number = 0, vertices = 0;
  bool ended = false, in_facet = false;
  c.declared_faces = 0;
  while (std::getline(in, line) && c.problem.empty()) {
    ++number;
    if (number == 1 && starts_with(line, "\xEF\xBB\xBF"))
      line.erase(0, 3);
    std::istringstream words(line);
    std::string keyword;
    if (!(words >> keyword))
      continue;
    for (char& ch : keyword)
      ch = char(std::tolower(static_cast<unsigned char>(ch)));
    const auto fail = [&](const std::string& what) { c.problem = "line " + std::to_string(number) + ": " + what; };
    if (ended)
      fail("content after endsolid");
    else if (keyword == "solid" && number > 1 && c.declared_faces > 0)
      fail("a second solid (only one is read)");
    else if (keyword == "facet") {
      ++c.declared_faces;
      in_facet = true;
      vertices = 0;
    } else if (keyword == "vertex") {
      const std::string rest = line.substr(line.find_first_of("xX") + 1);
      check_numbers(rest, number, c);
      if (c.nonfinite_line >= 0)
        return;
      const std::vector<std::string> w = numeric_words(rest, number, kFloatWord, c);
      if (c.problem.empty() && (w.size() != 3 || !in_facet))
        fail(in_facet ? "a vertex of " + std::to_string(w.size()) + " numbers (x y z)" : "a vertex outside a facet");
      ++vertices;
    } else if (keyword == "endfacet") {
      if (vertices != 3)
        fail("a facet of " + std::to_string(vertices) + " vertices (STL facets are triangles)");
      in_facet = false;
    } else if (keyword == "endsolid") {
      if (in_facet)
        fail("endsolid inside a facet");
      ended = true;
    } else if (keyword != "solid" && keyword != "outer" && keyword != "endloop") {
      fail(shown(keyword) + " is not an STL keyword");
    }
  }
  if (c.problem.empty() && !ended)
    c.problem = "the ASCII STL ends without endsolid (truncated?)";
}

//! Walks an ASCII PLY body word by word, as the header lays it out: a
//! non-finite vertex coordinate is noted, and a list count (which OpenMesh
//! allocates) must be a number from 0 to the vertex count.
void check_ply_ascii_body(std::istream& in, long& number, const std::vector<PlyElement>& elements, long nv,
                          FileCensus& c)
{
  std::string line, word;
  std::istringstream words;
  const auto next = [&]() {
    while (!(words >> word)) {
      if (!std::getline(in, line))
        return false;
      ++number;
      words.clear();
      words.str(line);
    }
    return true;
  };
  for (const PlyElement& e : elements)
    for (long k = 0; k < e.count; ++k)
      for (std::size_t p = 0; p < e.lists.size(); ++p) {
        const bool list = e.lists[p];
        if (!next()) {
          c.problem = "the PLY body ends before its " + std::to_string(e.count) + " " + e.name +
                      " elements (truncated?)";
          return;
        }
        if (!list) {
          if (e.name == "vertex" && c.nonfinite_line < 0 && nonfinite_word(word)) {
            const std::string& name = e.names[p];
            if (name != "x" && name != "y" && name != "z") { // a property, not a coordinate: say which
              c.problem = "line " + std::to_string(number) + ": vertex " + std::to_string(k) + " has the non-finite "
                          "value " + shown(word) + " in its property '" + excerpt(name) + "'";
              return;
            }
            c.nonfinite_line = number;
            c.nonfinite_token = word;
            return;
          }
          if (!is_number(word, kFloatWord)) {
            c.problem = "line " + std::to_string(number) + ": " + shown(word) + " is not a number that fits";
            return;
          }
          if (e.name == "vertex" && is_real_colour(e.names[p], e.types[p]) && !unit_number(word)) {
            c.problem = "line " + std::to_string(number) + ": colour " + e.names[p] + " " + shown(word) +
                        " is outside 0-1";
            return;
          }
          continue;
        }
        char* end = nullptr;
        errno = 0;
        const long n = std::strtol(word.c_str(), &end, 10);
        if (end == word.c_str() || *end || errno == ERANGE || n < 0 || n > nv) {
          c.problem = "line " + std::to_string(number) + ": a " + e.name + " list of " + shown(word) +
                      " items, but there are " + std::to_string(nv) + " vertices";
          return;
        }
        for (long i = 0; i < n; ++i) {
          if (!next()) {
            c.problem = "the PLY body ends inside a " + e.name + " list (truncated?)";
            return;
          }
          const char* text = word.c_str();
          char* end = nullptr;
          const long index = std::strtol(text, &end, 10);
          if (end == text || *end || index < 0 || index > long(kIntWord)) {
            c.problem = "line " + std::to_string(number) + ": " + shown(word) + " is not a vertex index";
            return;
          }
        }
      }
  if (next())
    c.problem = "line " + std::to_string(number) + ": " + shown(word) +
                " after the elements the PLY header declares";
}

//! Element counts a file of `size` bytes cannot hold (at `min_bytes` per
//! vertex or face) would make the reader reserve memory for nothing.
FileCensus& check_counts(long vertices, long faces, long size, long min_bytes, FileCensus& c)
{
  for (const auto& [count, what] : {std::pair{vertices, "vertices"}, std::pair{faces, "faces"}})
    if (count < 0 || count > size / min_bytes + 1) {
      c.problem = "declares " + std::to_string(count) + " " + what + ", more than its " +
                  std::to_string(size) + " bytes can hold";
      break;
    }
  return c;
}

//! The body of a binary OFF file after its counts: three floats per vertex,
//! then per face a corner count and that many vertex indices. OpenMesh
//! reserves what a face's count says before it reads, and goes on reading
//! past the end of the file: every count must be a face's and fit the file.
FileCensus& check_binary_off_faces(std::istream& in, long vertices, long faces, long size, FileCensus& c)
{
  if (!in.seekg(12 * vertices, std::ios::cur) || in.peek() == std::char_traits<char>::eof()) {
    if (faces > 0)
      c.problem = "the binary OFF vertices run past the end of the file";
    return c;
  }
  for (long f = 0; f < faces; ++f) {
    std::int32_t corners = 0;
    if (!in.read(reinterpret_cast<char*>(&corners), sizeof corners)) {
      c.problem = "binary OFF face " + std::to_string(f) + " runs past the end of the file";
      break;
    }
    if (corners < 1 || corners > vertices) {
      c.problem = "binary OFF face " + std::to_string(f) + " has " + std::to_string(corners) +
                  " corners, but there are only " + std::to_string(vertices) + " vertices";
      break;
    }
    if (!in.seekg(4 * std::streamoff(corners), std::ios::cur) || long(in.tellg()) > size) {
      c.problem = "binary OFF face " + std::to_string(f) + " runs past the end of the file";
      break;
    }
  }
  return c;
}

} // namespace

FileCensus take_census(const std::string& path, const std::string& ext)
{
  FileCensus c;
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in)
    return c;
  const long file_size = long(in.tellg());
  in.seekg(0);
  std::string line;
  long number = 0;

  if (ext == ".obj") {
    c.declared_faces = 0;
    c.text = true;
    long vertices = 0, coloured_vertices = 0, colour_lines = 0;
    while (std::getline(in, line) && c.problem.empty()) {
      ++number;
      if (number == 1 && starts_with(line, "\xEF\xBB\xBF"))
        line.erase(0, 3);
      // OpenMesh reads the keyword as a word, leading blanks skipped.
      std::istringstream words(line);
      std::string keyword;
      words >> keyword;
      if (keyword == "f") {
        ++c.declared_faces;
        const std::streampos at = words.tellg(); // -1 when the line ends at the keyword
        check_obj_face(words, number, c);
        // A face cut short (the last line of a truncated file) is no face.
        std::istringstream again(at < 0 ? std::string() : line.substr(std::size_t(at)));
        long corners = 0;
        for (std::string w; again >> w;)
          ++corners;
        if (c.problem.empty() && corners < 3)
          c.problem = "line " + std::to_string(number) + ": a face of " + std::to_string(corners) +
                      " corners (truncated?)";
      } else if (keyword == "v") {
        // x y z, with w or with r g b: a line OpenMesh cannot read whole
        // would be skipped, and every later index would name the wrong vertex.
        check_numbers(line.substr(line.find('v') + 1), number, c);
        if (c.nonfinite_line >= 0)
          break;
        const std::vector<std::string> w = numeric_words(line.substr(line.find('v') + 1), number, kFloatWord, c);
        ++vertices;
        coloured_vertices += w.size() >= 6 ? 1 : 0;
        if (c.problem.empty() && w.size() != 3 && w.size() != 4 && w.size() != 6 && w.size() != 7)
          c.problem = "line " + std::to_string(number) + ": a vertex of " + std::to_string(w.size()) +
                      " numbers (x y z, x y z w, or x y z r g b)";
        if (w.size() >= 6)
          check_colour_words(w, 3, number, c);
      } else if (keyword == "vc") {
        // OpenMesh takes vertex colours from these lines too, scaled by 255 into a byte.
        check_numbers(line.substr(line.find("vc") + 2), number, c);
        if (c.nonfinite_line >= 0)
          break;
        const std::vector<std::string> w = numeric_words(line.substr(line.find("vc") + 2), number, kFloatWord, c);
        ++colour_lines;
        check_colour_words(w, 0, number, c);
      }
    }
    // OpenMesh gives vertex i the i-th colour it read, from either kind of
    // line, without a bounds check: fewer colours than vertices read past
    // its list, and a mix of the two kinds pairs colours with wrong vertices.
    const long colours = coloured_vertices + colour_lines;
    if (c.problem.empty() && c.nonfinite_line < 0 && colours > 0) {
      if (coloured_vertices > 0 && colour_lines > 0)
        c.problem = "vertex colours given both on 'v' lines and on 'vc' lines";
      else if (colours != vertices)
        c.problem = std::to_string(colours) + " vertex colours for " + std::to_string(vertices) +
                    " vertices: colours must be given for every vertex or none";
    }
  } else if (ext == ".off") {
    // Text OFF goes through read_off_text(); here only OpenMesh's binary
    // OFF, BINARY on the first line.
    std::getline(in, line);
    c.binary = true;
    // OpenMesh reads other keywords on that line as options (colours,
    // normals, ...) with a layout of their own: only its own header is read.
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    if (line != "OFF BINARY") {
      c.problem = "a binary OFF file must start with the line 'OFF BINARY', not '" + excerpt(line) + "'";
      return c;
    }
    std::int32_t counts[3] = {0, 0, 0};
    if (!in.read(reinterpret_cast<char*>(counts), sizeof counts))
      c.problem = "the binary OFF header is truncated";
    else
      check_counts(counts[0], counts[1], file_size, 12, c);
    c.declared_faces = counts[1];
    if (c.problem.empty())
      check_binary_off_faces(in, counts[0], counts[1], file_size, c);
    return c;
  } else if (ext == ".ply") {
    bool ascii = false, ended = false, big_endian = false;
    long nv = 0, nf = 0;
    std::vector<PlyElement> elements; // in file order
    while (!ended && std::getline(in, line) && c.problem.empty()) {
      ++number;
      if (!line.empty() && line.back() == '\r')
        line.pop_back();
      std::istringstream words(line);
      std::vector<std::string> w;
      for (std::string word; words >> word;)
        w.push_back(word);
      if (w.empty() && number > 1)
        continue;
      if (w.empty() || number > 10000) {
        c.problem = "line " + std::to_string(number) + ": not a PLY header line";
        break;
      }
      ended = check_ply_header_line(w, number, !elements.empty(), c);
      if (!c.problem.empty())
        break;
      if (w[0] == "format")
        ascii = w[1] == "ascii";
      if (w[0] == "element") {
        // OpenMesh reads vertices and faces; other elements would shift
        // what it reads after them.
        if (w[1] != "vertex" && w[1] != "face") {
          c.problem = "line " + std::to_string(number) + ": PLY element " + shown(w[1]) +
                      " is not read (only vertex and face)";
          break;
        }
        elements.push_back({w[1], std::stol(w[2]), {}, {}, {}, {}});
        (w[1] == "face" ? nf : nv) += elements.back().count;
      }
      if (w[0] == "property") {
        PlyElement& e = elements.back();
        const bool list = w[1] == "list";
        e.lists.push_back(list);
        e.names.push_back(w.back());
        e.types.push_back(list ? w[3] : w[1]);
        e.count_types.push_back(list ? w[2] : "");
        // A list's count is a number of items: a real type cannot be one.
        if (list && (w[2] == "float" || w[2] == "float32" || w[2] == "double" || w[2] == "float64")) {
          c.problem = "line " + std::to_string(number) + ": a list count of type " + w[2];
          break;
        }
      }
      if (w[0] == "format")
        big_endian = w[1] == "binary_big_endian";
    }
    if (!c.problem.empty())
      return c;
    c.declared_faces = nf;
    // OpenMesh's PLY reader does not return on a header without its end.
    if (!ended) {
      c.problem = "the PLY header has no end_header line";
      return c;
    }
    if (!check_counts(nv, c.declared_faces, file_size, ascii ? 6 : 12, c).problem.empty())
      return c;
    c.binary = !ascii;
    c.text = ascii;
    if (!elements.empty() && elements.front().name != "vertex" && nv > 0)
      c.problem = "the PLY face element comes before the vertex element, which is not read";
    else if (ascii)
      check_ply_ascii_body(in, number, elements, nv, c);
    else
      check_ply_binary_body(in, elements, nv, file_size, big_endian, c);
  } else if (ext == ".stl") {
    // Binary exactly when the length is a binary STL's for the count in its
    // header: an ASCII file may start with a byte-order mark, a blank line
    // or SOLID, and a binary one with "solid".
    char header[84];
    in.read(header, 84);
    std::uint32_t n = 0;
    if (in.gcount() == 84)
      std::memcpy(&n, header + 80, 4);
    std::size_t first = 0;
    while (first < std::size_t(in.gcount()) && (std::isspace(static_cast<unsigned char>(header[first])) ||
                                                static_cast<unsigned char>(header[first]) >= 0x80))
      ++first;
    std::string opening(header + first, header + std::min<long>(long(in.gcount()), long(first) + 5));
    for (char& ch : opening)
      ch = char(std::tolower(static_cast<unsigned char>(ch)));
    const bool says_solid = opening == "solid";
    if (in.gcount() == 84 && file_size == 84 + 50 * long(n)) {
      c.binary = true;
      c.declared_faces = long(n);
      check_binary_stl_numbers(in, long(n), c);
    } else if (!says_solid) {
      c.problem = in.gcount() < 84 ? "too short for a binary STL header and not ASCII STL ('solid')"
                                   : "a binary STL of " + std::to_string(n) + " triangles has " +
                                         std::to_string(84 + 50 * long(n)) + " bytes, this file " +
                                         std::to_string(file_size) + " (truncated or not STL)";
    } else {
      in.clear();
      in.seekg(0);
      c.text = true;
      check_ascii_stl(in, c);
    }
  }
  return c;
}

long header_face_count(const std::string& path, const std::string& ext)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in)
    return -1;
  const long size = long(in.tellg());
  in.seekg(0);
  long faces = -1, min_bytes = 12;
  if (ext == ".stl") {
    char header[84];
    std::uint32_t n = 0;
    if (in.read(header, 84) && (std::memcpy(&n, header + 80, 4), size == 84 + 50 * long(n)))
      faces = long(n);
  } else if (ext == ".ply") {
    std::string line;
    for (int k = 0; k < 10000 && std::getline(in, line); ++k) {
      std::istringstream words(line);
      std::string keyword, element;
      long count = 0;
      words >> keyword;
      if (keyword == "format" && line.find("ascii") != std::string::npos)
        min_bytes = 6;
      if (keyword == "end_header")
        break;
      if (keyword == "element" && words >> element >> count && element == "face")
        faces = std::max(0L, faces) + count;
    }
  } else if (ext == ".off") {
    std::string first;
    if (!std::getline(in, first))
      return -1;
    if (first.rfind("OFF BINARY", 0) == 0) {
      std::int32_t counts[3] = {0, 0, 0};
      if (in.read(reinterpret_cast<char*>(counts), sizeof counts))
        faces = counts[1];
    } else if (first.rfind("OFF", 0) == 0) {
      // "OFF" alone, or followed by the counts; comments may come between.
      // (Other OFF headers, COFF and the like, give no plan.)
      std::istringstream counts(first.substr(3));
      long vertices = 0;
      std::string line;
      for (int k = 0; !(counts >> vertices >> faces); ++k) {
        faces = -1;
        const bool blank = counts.str().find_first_not_of(" \t\r") == std::string::npos;
        if ((!blank && counts.str()[counts.str().find_first_not_of(" \t\r")] != '#') || k > 100 ||
            !std::getline(in, line))
          return -1;
        counts.clear();
        counts.str(line);
      }
      min_bytes = 6;
    }
  }
  return faces < 0 || faces > size / min_bytes + 1 ? -1 : faces;
}

} // namespace meshpaint
