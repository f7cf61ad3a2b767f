// What a painted surface is exported as: the one export path of the command
// line (`meshpaint paint -o`), vtkPaintSurface::ExportModel and the window.
#ifndef PaintingExport_h
#define PaintingExport_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include "core/cancellation.h"   // for meshpaint::CancelFlag
#include "core/progress.h"       // for meshpaint::Progress
#include "paint/paint_surface.h" // for meshpaint::PaintSurface
#include "project/labels.h"      // for meshpaint::LabelClass

#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint {

//! The model level exports use unless told otherwise: two levels below the
//! painting level `level`, at least 1.
MESHPAINTVIS_EXPORT int default_model_level(int level);

//! What export_model() and export_painting() wrote.
struct PaintingExportReport
{
  std::string surface_path;  //!< DIR/surface.vtp; empty from export_model()
  std::size_t model_quads = 0;
  int map_width = 0, map_height = 0;
};

//! Creates DIR if missing and writes, each atomically, DIR/model.obj and
//! model.mtl at `model_level` (1 .. the painting level), the PNG texture
//! maps diffuse, specular, roughness, displacement and metallic_roughness,
//! and DIR/model.gltf, the same model as glTF 2.0 using those maps (the
//! window's Ctrl+E). The files land together (AtomicWriteBatch): on an
//! error or when `cancel` is set (looked at between the model, the maps and
//! the files) none is written, the previous ones stay whole and a DIR made
//! for them goes again.
//! \throw IOError when DIR cannot be created or a file not written;
//! StorageError when the disk is full; Cancelled.
MESHPAINTVIS_EXPORT PaintingExportReport export_model(PaintSurface& surface, int model_level, const std::string& dir,
                                                      CancelFlag cancel = nullptr);

//! export_model(), and before it DIR/surface.vtp: the painted limit surface
//! with its channel arrays and the label classes as field data
//! (add_label_classes()) (`meshpaint paint -o DIR`, ExportModel()); one
//! task "writing DIR" on `progress`, a step per file or group of files.
//! \throw IOError when DIR cannot be created or a file not written;
//! StorageError when the disk is full.
MESHPAINTVIS_EXPORT PaintingExportReport export_painting(PaintSurface& surface, int model_level,
                                                         const std::string& dir,
                                                         const std::vector<LabelClass>& labels = {},
                                                         Progress* progress = nullptr);

//! Writes the model at `model_level` as one self-contained glTF 2.0 file,
//! textures inside: binary .glb or text .gltf by the extension of `path`
//! (`meshpaint paint --gltf FILE`). Atomic; `cancel` is looked at between
//! the model, the textures and the write (a cancelled export writes nothing).
//! \throw InputError for another extension; IOError, StorageError as above;
//! Cancelled.
MESHPAINTVIS_EXPORT void export_gltf(PaintSurface& surface, int model_level, const std::string& path,
                                     CancelFlag cancel = nullptr);

//! Creates `dir` and its parents unless it exists (those it made go again
//! when an AtomicWriteBatch living then ends uncommitted).
//! \throw IOError when it cannot.
MESHPAINTVIS_EXPORT void make_directory(const std::string& dir);

} // namespace meshpaint

#endif
