#include "SharedArrays.h"

#include <vtkAbstractArray.h> // for vtkAbstractArray::VTK_DATA_ARRAY_USER_DEFINED
#include <vtkFloatArray.h>    // for vtkFloatArray
#include <vtkIntArray.h>      // for vtkIntArray
#include <vtkPointData.h>     // for vtkPointData
#include <vtkPoints.h>        // for vtkPoints
#include <vtkPolyData.h>      // for vtkPolyData
#include <vtkSmartPointer.h>  // for vtkSmartPointer

#include <map>   // for std::map
#include <mutex> // for std::mutex

namespace meshpaint {
namespace {

// VTK's free callback takes the address alone: the owner of each shared
// address, and how many VTK arrays use it, are looked up here; the owner
// is let go when the last of them is freed.
struct Owner
{
  std::shared_ptr<DisplayArrays> arrays;
  int users = 0;
};
std::mutex owners_mutex;
std::map<void*, Owner>& owners()
{
  static std::map<void*, Owner> map;
  return map;
}

void release(void* data)
{
  std::shared_ptr<DisplayArrays> last; // destroyed outside the lock
  std::lock_guard<std::mutex> lock(owners_mutex);
  const auto it = owners().find(data);
  if (it != owners().end() && --it->second.users == 0) {
    last = std::move(it->second.arrays);
    owners().erase(it);
  }
}

template <typename Array, typename Value>
vtkSmartPointer<vtkDataArray> wrap(const std::shared_ptr<DisplayArrays>& arrays, std::size_t k)
{
  const DisplayArrays::Array& a = arrays->arrays()[k];
  void* data = arrays->data(k);
  {
    std::lock_guard<std::mutex> lock(owners_mutex);
    Owner& owner = owners()[data];
    owner.arrays = arrays;
    ++owner.users;
  }
  auto out = vtkSmartPointer<Array>::New();
  out->SetName(a.name.c_str());
  out->SetNumberOfComponents(a.components);
  out->SetArray(static_cast<Value*>(data), vtkIdType(arrays->vertices()) * a.components, 0,
                vtkAbstractArray::VTK_DATA_ARRAY_USER_DEFINED);
  out->SetArrayFreeFunction(&release);
  return out;
}

//! The array of `poly` that array k stands for (null when it has none).
vtkDataArray* slot(vtkPolyData* poly, const DisplayArrays::Array& a)
{
  if (a.name == "Points")
    return poly->GetPoints() ? poly->GetPoints()->GetData() : nullptr;
  if (a.name == "Normals")
    return poly->GetPointData()->GetNormals();
  return poly->GetPointData()->GetArray(a.name.c_str());
}

void put(vtkPolyData* poly, const std::shared_ptr<DisplayArrays>& arrays, std::size_t k)
{
  const DisplayArrays::Array& a = arrays->arrays()[k];
  const vtkSmartPointer<vtkDataArray> array =
    a.integer ? wrap<vtkIntArray, int>(arrays, k) : wrap<vtkFloatArray, float>(arrays, k);
  if (a.name == "Points")
    poly->GetPoints()->SetData(array);
  else if (a.name == "Normals")
    poly->GetPointData()->SetNormals(array);
  else
    poly->GetPointData()->AddArray(array); // replaces the array of that name
}

} // namespace

void share_arrays(vtkPolyData* poly, const std::shared_ptr<DisplayArrays>& arrays)
{
  for (std::size_t k = 0; k < arrays->arrays().size(); ++k)
    if (slot(poly, arrays->arrays()[k]) && arrays->data(k))
      put(poly, arrays, k);
}

bool refresh_shared_arrays(vtkPolyData* poly, const std::shared_ptr<DisplayArrays>& arrays,
                           std::vector<std::uint64_t>& seen)
{
  bool moved = false;
  seen.resize(arrays->arrays().size(), 0);
  for (std::size_t k = 0; k < arrays->arrays().size(); ++k) {
    vtkDataArray* now = slot(poly, arrays->arrays()[k]);
    if (!now || !arrays->data(k)) // not mapped back: keep what is drawn
      continue;
    if (now->GetVoidPointer(0) != arrays->data(k)) {
      put(poly, arrays, k);
      moved = true;
    } else if (arrays->version(k) != seen[k]) {
      now->Modified();
    }
    seen[k] = arrays->version(k);
  }
  if (moved)
    poly->Modified();
  return moved;
}

} // namespace meshpaint
