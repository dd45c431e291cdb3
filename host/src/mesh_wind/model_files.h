// boreas: reading model files for the tree import and the preprocessed-tree cache — a
// whole file's bytes with errors that say why, and tinygltf's parse of glTF bytes.
#pragma once

#include <string>

namespace tinygltf {
class Model;
}

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

}  // namespace boreas::impl
