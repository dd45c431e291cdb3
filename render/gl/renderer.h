// boreas render: one frame of the scene with OpenGL 4.5, from buffers the kernels wrote.
// Passes, in order:
//   1. shadow: branches, leaves, impostors, imported trees and underbrush into the sun's
//      depth map (orthographic, fitted to the geometry's bounds);
//   2. scene into a half-float HDR target: ground, bark (the deformer in the vertex shader),
//      leaves (instanced alpha-tested quads), far trees' impostors, imported trees' bark and
//      leaves (their own triangles, moved by the kernels), underbrush strips, then the sky
//      where nothing was drawn;
// The generated trees cost the CPU nothing per tree: the records' one call
// (boreas_world_enqueue_tree_records, for tree_view()) culled them, thinned the far crowns'
// leaves and wrote the far trees' impostor records on the device; a compute dispatch a
// frame (shaders/tree_ranges.comp) turns its range records into the draw commands of both
// passes, and each pass draws every tree's bark in one indirect multi-draw, every tree's
// leaves in another, and the impostors in two instanced indirect draws: the call's, with
// the count it wrote, and those handing over (gl/tree_table.h).
//   3. tone mapping (Reinhard with a white point, sRGB) into an 8-bit target that is read
//      back, or shown in a window.
// Radiance is in kcd/m^2 throughout (render/sky); the exposure scales it once, in pass 3.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "boreas/boreas_cl.h"
#include "gl/camera.h"
#include "gl/gl_objects.h"
#include "gl/program.h"
#include "gl/scene_light.h"
#include "gl/vegetation_textures.h"
#include "sky/preetham.h"

