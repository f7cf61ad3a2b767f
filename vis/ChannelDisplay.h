// Which channel a painted surface is drawn with, and the colours that show
// it: the material, label classes in their colours, or a channel through a
// colour map.
#ifndef ChannelDisplay_h
#define ChannelDisplay_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include "project/labels.h" // for meshpaint::LabelClass

#include <vtkSmartPointer.h> // for vtkSmartPointer

#include <array>  // for std::array
#include <string> // for std::string
#include <vector> // for std::vector

class vtkActor;
class vtkPolyData;
class vtkScalarsToColors;
class vtkUnsignedCharArray;

namespace meshpaint {

//! The channel a surface is shown with.
enum class ShownChannel
{
  diffuse, //!< the materials (show_materials())
  label,   //!< label classes in their colours, unlabelled surface in its material
  specular,
  roughness,
  displacement,
  mask
};

//! The names `--show` takes, in the order the window's key cycles them.
MESHPAINTVIS_EXPORT const std::vector<std::string>& shown_channel_names();
MESHPAINTVIS_EXPORT const std::string& shown_channel_name(ShownChannel channel);
//! \throw InputError naming the channels there are.
MESHPAINTVIS_EXPORT ShownChannel parse_shown_channel(const std::string& name);

//! The colour of label `id`: its class's when `labels` has one, else a fixed
//! colour of a ten-colour palette (by id), so that labels painted without
//! classes show too. `has_colour` false: id 0 without a class (unlabelled).
MESHPAINTVIS_EXPORT std::array<double, 3> label_colour(int id, const std::vector<LabelClass>& labels,
                                                       bool* has_colour = nullptr);

//! The entry shown for label `id` painted without a class: "label ID" in
//! label_colour()'s palette colour, as the surface shows it.
MESHPAINTVIS_EXPORT LabelClass unnamed_label_class(int id);

//! The classes a legend of `surface`'s labels lists: those of `labels` not in
//! `hidden`, and an unnamed_label_class() for each id other than 0 painted on
//! the surface without a class (and not hidden), in order of id.
MESHPAINTVIS_EXPORT std::vector<LabelClass> shown_label_classes(vtkPolyData* surface,
                                                                const std::vector<LabelClass>& labels,
                                                                const std::vector<int>& hidden);

//! The colour map of a scalar channel (roughness, mask: 0 to 1; displacement:
//! blue below 0, white at 0, red above, symmetric about 0 over the surface's
//! largest height); null for diffuse, label and specular, which are colours.
MESHPAINTVIS_EXPORT vtkSmartPointer<vtkScalarsToColors> channel_colour_map(vtkPolyData* surface,
                                                                          ShownChannel channel);

//! RGB bytes per point of `surface` (to_polydata() of a painted surface)
//! showing `channel` (not diffuse): labels over the diffuse colour, the
//! specular colour as it is, scalar channels through channel_colour_map().
//! \throw InputError when the surface lacks the channel's array.
//! Label ids in `hidden` show the material, as unlabelled surface does.
MESHPAINTVIS_EXPORT vtkSmartPointer<vtkUnsignedCharArray> channel_colours(vtkPolyData* surface,
                                                                         ShownChannel channel,
                                                                         const std::vector<LabelClass>& labels,
                                                                         const std::vector<int>& hidden = {});

//! Makes `actor` draw `surface` showing `channel`: show_materials() for
//! diffuse, else channel_colours() on a shallow copy, lit by VTK's lights.
MESHPAINTVIS_EXPORT void show_channel(vtkActor* actor, vtkPolyData* surface, ShownChannel channel,
                                      const std::vector<LabelClass>& labels, const std::vector<int>& hidden = {});

} // namespace meshpaint

#endif
