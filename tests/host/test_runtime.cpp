// boreas tests: the OpenCL runtime — device choice, build errors with the compiler's log,
// the on-disk binary cache (hits, corrupt entries), embedded sources, and a missing driver.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "errors.h"
#include "fnv1a.h"
#include "reference/probe_kernels.h"
#include "runtime/device.h"
#include "runtime/kernel_source.h"
#include "runtime/launch.h"
#include "support/test_support.h"

namespace boreas::embedded {
const std::vector<std::pair<const char*, const char*>>& kernel_files();
}

namespace boreas::test {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> cache_files(const TempDir& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir.path())) files.push_back(e.path());
  return files;
}

// The copy kernel these tests run is a probe kernel, not part of the library.
const bool kProbeKernels = (impl::use_probe_kernels(), true);

// The library carries its own kernels only: the probes tests and benchmarks run are in
// boreas_probe_kernels.
TEST(Runtime, ShippedKernelTableHoldsNoProbeKernels) {
  int kernels = 0;
  for (const auto& [name, text] : embedded::kernel_files()) {
    const std::string file = name;
    EXPECT_EQ(file.find("probe"), std::string::npos) << file;
    EXPECT_NE(file, "bandwidth_copy.cl");
    kernels += file.size() > 3 && file.compare(file.size() - 3, 3, ".cl") == 0;
  }
  EXPECT_GT(kernels, 10);
}

// Runs the copy kernel on 256 floats: proof that a (cached) program really works.
void expect_copy_kernel_works(impl::Runtime& rt) {
  cl::Kernel k = rt.kernel("bandwidth_copy.cl", "boreas_bandwidth_copy");
  std::vector<float> in(256), out(256, -1.0f);
  for (size_t i = 0; i < in.size(); ++i) in[i] = float(i) * 0.5f;
  cl::Buffer a = rt.buffer(CL_MEM_READ_ONLY, 1024), b = rt.buffer(CL_MEM_WRITE_ONLY, 1024);
  rt.queue().enqueueWriteBuffer(a, CL_TRUE, 0, 1024, in.data());
  impl::launch(rt, k, impl::Items(64), a, b);  // a float4 per item
  rt.queue().enqueueReadBuffer(b, CL_TRUE, 0, 1024, out.data());
  EXPECT_EQ(in, out);
}

TEST(Runtime, BinaryCacheIsWrittenThenHit) {
  TempDir dir;
  {
    impl::Runtime rt(nullptr, dir.str().c_str());
    expect_copy_kernel_works(rt);
    EXPECT_EQ(rt.programs().compiles(), 1);
    EXPECT_EQ(rt.programs().disk_hits(), 0);
  }
  ASSERT_EQ(cache_files(dir).size(), 1u);
  impl::Runtime again(nullptr, dir.str().c_str());
  expect_copy_kernel_works(again);
  EXPECT_EQ(again.programs().compiles(), 0) << "the second run must load the binary";
  EXPECT_EQ(again.programs().disk_hits(), 1);
}

// Kernel variants (the same kernel built with other slot counts) are kept per kernel up
// to a bound, least recently used released first, with their programs: a world that
// lives for hours and changes its wave or collider counts must not keep every program it
// ever built (each costs 1-2 MiB on PoCL). A released variant comes back from the disk
// cache and works.
TEST(Runtime, KernelVariantsAreBoundedLeastRecentlyUsedFirst) {
  TempDir dir;
  impl::Runtime rt(nullptr, dir.str().c_str());
  const int kept = impl::Runtime::kKernelVariantsKept;
  auto variant = [](int i) { return "#define BOREAS_VARIANT_PROBE " + std::to_string(i) + "\n"; };
  auto get = [&](int i) -> cl::Kernel& {
    return rt.kernel("bandwidth_copy.cl", "boreas_bandwidth_copy", variant(i));
  };
  const cl_kernel first = get(0)();
  for (int i = 1; i < 3 * kept; ++i) {
    get(i);
    EXPECT_EQ(get(0)(), first) << "variant 0 is used every time, so it is never released";
    EXPECT_LE(rt.kernel_variants("bandwidth_copy.cl", "boreas_bandwidth_copy"), size_t(kept));
    EXPECT_LE(rt.programs().programs_held(), size_t(kept));
  }
  EXPECT_EQ(rt.kernel_variants(), size_t(kept));
  EXPECT_EQ(rt.programs().compiles(), 3 * kept);
  EXPECT_EQ(rt.programs().disk_hits(), 0);
  // Variant 1 was released long ago: asking again loads it from disk, and it copies.
  get(1);
  EXPECT_EQ(rt.programs().compiles(), 3 * kept);
  EXPECT_EQ(rt.programs().disk_hits(), 1);
  cl::Kernel k = get(1);
  std::vector<float> in(256), out(256, -1.0f);
  for (size_t i = 0; i < in.size(); ++i) in[i] = float(i) * 0.25f;
  cl::Buffer a = rt.buffer(CL_MEM_READ_ONLY, 1024), b = rt.buffer(CL_MEM_WRITE_ONLY, 1024);
  rt.queue().enqueueWriteBuffer(a, CL_TRUE, 0, 1024, in.data());
  impl::launch(rt, k, impl::Items(64), a, b);
  rt.queue().enqueueReadBuffer(b, CL_TRUE, 0, 1024, out.data());
  EXPECT_EQ(in, out);
  // Other kernels have their own bound: one variant of another kernel releases nothing.
  rt.kernel("tile_copy.cl", "boreas_tile_copy");
  EXPECT_EQ(rt.kernel_variants("bandwidth_copy.cl", "boreas_bandwidth_copy"), size_t(kept));
  EXPECT_EQ(rt.kernel_variants(), size_t(kept) + 1);
}

