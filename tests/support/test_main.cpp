// boreas tests: the main of the GoogleTest executables. Kernel binaries are cached in the
// build folder rather than the user's ~/.cache, unless BOREAS_CACHE_DIR is already set.
#include <gtest/gtest.h>

#include <cstdlib>

int main(int argc, char** argv) {
  setenv("BOREAS_CACHE_DIR", BOREAS_TEST_CACHE_DIR, /*overwrite=*/0);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
