// Laplacian passes over the welded quad mesh of a level: the brush's tiles
// are gathered into one array with an entry per vertex, each pass reads the
// neighbours from there, and the result goes back to every stored copy.
// A pass costs a gather from a compact array per neighbour, where the tile
// kernels it replaces gathered across patches per side and corner.
#pragma once

#include "atlas/atlas.h"
#include "atlas/welded_neighbours.h"
#include "cl/opencl.h"

#include <map>    // for std::map
#include <vector> // for std::vector

namespace meshpaint {

class Runtime;

class WeldedSmoothing
{
public:
  //! The kernels of geometry.cl that read and write a layer, built for its
  //! storage.
  struct LayerKernels
  {
    cl::Kernel gather, scatter;
  };

  WeldedSmoothing(Runtime& runtime, const AtlasTopology& topology, const cl::Program& program);

  //! One pass per step (x + step * w * (mean - x)) over `layer` at level
  //! `l`, on the patches of `set` (host lists taken with Reach::All, or every
  //! patch);
  //! `weights` per texel of that level, patch-major.
  void run(const LayerKernels& kernels, const cl::Memory& layer, const LevelLayout& l, const PatchSet& set,
           const cl::Buffer& weights, const std::vector<float>& steps);
  //! The same on every patch, with nothing written back: the result per
  //! welded vertex (weld_map() order) is read to the host.
  std::vector<Float4> run_welded(const LayerKernels& kernels, const cl::Memory& layer, const LevelLayout& l,
                                 const cl::Buffer& weights, const std::vector<float>& steps);

  //! From dense_from() of a level's vertices moved on, run() passes over
  //! every vertex, those not moved weighing 0, instead of a list of the
  //! moved. The two give the same bits; the setter is for tests that compare
  //! them (0: every vertex always; above 1: lists always).
  static constexpr double kDenseFrom = 0.75;
  double dense_from() const { return dense_from_; }
  void set_dense_from(double share) { dense_from_ = share; }

  //! Device memory that run() allocates for a level of `texels` and
  //! `vertices` (the finest level's bounds every level's).
  static std::size_t bytes(std::size_t texels, std::size_t vertices);

private:
  struct Level
  {
    WeldedNumbering numbering; // the host's part: which vertices a set moves
    std::size_t vertices = 0;
    cl::Buffer vertex_of, texel, first, ring, around;
  };
  Level& level(const LevelLayout& l);
  const cl::Buffer& passes(const LayerKernels& kernels, const cl::Memory& layer, const LevelLayout& l,
                           const PatchSet* set, const cl::Buffer& list, const cl::Buffer& weights,
                           const std::vector<float>& steps);

  Runtime& runtime_;
  const AtlasTopology& topology_;
  cl::Kernel smooth_, listed_weights_;
  std::map<int, Level> levels_;
  cl::Buffer a_, b_, weights_;
  std::size_t capacity_ = 0;
  double dense_from_ = kDenseFrom;
};

} // namespace meshpaint