TEST(Runtime, CorruptCacheEntryIsIgnoredAndRebuilt) {
  TempDir dir;
  { impl::Runtime rt(nullptr, dir.str().c_str()); expect_copy_kernel_works(rt); }
  fs::path entry = cache_files(dir).at(0);
  auto size = fs::file_size(entry);
  for (int mode = 0; mode < 3; ++mode) {
    if (mode == 0) fs::resize_file(entry, size / 2);  // truncated
    if (mode == 1) {                                   // flipped payload bytes
      std::fstream f(entry, std::ios::in | std::ios::out | std::ios::binary);
      f.seekp(static_cast<std::streamoff>(size - 16));
      f.write("garbage-garbage!", 16);
    }
    if (mode == 2) std::ofstream(entry, std::ios::trunc) << "not a cache file";
    impl::Runtime rt(nullptr, dir.str().c_str());
    expect_copy_kernel_works(rt);
    EXPECT_EQ(rt.programs().compiles(), 1) << "mode " << mode;
    EXPECT_EQ(rt.programs().disk_hits(), 0) << "mode " << mode;
    EXPECT_EQ(fs::file_size(entry), size) << "the entry is rewritten whole";
  }
}

TEST(Runtime, ACacheEntryTheDriverRefusesIsRebuilt) {
  // An entry whose header and checksum are right but whose binary is not one the driver
  // takes (another driver's, or bytes damaged before the checksum was made): the driver's
  // refusal must not be fatal either.
  TempDir dir;
  {
    impl::Runtime rt(nullptr, dir.str().c_str());
    expect_copy_kernel_works(rt);
  }
  fs::path entry = cache_files(dir).at(0);
  std::string bytes;
  {
    std::ifstream in(entry, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  constexpr size_t kHeader = 8 + 3 * sizeof(unsigned long long);
  ASSERT_GT(bytes.size(), kHeader);
  for (size_t i = kHeader; i < bytes.size(); ++i) bytes[i] = char((i * 131u) ^ 0x5a);
  unsigned long long hash = impl::fnv1a64(bytes.data() + kHeader, bytes.size() - kHeader);
  std::memcpy(&bytes[8 + 2 * sizeof(unsigned long long)], &hash, sizeof hash);
  std::ofstream(entry, std::ios::binary | std::ios::trunc) << bytes;
  impl::Runtime rt(nullptr, dir.str().c_str());
  expect_copy_kernel_works(rt);
  EXPECT_EQ(rt.programs().disk_hits(), 0);
  EXPECT_EQ(rt.programs().compiles(), 1);
}

TEST(Runtime, ACacheFolderThatCannotBeMadeIsNotFatal) {
  // The cache path names a file, or lies under one: nothing can be cached, and everything
  // still builds and runs.
  TempDir dir;
  const fs::path file = dir.path() / "a-file";
  std::ofstream(file) << "not a folder";
  for (const fs::path& cache : {file, file / "below"}) {
    impl::Runtime rt(nullptr, cache.string().c_str());
    expect_copy_kernel_works(rt);
    EXPECT_EQ(rt.programs().compiles(), 1) << cache;
  }
  EXPECT_TRUE(fs::is_regular_file(file)) << "the file was left alone";
}

TEST(Runtime, ACacheEntryThatIsAFolderIsNotFatal) {
  TempDir dir;
  {
    impl::Runtime rt(nullptr, dir.str().c_str());
    expect_copy_kernel_works(rt);
  }
  fs::path entry = cache_files(dir).at(0);
  fs::remove(entry);
  fs::create_directories(entry / "odd");
  impl::Runtime rt(nullptr, dir.str().c_str());
  expect_copy_kernel_works(rt);
  EXPECT_EQ(rt.programs().compiles(), 1);
}

TEST(Runtime, ABrokenKernelInTheKernelFolderIsRefusedWithItsLog) {
  // BOREAS_KERNEL_DIR with a wind kernel that does not compile: the call that needs it fails
  // with BOREAS_ERROR_KERNEL_BUILD, the file and the compiler's complaint named; a folder
  // with the kernel missing is named too.
  TempDir dir;
  for (const fs::path& f : fs::recursive_directory_iterator(BOREAS_KERNEL_SOURCE_DIR)) {
    const fs::path to = dir.path() / fs::relative(f, BOREAS_KERNEL_SOURCE_DIR);
    if (fs::is_directory(f))
      fs::create_directories(to);
    else
      fs::copy_file(f, to);
  }
  std::ofstream(dir.path() / "wind_sample_points.cl", std::ios::app)
      << "\n__kernel void boreas_broken(__global float* x) { x[0] = no_such_function(1); }\n";
  boreas_world_def def = boreas_default_world_def();
  def.cache_dir = "";
  // Kernels build when first needed (a calm world's step launches none with
  // exact wind sampling, the default): sampling the wind
  // needs wind_sample_points.cl. The world that refused stays as it was.
  auto first_failure = [&](std::string* message) {
    ScopedEnv env("BOREAS_KERNEL_DIR", dir.str().c_str());
    boreas_world world = nullptr;
    boreas_status s = boreas_world_create(&def, &world);
    if (s == BOREAS_OK) {
      const float p[3] = {0.0f, 1.0f, 0.0f};
      float out[3];
      s = boreas_wind_sample(world, p, 1, out);
      *message = boreas_last_error();
      EXPECT_EQ(boreas_world_step(world, 0.1f), BOREAS_OK) << "the world steps on";
    } else {
      *message = boreas_last_error();
    }
    boreas_world_destroy(world);
    return s;
  };
  std::string message;
  EXPECT_EQ(first_failure(&message), BOREAS_ERROR_KERNEL_BUILD);
  EXPECT_NE(message.find("wind_sample_points.cl"), std::string::npos) << message;
  EXPECT_NE(message.find("no_such_function"), std::string::npos) << message;
  fs::remove(dir.path() / "wind_sample_points.cl");
  EXPECT_NE(first_failure(&message), BOREAS_OK);
  EXPECT_NE(message.find("wind_sample_points.cl"), std::string::npos) << message;
  boreas_world world = nullptr;
  ASSERT_EQ(boreas_world_create(&def, &world), BOREAS_OK) << "without the override all is well";
  boreas_world_destroy(world);
}

TEST(Runtime, CacheFolderCanBeChangedAndTurnedOff) {
  TempDir a, b;
  { impl::Runtime rt(nullptr, a.str().c_str()); expect_copy_kernel_works(rt); }
  {
    ScopedEnv env("BOREAS_CACHE_DIR", b.str().c_str());
    impl::Runtime rt(nullptr, nullptr);
    EXPECT_EQ(rt.programs().cache_dir(), b.str());
    expect_copy_kernel_works(rt);
  }
  EXPECT_EQ(cache_files(b).size(), 1u);
  impl::Runtime off(nullptr, "");
  expect_copy_kernel_works(off);
  EXPECT_EQ(off.programs().disk_hits(), 0);
  EXPECT_EQ(off.programs().compiles(), 1);
}

TEST(Runtime, BuildFailureCarriesTheCompilerLog) {
  impl::Runtime rt(nullptr, "");
  try {
    rt.programs().build_source("broken.cl",
                               "__kernel void broken(__global float* x) { x[0] = no_such_fn(1); }\n");
    FAIL() << "a broken kernel must not build";
  } catch (const impl::Error& e) {
    EXPECT_EQ(e.status(), BOREAS_ERROR_KERNEL_BUILD);
    std::string msg = e.what();
    EXPECT_NE(msg.find("broken.cl"), std::string::npos) << msg;
    EXPECT_NE(msg.find("no_such_fn"), std::string::npos) << "the log names the culprit: " << msg;
  }
}

size_t occurrences(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Headers are inlined once, as under #pragma once; a .inc body (one SIMD width's
// instantiation, cl/shared/simd_width.h) at each of its includes.
TEST(Runtime, EmbeddedSourcesHaveTheirIncludesResolvedOnce) {
  std::string src = impl::kernel_source("wind_grid_step.cl");
  EXPECT_EQ(src.find("#include \""), std::string::npos) << "quoted includes are inlined";
  EXPECT_EQ(occurrences(src, "#define BOREAS_CL_SHARED_FAST_MATH_H"), 1u);
  EXPECT_EQ(occurrences(src, "#line 1 \"shared/fast_math.h\""), 1u);
  EXPECT_EQ(occurrences(src, "boreas_poly_sin(BOREAS_F x)"), 2u) << "width 1 and BOREAS_W";
  EXPECT_EQ(src.find("\n#include BOREAS_WIDTH_BODY"), std::string::npos) << "named bodies too";
  EXPECT_NE(src.find("__kernel void boreas_wind_grid_step"), std::string::npos);
  EXPECT_THROW(impl::kernel_source("no_such_kernel.cl"), impl::Error);
}

TEST(Runtime, KernelDirectoryOverrideReadsFromDisk) {
  TempDir dir;
  fs::create_directories(dir.path() / "shared");
  std::ofstream(dir.path() / "probe.cl") << "#include \"shared/x.h\"\n__kernel void k() {}\n";
  std::ofstream(dir.path() / "shared" / "x.h") << "#define FROM_DISK 1\n";
  ScopedEnv env("BOREAS_KERNEL_DIR", dir.str().c_str());
  std::string src = impl::kernel_source("probe.cl");
  EXPECT_NE(src.find("FROM_DISK"), std::string::npos);
  EXPECT_THROW(impl::kernel_source("missing.cl"), impl::Error);
}

// `#include NAME` with NAME #defined as a quoted file (cl/shared/width_instantiate.inc's
// BOREAS_WIDTH_BODY) is inlined from the file last defined, each time, as the
// preprocessor would; an unknown name is left for the compiler to report.
TEST(Runtime, IncludesOfAFileNamedByAMacroAreResolved) {
  TempDir dir;
  fs::create_directories(dir.path() / "shared");
  std::ofstream(dir.path() / "probe.cl")
      << "#define BODY \"shared/a.inc\"\n#include BODY\n#include BODY\n"
      << "#define BODY \"shared/b.inc\"\n#include BODY\n#include UNKNOWN\n";
  std::ofstream(dir.path() / "shared" / "a.inc") << "int from_a;\n";
  std::ofstream(dir.path() / "shared" / "b.inc") << "int from_b;\n";
  ScopedEnv env("BOREAS_KERNEL_DIR", dir.str().c_str());
  std::string src = impl::kernel_source("probe.cl");
  EXPECT_EQ(occurrences(src, "int from_a;"), 2u);
  EXPECT_EQ(occurrences(src, "int from_b;"), 1u);
  EXPECT_EQ(occurrences(src, "#include BODY"), 0u);
  EXPECT_EQ(occurrences(src, "#include UNKNOWN"), 1u);
}

TEST(Device, RequestsPickTheRightDevice) {
  std::vector<impl::Device> devices = impl::list_devices();
  ASSERT_FALSE(devices.empty());
  ScopedEnv clear("BOREAS_DEVICE", nullptr);
  int best = impl::choose_device(devices, "");
  for (const impl::Device& d : devices) {
    if (d.is_gpu()) EXPECT_TRUE(devices[size_t(best)].is_gpu()) << "a GPU wins over a CPU";
  }
  const impl::Device& first = devices[0];
  EXPECT_EQ(impl::choose_device(devices, std::to_string(first.platform_index) + ":" +
                                              std::to_string(first.device_index)),
            0);
  EXPECT_EQ(impl::choose_device(devices, first.name.substr(0, 6)), 0) << "name prefix";
  if (!first.is_gpu()) EXPECT_EQ(devices[size_t(impl::choose_device(devices, "cpu"))].is_gpu(), false);
  try {
    impl::choose_device(devices, "9:9");
    FAIL();
  } catch (const impl::Error& e) {
    EXPECT_EQ(e.status(), BOREAS_ERROR_NO_DEVICE);
    EXPECT_NE(std::string(e.what()).find(first.name), std::string::npos) << "lists what exists";
  }
  ScopedEnv env("BOREAS_DEVICE", "definitely-not-a-device");
  EXPECT_THROW(impl::choose_device(devices, ""), impl::Error);
  EXPECT_EQ(impl::choose_device(devices, "0:0"), 0) << "an explicit request beats the environment";
}

TEST(NoPlatform, ClearErrorNamingThePackage) {
  if (!std::getenv("BOREAS_EXPECT_NO_PLATFORM"))
    GTEST_SKIP() << "runs as its own ctest with no OpenCL driver registered";
  int count = -1;
  EXPECT_EQ(boreas_list_devices(nullptr, 0, &count), BOREAS_ERROR_NO_DEVICE);
  std::string msg = boreas_last_error();
  EXPECT_NE(msg.find("no OpenCL platform"), std::string::npos) << msg;
  EXPECT_NE(msg.find("pocl-opencl-icd"), std::string::npos) << msg;
  boreas_world_def def = boreas_default_world_def();
  boreas_world w = nullptr;
  EXPECT_EQ(boreas_world_create(&def, &w), BOREAS_ERROR_NO_DEVICE);
  EXPECT_EQ(w, nullptr);
}

}  // namespace
}  // namespace boreas::test
