#include "RasterIO.h"

#include "core/errors.h" // for meshpaint::IOError, InputError
#include "core/format.h" // for meshpaint::lower_extension
#include "paint/png_check.h" // for meshpaint::png_problem

#include <vtkCallbackCommand.h>      // for vtkCallbackCommand
#include <vtkCommand.h>              // for vtkCommand::ErrorEvent
#include <vtkDataArray.h>            // for vtkDataArray
#include <vtkExecutive.h>            // for vtkExecutive
#include <vtkInformation.h>          // for vtkInformation
#include <vtkImageData.h>            // for vtkImageData
#include <vtkImageReader2.h>         // for vtkImageReader2
#include <vtkImageReader2Factory.h>  // for vtkImageReader2Factory
#include <vtkPointData.h>            // for vtkPointData
#include <vtkSmartPointer.h>         // for vtkSmartPointer
#include <vtkStreamingDemandDrivenPipeline.h> // for vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT
#include <vtkXMLImageDataReader.h>   // for vtkXMLImageDataReader

#include <algorithm>  // for std::min, std::max
#include <filesystem> // for std::filesystem::exists
#include <fstream>    // for std::ifstream

namespace meshpaint {
namespace {

//! Keeps the first error or warning VTK reports on an object instead of
//! printing it: the command line says one line, from the exception.
void keep_message(vtkObject*, unsigned long, void* client, void* call)
{
  auto* kept = static_cast<std::string*>(client);
  if (kept->empty() && call)
    *kept = static_cast<const char*>(call);
}

//! Routes a reader's and its executive's messages into `kept`.
void capture_messages(vtkAlgorithm* reader, std::string& kept)
{
  auto callback = vtkSmartPointer<vtkCallbackCommand>::New();
  callback->SetCallback(keep_message);
  callback->SetClientData(&kept);
  for (vtkObject* o : {static_cast<vtkObject*>(reader), static_cast<vtkObject*>(reader->GetExecutive())}) {
    o->AddObserver(vtkCommand::ErrorEvent, callback);
    o->AddObserver(vtkCommand::WarningEvent, callback);
  }
}

//! VTK's message without its source-file prefix and line ends.
std::string one_line(std::string message)
{
  const std::size_t text = message.rfind("): ");
  if (text != std::string::npos)
    message.erase(0, text + 3);
  for (char& c : message)
    if (c == '\n' || c == '\r')
      c = ' ';
  while (!message.empty() && message.back() == ' ')
    message.pop_back();
  return message;
}

bool has_png_signature(const std::string& path)
{
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  unsigned char head[8] = {};
  std::ifstream in(path, std::ios::binary);
  in.read(reinterpret_cast<char*>(head), 8);
  return in.gcount() == 8 && std::equal(head, head + 8, kSignature);
}

} // namespace

Raster load_raster(const std::string& path)
{
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw IOError("cannot open '" + path + "': no such file");
  if (std::filesystem::file_size(path, ec) == 0)
    throw InputError("cannot read '" + path + "': the file is empty");
  // libpng first: VTK's PNG reader crashes on a damaged file and allocates
  // whatever the header states before reading a row.
  if (has_png_signature(path)) {
    const std::string problem = png_problem(path, kMaxRasterSamples);
    if (!problem.empty())
      throw InputError("cannot read '" + path + "': " + problem);
  }
  std::string message;
  vtkSmartPointer<vtkImageData> image;
  vtkSmartPointer<vtkAlgorithm> source;
  if (lower_extension(path) == ".vti") {
    auto reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
    if (!reader->CanReadFile(path.c_str()))
      throw IOError("cannot read '" + path + "' as VTK image data");
    reader->SetFileName(path.c_str());
    source = reader;
  } else {
    vtkSmartPointer<vtkImageReader2> reader;
    {
      // The factory asks every reader whether it knows the file; some say
      // why not on the console, a probe's answer rather than a problem.
      const int display = vtkObject::GetGlobalWarningDisplay();
      vtkObject::GlobalWarningDisplayOff();
      reader.TakeReference(vtkImageReader2Factory::CreateImageReader2(path.c_str()));
      vtkObject::SetGlobalWarningDisplay(display);
    }
    if (!reader)
      throw IOError("cannot read '" + path + "': not an image VTK knows (PNG, JPEG, TIFF, BMP, PNM, .vti)");
    reader->SetFileName(path.c_str());
    source = reader;
  }
  // The header's extent against the budget before the samples are read.
  capture_messages(source, message);
  source->UpdateInformation();
  int extent[6] = {0, -1, 0, -1, 0, -1};
  source->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  std::uint64_t samples = std::uint64_t(
    std::max(1, vtkImageData::GetNumberOfScalarComponents(source->GetOutputInformation(0))));
  for (int a = 0; a < 3; ++a)
    samples *= std::uint64_t(std::max(0, extent[2 * a + 1] - extent[2 * a] + 1));
  if (message.empty() && samples > kMaxRasterSamples)
    throw InputError("cannot read '" + path + "': " + std::to_string(extent[1] - extent[0] + 1) + " x " +
                     std::to_string(extent[3] - extent[2] + 1) + " x " + std::to_string(extent[5] - extent[4] + 1) +
                     " samples are more than the " + std::to_string(kMaxRasterSamples) + " accepted");
  if (message.empty())
    source->Update();
  if (!message.empty())
    throw InputError("cannot read '" + path + "': " + one_line(message));
  image = vtkImageData::SafeDownCast(source->GetOutputDataObject(0));
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  if (!scalars || scalars->GetNumberOfTuples() == 0)
    throw IOError("cannot read '" + path + "': no samples");
  int dims[3];
  image->GetDimensions(dims);
  Raster r;
  r.width = dims[0];
  r.height = dims[1];
  r.depth = dims[2];
  r.channels = std::min(scalars->GetNumberOfComponents(), 4);
  const bool integer = scalars->GetDataType() != VTK_FLOAT && scalars->GetDataType() != VTK_DOUBLE;
  const double top = integer ? scalars->GetDataTypeMax() : 1.0;
  r.samples.reserve(std::size_t(scalars->GetNumberOfTuples()) * r.channels);
  for (vtkIdType t = 0; t < scalars->GetNumberOfTuples(); ++t)
    for (int c = 0; c < r.channels; ++c)
      r.samples.push_back(float(std::min(1.0, std::max(0.0, scalars->GetComponent(t, c) / top))));
  return r;
}

void load_stroke_rasters(StrokeScript& script)
{
  for (std::size_t k = 0; k < script.strokes.size(); ++k) {
    Stroke& s = script.strokes[k];
    const std::string where = "stroke " + std::to_string(k) + ": ";
    try {
      if (s.pattern() && !s.pattern()->file.empty()) {
        Pattern& pattern = s.paint().pattern;
        auto r = std::make_shared<Raster>(load_raster(pattern.file));
        if (pattern.kind == PATTERN_VOLUME && r->depth < 2)
          throw InputError("'" + pattern.file + "' is a 2D image; a volume pattern needs a 3D .vti file");
        if (pattern.kind == PATTERN_IMAGE && r->depth > 1)
          throw InputError("'" + pattern.file + "' is a volume; use \"type\": \"volume\"");
        pattern.raster = r;
      }
      if (!s.brush.stamp_file.empty()) {
        auto r = std::make_shared<Raster>(load_raster(s.brush.stamp_file));
        if (r->depth > 1)
          throw InputError("'" + s.brush.stamp_file + "' is a volume, not a brush image");
        s.brush.stamp = r;
      }
    } catch (const std::exception& e) {
      throw InputError(where + e.what());
    }
  }
}

} // namespace meshpaint
