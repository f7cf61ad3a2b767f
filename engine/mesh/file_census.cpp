#include "mesh/file_census.h"

#include <algorithm> // for std::max, std::all_of, std::none_of
#include <cctype>    // for std::tolower, std::isprint
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
    if (end == text || index == 0 || errno == ERANGE || (*end != '\0' && *end != '/')) {
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
  return end != w.c_str() && !*end && (!std::isfinite(v) || std::fabs(v) <= limit);
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

//! The next word as an element count; false when there is none. A word
//! that is not a non-negative number is a problem (OpenMesh would read a
//! wrapped or partial value and reserve for it).
bool read_count(std::istream& words, long& value, long number, FileCensus& c)
{
  std::string word;
  if (!(words >> word))
    return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtol(word.c_str(), &end, 10);
  if (end == word.c_str() || *end || errno == ERANGE || value < 0) {
    c.problem = "line " + std::to_string(number) + ": " + shown(word) + " is not a count";
    return false;
  }
  return true;
}

struct PlyElement
{
  std::string name;
  long count = 0;
  std::vector<bool> lists; //!< per property: a list (count, then items)
};

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
      for (const bool list : e.lists) {
        if (!next())
          return; // ends early: the reader delivers fewer faces, which is counted
        if (!list) {
          if (e.name == "vertex" && c.nonfinite_line < 0 && nonfinite_word(word)) {
            c.nonfinite_line = number;
            c.nonfinite_token = word;
            return;
          }
          if (!is_number(word, kFloatWord)) {
            c.problem = "line " + std::to_string(number) + ": " + shown(word) + " is not a number that fits";
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
          if (!next())
            return;
          const char* text = word.c_str();
          char* end = nullptr;
          const long index = std::strtol(text, &end, 10);
          if (end == text || *end || index < 0 || index > long(kIntWord)) {
            c.problem = "line " + std::to_string(number) + ": " + shown(word) + " is not a vertex index";
            return;
          }
        }
      }
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
    while (std::getline(in, line) && c.problem.empty()) {
      ++number;
      // OpenMesh reads the keyword as a word, leading blanks skipped.
      std::istringstream words(line);
      std::string keyword;
      words >> keyword;
      if (keyword == "f") {
        ++c.declared_faces;
        check_obj_face(words, number, c);
      } else if (keyword == "v") {
        check_numbers(line.substr(line.find('v') + 1), number, c);
      }
    }
  } else if (ext == ".off") {
    long nv = -1, seen_vertices = 0, face_lines = 0;
    while (std::getline(in, line)) {
      ++number;
      // OpenMesh looks for BINARY anywhere in the header line, comment or not.
      const bool binary = number == 1 && line.find("BINARY") != std::string::npos;
      if (binary) {
        // Three 32-bit counts (vertices, faces, edges) follow the line.
        std::int32_t counts[3] = {0, 0, 0};
        if (!in.read(reinterpret_cast<char*>(counts), sizeof counts))
          c.problem = "the binary OFF header is truncated";
        else
          check_counts(counts[0], counts[1], file_size, 12, c);
        c.declared_faces = counts[1];
        if (c.problem.empty())
          check_binary_off_faces(in, counts[0], counts[1], file_size, c);
        return c;
      }
      const std::size_t hash = line.find('#');
      if (hash != std::string::npos)
        line.erase(hash);
      if (line.find_first_not_of(" \t\r\v\f") == std::string::npos) // blank as OpenMesh reads it
        continue;
      if (number == 1 && line.find("OFF") != std::string::npos) {
        // The variants with per-vertex colours, normals or texture
        // coordinates (COFF, NOFF, STOFF, ...) are refused: OpenMesh reads
        // their numbers across line ends, and no rule here could follow it.
        const std::size_t start = line.find_first_not_of(" \t");
        if (line.compare(start, 3, "OFF") != 0) {
          c.problem = "line 1: " + shown(line.substr(start, line.find_first_of(" \t\r", start) - start)) +
                      " files (per-vertex colours, normals or texture coordinates) are not read; only plain OFF";
          return c;
        }
        // OpenMesh reads the counts from the next line, whatever follows
        // the keyword here: the file would be read out of step.
        std::istringstream rest(line.substr(line.find("OFF") + 3));
        std::string word;
        if (rest >> word) {
          c.problem = "line 1: " + shown(word) + " after OFF is not read; the counts go on the next line";
          return c;
        }
        continue;
      }
      if (nv < 0) {
        std::istringstream counts(line);
        long f = -1, v = -1;
        const bool counted = read_count(counts, v, number, c);
        if (counted)
          nv = v;
        long e = -1;
        if (!counted || !read_count(counts, f, number, c) || !read_count(counts, e, number, c)) {
          // OpenMesh would take the missing counts from the lines that follow.
          if (c.problem.empty())
            c.problem = "line " + std::to_string(number) + ": the counts need vertices, faces and edges";
          return c;
        }
        std::string extra;
        if (counts >> extra) { // OpenMesh would read it as the first coordinate
          c.problem = "line " + std::to_string(number) + ": " + shown(extra) +
                      " after the vertex, face and edge counts";
          return c;
        }
        c.declared_faces = f;
        if (!check_counts(nv, f, file_size, 6, c).problem.empty())
          return c;
      } else if (seen_vertices < nv) {
        ++seen_vertices;
        check_numbers(line, number, c);
        // OpenMesh reads numbers across line ends: a vertex line must hold
        // its three coordinates (exactly three in plain OFF), all numbers,
        // or what follows is read out of step.
        const std::vector<std::string> w = numeric_words(line, number, kFloatWord, c);
        if (c.problem.empty() && w.size() != 3)
          c.problem = "line " + std::to_string(number) + ": a vertex of " + std::to_string(w.size()) +
                      " numbers (x y z)";
        if (!c.problem.empty())
          return c;
      } else {
        // A face starts with its corner count, which OpenMesh allocates,
        // then names that many vertices.
        ++face_lines;
        const std::vector<std::string> w = numeric_words(line, number, kIntWord, c);
        if (!c.problem.empty())
          return c;
        const long corners = std::strtol(w[0].c_str(), nullptr, 10);
        if (corners < 1 || corners > nv) {
          c.problem = "line " + std::to_string(number) + ": a face of " + w[0] +
                      " corners, but there are only " + std::to_string(nv) + " vertices";
          return c;
        }
        // Plain OFF faces carry no colour: OpenMesh would read extra
        // numbers as the next face.
        if (long(w.size()) != corners + 1) {
          c.problem = "line " + std::to_string(number) + ": a face of " + w[0] + " corners names " +
                      std::to_string(w.size() - 1) + " vertices";
          return c;
        }
        for (long k = 1; k <= corners; ++k) {
          char* end = nullptr;
          const long index = std::strtol(w[std::size_t(k)].c_str(), &end, 10);
          if (*end || index < 0 || index >= nv) {
            c.problem = "line " + std::to_string(number) + ": face " + std::to_string(face_lines - 1) +
                        " names vertex " + w[std::size_t(k)] + ", but there are only " + std::to_string(nv) +
                        " vertices";
            return c;
          }
        }
      }
    }
    // A text OFF file that ends early: OpenMesh would make up the rest (or,
    // without even the counts, wait for them forever).
    if (c.problem.empty() && nv < 0)
      c.problem = "has no counts line (vertices faces edges) after OFF";
    else if (nv > seen_vertices)
      c.problem = "declares " + std::to_string(nv) + " vertices, but the file ends after " +
                  std::to_string(seen_vertices) + " (truncated?)";
    else if (c.declared_faces > face_lines)
      c.problem = "declares " + std::to_string(c.declared_faces) + " faces, but the file ends after " +
                  std::to_string(face_lines) + " (truncated?)";
  } else if (ext == ".ply") {
    bool ascii = false, ended = false;
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
        elements.push_back({w[1], std::stol(w[2]), {}});
        (w[1] == "face" ? nf : nv) += elements.back().count;
      }
      if (w[0] == "property")
        elements.back().lists.push_back(w[1] == "list");
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
    if (ascii)
      check_ply_ascii_body(in, number, elements, nv, c);
  } else if (ext == ".stl") {
    char header[84];
    in.read(header, 84);
    if (in.gcount() == 84 && !starts_with(std::string(header, 5), "solid")) {
      std::uint32_t n = 0;
      std::memcpy(&n, header + 80, 4);
      c.declared_faces = long(n);
    } else {
      in.clear();
      in.seekg(0);
      c.declared_faces = 0;
      while (std::getline(in, line)) {
        ++number;
        const std::size_t first = line.find_first_not_of(" \t");
        if (first == std::string::npos)
          continue;
        if (line.compare(first, 5, "facet") == 0)
          ++c.declared_faces;
        else if (line.compare(first, 6, "vertex") == 0)
          check_numbers(line.substr(first + 6), number, c);
      }
    }
  }
  return c;
}

} // namespace meshpaint
