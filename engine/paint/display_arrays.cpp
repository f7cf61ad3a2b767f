#include "paint/display_arrays.h"

#include "cl/runtime.h"
#include "core/errors.h"

#include <algorithm> // for std::fill

namespace meshpaint {

bool DisplayArrays::supported(const Runtime& runtime) { return runtime.info().host_memory; }

DisplayArrays::DisplayArrays(std::shared_ptr<Runtime> runtime, std::size_t vertices, bool two_sided)
  : runtime_(std::move(runtime)), vertices_(vertices)
{
  arrays_ = {{"Points", 3, false},   {"Normals", 3, false}, {"diffuse", 3, false}, {"specular", 3, false},
             {"roughness", 1, false}, {"displacement", 1, false}, {"mask", 1, false}, {"label", 1, true}};
  if (two_sided)
    arrays_.insert(arrays_.end(), {{"inside_diffuse", 3, false}, {"inside_specular", 3, false},
                                   {"inside_roughness", 1, false}});
  try {
    // Allocated by the implementation in host memory, so that mapping
    // hands out that memory itself rather than a copy.
    for (const Array& a : arrays_)
      buffers_.emplace_back(runtime_->context(), CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR,
                            std::max<std::size_t>(1, vertices_) * std::size_t(a.components) * 4);
    flags_ = cl::Buffer(runtime_->context(), CL_MEM_READ_WRITE, arrays_.size() * sizeof(int));
    mapped_.assign(arrays_.size(), nullptr);
    last_.assign(arrays_.size(), nullptr);
    changed_.assign(arrays_.size(), 0);
    versions_.assign(arrays_.size(), 0);
    map_all();
  } catch (const cl::Error& e) {
    throw DeviceError("cannot share the display arrays with " + runtime_->info().name + ": " + describe(e));
  }
}

DisplayArrays::~DisplayArrays()
{
  try {
    for (std::size_t k = 0; k < buffers_.size(); ++k)
      if (mapped_[k])
        runtime_->queue().enqueueUnmapMemObject(buffers_[k], mapped_[k]);
    runtime_->queue().finish();
  } catch (const cl::Error&) { // nothing to do about it while tearing down
  }
}

void DisplayArrays::map_all()
{
  for (std::size_t k = 0; k < buffers_.size(); ++k)
    if (!mapped_[k])
      mapped_[k] = runtime_->queue().enqueueMapBuffer(buffers_[k], CL_TRUE, CL_MAP_READ | CL_MAP_WRITE, 0,
                                                      std::max<std::size_t>(1, vertices_) *
                                                        std::size_t(arrays_[k].components) * 4);
}

const std::vector<cl::Buffer>& DisplayArrays::begin_write()
{
  for (std::size_t k = 0; k < buffers_.size(); ++k)
    if (mapped_[k]) {
      runtime_->queue().enqueueUnmapMemObject(buffers_[k], mapped_[k]);
      last_[k] = mapped_[k];
      mapped_[k] = nullptr;
    }
  std::fill(changed_.begin(), changed_.end(), 0);
  runtime_->queue().enqueueWriteBuffer(flags_, CL_TRUE, 0, changed_.size() * sizeof(int), changed_.data());
  return buffers_;
}

bool DisplayArrays::end_write() noexcept
{
  try {
    runtime_->queue().enqueueReadBuffer(flags_, CL_TRUE, 0, changed_.size() * sizeof(int), changed_.data());
  } catch (const cl::Error&) {
    std::fill(changed_.begin(), changed_.end(), 1); // unknown: as if all changed
  }
  for (std::size_t k = 0; k < changed_.size(); ++k)
    versions_[k] += changed_[k] != 0;
  try {
    map_all();
  } catch (const cl::Error&) { // unmapped ones stay null; the next write maps them again
  }
  return mapped_ != last_;
}

} // namespace meshpaint
