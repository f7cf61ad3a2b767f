#include "mesh/far_refiner.h"

#include "core/errors.h"

#include <opensubdiv/far/error.h>                  // for Far::SetErrorCallback

#include <opensubdiv/far/primvarRefiner.h>         // for Far::PrimvarRefiner
#include <opensubdiv/far/topologyDescriptor.h>     // for Far::TopologyDescriptor
#include <opensubdiv/far/topologyRefinerFactory.h> // for Far::TopologyRefinerFactory

namespace meshpaint {
namespace {

//! A position as OpenSubdiv's primvar interpolation wants it.
struct Point
{
  Vec3 p{0.f, 0.f, 0.f};
  void Clear(void* = nullptr) { p = {0.f, 0.f, 0.f}; }
  void AddWithWeight(const Point& src, float w)
  {
    p[0] += w * src.p[0];
    p[1] += w * src.p[1];
    p[2] += w * src.p[2];
  }
};

thread_local std::string far_message;

//! OpenSubdiv reports through callbacks that print by default; keep the
//! message for our own error instead.
void keep_error(Far::ErrorType, const char* message) { far_message = message; }
void keep_warning(const char* message) { far_message = message; }

} // namespace

std::unique_ptr<Far::TopologyRefiner> make_refiner(const BaseMesh& mesh)
{
  namespace Sdc = OpenSubdiv::Sdc;
  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);

  Far::TopologyDescriptor desc;
  desc.numVertices = int(mesh.vertex_count());
  desc.numFaces = int(mesh.face_count());
  desc.numVertsPerFace = mesh.face_sizes.data();
  desc.vertIndicesPerFace = mesh.face_vertices.data();

  Far::SetErrorCallback(keep_error);
  Far::SetWarningCallback(keep_warning);
  far_message.clear();
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(
    Factory::Create(desc, Factory::Options(Sdc::SCHEME_CATMARK, options)));
  if (!refiner)
    throw InputError(mesh.name + ": OpenSubdiv rejects the mesh topology" +
                     (far_message.empty() ? std::string() : ": " + far_message));
  return refiner;
}

void refine_uniform(Far::TopologyRefiner& refiner, int level, bool full_topology)
{
  Far::TopologyRefiner::UniformOptions options(level);
  options.fullTopologyInLastLevel = full_topology;
  refiner.RefineUniform(options);
}

std::vector<std::vector<Vec3>> interpolate_levels(const Far::TopologyRefiner& refiner,
                                                  const std::vector<Vec3>& base)
{
  const int levels = refiner.GetMaxLevel();
  std::vector<std::vector<Point>> pts(levels + 1);
  pts[0].resize(base.size());
  for (std::size_t v = 0; v < base.size(); ++v)
    pts[0][v].p = base[v];
  Far::PrimvarRefiner primvar(refiner);
  for (int l = 1; l <= levels; ++l) {
    pts[l].resize(refiner.GetLevel(l).GetNumVertices());
    const Point* src = pts[l - 1].data();
    Point* dst = pts[l].data();
    primvar.Interpolate(l, src, dst);
  }
  std::vector<std::vector<Vec3>> out(levels + 1);
  for (int l = 0; l <= levels; ++l)
    for (const Point& p : pts[l])
      out[l].push_back(p.p);
  return out;
}

} // namespace meshpaint
