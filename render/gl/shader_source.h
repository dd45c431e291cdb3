// boreas render: GLSL sources, embedded at build from render/shaders/ (or read from
// BOREAS_SHADER_DIR, for editing shaders without rebuilding). GLSL has no #include:
// a line `#include "file.glsl"` is replaced by that file, once per program.
#pragma once

#include <stdexcept>
#include <string>

namespace boreas::render {

struct ShaderError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The text of shader file `name` (e.g. "branch.vert") with its includes resolved.
// Throws ShaderError naming the file (and the including file) when one is missing.
std::string shader_source(const std::string& name);

}  // namespace boreas::render
