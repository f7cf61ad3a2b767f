#include "RasterIO.h"

#include "core/errors.h" // for meshpaint::IOError, InputError
#include "core/format.h" // for meshpaint::lower_extension

#include <vtkDataArray.h>            // for vtkDataArray
#include <vtkImageData.h>            // for vtkImageData
#include <vtkImageReader2.h>         // for vtkImageReader2
#include <vtkImageReader2Factory.h>  // for vtkImageReader2Factory
#include <vtkPointData.h>            // for vtkPointData
#include <vtkSmartPointer.h>         // for vtkSmartPointer
#include <vtkXMLImageDataReader.h>   // for vtkXMLImageDataReader

#include <algorithm>  // for std::min, std::max
#include <filesystem> // for std::filesystem::exists

namespace meshpaint {

Raster load_raster(const std::string& path)
{
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw IOError("cannot open '" + path + "': no such file");
  vtkSmartPointer<vtkImageData> image;
  if (lower_extension(path) == ".vti") {
    auto reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
    if (!reader->CanReadFile(path.c_str()))
      throw IOError("cannot read '" + path + "' as VTK image data");
    reader->SetFileName(path.c_str());
    reader->Update();
    image = reader->GetOutput();
  } else {
    vtkSmartPointer<vtkImageReader2> reader;
    reader.TakeReference(vtkImageReader2Factory::CreateImageReader2(path.c_str()));
    if (!reader)
      throw IOError("cannot read '" + path + "': not an image VTK knows (PNG, JPEG, TIFF, BMP, PNM, .vti)");
    reader->SetFileName(path.c_str());
    reader->Update();
    image = reader->GetOutput();
  }
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
