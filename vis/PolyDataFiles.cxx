#include "PolyDataFiles.h"

#include "XmlPolyDataCheck.h" // for meshpaint::check_xml_polydata_arrays

#include "core/errors.h" // for meshpaint::IOError, InputError
#include "core/format.h" // for meshpaint::lower_extension, excerpt
#include "project/labels.h" // for meshpaint::LabelClass, check_labels

#include <vtkCellArray.h>         // for vtkCellArray
#include <vtkDataArray.h>         // for vtkDataArray
#include <vtkFieldData.h>         // for vtkFieldData
#include <vtkLogger.h>            // for vtkLogger::SetStderrVerbosity
#include <vtkObjectFactory.h>     // for vtkStandardNewMacro
#include <vtkOutputWindow.h>      // for vtkOutputWindow
#include <vtkPointData.h>         // for vtkPointData
#include <vtkPolyDataReader.h>    // for vtkPolyDataReader
#include <vtkStringArray.h>       // for vtkStringArray
#include <vtkXMLPolyDataReader.h> // for vtkXMLPolyDataReader

#include <algorithm>  // for std::transform, std::any_of
#include <cctype>     // for std::tolower
#include <cmath>      // for std::isfinite
#include <cstdlib>    // for std::strtod, std::getenv
#include <filesystem> // for std::filesystem::file_size, path
#include <initializer_list> // for std::initializer_list
#include <fstream>    // for std::ifstream
#include <iterator>   // for std::istreambuf_iterator
#include <limits>     // for std::numeric_limits
#include <map>        // for std::map
#include <regex>      // for std::regex, std::sregex_iterator
#include <set>        // for std::set
#include <sstream>    // for std::istringstream
#include <vector>     // for std::vector

namespace meshpaint {
namespace {

//! The most bytes a polydata file can describe (zlib compresses at most
//! about 1000 to 1).
double polydata_budget(const std::string& path)
{
  std::error_code ec;
  return 1100.0 * double(std::filesystem::file_size(path, ec));
}

//! VTK's readers allocate what the header says before reading data: counts
//! and component numbers are bounded by what the file could hold
//! (polydata_budget()): the XML attributes of .vtp, the POINTS, POLYGONS,
//! ... and SCALARS/COLOR_SCALARS counts and FIELD array numbers of legacy .vtk.
void check_polydata_sizes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string head(1 << 16, '\0');
  in.read(&head[0], std::streamsize(head.size()));
  head.resize(std::size_t(in.gcount()));
  const auto cut = head.find("<AppendedData");
  if (cut != std::string::npos)
    head.resize(cut);
  const double budget = polydata_budget(path);
  static const std::regex attribute(
    R"re((NumberOf(Points|Polys|Cells|Verts|Lines|Strips|Components|Tuples))="\s*(-?[0-9]+)\s*"|\n(POINTS|POLYGONS|VERTICES|LINES|TRIANGLE_STRIPS|POINT_DATA|CELL_DATA|COLOR_SCALARS [^ \n]+|SCALARS [^ \n]+ [^ \n]+|FIELD [^ \n]+) +(-?[0-9]+))re");
  for (auto it = std::sregex_iterator(head.begin(), head.end(), attribute); it != std::sregex_iterator(); ++it) {
    const bool xml = (*it)[1].matched;
    const std::string name = xml ? (*it)[1].str() : (*it)[4].str(), value = xml ? (*it)[3].str() : (*it)[5].str();
    const double n = std::strtod(value.c_str(), nullptr);
    // For legacy SCALARS and COLOR_SCALARS the number is the components.
    const bool components = name == "NumberOfComponents" || name.rfind("SCALARS", 0) == 0 ||
                            name.rfind("COLOR_SCALARS", 0) == 0;
    if (n < 0 || (components && n > 4096) || n > budget)
      throw InputError("'" + path + "': " + name + (xml ? "=\"" : " ") + value.substr(0, 20) +
                       (xml ? "\"" : "") + " is more than the file can hold");
  }
}

//! VTK's legacy reader takes the layout of the cells from the header's
//! version: a body in version 5's layout (OFFSETS, CONNECTIVITY) under an
//! older or unreadable version makes it dereference a null array (a fuzz
//! finding). The version must read as M.N, and below 5 no line of the file
//! may start a version-5 cell section.
void check_legacy_version(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string first;
  std::getline(in, first);
  static const std::regex version(R"(# vtk DataFile Version ([0-9]{1,4})\.[0-9]{1,4}\s*)");
  std::smatch m;
  if (!std::regex_match(first, m, version))
    throw InputError("'" + path + "': not a legacy VTK file (its first line must be '# vtk DataFile Version M.N')");
  if (std::stoi(m[1].str()) >= 5)
    return;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("OFFSETS ", 0) == 0 || line.rfind("CONNECTIVITY ", 0) == 0)
      throw InputError("'" + path + "': cells in the layout of version 5 (OFFSETS, CONNECTIVITY) under a header of "
                       "version " + m[1].str() + ".x");
}

