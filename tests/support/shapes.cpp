#include "support/shapes.h"

#include <cmath>      // for std::cos, std::sin
#include <filesystem> // for std::filesystem::exists
#include <iterator>   // for std::make_reverse_iterator
#include <map>        // for std::map
#include <stdexcept>  // for std::invalid_argument

#ifndef MESHPAINT_SOURCE_DIR
#error "MESHPAINT_SOURCE_DIR must name the source tree"
#endif

namespace meshpaint::test {

BaseMesh tetrahedron()
{
  return make_base_mesh({{1, 1, 1}, {-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}},
                        {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}, "tetrahedron");
}

BaseMesh cube()
{
  return make_base_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
                        {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}},
                        "cube");
}

BaseMesh mixed_polygons()
{
  std::vector<Vec3> pts;
  for (int z = 0; z < 2; ++z)
    for (int k = 0; k < 5; ++k) {
      const double a = 2.0 * M_PI * k / 5.0;
      pts.push_back({float(std::cos(a)), float(std::sin(a)), float(z * 1.3)});
    }
  std::vector<std::vector<int>> faces = {{4, 3, 2, 1, 0}, {5, 6, 7, 8, 9}};
  for (int k = 0; k < 5; ++k) {
    const int a = k, b = (k + 1) % 5;
    if (k == 2) {
      faces.push_back({a, b, b + 5});
      faces.push_back({a, b + 5, a + 5});
    } else {
      faces.push_back({a, b, b + 5, a + 5});
    }
  }
  return make_base_mesh(pts, faces, "mixed_polygons");
}

BaseMesh genus_two()
{
  const int nx = 5, ny = 3;
  auto filled = [&](int x, int y, int z) {
    if (x < 0 || y < 0 || z != 0 || x >= nx || y >= ny)
      return false;
    return !(y == 1 && (x == 1 || x == 3));
  };
  std::map<std::array<int, 3>, int> index;
  std::vector<Vec3> pts;
  std::vector<std::vector<int>> faces;
  auto vertex = [&](std::array<int, 3> p) {
    auto [it, fresh] = index.emplace(p, int(pts.size()));
    if (fresh)
      pts.push_back({float(p[0]), float(p[1]), float(p[2])});
    return it->second;
  };
  for (int x = 0; x < nx; ++x)
    for (int y = 0; y < ny; ++y) {
      if (!filled(x, y, 0))
        continue;
      for (int a = 0; a < 3; ++a)
        for (int s : {-1, 1}) {
          std::array<int, 3> cell{x, y, 0}, nb = cell;
          nb[a] += s;
          if (filled(nb[0], nb[1], nb[2]))
            continue;
          const int b = (a + 1) % 3, c = (a + 2) % 3;
          std::array<int, 3> o = cell;
          if (s > 0)
            o[a] += 1;
          std::vector<int> f;
          for (auto [db, dc] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
            std::array<int, 3> p = o;
            p[b] += db;
            p[c] += dc;
            f.push_back(vertex(p));
          }
          if (s < 0)
            std::swap(f[1], f[3]);
          faces.push_back(f);
        }
    }
  return make_base_mesh(pts, faces, "genus_two");
}

BaseMesh open_grid()
{
  std::vector<Vec3> pts;
  for (int y = 0; y <= 3; ++y)
    for (int x = 0; x <= 3; ++x)
      pts.push_back({float(x), float(y), float(0.2 * ((x * 7 + y * 3) % 5))});
  std::vector<std::vector<int>> faces;
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x)
      faces.push_back({y * 4 + x, y * 4 + x + 1, (y + 1) * 4 + x + 1, (y + 1) * 4 + x});
  return make_base_mesh(pts, faces, "open_grid");
}

BaseMesh open_fan()
{
  std::vector<Vec3> pts = {{0, 0, 0}};
  for (int k = 0; k <= 5; ++k) {
    const double a = M_PI * k / 5.0;
    pts.push_back({float(std::cos(a)), float(std::sin(a)), float(0.15 * (k % 2))});
  }
  pts.push_back({1.2f, -1.0f, 0.1f});
  pts.push_back({0.1f, -1.1f, -0.2f});
  std::vector<std::vector<int>> faces;
  for (int k = 0; k < 5; ++k)
    faces.push_back({0, k + 1, k + 2});
  faces.push_back({0, 8, 7, 1});
  for (Vec3& p : pts) // away from the origin, so masks that are not translation invariant show
    p = {p[0] + 3.f, p[1] - 2.f, p[2] + 1.f};
  return make_base_mesh(pts, faces, "open_fan");
}

