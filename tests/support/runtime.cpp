#include "support/runtime.h"

namespace meshpaint::test {

std::shared_ptr<Runtime> runtime()
{
  static std::shared_ptr<Runtime> rt = Runtime::open();
  return rt;
}

} // namespace meshpaint::test
