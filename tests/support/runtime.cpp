#include "support/runtime.h"

namespace meshpaint::test {

std::shared_ptr<Runtime> runtime()
{
  static std::shared_ptr<Runtime> rt = Runtime::open();
  return rt;
}

std::vector<AtlasStorage> storages()
{
  std::vector<AtlasStorage> s{AtlasStorage::Buffer};
  if (runtime()->info().images)
    s.push_back(AtlasStorage::Image);
  return s;
}

} // namespace meshpaint::test
