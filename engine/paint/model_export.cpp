#include "paint/model_export.h"

#include "atlas/weld.h"
#include "core/atomic_file.h"
#include "core/errors.h"
#include "paint/paint_surface.h"

#include <algorithm> // for std::min, std::max, std::clamp
#include <cstdarg>   // for va_list
#include <cstdio>    // for std::vsnprintf

namespace meshpaint {

void build_export(PaintSurface& surface, int model_level, ExportModel& model, TextureMaps& maps)
{
  Atlas& atlas = surface.atlas();
  const int level = surface.level();
  if (model_level < 1 || model_level > level)
    throw InputError("model level " + std::to_string(model_level) + " must be from 1 to the painting level " +
                     std::to_string(level));
  const LevelLayout fine = atlas.layout(level), coarse = atlas.layout(model_level);
  const int step = fine.n / coarse.n, pitch = fine.tile + 2;
  const std::vector<Float4> pos = atlas.read_limit_positions(), nrm = atlas.read_limit_normals();
  const PaintChannels ch = surface.read_channels();

  // Texture maps: tile p at (p % tiles_x, p / tiles_x) * pitch, texel (i, j)
  // one pixel in from the tile's corner; the gutter repeats the border.
  maps.width = fine.tiles_x * pitch;
  maps.height = fine.tiles_y * pitch;
  const std::size_t pixels = std::size_t(maps.width) * maps.height;
  maps.diffuse.assign(3 * pixels, 0.f);
  maps.specular.assign(3 * pixels, 0.f);
  maps.roughness.assign(pixels, 0.f);
  maps.displacement.assign(pixels, 0.f);
  const bool two_sided = !ch.inside_diffuse.empty();
  if (two_sided) {
    maps.inside_diffuse.assign(3 * pixels, 0.f);
    maps.inside_specular.assign(3 * pixels, 0.f);
    maps.inside_roughness.assign(pixels, 0.f);
  }
  maps.displacement_min = maps.displacement_max = ch.material.empty() ? 0.f : ch.material[0][1];
  for (const Float4& m : ch.material) {
    maps.displacement_min = std::min(maps.displacement_min, m[1]);
    maps.displacement_max = std::max(maps.displacement_max, m[1]);
  }
  std::array<std::array<double, 4>, 2> sums{}; // specular rgb and roughness, outside and inside
  for (int p = 0; p < fine.patches; ++p) {
    const int ox = (p % fine.tiles_x) * pitch, oy = (p / fine.tiles_x) * pitch;
    for (int y = 0; y < pitch; ++y)
      for (int x = 0; x < pitch; ++x) {
        const int i = std::clamp(x - 1, 0, fine.n), j = std::clamp(y - 1, 0, fine.n);
        const std::size_t t = fine.index(p, i, j), px = std::size_t(oy + y) * maps.width + ox + x;
        for (int c = 0; c < 3; ++c) {
          maps.diffuse[3 * px + c] = ch.diffuse[t][c];
          maps.specular[3 * px + c] = ch.specular[t][c];
        }
        maps.roughness[px] = ch.material[t][0];
        maps.displacement[px] = ch.material[t][1];
        for (int c = 0; c < 3; ++c)
          sums[0][c] += ch.specular[t][c];
        sums[0][3] += ch.material[t][0];
        if (two_sided) {
          for (int c = 0; c < 3; ++c) {
            maps.inside_diffuse[3 * px + c] = ch.inside_diffuse[t][c];
            maps.inside_specular[3 * px + c] = ch.inside_specular[t][c];
            sums[1][c] += ch.inside_specular[t][c];
          }
          maps.inside_roughness[px] = ch.inside_material[t][0];
          sums[1][3] += ch.inside_material[t][0];
        }
      }
  }
  const double count = std::max(1.0, double(fine.patches) * pitch * pitch);
  for (int side = 0; side < 2; ++side) {
    for (int c = 0; c < 3; ++c)
      maps.mean_specular[side][c] = float(sums[side][c] / count);
    maps.mean_roughness[side] = float(sums[side][3] / count);
  }

  // Model: the coarse level's welded vertices, placed at the matching fine
  // texels of the limit surface; each quad corner's texture coordinate is
  // the centre of that texel's pixel.
  const std::vector<int> weld = weld_map(atlas.topology(), coarse);
  model.mesh = WeldedSurface();
  model.mesh.level = model_level;
  model.mesh.points.resize(atlas.topology().unique_vertices(model_level));
  model.mesh.normals.resize(model.mesh.points.size());
  model.uvs.clear();
  for (int p = 0; p < coarse.patches; ++p) {
    const int ox = (p % fine.tiles_x) * pitch, oy = (p / fine.tiles_x) * pitch;
    for (int j = 0; j <= coarse.n; ++j)
      for (int i = 0; i <= coarse.n; ++i) {
        const std::size_t t = fine.index(p, i * step, j * step);
        const int v = weld[coarse.index(p, i, j)];
        model.mesh.points[v] = {pos[t][0], pos[t][1], pos[t][2]};
        model.mesh.normals[v] = {nrm[t][0], nrm[t][1], nrm[t][2]};
      }
    static const int corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int j = 0; j < coarse.n; ++j)
      for (int i = 0; i < coarse.n; ++i) {
        std::array<int, 4> quad;
        for (int k = 0; k < 4; ++k) {
          const int ci = i + corner[k][0], cj = j + corner[k][1];
          quad[k] = weld[coarse.index(p, ci, cj)];
          const float px = float(ox + 1 + ci * step) + 0.5f, py = float(oy + 1 + cj * step) + 0.5f;
          model.uvs.push_back({px / float(maps.width), 1.f - py / float(maps.height)});
        }
        model.mesh.quads.push_back(quad);
      }
  }
}

