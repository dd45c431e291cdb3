// boreas: model files' bytes and glTF parsing (see model_files.h).
#include "mesh_wind/model_files.h"

#include <tiny_gltf.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "errors.h"

namespace boreas::impl {

namespace fs = std::filesystem;

std::string read_file_bytes(const std::string& path, const std::string& what) {
  const std::string cannot = "cannot read " + what + " '" + path + "': ";
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    fail(BOREAS_ERROR_IO, cannot + (fs::exists(path, ec) ? "not a regular file" : "no such file"));
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(BOREAS_ERROR_IO, cannot + std::strerror(errno));
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) fail(BOREAS_ERROR_IO, cannot + "read failed");
  return bytes.str();
}

namespace {

bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                const unsigned char*, int, void*) {
  return true;
}

}  // namespace

bool parse_gltf(const std::string& bytes, const std::string& path, tinygltf::Model* model,
                std::string* error) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&skip_image, nullptr);
  std::string warning;
  const std::string base_dir = fs::path(path).parent_path().string();
  const bool binary = bytes.compare(0, 4, "glTF") == 0;
  try {
    return binary
               ? loader.LoadBinaryFromMemory(model, error, &warning,
                                             reinterpret_cast<const unsigned char*>(bytes.data()),
                                             unsigned(bytes.size()), base_dir)
               : loader.LoadASCIIFromString(model, error, &warning, bytes.data(),
                                            unsigned(bytes.size()), base_dir);
  } catch (const std::exception& e) {
    *error = e.what();
    return false;
  }
}

}  // namespace boreas::impl
