#include "project/project_surface.h"

#include "atlas/weld.h"
#include "core/errors.h"
#include "core/file_lock.h"

#include <algorithm>  // for std::max
#include <filesystem> // for std::filesystem::equivalent
#include <optional>   // for std::optional
#include <utility>    // for std::move

namespace meshpaint {

std::unique_ptr<PaintSurface> open_project_surface(std::shared_ptr<Runtime> runtime, const Project& project,
                                                   AtlasStorage storage)
{
  auto surface = std::make_unique<PaintSurface>(std::move(runtime), project.mesh, project.level, storage);
  Atlas& atlas = surface->atlas();
  // Saved meshes are already in spatial order, which reordering keeps.
  const std::vector<int>& order = atlas.base_face_order();
  for (std::size_t f = 0; f < order.size(); ++f)
    if (order[f] != int(f))
      throw InputError("project '" + project.mesh.name + "': its base mesh is not in atlas order");
  const std::size_t texels = atlas.layout(project.level).texels();
  if (project.positions.size() != texels)
    throw InputError("project '" + project.mesh.name + "': " + std::to_string(project.positions.size()) +
                     " texels do not fit its level-" + std::to_string(project.level) + " atlas of " +
                     std::to_string(texels));
  atlas.write_positions(project.level, project.positions);
  surface->geometry_changed();
  surface->write_channels(project.channels);
  return surface;
}

WeldedSurface reference_surface(std::shared_ptr<Runtime> runtime, const Project& project, AtlasStorage storage)
{
  Atlas atlas(std::move(runtime), project.mesh, project.level, storage);
  atlas.subdivide(1, project.level);
  if (!project.reference.empty())
    atlas.write_positions(project.level, project.reference);
  return level_surface(atlas, project.level, true);
}

std::vector<Float4> reference_at_level(std::shared_ptr<Runtime> runtime, const Project& project, int level,
                                       AtlasStorage storage)
{
  Atlas atlas(std::move(runtime), project.mesh, std::max(level, project.level), storage);
  atlas.subdivide(1, project.level);
  atlas.write_positions(project.level, project.reference);
  if (level > project.level)
    atlas.subdivide(project.level, level);
  else if (level < project.level)
    atlas.reduce(project.level, level);
  atlas.finish();
  return atlas.read_positions(level);
}

StrokeScript stroke_history(const std::string& history)
{
  return history.empty() ? StrokeScript() : parse_stroke_script(history);
}

std::string continued_history(const std::string& previous, const std::vector<Stroke>& applied, int level)
{
  StrokeScript history = stroke_history(previous);
  history.level = level;
  history.strokes.insert(history.strokes.end(), applied.begin(), applied.end());
  return stroke_script_json(history);
}

void capture_surface(PaintSurface& surface, Project& p)
{
  p.mesh = surface.atlas().base_mesh();
  p.level = surface.level();
  p.positions = surface.atlas().read_positions(p.level);
  p.channels = surface.read_channels();
}

ProjectOrigin save_painted_project(PaintSurface& surface, Project base, const std::string& path, SaveTurn turn)
{
  base.history = continued_history(base.history, surface.history(), surface.level());
  capture_surface(surface, base);
  std::optional<FileLock> lock;
  if (turn == SaveTurn::take)
    lock.emplace(path, nullptr);
  // Checked under the lock: a save between this check and the rename waits.
  std::error_code ec;
  if (!base.origin.path.empty() && std::filesystem::equivalent(base.origin.path, path, ec) &&
      project_header_crc(path) != base.origin.header_crc)
    throw InputError("'" + path + "' was saved by another run after this surface was loaded from or saved to it: "
                     "saving would lose that run's strokes; save under another name");
  return {path, save_project(base, path)};
}

} // namespace meshpaint
