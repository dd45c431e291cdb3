// render tests: `boreas info` lists devices and names the one boreas picks, honouring
// --device and BOREAS_DEVICE, and fails cleanly when nothing matches.
#include <gtest/gtest.h>

#include "command_runner.h"

namespace boreas::render::testing {
namespace {

TEST(CliInfo, ListsDevicesAndNamesThePick) {
  TempDir dir;
  CommandResult r = run_boreas("info", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("OpenCL devices"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("compute units"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("gl sharing"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fp64"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fast math"), std::string::npos) << r.out;
  // The strategy `boreas run --interop auto` takes: a CPU device draws in place.
  if (r.out.find("type          CPU") != std::string::npos) {
    EXPECT_NE(r.out.find("interop       zero_copy"), std::string::npos) << r.out;
  }
  EXPECT_NE(r.out.find("boreas picks [0]"), std::string::npos) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST(CliInfo, DeviceOptionSaysWhatItPicks) {
  TempDir dir;
  CommandResult r = run_boreas("info --device 0:0", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("(--device '0:0')"), std::string::npos) << r.out;
}

TEST(CliInfo, EnvironmentRequestIsHonoured) {
  TempDir dir;
  CommandResult r = run_boreas("info", dir, "BOREAS_DEVICE=0:0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("BOREAS_DEVICE='0:0'"), std::string::npos) << r.out;
}

TEST(CliInfo, UnknownDeviceFailsWithExitCode2) {
  TempDir dir;
  CommandResult r = run_boreas("info", dir, "BOREAS_DEVICE=nonexistent");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("boreas: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("'nonexistent' matches no OpenCL device"), std::string::npos) << r.err;
  // The list still comes first, so the user sees what there is to choose from.
  EXPECT_NE(r.out.find("OpenCL devices"), std::string::npos) << r.out;
}

TEST(CliInfo, NoOpenClPlatformFailsWithExitCode2AndNamesThePackage) {
  TempDir dir;
  // The ICD loader finds no driver when its vendor folder is empty.
  CommandResult r = run_boreas("info", dir, "OCL_ICD_VENDORS='" + dir.path().string() + "'");
  if (r.exit_code == 0) GTEST_SKIP() << "this OpenCL loader ignores OCL_ICD_VENDORS";
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_EQ(r.err.rfind("boreas: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("pocl-opencl-icd"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace boreas::render::testing