namespace boreas::render {

class TreeTable;

// Metres of bark one repeat of the bark texture covers, around and along a branch
// (bark_textures.h's default tile).
constexpr float kBarkTileM = 0.2f;

struct RenderSettings {
  int width = 1280, height = 720;  // pixels
  int shadow_map_size = 2048;      // texels; 0 turns shadows off
  bool translucency = true;        // false: leaves and blades let no light through
  // Samples per pixel of the scene pass (1: none). Multisampling, not alpha to coverage
  // or a post-process filter: blades, stalks and twigs are thinner than a pixel, so only
  // coverage measured per sample keeps them continuous lines instead of dotted ones, and
  // the blades' widening (meadow.vert) keeps them at least a pixel wide for it to act on.
  // Resolved (averaged) in HDR before tone mapping. 1..16; settings() holds the count
  // used, capped at the driver's most.
  int msaa_samples = 4;
  // Stochastic simplification (Cook et al. 2007) of what is too small to be resolved: leaves
  // under 3 x 3 pixels (3 x 3 shadow-map texels), twigs and blades under a pixel (a texel)
  // wide are kept with a probability that is their size over that, and the kept ones drawn
  // larger by as much, so the expected coverage stays and the rasterizer sees fewer of
  // them (leaf.vert, branch.vert, meadow.vert). false: every one drawn at its size.
  bool thinning = true;
  // Post effects, added to the radiance before tone mapping (Kusternig sec. 6.1), at a
  // quarter of the frame's size: bloom, the share of the light above an exposed luminance
  // of 2 that a lens spreads around bright pixels as glare (0: none); light shafts, sky
  // light through gaps in the canopy streaked toward the sun by haze (Mitchell, GPU Gems 3
  // ch. 13), this times the default strength (0: none).
  float bloom = 0.04f;
  float light_shafts = 1.0f;
  float exposure = 1.0f;           // multiplies the automatic exposure
  // m from the camera to a tree's base past which its impostor is drawn instead of its
  // branches and leaves (with a template baked: bake_impostors), dithered from one to the
  // other over the next kImpostorHandover of it; 0: never. Where a tree of 20 m is about
  // 170 pixels tall at 1280 x 720 and 55 degrees, and its leaves under a pixel.
  float impostor_distance = 80.0f;
  // Measure each part of the frame on the GPU (timer queries, waited for: a frame's parts
  // then run one after the other): part_seconds().
  bool time_parts = false;
};

// The share of the impostor distance over which a tree changes from geometry to impostor.
constexpr float kImpostorHandover = 0.25f;

// `count` branches from record `first_record` on, all swept on the same grid.
struct BranchDraw {
  int first_record = 0;
  int count = 0;
  int rings = 1, sides = 3;
  glm::vec3 crown_center{0.0f};  // m: the tree's crown, for the bark's occlusion
  glm::vec3 crown_radius{1.0f};  // m, half extents
  // m: a box the tree stays in as it sways; the draw is skipped where the box lies outside
  // the pass's frustum. The default never is.
  glm::vec3 bounds_min{-1e30f}, bounds_max{1e30f};
};

// One tree's leaves: `count` leaves from `first` on, inside the box while they sway.
struct LeafDraw {
  int first = 0;
  int count = 0;
  glm::vec3 bounds_min{-1e30f}, bounds_max{1e30f};  // m
  // m^2: its leaves' mean length x width. With thinning, the shadow pass draws every n-th
  // of a crown whose leaves the shadow map cannot resolve (tree_ranges.comp); 0: all.
  float mean_area = 0.0f;
  // Where its leaves' static data (FrameGeometry::leaf_static) begins, and what multiplies
  // the lengths and widths there: trees of one template share one copy at scale 1 (issue
  // 39), each reading it at its own scale. -1: at `first`, as its records.
  int first_static = -1;
  float static_scale = 1.0f;
};

// One meadow's components: `count` from `first` on, inside the box as they bend.
struct MeadowDraw {
  int first = 0;
  int count = 0;
  glm::vec3 bounds_min{-1e30f}, bounds_max{1e30f};  // m
};

// One tree of a FrameGeometry: which of its branch and leaf draws are its own, where it
// stands, and the template whose impostor stands in for it far away.
struct TreeInstance {
  int first_branch_draw = 0, branch_draw_count = 0;  // into FrameGeometry::branch_draws
  int leaf_draw = -1;          // into FrameGeometry::leaf_draws; -1: no leaves
  int impostor_template = -1;  // into FrameGeometry::impostor_templates; -1: always in full
  int trunk_record = -1;       // its trunk's branch record: the tip the impostor sways with
  glm::vec3 position{0.0f};    // m: the trunk's base
  float rotation = 0.0f;       // rad about +Y (boreas_tree_def)
  float scale = 1.0f;
  glm::vec3 rest_tip{0.0f};    // m: the trunk's tip at rest, world space
  // Its boreas_tree_id (what the records' one call's range records name it by; index -1:
  // none) and its world template (boreas_tree_get_template; -1: none).
  int id_index = -1, id_generation = 0;
  int world_template = -1;
};

// A tree model shared by trees (boreas_tree_def: same species and seed), baked once at rest
// into an impostor (gl/impostor_math.h) from one of its trees.
struct ImpostorTemplate {
  int tree = 0;                  // into FrameGeometry::trees: the one baked
  glm::vec3 center{0.0f};        // m, template space: the bounding sphere of its wood and leaves
  float radius = 1.0f;           // m
  float tip_height = 1.0f;       // m, template space: the trunk tip's height at rest
  glm::vec3 leaf_transmittance{0.06f, 0.13f, 0.02f};  // linear rgb, its leaves' mean
  // How far before its tree's own offsets its branch and leaf records lie in the geometry
  // the bake reads (WorldBuffers::update_at_rest writes the templates' trees alone, one
  // after the other); 0: at them.
  int rest_branch_shift = 0, rest_leaf_shift = 0;
};

// One imported tree's trunk: `index_count` element indices from `first_index` on.
struct MeshTrunkDraw {
  int first_index = 0;
  int index_count = 0;
  glm::vec3 crown_center{0.0f};  // m: the tree's crown, for the bark's occlusion
  glm::vec3 crown_radius{1.0f};  // m, half extents
};

// What a frame draws: OpenGL buffer names (interop::SharedBuffer::gl() or any buffer of
// the same layout) and counts. A zero name or count skips that part.
struct FrameGeometry {
  unsigned branch_records = 0;  // 24 floats per branch (boreas_cl.h)
  std::vector<BranchDraw> branch_draws;
  unsigned leaf_records = 0;  // 9 floats per leaf (boreas_cl.h)
  unsigned leaf_static = 0;   // 6 floats per leaf: length (m), width (m), ambient occlusion
                              // (r, g, b), layer of the leaf maps; where LeafDraw says
  int leaf_count = 0;
  // Per tree, for skipping trees out of view; empty: every leaf in one draw.
  std::vector<LeafDraw> leaf_draws;
  unsigned meadow_vertices = 0;  // boreas_meadow_vertex, 18 per component
  unsigned meadow_styles = 0;    // 8 floats per component: linear albedo, transmittance,
                                 // widest (m), unused
  int meadow_components = 0;
  // Per meadow, for skipping meadows out of view; empty: every component in one draw.
  std::vector<MeadowDraw> meadow_draws;
  // Imported trees (boreas_mesh_tree_enqueue_vertices; layouts in gl/mesh_tree_surface.h):
  unsigned mesh_trunk_positions = 0;  // 3 floats per vertex, every tree's trunk in turn
  unsigned mesh_trunk_static = 0;     // kMeshBarkFloats per vertex
  unsigned mesh_trunk_indices = 0;    // three per triangle, into the buffers above
  std::vector<MeshTrunkDraw> mesh_trunk_draws;
  unsigned mesh_leaf_vertices = 0;  // 6 floats per vertex: position, normal
  unsigned mesh_leaf_static = 0;    // kMeshLeafFloats per vertex
  unsigned mesh_leaf_indices = 0;
  int mesh_leaf_index_count = 0;
  // Generated trees, each with its draws above; empty: every branch and leaf draw is drawn
  // in full, as a tree of its own. Trees whose template has an impostor are drawn as it
  // beyond RenderSettings::impostor_distance.
  std::vector<TreeInstance> trees;
  std::vector<ImpostorTemplate> impostor_templates;
  // The records' one call (boreas_world_enqueue_tree_records): branch_records and
  // leaf_records then hold what it wrote for the frame's view, and these its impostor
  // records, range records (tree_range_capacity of them at most) and 20 indirect words.
  // tree_ranges 0: the records lie at the draws' own offsets (every tree in full).
  unsigned tree_impostors = 0, tree_ranges = 0, tree_indirect = 0;
  int tree_range_capacity = 0;
  std::vector<glm::vec4> balls;  // colliders: center (m), radius (m); at most 64 drawn
  glm::vec3 bounds_min{-1.0f}, bounds_max{1.0f};  // m: everything that casts a shadow
};

// The ground: a flat square at height y.
struct Ground {
  float y = 0.0f;                                   // m
  glm::vec4 rect{-1000.0f, -1000.0f, 1000.0f, 1000.0f};  // m: min x, min z, max x, max z
  float haze_distance = 900.0f;                     // m: aerial perspective's 1/e length
  // Meadows (min x, min z, max x, max z; at most 16): green sward under their components.
  std::vector<glm::vec4> meadow_rects;
};

class Renderer {
 public:
  // Needs a current OpenGL 4.5 context; compiles the shaders and uploads the textures
  // (ShaderError, std::invalid_argument for bad settings).
  Renderer(const RenderSettings& settings, const TextureSet& textures, const SkyParams& sky);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  const RenderSettings& settings() const { return settings_; }
  const SceneLight& light() const { return light_; }
  // The layer of the leaf maps a tree of this leaf kind draws with (0: the set's leaf).
  int leaf_layer(const std::string& kind) const { return textures_.leaf_layer(kind); }
  // The mean transmittance (linear r, g, b) of that kind's leaf: what its crown's occlusion
  // is tinted by (boreas_tree_get_leaf_occlusion).
  glm::vec3 leaf_transmittance(const std::string& kind) const {
    return textures_.leaf_transmittance[size_t(textures_.leaf_layer(kind))];
  }
  void set_sky(const SkyParams& sky);
  void set_translucency(bool on) { settings_.translucency = on; }
  void set_exposure(float multiplier) { settings_.exposure = multiplier; }

