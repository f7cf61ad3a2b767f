// The OpenCL runtime: device choice and kernel builds.

#include "cl/kernel_clock.h"
#include "cl/kernel_programs.h"
#include "cl/kernel_sources.h"
#include "cl/launch.h"
#include "cl/program.h"
#include "core/errors.h"
#include "support/runtime.h"

#include <gtest/gtest.h>

namespace meshpaint {
namespace {

TEST(Runtime, BuildFailureCarriesFileAndLog)
{
  const std::vector<SourceFile> files = {
    {"good.cl", "__kernel void ok(__global float* x) { x[0] = 1.0f; }\n"},
    {"broken.cl", "__kernel void bad(__global float* x) {\n  x[0] = undeclared_name;\n}\n"}};
  try {
    build_program(*test::runtime(), files, "-cl-std=CL1.2");
    FAIL() << "a kernel with an undeclared name built";
  } catch (const DeviceError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("kernel build failed for good.cl, broken.cl"), std::string::npos) << what;
    EXPECT_NE(what.find("broken.cl:2"), std::string::npos) << "the log should point at the line: " << what;
    EXPECT_NE(what.find("undeclared_name"), std::string::npos) << what;
  }
}

// NVIDIA's compiler ignores #line and counts lines of the whole program.
TEST(Runtime, LogLinesOfTheWholeProgramNameTheirFile)
{
  const std::vector<SourceFile> files = {{"a.cl", "one\ntwo\n"}, {"b.cl", "three\nfour"}};
  // #line, one, two, (blank), #line, three, four
  EXPECT_EQ(name_source_lines("<kernel>:3:5: error: x\n<kernel>:7:1: note\n", files),
            "a.cl:2:5: error: x\nb.cl:2:1: note\n");
  EXPECT_EQ(name_source_lines("<kernel>:1:1: in the directive", files), "<kernel>:1:1: in the directive");
  EXPECT_EQ(name_source_lines("b.cl:1:2: named already", files), "b.cl:1:2: named already");
}

TEST(Runtime, EmbeddedKernelsBuild)
{
  EXPECT_NO_THROW(build_program(*test::runtime(),
                                std::vector<std::string>{"atlas_types.h", "atlas_access.cl", "subdivide.cl"},
                                "-cl-std=CL1.2"));
  EXPECT_THROW(build_program(*test::runtime(), std::vector<std::string>{"missing.cl"}, ""), DeviceError);
}

// Each kernel file builds from itself and the files it declares it needs, in
// every storage variant: none compiles only because of what precedes it.
TEST(Runtime, EveryKernelFileBuildsFromItsNeeds)
{
  std::vector<std::string> variants = {"-cl-std=CL1.2", "-cl-std=CL1.2 -D ATLAS_PREFETCH"};
  if (test::runtime()->info().images)
    variants.push_back("-cl-std=CL1.2 -D ATLAS_IMAGE");
  for (const std::string& options : variants)
    for (const std::string& file : kernel_files())
      EXPECT_NO_THROW(build_program(*test::runtime(), kernel_file_with_needs(file), options)) << file << ", " << options;
  EXPECT_EQ(kernel_file_with_needs("geometry.cl"), (std::vector<std::string>{"atlas_types.h", "atlas_access.cl",
                                                                             "brush_space.cl", "lanes.cl", "geometry.cl"}));
  EXPECT_THROW(kernel_file_with_needs("missing.cl"), DeviceError);
}

// OpenCL C has no variadic macros. PoCL's compiler takes them anyway;
// NVIDIA's refuses the whole program, so nothing here may rely on them.
TEST(Runtime, KernelsUseNoVariadicMacros)
{
  for (const std::string& file : kernel_files())
    EXPECT_EQ(kernel_source(file).find("__VA_ARGS__"), std::string::npos) << file;
}

TEST(Runtime, ProgramsAreBuiltOncePerOptions)
{
  Runtime& rt = *test::runtime();
  const cl::Program& a = kernel_program(rt, KernelProgram::Detail, "-cl-std=CL1.2");
  EXPECT_EQ(kernel_program(rt, KernelProgram::Detail, "-cl-std=CL1.2")(), a());
  EXPECT_NE(kernel_program(rt, KernelProgram::Detail, "-cl-std=CL1.2 -D ATLAS_PREFETCH")(), a());
}

// A clock names each kernel launched while it runs, leaves the results
// alone, and gives the queue back without profiling.
TEST(Runtime, KernelClockTimesLaunchesByName)
{
  Runtime& rt = *test::runtime();
  cl::Kernel copy(kernel_program(rt, KernelProgram::Copy, "-cl-std=CL1.2"), "copy_float4");
  const std::vector<cl_float4> values = {{{1, 2, 3, 4}}, {{5, 6, 7, 8}}, {{9, 10, 11, 12}}};
  cl::Buffer src(rt.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof(cl_float4) * values.size(),
                 const_cast<cl_float4*>(values.data()));
  cl::Buffer dst(rt.context(), CL_MEM_READ_WRITE, sizeof(cl_float4) * values.size());
  const cl_int count = cl_int(values.size());
  launch(rt.queue(), copy, cl::NDRange(count), cl::NullRange, src, dst, count); // before: not timed
  std::map<std::string, double> ms;
  {
    KernelClock clock(rt);
    EXPECT_THROW(KernelClock{rt}, std::logic_error);
    EXPECT_EQ(KernelClock::of(rt.queue()), &clock);
    launch(rt.queue(), copy, cl::NDRange(count), cl::NullRange, src, dst, count);
    launch(rt.queue(), copy, cl::NDRange(count), cl::NullRange, src, dst, count);
    ms = clock.take();
    EXPECT_TRUE(clock.take().empty()) << "take() starts afresh";
  }
  ASSERT_EQ(ms.size(), 1u);
  EXPECT_EQ(ms.begin()->first, "copy_float4");
  EXPECT_GE(ms.begin()->second, 0.0);
  EXPECT_EQ(KernelClock::of(rt.queue()), nullptr);
  EXPECT_EQ(rt.queue().getInfo<CL_QUEUE_PROPERTIES>() & CL_QUEUE_PROFILING_ENABLE, 0u);
  std::vector<cl_float4> out(values.size());
  rt.queue().enqueueReadBuffer(dst, CL_TRUE, 0, sizeof(cl_float4) * out.size(), out.data());
  for (std::size_t k = 0; k < out.size(); ++k)
    for (int c = 0; c < 4; ++c)
      EXPECT_EQ(out[k].s[c], values[k].s[c]);
}

TEST(Runtime, DeviceSelectors)
{
  const auto devices = Runtime::list_devices();
  ASSERT_FALSE(devices.empty());
  const DeviceInfo& d = devices.front();
  EXPECT_EQ(Runtime::open(std::to_string(d.platform_index) + ":" + std::to_string(d.device_index))->info().name,
            d.name);
  EXPECT_EQ(Runtime::open(d.name.substr(0, 5))->info().name.substr(0, 5), d.name.substr(0, 5));
  EXPECT_THROW(Runtime::open("9:9"), DeviceError);
  EXPECT_THROW(Runtime::open("no-such-device-anywhere"), DeviceError);
}

} // namespace
} // namespace meshpaint
