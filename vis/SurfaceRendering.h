// Drawing a painted surface with VTK: its materials as shading, the camera,
// and pictures written to PNG.
#ifndef SurfaceRendering_h
#define SurfaceRendering_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include "ChannelDisplay.h" // for meshpaint::ShownChannel
#include "project/labels.h" // for meshpaint::LabelClass

#include <array>  // for std::array
#include <string> // for std::string
#include <vector> // for std::vector

class vtkActor;
class vtkPolyData;
class vtkRenderer;
class vtkRenderWindow;

namespace meshpaint {

class PaintSurface;

//! A view direction relative to VTK's default camera (looking down -z at the
//! bounds): azimuth and elevation in degrees, then zoom (> 1: closer).
struct CameraView
{
  double azimuth = 0, elevation = 0, zoom = 1;
};

//! Makes `actor` draw `surface` (the point arrays of to_polydata() for a
//! painted surface) with its materials: "diffuse" as colour, "specular" as
//! the specular colour and "roughness" as the Blinn-Phong exponent
//! 2 / r^2 - 2, per vertex; positions already carry the displacement.
//! Arrays it lacks fall back to the actor's property.
MESHPAINTVIS_EXPORT void show_materials(vtkActor* actor, vtkPolyData* surface);

//! The paper's high-quality look (Ritschel et al., section 7): `surface`
//! drawn with the colour baked from its "diffuse" and "scattered_light"
//! arrays (ambient plus the light diffused in atlas space, tone-mapped),
//! VTK's own lighting off. show_materials() where there is no light array.
MESHPAINTVIS_EXPORT void show_scattered_light(vtkActor* actor, vtkPolyData* surface);

//! Adds to `surface` (to_polydata() of `painted`) the point array
//! "scattered_light": the light arriving from direction `towards_light`
//! diffused over the atlas in `passes` passes (scattered_light(), subsurface_light.h).
//! An array of that name already there is replaced.
MESHPAINTVIS_EXPORT void add_scattered_light(vtkPolyData* surface, PaintSurface& painted,
                                             const std::array<double, 3>& towards_light, int passes);

//! The direction towards the camera (VTK's headlight) of `view`, in the
//! frame of the default camera, which looks down -z with +y up.
MESHPAINTVIS_EXPORT std::array<double, 3> headlight_direction(const CameraView& view);

//! Resets the camera to the renderer's visible bounds and turns it by `view`.
MESHPAINTVIS_EXPORT void set_camera(vtkRenderer* renderer, const CameraView& view);

//! Renders `window` and writes what it shows as an RGB PNG, atomically.
//! \throw IOError when the file cannot be written.
MESHPAINTVIS_EXPORT void write_screenshot(vtkRenderWindow* window, const std::string& path);

//! Renders `surface` offscreen with show_materials() (show_scattered_light()
//! when it has a "scattered_light" array), or showing another `channel`
//! (show_channel(), label classes coloured as `labels` say), at width x
//! height pixels and writes the PNG.
//! \throw DeviceError when there is no X display to render with (require_display()).
MESHPAINTVIS_EXPORT void render_screenshot(vtkPolyData* surface, const CameraView& view, int width, int height,
                                           const std::string& path, ShownChannel channel = ShownChannel::diffuse,
                                           const std::vector<LabelClass>& labels = {});

} // namespace meshpaint

#endif
