#include "reference/opensubdiv_reference.h"

#include "atlas/patch_layout.h"
#include "atlas/weld.h"
#include "mesh/far_refiner.h"

#include <opensubdiv/far/primvarRefiner.h>    // for Far::PrimvarRefiner
#include <opensubdiv/far/stencilTable.h>      // for Far::StencilTable
#include <opensubdiv/far/stencilTableFactory.h> // for Far::StencilTableFactory
#include <opensubdiv/osd/cpuEvaluator.h>      // for Osd::CpuEvaluator
#include <opensubdiv/osd/cpuVertexBuffer.h>   // for Osd::CpuVertexBuffer

#include <chrono>    // for std::chrono
#include <cmath>     // for std::sqrt
#include <stdexcept> // for std::logic_error

namespace meshpaint {
namespace {

namespace Osd = OpenSubdiv::Osd;

struct Point
{
  float p[3] = {0.f, 0.f, 0.f};
  void Clear(void* = nullptr) { p[0] = p[1] = p[2] = 0.f; }
  void AddWithWeight(const Point& s, float w)
  {
    for (int a = 0; a < 3; ++a)
      p[a] += w * s.p[a];
  }
};

Vec3 to_vec(const Point& q) { return {q.p[0], q.p[1], q.p[2]}; }

} // namespace

ReferenceLevel opensubdiv_level(const BaseMesh& mesh, int level, bool limit)
{
  auto refiner = make_refiner(mesh);
  refine_uniform(*refiner, level, limit);
  std::vector<Point> cur(mesh.vertex_count()), next;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
    for (int a = 0; a < 3; ++a)
      cur[v].p[a] = mesh.points[v][a];
  Far::PrimvarRefiner primvar(*refiner);
  for (int l = 1; l <= level; ++l) {
    next.assign(refiner->GetLevel(l).GetNumVertices(), Point());
    const Point* src = cur.data();
    Point* dst = next.data();
    primvar.Interpolate(l, src, dst);
    cur.swap(next);
  }
  ReferenceLevel out;
  for (const Point& q : cur)
    out.points.push_back(to_vec(q));
  if (limit) {
    std::vector<Point> pos(cur.size()), du(cur.size()), dv(cur.size());
    const Point* src = cur.data();
    Point *p = pos.data(), *u = du.data(), *w = dv.data();
    primvar.Limit(src, p, u, w);
    for (std::size_t v = 0; v < cur.size(); ++v) {
      out.limit_points.push_back(to_vec(pos[v]));
      const float* a = du[v].p;
      const float* b = dv[v].p;
      Vec3 n = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
      const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      for (float& c : n)
        c /= len;
      out.limit_normals.push_back(n);
    }
  }
  return out;
}

std::vector<int> opensubdiv_vertex_order(const BaseMesh& mesh, const AtlasTopology& topo, int level)
{
  auto refiner = make_refiner(mesh);
  refine_uniform(*refiner, level, false);
  static const int dxy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

  // Per patch, the Far face and rotation of each level-l cell: cell corner k
  // is Far face vertex (k + rot) % 4.
  struct Cell
  {
    int face, rot;
  };
  int n = 1;
  std::vector<Cell> cells(topo.patch_count);
  for (int p = 0; p < topo.patch_count; ++p)
    cells[p] = {p, 0};
  for (int l = 1; l < level; ++l) {
    const auto& lev = refiner->GetLevel(l);
    const auto& child = refiner->GetLevel(l + 1);
    std::vector<Cell> finer(std::size_t(topo.patch_count) * 4 * n * n);
    for (int p = 0; p < topo.patch_count; ++p)
      for (int cj = 0; cj < n; ++cj)
        for (int ci = 0; ci < n; ++ci) {
          const Cell c = cells[(std::size_t(p) * n + cj) * n + ci];
          const auto fv = lev.GetFaceVertices(c.face);
          const auto kids = lev.GetFaceChildFaces(c.face);
          for (int k = 0; k < 4; ++k) {
            const int cv = lev.GetVertexChildVertex(fv[(k + c.rot) % 4]);
            Cell found{-1, 0};
            for (int kid : kids) {
              const auto kv = child.GetFaceVertices(kid);
              for (int m = 0; m < kv.size(); ++m)
                if (kv[m] == cv)
                  found = {kid, (m - k + 4) % 4};
            }
            if (found.face < 0)
              throw std::logic_error("no child face at a corner of Far face " + std::to_string(c.face));
            const int x = 2 * ci + dxy[k][0], y = 2 * cj + dxy[k][1];
            finer[(std::size_t(p) * 2 * n + y) * 2 * n + x] = found;
          }
        }
    cells.swap(finer);
    n *= 2;
  }

  const LevelLayout layout = level_layout(topo.patch_count, level);
  const std::vector<int> weld = weld_map(topo, layout);
  const auto& last = refiner->GetLevel(level);
  std::vector<int> order(topo.unique_vertices(level), -1);
  for (int p = 0; p < topo.patch_count; ++p) {
    for (int cj = 0; cj < n; ++cj)
      for (int ci = 0; ci < n; ++ci) {
        const Cell c = cells[(std::size_t(p) * n + cj) * n + ci];
        const auto fv = last.GetFaceVertices(c.face);
        for (int k = 0; k < 4; ++k) {
          const int id = weld[layout.index(p, ci + dxy[k][0], cj + dxy[k][1])];
          const int osd = fv[(k + c.rot) % 4];
          if (order[id] >= 0 && order[id] != osd)
            throw std::logic_error("welded vertex " + std::to_string(id) + " is two Far vertices");
          order[id] = osd;
        }
      }
  }
  return order;
}

struct StencilPeer::Impl
{
  std::unique_ptr<const Far::StencilTable> stencils;
  std::unique_ptr<Osd::CpuVertexBuffer> src, dst;
  std::size_t base_points = 0;
};

StencilPeer::StencilPeer(const BaseMesh& mesh, int level) : impl_(std::make_unique<Impl>())
{
  const auto t0 = std::chrono::steady_clock::now();
  auto refiner = make_refiner(mesh);
  refine_uniform(*refiner, level, false);
  Far::StencilTableFactory::Options options;
  options.generateIntermediateLevels = false; // only the last level's vertices
  options.factorizeIntermediateLevels = true; // weights straight from the base points
  options.generateOffsets = true;
  impl_->stencils.reset(Far::StencilTableFactory::Create(*refiner, options));
  build_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

  const int nsrc = int(mesh.vertex_count()), ndst = impl_->stencils->GetNumStencils();
  impl_->base_points = std::size_t(nsrc);
  impl_->src.reset(Osd::CpuVertexBuffer::Create(3, nsrc));
  impl_->dst.reset(Osd::CpuVertexBuffer::Create(3, ndst));
  impl_->src->UpdateData(&mesh.points[0][0], 0, nsrc);
}

StencilPeer::~StencilPeer() = default;

void StencilPeer::evaluate()
{
  const Osd::BufferDescriptor desc(0, 3, 3);
  Osd::CpuEvaluator::EvalStencils(impl_->src.get(), desc, impl_->dst.get(), desc, impl_->stencils.get());
}

std::size_t StencilPeer::vertices() const { return std::size_t(impl_->stencils->GetNumStencils()); }

std::size_t StencilPeer::stencil_weights() const { return impl_->stencils->GetControlIndices().size(); }

std::size_t StencilPeer::bytes_moved() const
{
  // Tables (size + offset per stencil, index + weight per entry), the base
  // points read once and the level written once; repeated gathers of the
  // same base point are counted as cache hits.
  return vertices() * (8 + 12) + stencil_weights() * 8 + impl_->base_points * 12;
}

std::vector<Vec3> StencilPeer::result() const
{
  const float* d = impl_->dst->BindCpuBuffer();
  std::vector<Vec3> out(vertices());
  for (std::size_t v = 0; v < out.size(); ++v)
    out[v] = {d[3 * v], d[3 * v + 1], d[3 * v + 2]};
  return out;
}

} // namespace meshpaint
