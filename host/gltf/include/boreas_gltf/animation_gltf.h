// boreas gltf: an animated forest as binary glTF — trees as skinned meshes, a template's
// meshes (its pieces: 16-bit indices, at most 256 joints, part_split.h) shared by every
// tree grown from it, one animation with a translation and a rotation channel per joint.
// Attributes are quantized (KHR_mesh_quantization: positions int16, normals int8, joints
// uint8) where that shrinks the file; the dequantization is folded into
// the inverse bind matrices, as a skinned mesh's node transform is ignored. Meadows and
// imported trees are morphed meshes: a base shared by its copies, each copy's motion a
// few int16 morph targets weighted per key (morph_basis.h). Plain data in,
// bytes out: the library gathers the data (host/src/export/), this writes them.
#pragma once

#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace boreas::gltf {

// A part of a template's mesh in the template's own space (the tree at the origin,
// unturned, at scale 1), bound to joints: 4 joints and 4 weights per vertex.
struct SkinnedPart {
  std::vector<float> positions;           // 3 per vertex
  std::vector<float> normals;             // 3 per vertex, or none: flat (the client's flat normals)
  std::vector<float> uvs;                 // 2 per vertex in 0..1, or none
  std::vector<uint32_t> indices;          // triangles
  std::vector<int32_t> joints;            // 4 per vertex: indices in its tree's joint list
  std::vector<float> weights;             // 4 per vertex, summing to 1
  size_t vertex_count() const { return positions.size() / 3; }
};

struct TreeTemplate {
  std::string name;
  SkinnedPart bark, leaves;  // leaves may be empty
};

// A joint's frame in world: origin and unit quaternion (x, y, z, w).
struct JointPose {
  std::array<double, 3> position{};
  std::array<double, 4> rotation{0, 0, 0, 1};
};

struct AnimatedTree {
  std::string name;
  int template_index = 0;
  // Template space to world: position + R_y(rotation) (scale p).
  std::array<double, 3> position{};
  double rotation = 0.0, scale = 1.0;
  std::vector<int32_t> joint_parents;        // -1 for a root
  std::vector<std::vector<JointPose>> frames;  // frames[f][j]
  std::vector<JointPose> bind;  // the joints where the template's mesh was taken; none: frames[0]
};

// A mesh whose vertices move each on its own (a meadow's strips, an imported tree), at
// rest in its own space: written once, shared by every MorphedMesh on it.
struct MorphBase {
  std::string name;
  std::vector<float> positions;  // 3 per vertex
  std::vector<float> normals;    // 3 per vertex, or none
  std::vector<float> colors;     // 3 per vertex (linear RGB, 0..1), or none
  std::vector<uint32_t> indices; // triangles
  // The double-sided leaf material, else the bark's; a base with colors gets a white
  // double-sided one instead ("underbrush"), which its colors tint.
  bool leaf_material = false;
  size_t vertex_count() const { return positions.size() / 3; }
};

// One placed copy of a base and its vertices at every key, as morph targets weighted per
// key (morph_basis.h: within ForestAnimation::morph_tolerance of these positions).
struct MorphedMesh {
  std::string name;
  int base = 0;
  // Base space to world: position + R_y(rotation) (scale p), as AnimatedTree.
  std::array<double, 3> position{};
  double rotation = 0.0, scale = 1.0;
  std::vector<std::vector<float>> keys;  // keys[k]: 3 per vertex, base space
  // None: one node at the placement above. Else a node per instance (sharing the mesh, the
  // placement above unused), each with a weights channel of its own: the keys taken as a
  // loop (the last key is the first) started `phase` keys in, so copies sway out of step.
  struct Instance {
    std::string name;
    std::array<double, 3> position{};
    int phase = 0;  // keys, 0..keys - 2
  };
  std::vector<Instance> instances;
};

struct ForestAnimation {
  std::string generator;
  double frame_time = 1.0 / 24.0;  // s
  std::vector<TreeTemplate> templates;
  std::vector<AnimatedTree> trees;
  std::vector<MorphBase> morph_bases;
  std::vector<MorphedMesh> morphed;  // as many keys as the trees have frames
  double morph_tolerance = 1e-3;     // m, world: a morphed vertex's distance at a key
};

// What a morphed mesh came to: its targets and the largest distance left (world metres).
struct MorphReport {
  std::string name;
  size_t targets = 0;
  double max_error = 0.0;
};

// The animation written to out as .glb (to a file: no copy of its bytes in memory); false
// with a message if it could not be built or written. report (may be NULL) receives one
// entry per morphed mesh. Taken by value: the morphed meshes' keys are let go as each is
// written (a meadow's are most of the memory).
bool write_animation_glb(ForestAnimation animation, std::ostream& out, std::string* error,
                         std::vector<MorphReport>* report = nullptr);

}  // namespace boreas::gltf