//! VTK's legacy reader crashes (a null array in ReadMeshSimple) on an ASCII
//! POINTS section cut short by other words (a fuzz finding): in an ASCII
//! file, every POINTS line must be followed by its 3 n numbers.
void check_legacy_points(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int k = 0; k < 3 && std::getline(in, line); ++k) {
  }
  if (line.rfind("ASCII", 0) != 0)
    return; // binary bodies: left to the size checks above
  long number = 3;
  while (std::getline(in, line)) {
    ++number;
    if (line.rfind("POINTS ", 0) != 0)
      continue;
    std::istringstream words(line.substr(7));
    double declared = -1;
    words >> declared;
    const long at = number;
    const long count = long(declared) * 3;
    for (long read = 0; read < count;) {
      std::string word;
      if (!(in >> word))
        throw InputError("'" + path + "': POINTS on line " + std::to_string(at) + " declares " +
                         std::to_string(count / 3) + " points, but the file ends after " + std::to_string(read) +
                         " of their " + std::to_string(count) + " coordinates");
      char* end = nullptr;
      std::strtod(word.c_str(), &end);
      if (end == word.c_str() || *end != '\0')
        throw InputError("'" + path + "': POINTS on line " + std::to_string(at) + " declares " +
                         std::to_string(count / 3) + " points, but coordinate " + std::to_string(read + 1) + " is '" +
                         excerpt(word) + "'");
      ++read;
    }
    return;
  }
}

//! VTK's legacy reader dereferences a null cell array when a cell section
//! is repeated or its line malformed (a fuzz finding): each of POINTS,
//! VERTICES, LINES, POLYGONS and TRIANGLE_STRIPS may start a line once (any
//! case, as VTK reads them), a cell section's line as `KEYWORD n m`, the
//! points' as `POINTS n TYPE`.
void check_legacy_sections(const std::string& path)
{
  static const std::set<std::string> sections{"points", "vertices", "lines", "polygons", "triangle_strips"};
  // A type VTK's reader cannot read leaves the points null (a fuzz finding).
  static const std::set<std::string> point_types{
    "char",         "signed_char", "unsigned_char", "short",        "unsigned_short", "int",       "unsigned_int",
    "long",         "unsigned_long", "vtktypeint64", "vtktypeuint64", "vtkidtype",      "float",     "double"};
  std::ifstream in(path, std::ios::binary);
  std::map<std::string, long> seen;
  long number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.size() > 256)
      continue; // binary data
    std::istringstream words(line);
    std::string key;
    words >> key;
    std::transform(key.begin(), key.end(), key.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (!sections.count(key))
      continue;
    const std::string where = "'" + path + "': line " + std::to_string(number) + " ('" + excerpt(line, 40) + "') ";
    if (seen.count(key))
      throw InputError(where + "repeats the section of line " + std::to_string(seen[key]));
    seen[key] = number;
    long long cells = -1, size = -1;
    std::string type, more;
    if (key == "points") {
      words >> cells >> type;
      std::transform(type.begin(), type.end(), type.begin(), [](unsigned char c) { return char(std::tolower(c)); });
      if (cells < 0 || !point_types.count(type) || (words >> more))
        throw InputError(where + "is not 'POINTS N TYPE' with a number type");
    } else if (!(words >> cells >> size) || cells < 0 || size < 0 || (words >> more)) {
      throw InputError(where + "is not '" + key + " CELLS SIZE'");
    }
  }
}

