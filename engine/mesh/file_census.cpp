#include "mesh/file_census.h"

#include <cctype>  // for std::tolower
#include <cstdint> // for std::uint32_t
#include <cstring> // for std::memcpy
#include <fstream> // for std::ifstream
#include <sstream> // for std::istringstream

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

} // namespace

FileCensus take_census(const std::string& path, const std::string& ext)
{
  FileCensus c;
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return c;
  std::string line;
  long number = 0;

  if (ext == ".obj") {
    c.declared_faces = 0;
    while (std::getline(in, line)) {
      ++number;
      if (starts_with(line, "f ") || starts_with(line, "f\t"))
        ++c.declared_faces;
      else if (starts_with(line, "v ") || starts_with(line, "v\t"))
        check_numbers(line.substr(2), number, c);
    }
  } else if (ext == ".off") {
    long nv = -1, seen_vertices = 0;
    while (std::getline(in, line)) {
      ++number;
      const std::size_t hash = line.find('#');
      if (hash != std::string::npos)
        line.erase(hash);
      if (line.find_first_not_of(" \t\r") == std::string::npos)
        continue;
      if (number == 1 && line.find("OFF") != std::string::npos) {
        if (line.find("BINARY") != std::string::npos)
          return c;
        std::istringstream rest(line.substr(line.find("OFF") + 3));
        long f = -1;
        if (rest >> nv >> f)
          c.declared_faces = f;
        continue;
      }
      if (nv < 0) {
        std::istringstream counts(line);
        long f = -1;
        if (!(counts >> nv >> f))
          return c;
        c.declared_faces = f;
      } else if (seen_vertices < nv) {
        ++seen_vertices;
        check_numbers(line, number, c);
      } else {
        break;
      }
    }
  } else if (ext == ".ply") {
    bool ascii = false;
    long nv = 0;
    while (std::getline(in, line)) {
      ++number;
      if (starts_with(line, "format ascii"))
        ascii = true;
      std::istringstream words(line);
      std::string a, b;
      long count = 0;
      if (words >> a >> b >> count && a == "element")
        (b == "face" ? c.declared_faces : nv) = count;
      if (starts_with(line, "end_header"))
        break;
    }
    for (long v = 0; ascii && v < nv && std::getline(in, line); ++v)
      check_numbers(line, ++number, c);
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
