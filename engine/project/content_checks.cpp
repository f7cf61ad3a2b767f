#include "project/content_checks.h"

#include "core/errors.h"
#include "core/format.h"     // for meshpaint::format_number
#include "core/input_file.h" // for meshpaint::kMaxStrokeScriptBytes

#include <cmath> // for std::isfinite, std::fabs, std::round

namespace meshpaint {
namespace {

//! The channel each component of a layer holds ("" where none is named).
const char* component_channel(int layer, int component)
{
  static const char* const kNames[3][4] = {{"diffuse", "diffuse", "diffuse", "diffuse"},
                                           {"specular", "specular", "specular", "specular"},
                                           {"roughness", "displacement", "label", "mask"}};
  return kNames[layer][component];
}

[[noreturn]] void corrupt(const std::string& where, const std::string& what)
{
  throw InputError(where + ": corrupt project (" + what + ")");
}

void check_points(const std::vector<Float4>& texels, const std::string& what, const std::string& where)
{
  for (std::size_t t = 0; t < texels.size(); ++t)
    for (int a = 0; a < 4; ++a) {
      const float x = texels[t][std::size_t(a)];
      if (!std::isfinite(x) || (a < 3 && std::fabs(x) > kMaxCoordinate))
        corrupt(where, what + " " + std::to_string(t) + " has the value " + format_number(x) +
                           " (finite, at most 1e15 in magnitude)");
    }
}

} // namespace

void check_project_content(const Project& p, const std::string& where)
{
  std::vector<std::vector<int>> faces(p.mesh.face_count());
  for (std::size_t f = 0; f < faces.size(); ++f)
    faces[f].assign(p.mesh.face_vertices.begin() + p.mesh.face_offsets[f],
                    p.mesh.face_vertices.begin() + p.mesh.face_offsets[f + 1]);
  try {
    const BaseMesh checked = make_base_mesh(p.mesh.points, faces, "base mesh");
    if (checked.report.changed())
      corrupt(where, "the base mesh needs repairs: " + checked.report.lines().front());
  } catch (const InputError& e) {
    if (std::string(e.what()).find("corrupt project") != std::string::npos)
      throw;
    corrupt(where, e.what());
  }
  check_points(p.positions, "control point", where);
  check_points(p.reference, "reference point", where);
  const std::vector<Float4>* outside[3] = {&p.channels.diffuse, &p.channels.specular, &p.channels.material};
  const std::vector<Float4>* inside[3] = {&p.channels.inside_diffuse, &p.channels.inside_specular,
                                          &p.channels.inside_material};
  for (int side = 0; side < 2; ++side)
    for (int layer = 0; layer < 3; ++layer) {
      const std::vector<Float4>& texels = *(side == 0 ? outside : inside)[layer];
      for (std::size_t t = 0; t < texels.size(); ++t)
        for (int a = 0; a < 4; ++a) {
          // The inside's displacement and label are the outside's: only finite.
          const std::string channel = component_channel(layer, a);
          const bool shared = side == 1 && (channel == "displacement" || channel == "label");
          const float v = texels[t][std::size_t(a)];
          const std::string problem = shared ? (std::isfinite(v) ? "" : "is not finite")
                                             : channel_value_problem(channel, v);
          if (!problem.empty())
            corrupt(where, std::string(side == 1 ? "inside " : "") + channel + " at texel " + std::to_string(t) +
                               " " + problem + " (" + format_number(v) + ")");
        }
    }
  try {
    check_labels(p.labels);
  } catch (const InputError& e) {
    corrupt(where, e.what());
  }
  if (p.history.size() > kMaxStrokeScriptBytes)
    corrupt(where, "a stroke history larger than a stroke script may be");
}

} // namespace meshpaint
