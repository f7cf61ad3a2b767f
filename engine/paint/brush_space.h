// Brush spaces (Hanrahan and Haeberli, section 4): the frames a dab measures
// its distance in, set up on the host once per dab for the kernels.
#pragma once

#include "atlas_types.h" // for BrushDab
#include "core/vec.h"
#include "paint/paint_state.h"
#include "paint/stroke.h" // for Brush, Camera

namespace meshpaint {

//! The brush image's axes in the tangent plane at a dab with unit `normal`:
//! u along the stroke's `heading` projected into the plane (or the world
//! axis most across the normal when there is none), v = normal x u.
void stamp_axes(const Vec3& normal, const Vec3& heading, BrushDab& dab);

//! The camera's frame at the dab's centre: eye, view axes, focal length, and
//! the centre's depth and position on the view plane (what screen brushes
//! and screen patterns project with).
void camera_frame(const Camera& camera, BrushDab& dab);

//! A silhouette for a screen brush (camera_frame() set): the centre lies
//! behind the eye, or the side the dab paints (`normal` times
//! BrushDab::side_sign) turns away from it. Screen strokes end there.
bool at_silhouette(const BrushDab& dab, const Vec3& normal);

//! The dab's brush space at its centre, for `brush`: the centre's limit
//! `normal`, the stamp's axes along `heading`, the camera's frame, and for
//! a parameter-space brush the centre's texel (`closest`) and the texel's
//! size. False where a screen brush meets a silhouette (the stroke ends).
//! The side it paints (BrushDab::side_sign) is set before.
bool aim(const PaintState& state, const Brush& brush, const Vec3& normal, const Vec3& heading,
         const CullRecord& closest, BrushDab& dab);

} // namespace meshpaint
