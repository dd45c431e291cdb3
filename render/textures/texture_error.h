// boreas textures: the one exception type of the texture generator and its files.
#pragma once

#include <stdexcept>
#include <string>

namespace boreas::render {

// A texture set that cannot be generated, written or read. The message names the file (or
// the parameter) and says what is wrong with it.
class TextureError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws TextureError "<params>.<name> must be <rule>, got <value>" unless ok.
inline void require_param(bool ok, const char* params, const char* name, const std::string& rule, double value) {
  if (!ok) throw TextureError(std::string(params) + "." + name + " must be " + rule + ", got " + std::to_string(value));
}

}  // namespace boreas::render
