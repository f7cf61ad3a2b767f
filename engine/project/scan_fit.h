// Fitting an atlas to a scan: the finest level's limit surface moved onto
// the scanned surface, and how far the two stay apart.
#pragma once

#include "atlas/atlas.h"
#include "core/progress.h"
#include "mesh/base_mesh.h"

#include <array>      // for std::array
#include <functional> // for std::function
#include <memory>     // for std::unique_ptr
#include <string>     // for std::string
#include <vector>     // for std::vector

namespace meshpaint {

//! Closest points and ray hits on a triangle surface
//! (aabb_surface_queries() answers with CGAL's AABB tree). The fit asks
//! from several threads at once: the const methods must allow that.
class SurfaceQuery
{
public:
  virtual ~SurfaceQuery() = default;
  //! The point of the surface closest to `p`.
  virtual Vec3 closest_point(const Vec3& p) const = 0;
  //! The triangle (its index as given) closest to `p`, and the point on it
  //! in `closest`; -1 when the surface has no triangle with area.
  virtual int closest_triangle(const Vec3& p, Vec3& closest) const = 0;
  //! The first point where the segment from `a` to `b` meets the surface.
  virtual bool first_hit(const Vec3& a, const Vec3& b, Vec3& hit) const = 0;
};

//! Builds a query over triangles (indices into points).
using SurfaceQueryFactory = std::function<std::unique_ptr<SurfaceQuery>(
  const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles)>;

//! Distances between two surfaces in one direction, world units.
struct FitError
{
  double rms = 0;
  double max = 0;
  Vec3 worst{};  //!< the point of `from` farthest from `to`
};

//! RMS and largest distance from each of `from` to the closest point of
//! `to`, and the point of `from` at that largest distance.
FitError surface_distance(const SurfaceQuery& to, const std::vector<Vec3>& from);

struct FitReport
{
  FitError scan_to_surface;   //!< from every scan vertex to the fitted limit surface
  FitError surface_to_scan;   //!< from every welded finest vertex to the scan
  double diagonal = 0;        //!< of the scan's bounding box
  std::size_t points = 0;     //!< welded finest-level vertices fitted
  std::size_t ray_misses = 0; //!< of those, in the last pass, moved to the closest point instead
  std::vector<int> folded;    //!< patches with a finest quad facing against the limit normal
  std::vector<int> stretched; //!< patches whose area grew or shrank more than 4 times
};

struct FitOptions
{
  int passes = 2; //!< limit evaluations and corrections
  //! Receives each pass as a task (steps: points moved) and notes between
  //! them; may be null.
  Progress* progress = nullptr;
  //! The scan's query, built beforehand (fit builds it while the scan is
  //! decimated); null: fit_atlas() makes it with its factory.
  const SurfaceQuery* scan_query = nullptr;
};

//! Smallest scan area fit_atlas() accepts, relative to the squared diagonal.
constexpr double kMinScanArea = 1e-9;

//! The scan's area (its triangles', in double precision).
double scan_area(const BaseMesh& scan);

//! The scan's faces fanned into triangles.
std::vector<std::array<int, 3>> triangles_of(const BaseMesh& mesh);

//! Fits the atlas's finest level to the scan. Each pass takes every welded
//! finest vertex's limit position P and normal N, looks for the scan along
//! the normal line through P (the closer hit of the two directions, within
//! four times the distance to the closest scan point), takes the closest
//! scan point where the line misses, and moves the control points by the
//! difference, so that the limit surface converges onto the scan; a pass's
//! steps that turn over a finest quad that was not folded before are
//! shortened until none does (halved, then dropped). Then it measures the
//! distances both ways and flags folded and stretched patches.
//! The atlas's coarser levels are left as subdivided.
//! \throw InputError when the scan has no area (kMinScanArea), or when a
//! pass would move the surface to non-finite positions or beyond
//! kMaxCoordinate.
FitReport fit_atlas(Atlas& atlas, const BaseMesh& scan, const SurfaceQueryFactory& make_query,
                    const FitOptions& options = FitOptions());

} // namespace meshpaint
