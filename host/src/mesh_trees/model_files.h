// boreas: reading model files for the tree import and the preprocessed-tree cache — a
// whole file's bytes with errors that say why, tinygltf's parse of glTF bytes, and glTF
// accessors read with every offset checked.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
struct Accessor;
}  // namespace tinygltf

namespace boreas::impl {

// The file's bytes. Throws Error (BOREAS_ERROR_IO) "cannot read <what> '<path>': <why>"
// (no such file, not a regular file, the system's reason).
std::string read_file_bytes(const std::string& path, const std::string& what);

// Parses glTF from bytes read from path (external buffers are found beside it), binary or
// text by the content, not the extension (some tools write binary glTF as .gltf); images
// are left undecoded (boreas uses no textures, and tinygltf refuses a file with embedded
// images when no loader is set). False with tinygltf's reason in *error when it fails.
// bytes must be under 4 GiB (the callers say so in their own words).
bool parse_gltf(const std::string& bytes, const std::string& path, tinygltf::Model* model,
                std::string* error);

// Reads glTF accessors, checking every offset against its buffer so that a malformed file
// fails with a message instead of reading out of bounds. Failures throw Error
// (INVALID_ARGUMENT) "<context><what>: <problem>", context naming the file and where in it.
class GltfAccessors {
 public:
  GltfAccessors(const tinygltf::Model& model, std::string context)
      : model_(model), context_(std::move(context)) {}

  // The elements of accessor `index` of `type` (TINYGLTF_TYPE_*), their components in
  // order: FLOAT, or the normalised unsigned byte and short that the spec allows for
  // texture coordinates.
  std::vector<double> floats(int index, const std::string& what, int type) const;
  // Unsigned byte, short or int SCALARs.
  std::vector<uint32_t> indices(int index, const std::string& what) const;

 private:
  [[noreturn]] void fail(const std::string& what, const std::string& problem) const;
  const tinygltf::Accessor& accessor(int index, const std::string& what, int type) const;
  const unsigned char* elements(const tinygltf::Accessor& a, const std::string& what,
                                size_t element_size, size_t* stride) const;

  const tinygltf::Model& model_;
  std::string context_;
};

}  // namespace boreas::impl
