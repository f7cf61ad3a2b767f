#include "SurfaceRendering.h"

#include "ChannelDisplay.h"  // for meshpaint::show_channel, ShownChannel
#include "DisplayCheck.h"    // for meshpaint::require_display
#include "core/atomic_file.h" // for meshpaint::write_bytes_atomically
#include "core/errors.h"      // for meshpaint::IOError, DeviceError
#include "paint/paint_surface.h" // for meshpaint::PaintSurface
#include "paint/subsurface_light.h" // for meshpaint::scattered_light
#include "SurfaceConversion.h"   // for meshpaint::png_bytes

#include <vtkActor.h>                   // for vtkActor
#include <vtkUnsignedCharArray.h>       // for vtkUnsignedCharArray

#include <algorithm> // for std::min, std::copy
#include <cmath>     // for std::sin, std::cos
#include <vtkCamera.h>                  // for vtkCamera
#include <vtkDataObject.h>              // for vtkDataObject::FIELD_ASSOCIATION_POINTS
#include <vtkFloatArray.h>              // for vtkFloatArray
#include <vtkNew.h>                     // for vtkNew
#include <vtkOpenGLPolyDataMapper.h>    // for vtkOpenGLPolyDataMapper
#include <vtkPointData.h>               // for vtkPointData
#include <vtkPolyData.h>                // for vtkPolyData
#include <vtkProperty.h>                // for vtkProperty
#include <vtkRenderWindow.h>            // for vtkRenderWindow
#include <vtkRenderer.h>                // for vtkRenderer
#include <vtkShaderProgram.h>           // for vtkShader::Vertex, vtkShader::Fragment
#include <vtkShaderProperty.h>          // for vtkShaderProperty
#include <vtkWindowToImageFilter.h>     // for vtkWindowToImageFilter