  // Bakes the impostors of the geometry's impostor_templates from their trees as the
  // record buffers hold them now (at rest: before the world's first step), on the GPU:
  // those with a tree near enough the impostor distance from one of the eyes (m) to need
  // it, or all with no eyes. The trees of a template not baked, all of them until this
  // is called and with impostor_distance 0, are drawn in full.
  void bake_impostors(const FrameGeometry& geometry, const std::vector<glm::vec3>& eyes = {});
  bool impostors_baked() const { return baked_templates_ > 0; }

  // The view the records' one call makes the geometry's trees for, from this camera
  // (gl/tree_view.h): the image's size and thinning, the sun's shadows, and, once impostors
  // are baked, impostors past the end of the handover.
  boreas_tree_view_def tree_view(const Camera& camera, const FrameGeometry& geometry) const;

  // Renders into the targets; returns once the commands are issued.
  void draw(const Camera& camera, const FrameGeometry& geometry, const Ground& ground);

  // What the last frame's tree commands drew in a pass (the scene's or the shadow map's):
  // branch and leaf records (instances summed over the commands) and the handover's
  // impostors. Reads the commands back (for tests; a frame never does).
  struct TreeDrawCounts {
    long long branches = 0, leaves = 0, handover_impostors = 0;
  };
  TreeDrawCounts tree_draw_counts(bool shadow_pass) const;

