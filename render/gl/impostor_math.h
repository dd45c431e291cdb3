// boreas render: the math of far trees' impostors, shared by the baking, the shaders
// (impostor.vert and tree_ranges.comp keep the same formulas in GLSL) and the tests.
//
// Hemi-octahedral impostors (Ryan Brucks' octahedral impostors; Cigolle et al., "A survey
// of efficient representations for independent unit vectors", for the mapping), not
// billboard clouds: a tree is baked from kImpostorFrames x kImpostorFrames directions
// spread evenly over the upper hemisphere, so a camera that orbits (`--window`) or walks
// anywhere, at any height, finds a frame within a few degrees of its view and the switch
// between frames is small; one texture layer per template serves every tree of it in one
// instanced draw. Billboard clouds (Decoret et al., "Billboard clouds for extreme model
// simplification") need a per-template search for planes and show those planes edge-on,
// and a crown of thousands of scattered leaves has no few planes that fit it.
//
// An impostor record (12 floats, written per far tree on the device: boreas_cl.h's layout,
// by boreas_world_enqueue_tree_records or tree_ranges.comp's handover): [0..2] trunk base
// (m), [3] scale, [4] rotation about +Y (rad), [5] template index (the world's in the
// call's records, the renderer's in the handover's), [6..8] the trunk tip's displacement
// from rest (m), [9..11] 0.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace boreas::render {

constexpr int kImpostorRecordFloats = 12;
// Frames per side of a template's atlas, and texels per side of a frame.
constexpr int kImpostorFrames = 8;
constexpr int kImpostorFrameTexels = 64;
constexpr int kImpostorAtlasTexels = kImpostorFrames * kImpostorFrameTexels;

struct ImpostorRecord {
  float position[3];  // m: the trunk's base
  float scale;        // of the template
  float rotation;     // rad about +Y, as boreas_tree_def's (counter-clockwise seen from above)
  float template_index;
  float sway[3];      // m: the trunk tip's displacement from rest
  float unused[3];
};
static_assert(sizeof(ImpostorRecord) == kImpostorRecordFloats * sizeof(float));

// Template space -> world: p -> position + R_y(rotation) (scale p), as the library places
// a tree (host/src/trees/tree_layout.cpp), then sheared by the sway: a point at template
// height y moves by sway * y / tip_height (the trunk tip, template space, m), so the base
// stays and the tip follows the trunk.
glm::mat4 impostor_matrix(const ImpostorRecord& record, float tip_height);
// The same without the sway, and its inverse (world -> template space).
glm::mat4 tree_placement(const glm::vec3& position, float rotation, float scale);
glm::mat4 tree_placement_inverse(const glm::vec3& position, float rotation, float scale);

// The upper hemisphere (y >= 0) on the unit square and back: the octahedron's upper half
// folded out to a diamond, turned 45 degrees to fill the square (y = 1 at the centre, the
// horizon on the square's border). Directions below the horizon map to the border.
glm::vec2 hemi_octahedral_uv(const glm::vec3& direction);
glm::vec3 hemi_octahedral_direction(const glm::vec2& uv);

// The direction frame (i, j) was baked from: its cell centre's.
glm::vec3 impostor_frame_direction(int i, int j);

// The orthographic view of frame direction d (unit, toward the viewer) of a template whose
// bounding sphere is (center, radius): a camera on the sphere looking at its center along
// -d, up toward +Y (or +Z looking straight down), the sphere filling the frame.
glm::mat4 impostor_frame_view_projection(const glm::vec3& direction, const glm::vec3& center, float radius);

}  // namespace boreas::render