namespace meshpaint {

void show_materials(vtkActor* actor, vtkPolyData* surface)
{
  vtkNew<vtkOpenGLPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  vtkPointData* pd = surface->GetPointData();
  if (pd->GetArray("diffuse")) {
    // Floats in [0, 1] are colours as they are, no lookup table.
    mapper->SetScalarModeToUsePointFieldData();
    mapper->SelectColorArray("diffuse");
    mapper->SetColorModeToDirectScalars();
    mapper->ScalarVisibilityOn();
  } else {
    mapper->ScalarVisibilityOff();
  }
  actor->SetMapper(mapper);
  vtkProperty* property = actor->GetProperty();
  property->LightingOn(); // show_scattered_light() may have turned it off
  property->SetInterpolationToPhong();
  property->SetDiffuse(1.0);
  property->SetAmbient(0.0);
  property->SetSpecular(1.0); // the specular colour itself carries the strength
  property->SetSpecularColor(0.04, 0.04, 0.04);
  property->SetSpecularPower(30.0);
  if (!pd->GetArray("specular") || !pd->GetArray("roughness"))
    return;
  // Per-vertex specular colour and roughness: VTK's Phong shading takes
  // them as uniforms, so they come in as vertex attributes and replace the
  // uniforms' values after VTK's own colour code has run.
  mapper->MapDataArrayToVertexAttribute("specularMC", "specular", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  mapper->MapDataArrayToVertexAttribute("roughnessMC", "roughness", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  vtkShaderProperty* sp = actor->GetShaderProperty();
  sp->AddVertexShaderReplacement("//VTK::Color::Dec", true,
                                 "//VTK::Color::Dec\n"
                                 "in vec3 specularMC;\nin float roughnessMC;\n"
                                 "out vec3 specularVSOut;\nout float roughnessVSOut;\n",
                                 false);
  sp->AddVertexShaderReplacement("//VTK::Color::Impl", true,
                                 "//VTK::Color::Impl\n"
                                 "  specularVSOut = specularMC;\n  roughnessVSOut = roughnessMC;\n",
                                 false);
  sp->AddFragmentShaderReplacement("//VTK::Color::Dec", true,
                                   "//VTK::Color::Dec\n"
                                   "in vec3 specularVSOut;\nin float roughnessVSOut;\n",
                                   false);
  sp->AddFragmentShaderReplacement("//VTK::Color::Impl", true,
                                   "//VTK::Color::Impl\n"
                                   "  specularColor = specularVSOut;\n"
                                   "  float r2 = pow(clamp(roughnessVSOut, 0.02, 1.0), 2.0);\n"
                                   "  specularPower = max(2.0 / r2 - 2.0, 1.0);\n",
                                   false);
}

void set_camera(vtkRenderer* renderer, const CameraView& view)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0, 0, 1);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  renderer->ResetCamera();
  camera->Azimuth(view.azimuth);
  camera->Elevation(view.elevation);
  camera->OrthogonalizeViewUp();
  camera->Zoom(view.zoom);
  renderer->ResetCameraClippingRange();
}

void write_screenshot(vtkRenderWindow* window, const std::string& path)
{
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  const std::string png = png_bytes(grab->GetOutput(), path);
  write_bytes_atomically(path, {png});
}

void show_scattered_light(vtkActor* actor, vtkPolyData* surface)
{
  vtkPointData* pd = surface->GetPointData();
  vtkDataArray* diffuse = pd->GetArray("diffuse");
  vtkDataArray* light = pd->GetArray("scattered_light");
  if (!diffuse || !light) {
    show_materials(actor, surface);
    return;
  }
  // Extended Reinhard tone mapping, white at 2: bright light saturates
  // smoothly instead of clipping.
  const auto tone = [](double x) { return std::min(1.0, x * (1.0 + x / 4.0) / (1.0 + x)); };
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("lit");
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(surface->GetNumberOfPoints());
  for (vtkIdType v = 0; v < surface->GetNumberOfPoints(); ++v) {
    const double e = 0.15 + 1.6 * light->GetComponent(v, 0);
    for (int c = 0; c < 3; ++c)
      colours->SetValue(3 * v + c, static_cast<unsigned char>(255.0 * tone(diffuse->GetComponent(v, c) * e) + 0.5));
  }
  vtkNew<vtkPolyData> lit;
  lit->ShallowCopy(surface);
  lit->GetPointData()->AddArray(colours);
  vtkNew<vtkOpenGLPolyDataMapper> mapper;
  mapper->SetInputData(lit);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("lit");
  mapper->SetColorModeToDirectScalars();
  mapper->ScalarVisibilityOn();
  actor->SetMapper(mapper);
  actor->GetShaderProperty()->ClearAllShaderReplacements(); // show_materials()'s, for arrays this mapper lacks
  actor->GetProperty()->LightingOff(); // the light is in the colours
}

void add_scattered_light(vtkPolyData* surface, PaintSurface& painted, const std::array<double, 3>& towards_light,
                         int passes)
{
  const std::vector<float> light = scattered_light(
    painted.state(), {float(towards_light[0]), float(towards_light[1]), float(towards_light[2])}, passes);
  vtkNew<vtkFloatArray> array;
  array->SetName("scattered_light");
  array->SetNumberOfValues(vtkIdType(light.size()));
  std::copy(light.begin(), light.end(), array->GetPointer(0));
  surface->GetPointData()->AddArray(array);
}

std::array<double, 3> headlight_direction(const CameraView& view)
{
  // vtkCamera::Azimuth turns about the view up (+y), then Elevation towards it.
  const double az = view.azimuth * M_PI / 180.0, el = view.elevation * M_PI / 180.0;
  return {std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el)};
}

void render_screenshot(vtkPolyData* surface, const CameraView& view, int width, int height, const std::string& path,
                       ShownChannel channel, const std::vector<LabelClass>& labels)
{
  require_display();
  vtkNew<vtkActor> actor;
  if (channel != ShownChannel::diffuse)
    show_channel(actor, surface, channel, labels);
  else if (surface->GetPointData()->GetArray("scattered_light"))
    show_scattered_light(actor, surface);
  else
    show_materials(actor, surface);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.1, 0.1, 0.12);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(width, height);
  set_camera(renderer, view);
  write_screenshot(window, path);
}

} // namespace meshpaint
