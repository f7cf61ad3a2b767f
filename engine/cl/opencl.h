// The one place that includes the OpenCL C++ bindings, with the settings the
// engine relies on (OpenCL 1.2 everywhere; errors as cl::Error exceptions).
#pragma once

#define CL_HPP_ENABLE_EXCEPTIONS
#define CL_HPP_TARGET_OPENCL_VERSION 120
#define CL_HPP_MINIMUM_OPENCL_VERSION 120
#include <CL/opencl.hpp> // for cl::Context, cl::CommandQueue, ...

#include <string> // for std::string

namespace meshpaint {

//! Symbolic name of an OpenCL status code, e.g. "CL_OUT_OF_RESOURCES".
std::string cl_status_name(cl_int status);

//! "clEnqueueNDRangeKernel failed: CL_OUT_OF_RESOURCES (-5)".
std::string describe(const cl::Error& error);

} // namespace meshpaint