float phong_exponent(float roughness)
{
  const double a = double(roughness) * double(roughness);
  if (a <= 0.0)
    return 1000.f;
  return float(std::clamp(2.0 / (a * a) - 2.0, 0.0, 1000.0));
}

namespace {

//! printf into a growing string: the files are built in memory and written
//! by write_bytes_atomically(), which checks every byte.
void append(std::string& out, const char* format, ...) __attribute__((format(printf, 2, 3)));
void append(std::string& out, const char* format, ...)
{
  char line[512];
  va_list args;
  va_start(args, format);
  const int n = std::vsnprintf(line, sizeof line, format, args);
  va_end(args);
  if (n < 0)
    return;
  if (std::size_t(n) < sizeof line) {
    out.append(line, std::size_t(n));
    return;
  }
  std::string long_line(std::size_t(n) + 1, '\0');
  va_start(args, format);
  std::vsnprintf(long_line.data(), long_line.size(), format, args);
  va_end(args);
  out.append(long_line.data(), std::size_t(n));
}

//! One MTL material: `prefix` is "" or "inside_" for the map names.
void append_material(std::string& out, const char* name, const char* prefix, const Vec3& ks, float roughness)
{
  append(out, "newmtl %s\nKa 0 0 0\nKd 1 1 1\nKs %.6g %.6g %.6g\nNs %.6g\nillum 2\n", name, double(ks[0]),
         double(ks[1]), double(ks[2]), double(phong_exponent(roughness)));
  append(out, "map_Kd %sdiffuse.png\nmap_Ks %sspecular.png\nmap_Pr %sroughness.png\ndisp displacement.png\n", prefix,
         prefix, prefix);
}

} // namespace

void write_obj_model(const ExportModel& model, const TextureMaps& maps, const std::string& dir)
{
  std::string mtl;
  const float range = maps.displacement_max - maps.displacement_min;
  append(mtl,
         "# meshpaint: the paint channels as texture maps\n"
         "# displacement.png is 16-bit: height = %.9g + %.9g * pixel / 65535 (world units,\n"
         "# along the normal); the model's points are not displaced.\n"
         "# Ks and Ns: the painted specular colour and roughness (as a Phong exponent), means over the surface.\n",
         double(maps.displacement_min), double(range));
  append_material(mtl, "painted", "", maps.mean_specular[0], maps.mean_roughness[0]);
  if (!maps.inside_diffuse.empty()) {
    mtl += "\n# the inside of the two-sided surface\n";
    append_material(mtl, "inside", "inside_", maps.mean_specular[1], maps.mean_roughness[1]);
  }
  write_bytes_atomically(dir + "/model.mtl", {mtl});

  std::string obj;
  obj.reserve(model.mesh.points.size() * 96 + model.mesh.quads.size() * 64);
  append(obj, "# meshpaint model: level %d, %zu vertices, %zu quads\nmtllib model.mtl\nusemtl painted\n",
         model.mesh.level, model.mesh.points.size(), model.mesh.quads.size());
  for (const Vec3& p : model.mesh.points)
    append(obj, "v %.9g %.9g %.9g\n", double(p[0]), double(p[1]), double(p[2]));
  const bool two_sided = !maps.inside_diffuse.empty();
  for (const float sign : {1.f, -1.f}) // the inside faces the other way
    if (sign > 0.f || two_sided)
      for (const Vec3& n : model.mesh.normals)
        append(obj, "vn %.7g %.7g %.7g\n", double(sign * n[0]), double(sign * n[1]), double(sign * n[2]));
  for (const auto& uv : model.uvs)
    append(obj, "vt %.9g %.9g\n", double(uv[0]), double(uv[1]));
  const int nv = int(model.mesh.normals.size());
  for (std::size_t q = 0; q < model.mesh.quads.size(); ++q) {
    obj += "f";
    for (int k = 0; k < 4; ++k) {
      const int v = model.mesh.quads[q][k] + 1;
      append(obj, " %d/%zu/%d", v, 4 * q + k + 1, v);
    }
    obj += "\n";
  }
  if (two_sided) {
    obj += "usemtl inside\n";
    for (std::size_t q = 0; q < model.mesh.quads.size(); ++q) {
      obj += "f";
      for (int k = 3; k >= 0; --k) {
        const int v = model.mesh.quads[q][std::size_t(k)] + 1;
        append(obj, " %d/%zu/%d", v, 4 * q + std::size_t(k) + 1, v + nv);
      }
      obj += "\n";
    }
  }
  write_bytes_atomically(dir + "/model.obj", {obj});
}

} // namespace meshpaint
