// Drawing a painted surface with VTK: its materials as shading, the camera,
// and pictures written to PNG.
#ifndef SurfaceRendering_h
#define SurfaceRendering_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include <string> // for std::string

class vtkActor;
class vtkPolyData;
class vtkRenderer;
class vtkRenderWindow;

namespace meshpaint {

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

//! Resets the camera to the renderer's visible bounds and turns it by `view`.
MESHPAINTVIS_EXPORT void set_camera(vtkRenderer* renderer, const CameraView& view);

//! Renders `window` and writes what it shows as an RGB PNG, atomically.
//! \throw IOError when the file cannot be written.
MESHPAINTVIS_EXPORT void write_screenshot(vtkRenderWindow* window, const std::string& path);

//! Renders `surface` offscreen with show_materials() at width x height
//! pixels and writes the PNG (needs an X display, e.g. under xvfb-run).
MESHPAINTVIS_EXPORT void render_screenshot(vtkPolyData* surface, const CameraView& view, int width, int height,
                                           const std::string& path);

} // namespace meshpaint

#endif
