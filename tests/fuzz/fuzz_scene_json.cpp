// boreas fuzzing: a scene file of the boreas command (load_scene_text: strict JSON, then
// every value checked, forests planted). A refusal is a SceneError naming the file; the
// species files and images a scene names are only resolved here, never read, and they
// resolve into a folder that does not exist. A scene may hold 4,096 trees here, not 2^20:
// a forest is planted at a few microseconds a tree under the sanitizers, and the limit is
// checked the same way whatever its value.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/scene_error.h"
#include "scene/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    boreas::render::SceneLimits limits;
    limits.trees = 4096;
    (void)boreas::render::load_scene_text(std::string(reinterpret_cast<const char*>(data), size),
                                          "fuzz.json", "/nonexistent", limits);
  } catch (const boreas::render::SceneError&) {
  }
  return 0;
}