  // With time_parts, the GPU seconds of each part of the frames drawn so far ("shadow
  // leaves", "scene meadows", ...), summed over frames.
  // Next to each, "cpu <part>": the process's CPU seconds over it (llvmpipe's threads draw
  // in the process; a loaded machine stretches these far less than the GPU seconds).
  const std::map<std::string, double>& part_seconds() const { return part_seconds_; }

  // The last frame, tone mapped: 8-bit sRGB RGB, rows top to bottom.
  std::vector<uint8_t> read_rgb8() const;
  // The last frame before tone mapping, exposure applied: linear RGB floats, rows top to
  // bottom (for EXR output).
  std::vector<float> read_hdr_rgb() const;
  // Copies the tone-mapped frame to the default framebuffer of a window of that size.
  void present(int window_width, int window_height) const;

 private:
  struct Programs;
  // The constructor's steps: the scene's HDR targets (and multisampled ones, the samples
  // capped at the driver's most), the post effects' quarter-size targets, the shadow map,
  // the vertex arrays.
  void make_scene_targets();
  void make_post_targets();
  void make_shadow_map();
  void make_vertex_arrays();
  void draw_shadow_map(const FrameGeometry& geometry);
  // m: a texel of the shadow map the geometry is drawn into (0 without shadows).
  float shadow_texel(const FrameGeometry& geometry) const;
  // draw()'s scene pass: its target bound and cleared with the vegetation's textures
  // bound, the ground, then (after the geometry) the sky where nothing was drawn.
  void begin_scene_pass(unsigned scene_fbo);
  void draw_ground(const glm::mat4& view_proj, const Ground& ground);
  void draw_sky(const glm::mat4& view_proj);
  // Pass 3 into ldr_color_, with the post effects when `post`.
  void draw_tone_mapping(bool post);
  // Bloom and light shafts into post_bloom_ and post_shafts_, from hdr_color_ and depth_.
  void draw_post_effects(const glm::mat4& view_proj);
  // Everything in the geometry, from the camera or (shadow_pass) into the shadow map: the
  // draw_* below in turn, each with the pass's program of its pair.
  void draw_geometry(const FrameGeometry& geometry, bool shadow_pass);
  struct GeometryPass;
  const Program& use_program(const Program& lit, const Program& shadow,
                             const GeometryPass& pass) const;
  // The frame's commands for the generated trees, both passes' (shaders/tree_ranges.comp);
  // each pass then draws their branches, leaves and impostors from them: four draws
  // whatever the number of trees.
  void write_tree_commands(const FrameGeometry& g);
  void draw_branches(const FrameGeometry& g, const GeometryPass& pass);
  void draw_leaves(const FrameGeometry& g, const GeometryPass& pass);
  void draw_impostors(const FrameGeometry& g, const GeometryPass& pass);
  // bake_impostors' steps: the atlas, then one template's frames.
  void make_impostor_atlas(const FrameGeometry& g, int templates);
  // Lists what the bake's thinning keeps of the tree (at texel_m, m) and counts it into the
  // bake's commands (its branch records branch_shift before its own offsets: the
  // template's rest_branch_shift); returns its first branch record.
  int thin_for_bake(int tree, float texel_m, int branch_shift);
  std::vector<int> templates_seen_far(const FrameGeometry& g, const std::vector<glm::vec3>& eyes) const;
  void bake_template(const FrameGeometry& g, int index);
  void bind_vegetation_textures() const;
  void draw_mesh_trunks(const FrameGeometry& g, const GeometryPass& pass);
  void draw_mesh_leaves(const FrameGeometry& g, const GeometryPass& pass);
  void draw_meadows(const FrameGeometry& g, const GeometryPass& pass);
  void draw_balls(const FrameGeometry& g, const GeometryPass& pass);
  // Runs body, timed as the part `name` of the pass with time_parts.
  template <typename Body>
  void timed_part(const GeometryPass& pass, const char* name, Body&& body);
  void set_frame_uniforms(const Program& program, const glm::mat4& view_proj) const;
  void ensure_meadow_indices(int components);
  float exposure() const;