BaseMesh high_valence(int n)
{
  std::vector<Vec3> pts;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * M_PI * k / n;
    pts.push_back({float(std::cos(a)), float(std::sin(a)), 0.f});
  }
  pts.push_back({0.f, 0.f, 1.5f});
  std::vector<std::vector<int>> faces;
  std::vector<int> base;
  for (int k = n - 1; k >= 0; --k)
    base.push_back(k);
  faces.push_back(base);
  for (int k = 0; k < n; ++k)
    faces.push_back({k, (k + 1) % n, n});
  return make_base_mesh(pts, faces, "high_valence");
}

BaseMesh two_components()
{
  const BaseMesh c = cube();
  std::vector<Vec3> pts = c.points;
  for (const Vec3& p : c.points)
    pts.push_back({p[0] + 3.f, p[1] * 0.5f, p[2]});
  std::vector<std::vector<int>> faces;
  for (int copy = 0; copy < 2; ++copy)
    for (std::size_t f = 0; f < c.face_count(); ++f) {
      std::vector<int> face;
      for (int k = 0; k < c.face_sizes[f]; ++k)
        face.push_back(c.face_vertices[c.face_offsets[f] + k] + copy * 8);
      faces.push_back(face);
    }
  return make_base_mesh(pts, faces, "two_components");
}

BaseMesh noisy_sphere(int n, float noise)
{
  std::map<std::array<int, 3>, int> index;
  std::vector<Vec3> pts;
  std::vector<std::vector<int>> faces;
  const auto vertex = [&](std::array<int, 3> g) {
    auto [it, fresh] = index.emplace(g, int(pts.size()));
    if (fresh) {
      const double x = 2.0 * g[0] / n - 1, y = 2.0 * g[1] / n - 1, z = 2.0 * g[2] / n - 1;
      const double len = std::sqrt(x * x + y * y + z * z);
      const double r = 1.0 + noise * std::sin(12.9898 * pts.size() + 78.233);
      pts.push_back({float(r * x / len), float(r * y / len), float(r * z / len)});
    }
    return it->second;
  };
  for (int a = 0; a < 3; ++a)
    for (int side : {0, n}) {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      for (int u = 0; u < n; ++u)
        for (int v = 0; v < n; ++v) {
          std::vector<int> f;
          for (auto [du, dv] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
            std::array<int, 3> g{};
            g[a] = side;
            g[b] = u + du;
            g[c] = v + dv;
            f.push_back(vertex(g));
          }
          if (side == 0)
            std::swap(f[1], f[3]);
          faces.push_back(f);
        }
    }
  return make_base_mesh(pts, faces, "noisy_sphere");
}

BaseMesh flat_grid(int n)
{
  std::vector<Vec3> pts;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x)
      pts.push_back({float(x), float(y), 0.f});
  std::vector<std::vector<int>> faces;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      faces.push_back({y * (n + 1) + x, y * (n + 1) + x + 1, (y + 1) * (n + 1) + x + 1, (y + 1) * (n + 1) + x});
  return make_base_mesh(pts, faces, "flat_grid");
}

BaseMesh wound_inwards(const BaseMesh& mesh)
{
  std::vector<std::vector<int>> faces;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const auto first = mesh.face_vertices.begin() + mesh.face_offsets[f];
    faces.emplace_back(std::make_reverse_iterator(first + mesh.face_sizes[f]), std::make_reverse_iterator(first));
  }
  return make_base_mesh(mesh.points, faces, mesh.name + "_inwards");
}

std::vector<std::string> shape_names()
{
  return {"tetrahedron", "cube", "mixed_polygons", "genus_two", "open_grid", "open_fan", "high_valence",
          "two_components"};
}

BaseMesh shape(const std::string& name)
{
  if (name == "tetrahedron") return tetrahedron();
  if (name == "cube") return cube();
  if (name == "mixed_polygons") return mixed_polygons();
  if (name == "genus_two") return genus_two();
  if (name == "open_grid") return open_grid();
  if (name == "open_fan") return open_fan();
  if (name == "high_valence") return high_valence();
  if (name == "two_components") return two_components();
  throw std::invalid_argument("no test shape " + name);
}

std::string scan_path(const std::string& file)
{
  const std::string path = std::string(MESHPAINT_SOURCE_DIR) + "/data/scans/" + file;
  return std::filesystem::exists(path) ? path : "";
}

} // namespace meshpaint::test