//! Whether a lower-case word starts as one of VTK's string array types
//! (its reader compares only the start of the name).
bool is_string_type(const std::string& type)
{
  return type.rfind("string", 0) == 0 || type.rfind("utf8_string", 0) == 0 || type.rfind("unicode_string", 0) == 0;
}

//! Whether a word is a count: digits only.
bool is_count(const std::string& word)
{
  return !word.empty() && word.find_first_not_of("0123456789") == std::string::npos;
}

//! VTK's legacy reader takes the length of each string in a binary string
//! array from the data and allocates it unchecked (a fuzz finding: 2^56
//! bytes for a CONNECTIVITY declared utf8_string). meshpaint reads no string
//! arrays: in a binary file, a line declaring one is refused.
void check_legacy_binary_strings(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int k = 0; k < 3 && std::getline(in, line); ++k) {
  }
  if (line.rfind("BINARY", 0) != 0)
    return;
  long number = 3;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    const auto space = line.find_last_of(' ');
    if (space == std::string::npos || line.size() > 256)
      continue;
    std::string type = line.substr(space + 1);
    std::transform(type.begin(), type.end(), type.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    // VTK's reader compares only the start of the type's name.
    if (is_string_type(type))
      throw InputError("'" + path + "': line " + std::to_string(number) + " ('" + excerpt(line, 40) +
                       "') declares a binary string array, which VTK's reader cannot read safely (write the file "
                       "as ASCII or .vtp)");
  }
  // VTK's reader takes words, not lines: a type may also follow its count
  // on the next line, or be run into it ("24string" reads as 24, then
  // "string"). A string type where the reader takes a type is refused too.
  in.clear();
  in.seekg(0);
  std::string before[2]; // the two words before this one, the nearer first
  for (std::string word; in >> word;) {
    std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    const std::size_t digits = word.find_first_not_of("0123456789");
    const std::string type = digits == std::string::npos ? "" : word.substr(digits);
    const auto one_of = [](const std::string& w, std::initializer_list<const char*> any) {
      return std::any_of(any.begin(), any.end(), [&](const char* a) { return w == a; });
    };
    const bool typed = (digits > 0 && is_count(before[0])) || (digits == 0 && is_count(before[0]) && is_count(before[1])) ||
                       one_of(before[1], {"scalars", "vectors", "normals", "tensors", "global_ids", "pedigree_ids", "points"}) ||
                       one_of(before[0], {"offsets", "connectivity"});
    if (typed && is_string_type(type))
      throw InputError("'" + path + "': the word '" + excerpt(word, 40) +
                       "' declares a binary string array, which VTK's reader cannot read safely (write the file "
                       "as ASCII or .vtp)");
    before[1] = std::move(before[0]);
    before[0] = std::move(word);
  }
}

//! VTK's legacy reader sizes a field array from its header, `NAME
//! COMPONENTS TUPLES TYPE`, without checking the two counts (a fuzz
//! finding: -4 tuples, then a write far outside the array). Read word by
//! word as the reader reads, two counts before one of its number types must
//! both be at least 0 and describe no more values than the file could hold.
void check_legacy_array_counts(const std::string& path)
{
  static const std::set<std::string> types{
    "bit",          "char",          "signed_char",   "unsigned_char", "short",     "unsigned_short",
    "int",          "unsigned_int",  "long",          "unsigned_long", "float",     "double",
    "vtkidtype",    "vtktypeint64",  "vtktypeuint64"};
  const double budget = polydata_budget(path);
  std::ifstream in(path, std::ios::binary);
  std::string before[2]; // the two words before this one, the nearer first
  const auto count = [](const std::string& w, double& n) {
    if (w.empty() || w.find_first_not_of("-0123456789") != std::string::npos || w.find('-', 1) != std::string::npos)
      return false;
    n = std::strtod(w.c_str(), nullptr);
    return true;
  };
  for (std::string word; in >> word;) {
    std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    double components = 0, tuples = 0;
    if (types.count(word) && count(before[1], components) && count(before[0], tuples) &&
        (components < 0 || tuples < 0 || components * tuples > budget))
      throw InputError("'" + path + "': an array declared with " + excerpt(before[1], 20) + " components and " +
                       excerpt(before[0], 20) + " tuples of " + word +
                       " (counts must be 0 or more and fit in the file)");
    before[1] = std::move(before[0]);
    before[0] = std::move(word);
  }
}