  RenderSettings settings_;
  std::unique_ptr<Programs> programs_;
  VegetationTextures textures_;
  SkyModel sky_;
  SceneLight light_;
  SkyUniforms sky_uniforms_;

  GlObject hdr_color_, depth_, hdr_fbo_;
  // With msaa_samples > 1 the scene is drawn here and resolved into hdr_color_.
  GlObject msaa_color_, msaa_depth_, msaa_fbo_;
  GlObject ldr_color_, ldr_fbo_;
  // The post effects' quarter-size targets: the bright part and the sky mask (written
  // together), the blur's scratch, the shafts.
  GlObject post_bloom_, post_sky_, post_scratch_, post_shafts_;
  GlObject post_input_fbo_, post_bloom_fbo_, post_scratch_fbo_, post_shafts_fbo_;
  GlObject shadow_depth_, shadow_fbo_;
  GlObject empty_vao_, meadow_vao_;
  GlObject meadow_indices_;
  int meadow_index_components_ = 0;
  std::unique_ptr<TreeTable> tree_table_;
  // The impostors' atlases: one layer per template, kImpostorFrames^2 frames in each.
  GlObject impostor_albedo_, impostor_normal_, impostor_leaf_, impostor_depth_, impostor_fbo_;
  // The baking's lists of what its thinning keeps of one tree, and their draw commands
  // (shaders/impostor_thinning.comp).
  GlObject bake_commands_, bake_branches_, bake_leaves_;
  int baked_templates_ = 0;
  GlObject part_query_;
  std::map<std::string, double> part_seconds_;

  Camera camera_;
  glm::mat4 light_view_proj_{1.0f};  // world -> the shadow map's clip space
  glm::mat4 light_matrix_{1.0f};     // world -> its texture coordinates and depth
  float shadow_texel_m_ = 0.0f;
  Ground ground_;
};

}  // namespace boreas::render
