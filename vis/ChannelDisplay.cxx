#include "ChannelDisplay.h"

#include "SurfaceRendering.h" // for meshpaint::show_materials

#include "core/errors.h" // for meshpaint::InputError
#include "core/format.h" // for meshpaint::index_of_name

#include <vtkActor.h>                 // for vtkActor
#include <vtkColorTransferFunction.h> // for vtkColorTransferFunction
#include <vtkDataArray.h>             // for vtkDataArray
#include <vtkNew.h>                   // for vtkNew
#include <vtkOpenGLPolyDataMapper.h>  // for vtkOpenGLPolyDataMapper
#include <vtkPointData.h>             // for vtkPointData
#include <vtkPolyData.h>              // for vtkPolyData
#include <vtkProperty.h>              // for vtkProperty
#include <vtkShaderProperty.h>        // for vtkShaderProperty
#include <vtkUnsignedCharArray.h>     // for vtkUnsignedCharArray

#include <algorithm> // for std::max, std::min, std::find
#include <cmath>     // for std::fabs, std::lround
#include <set>       // for std::set

namespace meshpaint {
namespace {

//! Distinct colours for label ids without a class (Tableau's ten).
constexpr double kPalette[10][3] = {{0.12, 0.47, 0.71}, {1.00, 0.50, 0.05}, {0.17, 0.63, 0.17}, {0.84, 0.15, 0.16},
                                    {0.58, 0.40, 0.74}, {0.55, 0.34, 0.29}, {0.89, 0.47, 0.76}, {0.50, 0.50, 0.50},
                                    {0.74, 0.74, 0.13}, {0.09, 0.75, 0.81}};

unsigned char byte(double v) { return static_cast<unsigned char>(std::lround(255.0 * std::min(1.0, std::max(0.0, v)))); }

vtkDataArray* channel_array(vtkPolyData* surface, const std::string& name)
{
  vtkDataArray* a = surface->GetPointData()->GetArray(name.c_str());
  if (!a)
    throw InputError("the surface has no '" + name + "' point array to show");
  return a;
}

} // namespace

const std::vector<std::string>& shown_channel_names()
{
  static const std::vector<std::string> names = {"diffuse", "label", "specular", "roughness", "displacement", "mask"};
  return names;
}

const std::string& shown_channel_name(ShownChannel channel) { return shown_channel_names()[std::size_t(channel)]; }

ShownChannel parse_shown_channel(const std::string& name)
{
  return ShownChannel(index_of_name(shown_channel_names(), name, "--show"));
}

std::array<double, 3> label_colour(int id, const std::vector<LabelClass>& labels, bool* has_colour)
{
  if (has_colour)
    *has_colour = true;
  for (const LabelClass& c : labels)
    if (c.id == id)
      return {c.colour[0], c.colour[1], c.colour[2]};
  if (id == 0 && has_colour)
    *has_colour = false;
  const double* p = kPalette[(id % 10 + 10) % 10];
  return {p[0], p[1], p[2]};
}

LabelClass unnamed_label_class(int id)
{
  const std::array<double, 3> c = label_colour(id, {});
  return {id, "label " + std::to_string(id), {float(c[0]), float(c[1]), float(c[2])}};
}

std::vector<LabelClass> shown_label_classes(vtkPolyData* surface, const std::vector<LabelClass>& labels,
                                            const std::vector<int>& hidden)
{
  const auto shown = [&](int id) { return std::find(hidden.begin(), hidden.end(), id) == hidden.end(); };
  std::vector<LabelClass> out;
  std::set<int> named;
  for (const LabelClass& c : labels) {
    named.insert(c.id);
    if (shown(c.id))
      out.push_back(c);
  }
  vtkDataArray* label = surface ? surface->GetPointData()->GetArray("label") : nullptr;
  std::set<int> unnamed;
  long last = 0;
  for (vtkIdType v = 0; label && v < label->GetNumberOfTuples(); ++v) {
    const long id = std::lround(label->GetComponent(v, 0));
    if (id != last && id != 0 && !named.count(int(id))) // 0 without a class: unlabelled surface
      unnamed.insert(int(id));
    last = id;
  }
  for (const int id : unnamed)
    if (shown(id))
      out.push_back(unnamed_label_class(id));
  std::stable_sort(out.begin(), out.end(), [](const LabelClass& a, const LabelClass& b) { return a.id < b.id; });
  return out;
}

vtkSmartPointer<vtkScalarsToColors> channel_colour_map(vtkPolyData* surface, ShownChannel channel)
{
  if (channel != ShownChannel::roughness && channel != ShownChannel::mask && channel != ShownChannel::displacement)
    return nullptr;
  auto map = vtkSmartPointer<vtkColorTransferFunction>::New();
  if (channel == ShownChannel::displacement) {
    double range[2];
    channel_array(surface, "displacement")->GetRange(range, 0);
    const double h = std::max({std::fabs(range[0]), std::fabs(range[1]), 1e-30});
    map->SetColorSpaceToDiverging();
    map->AddRGBPoint(-h, 0.23, 0.30, 0.75);
    map->AddRGBPoint(0.0, 0.87, 0.87, 0.87);
    map->AddRGBPoint(h, 0.71, 0.02, 0.15);
  } else { // a sequential map from dark blue through green to yellow
    map->AddRGBPoint(0.0, 0.27, 0.00, 0.33);
    map->AddRGBPoint(0.5, 0.13, 0.57, 0.55);
    map->AddRGBPoint(1.0, 0.99, 0.91, 0.14);
  }
  return map;
}

vtkSmartPointer<vtkUnsignedCharArray> channel_colours(vtkPolyData* surface, ShownChannel channel,
                                                      const std::vector<LabelClass>& labels,
                                                      const std::vector<int>& hidden)
{
  const vtkIdType n = surface->GetNumberOfPoints();
  auto out = vtkSmartPointer<vtkUnsignedCharArray>::New();
  out->SetName("shown");
  out->SetNumberOfComponents(3);
  out->SetNumberOfTuples(n);
  unsigned char* rgb = out->GetPointer(0);
  if (channel == ShownChannel::label) {
    vtkDataArray* label = channel_array(surface, "label");
    vtkDataArray* diffuse = surface->GetPointData()->GetArray("diffuse");
    // Few distinct ids: remember the last one's colour.
    long last = -1;
    bool coloured = false;
    std::array<double, 3> colour{};
    for (vtkIdType v = 0; v < n; ++v) {
      const long id = std::lround(label->GetComponent(v, 0));
      if (id != last) {
        colour = label_colour(int(id), labels, &coloured);
        coloured = coloured && std::find(hidden.begin(), hidden.end(), int(id)) == hidden.end();
        last = id;
      }
      for (int c = 0; c < 3; ++c)
        rgb[3 * v + c] = byte(coloured ? colour[std::size_t(c)] : diffuse ? diffuse->GetComponent(v, c) : 0.8);
    }
  } else if (channel == ShownChannel::specular || channel == ShownChannel::diffuse) {
    vtkDataArray* a = channel_array(surface, shown_channel_name(channel));
    for (vtkIdType v = 0; v < n; ++v)
      for (int c = 0; c < 3; ++c)
        rgb[3 * v + c] = byte(a->GetComponent(v, c));
  } else {
    vtkDataArray* a = channel_array(surface, shown_channel_name(channel));
    vtkSmartPointer<vtkScalarsToColors> map = channel_colour_map(surface, channel);
    for (vtkIdType v = 0; v < n; ++v) {
      const double* c = map->GetColor(a->GetComponent(v, 0));
      for (int k = 0; k < 3; ++k)
        rgb[3 * v + k] = byte(c[k]);
    }
  }
  return out;
}

void show_channel(vtkActor* actor, vtkPolyData* surface, ShownChannel channel, const std::vector<LabelClass>& labels,
                  const std::vector<int>& hidden)
{
  if (channel == ShownChannel::diffuse) {
    show_materials(actor, surface);
    return;
  }
  vtkNew<vtkPolyData> shown;
  shown->ShallowCopy(surface);
  shown->GetPointData()->AddArray(channel_colours(surface, channel, labels, hidden));
  vtkNew<vtkOpenGLPolyDataMapper> mapper;
  mapper->SetInputData(shown);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("shown");
  mapper->SetColorModeToDirectScalars();
  mapper->ScalarVisibilityOn();
  actor->SetMapper(mapper);
  actor->GetShaderProperty()->ClearAllShaderReplacements(); // show_materials()'s, for arrays this mapper lacks
  vtkProperty* property = actor->GetProperty();
  property->LightingOn();
  property->SetInterpolationToPhong();
  property->SetDiffuse(1.0);
  property->SetAmbient(0.0);
  property->SetSpecular(0.0); // the colours are the channel's, not a material
}

} // namespace meshpaint