//! The legacy file's bytes without its METADATA blocks (each from its
//! keyword line to the next empty line, as VTK writes them). They hold only
//! component names and array information, which nothing here reads, and
//! VTK's parser of them hangs or reads past its buffers on damaged ones
//! (fuzz findings).
std::string legacy_without_metadata(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // VTK's reader takes any line whose first 8 bytes read "metadata" in any
  // case (a fuzz finding: "METADATA" run into other bytes) as such a block.
  const auto starts_block = [&](std::size_t start) {
    if (start + 8 > text.size())
      return false;
    for (std::size_t k = 0; k < 8; ++k)
      if (std::tolower(static_cast<unsigned char>(text[start + k])) != "metadata"[k])
        return false;
    return true;
  };
  for (std::size_t at = text.find('\n'); at != std::string::npos;) {
    const std::size_t start = at + 1;
    if (starts_block(start)) {
      const std::size_t end = text.find("\n\n", start);
      text.erase(start, end == std::string::npos ? std::string::npos : end + 2 - start);
      continue; // the line now at `start` may start another
    }
    at = text.find('\n', start);
  }
  return text;
}

//! VTK's messages while a reader runs, kept instead of printed: the output
//! window and the logger's console output are swapped out for that time
//! and restored after, whatever happens.
class KeptVtkMessages : public vtkOutputWindow
{
public:
  static KeptVtkMessages* New();
  vtkTypeMacro(KeptVtkMessages, vtkOutputWindow);

  void DisplayText(const char* text) override
  {
    if (first.empty() && text)
      first = text;
    if (passed_on && text)
      passed_on->DisplayText(text);
  }

  //! The first message's text, without VTK's "ERROR: In FILE, line N" and
  //! the object's name and address.
  std::string message() const
  {
    std::string text = first;
    if (text.rfind("ERROR: In ", 0) == 0 || text.rfind("Warning: In ", 0) == 0)
      text.erase(0, text.find('\n') + 1);
    const auto address = text.find("): ");
    if (address != std::string::npos && address < 80)
      text.erase(0, address + 3);
    const auto end = text.find('\n');
    if (end != std::string::npos)
      text.erase(end);
    // Read from memory, the legacy reader names no file after it.
    const auto file = text.find(" for file: ");
    if (file != std::string::npos && text.find_first_not_of(' ', file + 11) == std::string::npos)
      text.erase(file);
    return excerpt(text, 200); // it may quote the file's bytes
  }

  std::string first;
  //! Where the messages also go when MESHPAINT_LIBRARY_MESSAGES is 1 (for
  //! looking into a failure, as the command line documents); else null.
  vtkOutputWindow* passed_on = nullptr;
};
vtkStandardNewMacro(KeptVtkMessages);

