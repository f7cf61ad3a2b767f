#include "PolyDataFiles.h"

#include "LegacyPolyDataCheck.h" // for meshpaint::checked_legacy_polydata
#include "XmlPolyDataCheck.h"    // for meshpaint::check_xml_polydata_arrays

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

#include <algorithm>  // for std::transform
#include <cctype>     // for std::tolower
#include <cmath>      // for std::isfinite
#include <cstdlib>    // for std::strtod, std::getenv
#include <filesystem> // for std::filesystem::file_size, path
#include <fstream>    // for std::ifstream
#include <limits>     // for std::numeric_limits
#include <regex>      // for std::regex, std::sregex_iterator
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

//! VTK's XML reader allocates what the header says before reading data:
//! the counts and component numbers of a .vtp are bounded by what the file
//! could hold (polydata_budget()).
void check_xml_polydata_sizes(const std::string& path)
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
    R"re((NumberOf(Points|Polys|Cells|Verts|Lines|Strips|Components|Tuples))="\s*(-?[0-9]+)\s*")re");
  for (auto it = std::sregex_iterator(head.begin(), head.end(), attribute); it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[1].str(), value = (*it)[3].str();
    const double n = std::strtod(value.c_str(), nullptr);
    if (n < 0 || (name == "NumberOfComponents" && n > 4096) || n > budget)
      throw InputError("'" + path + "': " + name + "=\"" + value.substr(0, 20) + "\" is more than the file can hold");
  }
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
  if (lower_extension(path) == ".vtk") {
    // VTK's reader takes the bytes' count as an int.
    if (std::filesystem::file_size(path, ec) > std::uintmax_t(std::numeric_limits<int>::max()))
      throw InputError("'" + path + "': a legacy .vtk file of 2 GiB or more (write it as .vtp)");
    const std::string text = checked_legacy_polydata(path);
    auto r = vtkSmartPointer<vtkPolyDataReader>::New();
    r->ReadFromInputStringOn();
    r->SetBinaryInputString(text.data(), int(text.size()));
    r->ReadAllScalarsOn();
    r->ReadAllColorScalarsOn();
    return read_checked(r, path);
  }
  check_xml_polydata_sizes(path);
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
