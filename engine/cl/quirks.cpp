#include "cl/quirks.h"

#include <cstdlib> // for setenv

namespace meshpaint {

void apply_runtime_quirks()
{
  // PoCL reads these once, when the ICD loader first initialises it;
  // setenv's last argument 0 leaves a user's own choice in place.
  setenv("POCL_KERNEL_CACHE", "1", 0);
}

} // namespace meshpaint