//! Installs a KeptVtkMessages for its lifetime.
class VtkMessagesKept
{
public:
  VtkMessagesKept() : previous_(vtkOutputWindow::GetInstance()), verbosity_(vtkLogger::GetCurrentVerbosityCutoff())
  {
    kept = vtkSmartPointer<KeptVtkMessages>::New();
    const char* through = std::getenv("MESHPAINT_LIBRARY_MESSAGES");
    vtkOutputWindow::SetInstance(kept);
    if (through && std::string(through) == "1")
      kept->passed_on = previous_; // printed through VTK's log, so that stays on
    else
      vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~VtkMessagesKept()
  {
    vtkOutputWindow::SetInstance(previous_);
    vtkLogger::SetStderrVerbosity(verbosity_);
  }
  VtkMessagesKept(const VtkMessagesKept&) = delete;
  VtkMessagesKept& operator=(const VtkMessagesKept&) = delete;

  vtkSmartPointer<KeptVtkMessages> kept;

private:
  vtkSmartPointer<vtkOutputWindow> previous_;
  vtkLogger::Verbosity verbosity_;
};

//! VTK's legacy polydata reader releases a FIELD block of the dataset
//! section without checking that it could be read (a null pointer when it
//! could not), goes on reading after points it could not read (from a
//! closed file), and imports cells of the layout before version 5 without
//! checking that each cell's count stays within the list (a read past it):
//! fuzz findings. This walks that section first with the reader's own
//! parts, as the reader will, and refuses the file when its points or one
//! of its FIELD blocks do not read or a cell list does not fit its size;
//! what else goes wrong is left for the reader to report.
class LegacyDatasetCheck : public vtkPolyDataReader
{
public:
  static LegacyDatasetCheck* New();
  vtkTypeMacro(LegacyDatasetCheck, vtkPolyDataReader);

  //! \throw InputError when the points or a FIELD block of the dataset
  //! section cannot be read or a cell list of the old layout does not fit
  //! its size.
  void check(const std::string& text, const std::string& path)
  {
    ReadFromInputStringOn();
    SetBinaryInputString(text.data(), int(text.size()));
    VtkMessagesKept messages;
    if (!OpenVTKFile() || !ReadHeader())
      return;
    if (next().rfind("dataset", 0) == 0 && next().rfind("polydata", 0) == 0)
      walk(path);
    CloseVTKFile();
  }

private:
  //! The next word, lower case; empty at the end.
  std::string next()
  {
    char word[256];
    return ReadString(word) ? std::string(LowerCase(word)) : std::string();
  }

  void walk(const std::string& path)
  {
    auto points = vtkSmartPointer<vtkPolyData>::New();
    for (std::string key = next(); !key.empty(); key = next()) {
      if (key.rfind("field", 0) == 0) {
        VtkMessagesKept reading; // its own reason, not an earlier section's
        vtkFieldData* fields = ReadFieldData();
        if (!fields) {
          const std::string why = reading.kept->message();
          throw InputError("'" + path + "': the dataset's FIELD data cannot be read" + (why.empty() ? "" : ": " + why));
        }
        fields->Delete();
      } else if (key.rfind("points", 0) == 0) {
        vtkIdType n = 0;
        if (!Read(&n))
          return;
        // The reader goes on after points it could not read, from a file
        // it may have closed (a null stream: a fuzz finding).
        VtkMessagesKept reading;
        if (!ReadPointCoordinates(points, n)) {
          const std::string why = reading.kept->message();
          throw InputError("'" + path + "': its points cannot be read" + (why.empty() ? "" : ": " + why));
        }
      } else if (key.rfind("vertices", 0) == 0 || key.rfind("lines", 0) == 0 || key.rfind("polygons", 0) == 0 ||
                 key.rfind("triangle_strips", 0) == 0) {
        skip_cells(key, path);
      } else {
        return; // the point and cell data, or a word the reader will refuse
      }
    }
  }

