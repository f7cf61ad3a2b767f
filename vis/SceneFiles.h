// What the painting window writes (Ctrl+S, Ctrl+E): the session saved and
// the scene's models exported, each object into its own folder.
#ifndef SceneFiles_h
#define SceneFiles_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include "core/cancellation.h" // for meshpaint::CancelFlag
#include "project/labels.h"    // for meshpaint::LabelClass

#include <functional> // for std::function
#include <string>     // for std::string
#include <vector>     // for std::vector

class vtkPolyData;

namespace meshpaint {

class PaintScene;
struct Project;
struct ProjectOrigin;

//! Saves a session into `dir`, each file atomically: DIR/strokes.json (the
//! recording), each object's drawn surface (`drawn(k)`, with its channel
//! arrays and the label classes `labels` as field data) as surface.vtp in
//! PaintScene::folder(dir, k), and with `project`
//! (where the first object came from) that folder's surface.meshpaint, the
//! project continued (save_painted_project(), checked against `origin`, the
//! file last loaded or saved, which becomes the file saved). Returns the
//! status message.
//! \throw IOError when a folder or file cannot be written; InputError as
//! save_painted_project().
MESHPAINTVIS_EXPORT std::string save_session(PaintScene& scene, const std::string& recording,
                         const std::function<vtkPolyData*(std::size_t)>& drawn,
                         const std::vector<LabelClass>& labels, const Project* project, ProjectOrigin& origin,
                         const std::string& dir);

//! Writes each object's model at `model_level` (export_model()) into
//! PaintScene::folder(dir, k), all files landing together; with `cancel`
//! set (looked at between objects and files) none lands. Returns the status
//! message.
//! \throw IOError when a folder or file cannot be written; Cancelled.
MESHPAINTVIS_EXPORT std::string export_scene(PaintScene& scene, int model_level, const std::string& dir,
                                             CancelFlag cancel = nullptr);

} // namespace meshpaint

#endif
