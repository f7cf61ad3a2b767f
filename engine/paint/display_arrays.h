// The painted surface per welded vertex in buffers that live in host memory
// (PoCL's CPU devices, integrated GPUs): a kernel writes what changed, and a
// viewer draws from the same memory without a copy.
#pragma once

#include "cl/opencl.h"

#include <cstddef> // for std::size_t
#include <cstdint> // for std::uint64_t
#include <memory>  // for std::shared_ptr
#include <string>  // for std::string
#include <vector>  // for std::vector

namespace meshpaint {

class Runtime;

class DisplayArrays
{
public:
  //! One array per welded vertex: the arrays of PaintedSurface, by the names
  //! the VTK conversion gives them ("Points", "Normals", "diffuse", ...).
  struct Array
  {
    std::string name;
    int components;
    bool integer; //!< int32, else float
  };

  //! Whether `runtime`'s device can share its memory with the host this way.
  static bool supported(const Runtime& runtime);

  //! Arrays for `vertices` welded vertices (the inside's too when
  //! `two_sided`), mapped for the host; their contents are undefined until
  //! the first write.
  DisplayArrays(std::shared_ptr<Runtime> runtime, std::size_t vertices, bool two_sided);
  ~DisplayArrays();
  DisplayArrays(const DisplayArrays&) = delete;
  DisplayArrays& operator=(const DisplayArrays&) = delete;

  std::size_t vertices() const { return vertices_; }
  const std::vector<Array>& arrays() const { return arrays_; }
  //! Host address of array k; valid until a write moves it (end_write()).
  //! Null while the device holds it, or when mapping it back failed.
  void* data(std::size_t k) const { return mapped_[k]; }
  //! Whether array k changed in the last write.
  bool changed(std::size_t k) const { return changed_[k] != 0; }
  //! How many writes changed array k so far: a viewer that last saw a
  //! smaller count must upload it again, whoever wrote.
  std::uint64_t version(std::size_t k) const { return versions_[k]; }

  //! Gives the buffers to the device (the host must not read them until
  //! end_write()) with every change flag cleared: array k's buffer, then
  //! the flags (one int per array).
  const std::vector<cl::Buffer>& begin_write();
  const cl::Buffer& flags() const { return flags_; }
  //! Back to the host once the device's writes are done (never throws: a
  //! flag it cannot read counts as changed). True when an address moved
  //! (the viewer must wrap the arrays again).
  bool end_write() noexcept;

private:
  void map_all();

  std::shared_ptr<Runtime> runtime_;
  std::size_t vertices_;
  std::vector<Array> arrays_;
  std::vector<cl::Buffer> buffers_;
  std::vector<void*> mapped_; // null: not mapped
  std::vector<void*> last_;   // the addresses before the last write
  std::vector<int> changed_;
  std::vector<std::uint64_t> versions_;
  cl::Buffer flags_;
};

} // namespace meshpaint