  //! \throw InputError when the cell section `key` cannot be read: VTK 9.1's
  //! reader goes on after a cell list of the old layout it could not read,
  //! from the file it closed (a null stream: a fuzz finding).
  void skip_cells(const std::string& key, const std::string& path)
  {
    VtkMessagesKept reading;
    const auto refuse = [&] {
      const std::string why = reading.kept->message();
      throw InputError("'" + path + "': its " + key + " cannot be read" + (why.empty() ? "" : ": " + why));
    };
    if (GetFileMajorVersion() >= 5) {
      vtkSmartPointer<vtkCellArray> cells;
      if (!ReadCells(cells))
        refuse();
      return;
    }
    vtkIdType cells = 0, size = 0;
    if (!Read(&cells) || !Read(&size) || size < 0)
      refuse();
    std::vector<int> ids(static_cast<std::size_t>(size));
    if (!ReadCellsLegacy(size, ids.data()))
      refuse();
    // Each cell is its count, then that many point ids; the reader takes
    // them until the list ends, wherever the counts point.
    std::size_t at = 0;
    while (at < ids.size()) {
      const int n = ids[at];
      if (n < 0 || std::size_t(n) >= ids.size() - at)
        throw InputError("'" + path + "': a cell of the " + key + " (entry " + std::to_string(at) + ") counts " +
                         std::to_string(n) + " points, more than its list of " + std::to_string(size) +
                         " entries holds");
      at += 1 + std::size_t(n);
    }
  }
};
vtkStandardNewMacro(LegacyDatasetCheck);

//! Colours as ParaView, MeshLab's VTK export and Blender's VTK add-ons write
//! them: 3 or 4 unsigned bytes per point (alpha ignored), as the point
//! scalars or an array named Colors, RGB or RGBA (any case); null if none.
vtkDataArray* byte_colours(vtkPolyData* poly)
{
  vtkPointData* pd = poly->GetPointData();
  std::vector<vtkDataArray*> candidates{pd->GetScalars()};
  for (int k = 0; k < pd->GetNumberOfArrays(); ++k) {
    std::string name = pd->GetArrayName(k) ? pd->GetArrayName(k) : "";
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (name == "colors" || name == "rgb" || name == "rgba")
      candidates.push_back(pd->GetArray(k));
  }
  for (vtkDataArray* a : candidates)
    if (a && a->GetDataType() == VTK_UNSIGNED_CHAR && (a->GetNumberOfComponents() == 3 || a->GetNumberOfComponents() == 4) &&
        a->GetNumberOfTuples() == poly->GetNumberOfPoints())
      return a;
  return nullptr;
}

//! Every numeric point array with a value per point, for take_channel_arrays().
void read_point_arrays(vtkPolyData* poly, PolygonSoup& soup)
{
  vtkPointData* pd = poly->GetPointData();
  const vtkIdType points = poly->GetNumberOfPoints();
  for (int k = 0; k < pd->GetNumberOfArrays(); ++k) {
    vtkDataArray* a = pd->GetArray(k);
    if (!a || !a->GetName() || a->GetNumberOfTuples() != points || a->GetNumberOfComponents() < 1)
      continue;
    VertexArray v;
    v.name = a->GetName();
    v.components = a->GetNumberOfComponents();
    v.integer = a->GetDataType() != VTK_FLOAT && a->GetDataType() != VTK_DOUBLE;
    v.values.resize(std::size_t(points) * std::size_t(v.components));
    for (vtkIdType t = 0; t < points; ++t)
      for (int c = 0; c < v.components; ++c)
        v.values[std::size_t(t) * std::size_t(v.components) + std::size_t(c)] = a->GetComponent(t, c);
    soup.arrays.push_back(std::move(v));
  }
}

//! The label classes named by the field data label_ids, label_names and
//! label_colors, as add_label_classes() writes them; none without label_ids.
void read_label_classes(vtkPolyData* poly, PolygonSoup& soup, const std::string& where)
{
  vtkFieldData* fd = poly->GetFieldData();
  vtkDataArray* ids = fd ? fd->GetArray("label_ids") : nullptr;
  if (!ids)
    return;
  auto* names = vtkStringArray::SafeDownCast(fd->GetAbstractArray("label_names"));
  vtkDataArray* colours = fd->GetArray("label_colors");
  const vtkIdType n = ids->GetNumberOfTuples();
  if (ids->GetNumberOfComponents() != 1 || !names || names->GetNumberOfValues() != n || !colours ||
      colours->GetNumberOfComponents() != 3 || colours->GetNumberOfTuples() != n)
    throw InputError(where + "the field data label_ids, label_names and label_colors do not agree (one id, one "
                     "name and one RGB byte colour per class)");
  std::vector<LabelClass> classes(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i) {
    LabelClass& c = classes[std::size_t(i)];
    const double id = ids->GetComponent(i, 0);
    if (!(id >= 0 && id <= double(kMaxLabelId)))
      throw InputError(where + "label_ids entry " + std::to_string(i) + " is not an id from 0 to " +
                       std::to_string(kMaxLabelId));
    c.id = int(id);
    c.name = names->GetValue(i);
    for (int a = 0; a < 3; ++a)
      c.colour[std::size_t(a)] = float(std::min(255.0, std::max(0.0, colours->GetComponent(i, a))) / 255.0);
  }
  try {
    check_labels(classes);
  } catch (const InputError& e) {
    throw InputError(where + "label classes of the field data: " + e.what());
  }
  for (const LabelClass& c : classes)
    soup.label_classes.push_back({c.id, c.name, c.colour});
}

//! The offsets of `cells` as VTK's traversal trusts them to be: from 0,
//! never decreasing, never beyond the connectivity. Damaged files give
//! others (fuzz findings: a decrease made a cell of negative size, a first
//! offset far past the connectivity a read out of bounds).
//! \throw InputError starting with `where`, naming the cell.
void check_cell_offsets(vtkCellArray* cells, const std::string& where, const char* cell)
{
  vtkDataArray* offsets = cells->GetOffsetsArray();
  if (!offsets)
    return;
  const double ids = double(cells->GetNumberOfConnectivityIds());
  double previous = 0;
  for (vtkIdType k = 0; k < offsets->GetNumberOfValues(); ++k) {
    const double at = offsets->GetComponent(k, 0);
    if (k == 0 && at != 0)
      throw InputError(where + "the first " + cell + " offset is " + std::to_string((long long)at) + ", not 0");
    if (at < previous)
      throw InputError(where + cell + " " + std::to_string(k - 1) + " has " + std::to_string((long long)(at - previous)) +
                       " points: the cell offsets decrease");
    if (at > ids)
      throw InputError(where + cell + " " + std::to_string(k - 1) + " ends at offset " + std::to_string((long long)at) +
                       ", past the " + std::to_string((long long)ids) + " point ids of the connectivity");
    previous = at;
  }
}

} // namespace

