// boreas gltf: the animated file's morphed meshes (meadows, imported trees). Per base: its
// rest geometry once (positions int16 in its box of every key of every copy, normals int8,
// colors, 16-bit indices where they fit); per copy: a mesh on those accessors with its own
// morph targets (morph_basis.h: int16, int8 where small), a node placing it (placement *
// the box), and a weights channel in the animation, a key per frame; a copy with instances
// (a meadow's clumps) a node per instance instead, its weights read as a loop from its phase.
#pragma once

#include <tiny_gltf.h>

#include <vector>

#include "boreas_gltf/animation_gltf.h"

namespace boreas::gltf {

// times: the key times' accessor (-1 with a single key); bark, leaf: the materials. Each
// morphed mesh's keys are used up (moved from) as it is written.
void add_morphed_meshes(tinygltf::Model& model, ForestAnimation& a, int times, int bark,
                        int leaf, tinygltf::Animation* animation, std::vector<MorphReport>* report);

}  // namespace boreas::gltf
