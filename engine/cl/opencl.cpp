#include "cl/opencl.h"

namespace meshpaint {

std::string cl_status_name(cl_int status)
{
  switch (status) {
#define MP_CASE(code) \
  case code: return #code;
    MP_CASE(CL_SUCCESS)
    MP_CASE(CL_DEVICE_NOT_FOUND)
    MP_CASE(CL_DEVICE_NOT_AVAILABLE)
    MP_CASE(CL_COMPILER_NOT_AVAILABLE)
    MP_CASE(CL_MEM_OBJECT_ALLOCATION_FAILURE)
    MP_CASE(CL_OUT_OF_RESOURCES)
    MP_CASE(CL_OUT_OF_HOST_MEMORY)
    MP_CASE(CL_BUILD_PROGRAM_FAILURE)
    MP_CASE(CL_IMAGE_FORMAT_NOT_SUPPORTED)
    MP_CASE(CL_INVALID_VALUE)
    MP_CASE(CL_INVALID_DEVICE)
    MP_CASE(CL_INVALID_CONTEXT)
    MP_CASE(CL_INVALID_COMMAND_QUEUE)
    MP_CASE(CL_INVALID_MEM_OBJECT)
    MP_CASE(CL_INVALID_IMAGE_SIZE)
    MP_CASE(CL_INVALID_BINARY)
    MP_CASE(CL_INVALID_BUILD_OPTIONS)
    MP_CASE(CL_INVALID_PROGRAM)
    MP_CASE(CL_INVALID_KERNEL_NAME)
    MP_CASE(CL_INVALID_KERNEL)
    MP_CASE(CL_INVALID_ARG_INDEX)
    MP_CASE(CL_INVALID_ARG_VALUE)
    MP_CASE(CL_INVALID_ARG_SIZE)
    MP_CASE(CL_INVALID_KERNEL_ARGS)
    MP_CASE(CL_INVALID_WORK_DIMENSION)
    MP_CASE(CL_INVALID_WORK_GROUP_SIZE)
    MP_CASE(CL_INVALID_GLOBAL_WORK_SIZE)
    MP_CASE(CL_INVALID_BUFFER_SIZE)
#undef MP_CASE
  case -1001: return "CL_PLATFORM_NOT_FOUND_KHR";
  default: return "CL_ERROR";
  }
}

std::string describe(const cl::Error& error)
{
  return std::string(error.what()) + " failed: " + cl_status_name(error.err()) + " (" +
         std::to_string(error.err()) + ")";
}

} // namespace meshpaint