bool is_polydata_path(const std::string& path)
{
  const std::string ext = lower_extension(path);
  return ext == ".vtp" || ext == ".vtk";
}

vtkSmartPointer<vtkPolyData> read_checked(vtkAlgorithm* reader, const std::string& path)
{
  std::string message;
  {
    VtkMessagesKept messages;
    reader->Update();
    message = messages.kept->message();
  }
  vtkPolyData* out = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  const std::string where = "cannot read '" + path + "': ";
  if (!message.empty())
    throw InputError(where + message);
  if (reader->GetErrorCode() != 0 || !out || out->GetNumberOfPoints() == 0)
    throw InputError(where + "not a readable " + lower_extension(path).substr(1) + " file with points");
  for (vtkIdType v = 0; v < out->GetNumberOfPoints(); ++v) {
    double x[3];
    out->GetPoint(v, x);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      throw InputError(where + "point " + std::to_string(v) + " is not finite");
  }
  // Cells naming points the file does not have would be written out as invalid cells.
  const vtkIdType points = out->GetNumberOfPoints();
  for (vtkCellArray* cells : {out->GetVerts(), out->GetLines(), out->GetPolys(), out->GetStrips()}) {
    if (!cells)
      continue;
    check_cell_offsets(cells, where, "cell");
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    vtkIdType cell = 0;
    for (cells->InitTraversal(); cells->GetNextCell(n, ids); ++cell) {
      for (vtkIdType k = 0; k < n; ++k)
        if (ids[k] < 0 || ids[k] >= points)
          throw InputError(where + "cell " + std::to_string(cell) + " names point " + std::to_string(ids[k]) +
                           ", but there are only " + std::to_string(points));
    }
  }
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(out);
  return copy;
}

