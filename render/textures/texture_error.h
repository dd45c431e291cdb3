// boreas textures: the one exception type of the texture generator and its files.
#pragma once

#include <stdexcept>

namespace boreas::render {

// A texture set that cannot be generated, written or read. The message names the file (or
// the parameter) and says what is wrong with it.
class TextureError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace boreas::render
