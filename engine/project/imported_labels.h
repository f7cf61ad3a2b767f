// A mesh file's own label ids carried onto a fresh painting surface as its
// label channel, with a label class for each id.
#pragma once

#include "mesh/base_mesh.h"
#include "paint/paint_surface.h"
#include "project/labels.h"

#include <vector> // for std::vector

namespace meshpaint {

//! When the surface's base mesh has labels (BaseMesh::labels), carries them
//! to the painting level and sets them as the label channel; does nothing
//! otherwise. Each id's 0/1 field over the base vertices is refined by
//! Catmull-Clark's weights (as OpenSubdiv interpolates any vertex data,
//! keeping the four largest at each vertex) and a refined vertex takes the
//! id whose field is largest there: the id of the base vertices nearest in
//! the subdivision's sense; an exact tie goes to the smallest id. Only ids of
//! the file appear. Not a stroke: no undo step.
void apply_imported_labels(PaintSurface& surface);

//! The classes the file names (BaseMesh::label_classes), and a class for
//! each other distinct id but 0 (unlabelled) of `mesh.labels`, named
//! "label ID", with a colour made from the id; ascending by id, empty when
//! there are none.
std::vector<LabelClass> imported_label_classes(const BaseMesh& mesh);

} // namespace meshpaint