vtkSmartPointer<vtkPolyData> read_polydata_file(const std::string& path)
{
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw IOError("cannot open '" + path + "': no such file");
  if (std::filesystem::file_size(path, ec) == 0)
    throw InputError("'" + path + "' is empty");
  check_polydata_sizes(path);
  if (lower_extension(path) == ".vtk") {
    check_legacy_version(path);
    check_legacy_points(path);
    check_legacy_binary_strings(path);
    check_legacy_array_counts(path);
    check_legacy_sections(path);
    // VTK's reader takes the bytes' count as an int.
    if (std::filesystem::file_size(path, ec) > std::uintmax_t(std::numeric_limits<int>::max()))
      throw InputError("'" + path + "': a legacy .vtk file of 2 GiB or more (write it as .vtp)");
    auto r = vtkSmartPointer<vtkPolyDataReader>::New();
    const std::string text = legacy_without_metadata(path);
    vtkSmartPointer<LegacyDatasetCheck>::New()->check(text, path);
    r->ReadFromInputStringOn();
    r->SetBinaryInputString(text.data(), int(text.size()));
    r->ReadAllScalarsOn();
    r->ReadAllColorScalarsOn();
    return read_checked(r, path);
  }
  {
    VtkMessagesKept kept; // the parser's own messages: VTK's reader repeats what matters
    check_xml_polydata_arrays(path, polydata_budget(path));
  }
  auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  r->SetFileName(path.c_str());
  return read_checked(r, path);
}

BaseMesh import_polydata(vtkPolyData* poly, const std::string& name, const std::string& where,
                         const ImportOptions& options)
{
  if (!poly)
    throw InputError(where + "has no faces");
  PolygonSoup soup;
  soup.points.reserve(std::size_t(poly->GetNumberOfPoints()));
  for (vtkIdType v = 0; v < poly->GetNumberOfPoints(); ++v) {
    double x[3];
    poly->GetPoint(v, x);
    soup.points.push_back({float(x[0]), float(x[1]), float(x[2])});
  }
  const vtkIdType points = poly->GetNumberOfPoints();
  if (vtkCellArray* polys = poly->GetPolys()) {
    check_cell_offsets(polys, where, "polygon");
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    for (polys->InitTraversal(); polys->GetNextCell(n, ids);) {
      for (vtkIdType k = 0; k < n; ++k)
        if (ids[k] < 0 || ids[k] >= points)
          throw InputError(where + "polygon " + std::to_string(soup.faces.size()) + " names point " +
                           std::to_string(ids[k]) + ", but there are only " + std::to_string(points));
      soup.faces.emplace_back(ids, ids + n);
    }
  }
  // Byte colours, unless an array becomes the diffuse channel (take_channel_arrays()).
  if (vtkDataArray* bytes = byte_colours(poly))
    for (vtkIdType v = 0; v < points; ++v)
      soup.colours.push_back({float(bytes->GetComponent(v, 0) / 255.0), float(bytes->GetComponent(v, 1) / 255.0),
                              float(bytes->GetComponent(v, 2) / 255.0)});
  read_point_arrays(poly, soup);
  read_label_classes(poly, soup, where);
  // The first integer, one-component point array named as labels are.
  for (const std::string& label : label_array_names()) {
    vtkDataArray* ids = poly->GetPointData()->GetArray(label.c_str());
    const bool integral = ids && ids->GetDataType() != VTK_FLOAT && ids->GetDataType() != VTK_DOUBLE;
    if (!integral || ids->GetNumberOfComponents() != 1 || ids->GetNumberOfTuples() != points)
      continue;
    for (vtkIdType v = 0; v < points; ++v) {
      const double id = ids->GetComponent(v, 0);
      if (!(id >= 0 && id <= double(1 << 24)))
        throw InputError(where + "point " + std::to_string(v) + " has " + label + " " + std::to_string((long long)id) +
                         ", outside 0 to " + std::to_string(1 << 24));
      soup.labels.push_back(int(id));
    }
    soup.label_array = label;
    break;
  }
  return import_mesh(std::move(soup), name, where, options);
}

BaseMesh load_polydata_mesh(const std::string& path, const ImportOptions& options)
{
  vtkSmartPointer<vtkPolyData> poly = read_polydata_file(path);
  return import_polydata(poly, std::filesystem::path(path).stem().string(), "'" + path + "': ", options);
}

} // namespace meshpaint
