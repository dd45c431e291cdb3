// boreas: model files' bytes and glTF parsing (see model_files.h).
#include "mesh_trees/model_files.h"

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

void GltfAccessors::fail(const std::string& what, const std::string& problem) const {
  fail_argument(context_ + what + ": " + problem);
}

// The accessor, after checking that it exists, has `type` and is not sparse.
const tinygltf::Accessor& GltfAccessors::accessor(int index, const std::string& what,
                                                  int type) const {
  if (index < 0 || size_t(index) >= model_.accessors.size()) {
    fail(what, "accessor " + std::to_string(index) + " does not exist (the file has " +
                   std::to_string(model_.accessors.size()) + ")");
  }
  const tinygltf::Accessor& a = model_.accessors[size_t(index)];
  if (a.type != type) {
    fail(what, "accessor " + std::to_string(index) + " has type " + std::to_string(a.type) +
                   ", expected " + std::to_string(type));
  }
  if (a.sparse.isSparse) fail(what, "sparse accessors are not supported");
  return a;
}

// The first element of the accessor's data, after checking that all `count` elements of
// `element_size` bytes lie inside its buffer view and the view inside its buffer.
const unsigned char* GltfAccessors::elements(const tinygltf::Accessor& a, const std::string& what,
                                             size_t element_size, size_t* stride) const {
  if (a.bufferView < 0 || size_t(a.bufferView) >= model_.bufferViews.size()) {
    fail(what, "the accessor has no buffer view (accessors without data are not supported)");
  }
  const tinygltf::BufferView& view = model_.bufferViews[size_t(a.bufferView)];
  if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size()) {
    fail(what, "buffer view " + std::to_string(a.bufferView) + " refers to a missing buffer");
  }
  const std::vector<unsigned char>& data = model_.buffers[size_t(view.buffer)].data;
  *stride = view.byteStride ? view.byteStride : element_size;
  const bool view_fits =
      view.byteOffset <= data.size() && view.byteLength <= data.size() - view.byteOffset;
  const size_t room = view_fits ? view.byteLength : 0;
  const bool fits =
      view_fits && *stride >= element_size && a.byteOffset <= room &&
      (a.count == 0 || (element_size <= room - a.byteOffset &&
                        (a.count - 1) <= (room - a.byteOffset - element_size) / *stride));
  if (!fits) {
    fail(what, std::to_string(a.count) + " elements of " + std::to_string(element_size) +
                   " bytes (stride " + std::to_string(*stride) + ") do not fit in buffer view " +
                   std::to_string(a.bufferView) + " (" + std::to_string(view.byteLength) +
                   " bytes at " + std::to_string(view.byteOffset) + " in a buffer of " +
                   std::to_string(data.size()) + ")");
  }
  return data.data() + view.byteOffset + a.byteOffset;
}

std::vector<double> GltfAccessors::floats(int index, const std::string& what, int type) const {
  const tinygltf::Accessor& a = accessor(index, what, type);
  const bool normalized_int =
      a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                       a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !normalized_int) {
    fail(what, "component type " + std::to_string(a.componentType) +
                   " is not supported (boreas reads FLOAT, or normalised unsigned byte or short)");
  }
  const size_t components = size_t(tinygltf::GetNumComponentsInType(uint32_t(type)));
  const size_t component_size =
      size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType)));
  size_t stride = 0;
  const unsigned char* base = elements(a, what, component_size * components, &stride);
  std::vector<double> out;
  out.reserve(a.count * components);
  for (size_t e = 0; e < a.count; ++e) {
    for (size_t k = 0; k < components; ++k) {
      const unsigned char* at = base + e * stride + k * component_size;
      if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
        float f;
        std::memcpy(&f, at, sizeof f);
        out.push_back(f);
      } else if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
        out.push_back(*at / 255.0);
      } else {
        uint16_t u;
        std::memcpy(&u, at, sizeof u);
        out.push_back(u / 65535.0);
      }
    }
  }
  return out;
}

std::vector<uint32_t> GltfAccessors::indices(int index, const std::string& what) const {
  const tinygltf::Accessor& a = accessor(index, what, TINYGLTF_TYPE_SCALAR);
  size_t size = 0;
  switch (a.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      size = 1;
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      size = 2;
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      size = 4;
      break;
    default:
      fail(what, "component type " + std::to_string(a.componentType) +
                     " is not an index type (unsigned byte, short or int)");
  }
  size_t stride = 0;
  const unsigned char* base = elements(a, what, size, &stride);
  std::vector<uint32_t> out(a.count);
  for (size_t e = 0; e < a.count; ++e) {
    const unsigned char* at = base + e * stride;
    if (size == 1) {
      out[e] = *at;
    } else if (size == 2) {
      uint16_t u;
      std::memcpy(&u, at, sizeof u);
      out[e] = u;
    } else {
      std::memcpy(&out[e], at, sizeof out[e]);
    }
  }
  return out;
}

}  // namespace boreas::impl
