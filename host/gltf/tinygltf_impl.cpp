// boreas: the one translation unit that compiles tinygltf's implementation, for the
// library's model import and mesh-tree cache and for the renderer's glTF export (image
// support left out: boreas's meshes carry no textures).
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
