// boreas views: motion in one picture. `boreas run --view trails` films the first frame
// and then only steps the world, following a few points as they move: the tips of branches
// on the trees nearest the camera and the tips of blades near it. Their paths, projected
// through the first frame's camera, are drawn over that frame, colored from the run's
// start to its end, each starting from a dot where the point was at rest.
//
// A blade's tip here is the point twice as far from its base as its center of mass (the
// tip of the blade held straight through that center), read from boreas_component without
// reading every strip back each step; a branch's tip is its Bezier curve's end (P3).
#pragma once

#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "image/image.h"
#include "image/tree_view.h"
#include "view/meadow_frames.h"

namespace boreas::render {

// Where a world point falls in a width x height image through view_proj, in pixels from
// the top-left corner; false behind the camera.
bool project_to_image(const glm::mat4& view_proj, int width, int height, const glm::vec3& p,
                      float& x, float& y);

struct MotionTrail {
  enum class Kind { branch, blade };
  Kind kind = Kind::branch;
  size_t tree = 0;              // branch: index into the poses
  size_t branch = 0;            // branch: index into the pose's branches
  size_t component = 0;         // blade: index into FrameMeadows::now
  std::vector<glm::vec3> path;  // one point per frame, the first at rest
};

// Up to `per_tree` branch tips of each traced tree (indices into poses; the finest level
// first), and up to `blades` blade tips (near enough that a 3 cm move is a pixel, or half
// the pixels of the nearest one's where none is so near; within blade_distance m of eye
// where that is above 0), that the first frame sees inside its edges (by a margin) and
// that lie at least `spacing` pixels from every tip chosen before, so the paths do not
// pile up. The choice is fixed by the indices and distances (no randomness).
struct TrailChoice {
  int per_tree = 6;
  int blades = 40;
  float blade_distance = 0.0f;  // m; 0: any
  float spacing = 28.0f;        // pixels
  float margin = 16.0f;         // pixels
  float legend_rows = 24.0f;    // pixels at the bottom kept clear for draw_trails' legend
};
std::vector<MotionTrail> choose_trails(const std::vector<TreePose>& poses,
                                       const std::vector<size_t>& traced_trees,
                                       const FrameMeadows& meadows, const glm::vec3& eye,
                                       const glm::mat4& view_proj, int width, int height,
                                       const TrailChoice& choice = {});

// Appends each trail's current point: its branch's tip from poses, its blade's tip from
// meadows.now.
void record_trails(std::vector<MotionTrail>& trails, const std::vector<TreePose>& poses,
                   const FrameMeadows& meadows);

// The point of a blade at its component's base and center of mass: base + 2 (center - base).
glm::vec3 blade_tip(const MeadowComponent& c);

// Draws the trails over image (the first frame): each path a line on a dark halo, its color
// running from the start of the run to its end (branches yellow to red, blades cyan to
// violet), a dot at its first point; a white cross where each branch broken by the run's
// end breaks off (its base, `breaks`); and a legend naming the colors, the run's length and
// the count of breaks.
void draw_trails(Image& image, const std::vector<MotionTrail>& trails, const glm::mat4& view_proj,
                 double seconds, const std::vector<glm::vec3>& breaks = {});

// Where the broken branches of `poses` break off: their bases (a broken branch's children,
// broken with it or not, ride it and are not counted again unless they broke too).
std::vector<glm::vec3> break_points(const std::vector<TreePose>& poses);

}  // namespace boreas::render
