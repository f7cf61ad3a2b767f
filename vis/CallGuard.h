// Calls from VTK classes into the engine: exceptions become a message.
#ifndef CallGuard_h
#define CallGuard_h

#include "cl/opencl.h" // for cl::Error, meshpaint::describe

#include <exception> // for std::exception
#include <string>    // for std::string

namespace meshpaint {

//! Runs `f`, keeping any exception's message in `error` (cleared first);
//! 1 on success, 0 on failure, as VTK methods report.
template <typename F>
int guarded(std::string& error, F&& f)
{
  error.clear();
  try {
    f();
    return 1;
  } catch (const cl::Error& e) {
    error = describe(e);
  } catch (const std::exception& e) {
    error = e.what();
  }
  return 0;
}

} // namespace meshpaint

#endif
