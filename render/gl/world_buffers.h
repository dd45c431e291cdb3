// boreas render: a world's trees, imported trees and meadows as the renderer's buffers. The
// kernels write into interop buffers after each step: the generated trees' records for the
// frame's view in one call (boreas_world_enqueue_tree_records: the trees it sees, far
// crowns thinned, far trees as impostor records, with its range records and indirect
// words), the imported trees' trunk positions and leaf vertices and the underbrush strips
// (every tree and meadow at its own offset); what does not move (leaf sizes and occlusion,
// one copy per template, the imported trees' indices and shading attributes, the
// components' colors) is uploaded once. The tree records' buffers hold what the views have needed so far: they grow (a
// quarter over) when a view needs more, which the call's counts say, read back without a
// wait and taken a frame later (update()); only the first frame waits for them.
//
// A frame:  update(camera, Renderer::tree_view(...))  (the world has stepped)
//           ->  Renderer::draw(..., geometry())  ->  end_draw()  (after the last GL
//           command that reads them).
// The impostors' bake:  update_at_rest()  (before the first step)  ->
//           Renderer::bake_impostors(rest_geometry())  ->  end_draw().
#pragma once

#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <CL/cl.h>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "boreas/boreas.h"
#include "boreas/boreas_cl.h"
#include "gl/crown_light.h"
#include "gl/gl_objects.h"
#include "gl/renderer.h"
#include "interop/shared_buffer.h"

namespace boreas::render {

struct TreeToDraw {
  boreas_tree_id id{};
  boreas_tree_level_def levels[4];  // the tree's def: rings and sides of each level's grid
  int leaf_layer = 0;               // its leaf kind's layer (Renderer::leaf_layer)
  // Its leaves' transmittance (Renderer::leaf_transmittance), tinting its crown's occlusion;
  // the default is the reference lamina's (render/textures/thin_slab.h).
  glm::vec3 leaf_transmittance{0.06f, 0.13f, 0.02f};
  // false: every leaf lit as if nothing of the crown stood between it and the sky (for
  // reference frames and tests).
  bool crown_occlusion = true;
  // Trees with the same non-empty model (one grown model: species and seed, and one leaf
  // kind) share one impostor, baked from the first of them; empty: always drawn in full.
  std::string model;
  // Its placement (boreas_tree_def): the template's space is the model's before it.
  glm::vec3 position{0.0f};  // m
  float rotation = 0.0f;     // rad about +Y
  float scale = 1.0f;
};

struct MeadowToDraw {
  boreas_meadow_id id{};
  // 6 floats per component (linear albedo, transmittance), in component order.
  std::vector<float> styles;
};

class WorldBuffers {
 public:
  // Reads the trees', imported trees' (mesh_trees, at rest: before their first step) and
  // meadows' static data once; the world must outlive this object and its context must
  // suit the strategy (gl_sharing: made from the current GL context).
  // The tree records' buffers hold every tree in full from the start where that is at most
  // whole_records_bytes (the default: some seventy aspens, at about 0.9 MB of branch and
  // leaf records each), and are never grown then; else they grow as views need.
  static constexpr size_t kWholeRecordsBytes = size_t(64) << 20;
  WorldBuffers(boreas_world world, interop::Strategy strategy, const std::vector<TreeToDraw>& trees,
               const std::vector<MeadowToDraw>& meadows,
               const std::vector<boreas_mesh_tree_id>& mesh_trees = {},
               size_t whole_records_bytes = kWholeRecordsBytes);
  ~WorldBuffers();
  WorldBuffers(const WorldBuffers&) = delete;
  WorldBuffers& operator=(const WorldBuffers&) = delete;

  interop::Strategy strategy() const { return strategy_; }
  // Whether zero-copy buffers are the GL mapping itself (no copy anywhere).
  bool maps_in_place() const;
  // The world's state as of its last step into the buffers: the trees the view sees
  // (Renderer::tree_view), camera (m) sets the meadows' level of detail. Returns once GL may
  // draw them.
  void update(const glm::vec3& camera, const boreas_tree_view_def& trees);
  // Every template's tree (TreeToDraw::model) in full, one after the other in buffers of
  // their own until the next update() (ImpostorTemplate::rest_*_shift says where): what
  // Renderer::bake_impostors reads.
  void update_at_rest();
  void end_draw();
  const FrameGeometry& geometry() const { return geometry_; }
  const FrameGeometry& rest_geometry() const { return rest_geometry_; }
  // The last update's indirect words (boreas_cl.h: what the call wrote and needed), read
  // back with a wait: for tests and reports after the frames, never in a frame.
  const uint32_t* tree_counts();
  // Reads of the needed counts update() enqueued, and of those the blocking ones (the
  // first frame's alone): what "a frame reads nothing back with a wait" is tested by.
  int64_t needed_reads() const { return reads_enqueued_; }
  int64_t blocking_reads() const { return blocking_reads_; }
  // The colliders the next frames draw (FrameGeometry::balls), so that a frame need not
  // copy the geometry's per-tree lists to add them.
  void set_balls(std::vector<glm::vec4> balls) { geometry_.balls = std::move(balls); }
  // Bytes of the buffers the kernels write per frame (their capacity: the tree records'
  // grow to what the views have needed).
  size_t bytes_per_frame() const;

 private:
  std::vector<interop::SharedBuffer*> shared() const;
  std::vector<interop::SharedBuffer*> tree_shared() const;

  boreas_world world_;
  interop::Strategy strategy_;
  size_t whole_records_bytes_;
  // The constructor's steps. A tree's or a meadow's draws, static data and room (bounds),
  // from the first record and component given (which grow by its own); then the buffers
  // of them all.
  void add_tree(const TreeToDraw& tree, size_t* branches, size_t* leaves,
                std::vector<float>* leaf_static, Bounds* bounds);
  void add_branch_draws(const TreeToDraw& tree, const std::vector<boreas_branch>& b,
                        int first_record, const Bounds& crown, const Bounds& sway);
  // The tree's TreeInstance, and its model's ImpostorTemplate where it is the first of it.
  void add_tree_instance(const TreeToDraw& tree, const std::vector<boreas_branch>& b,
                         int first_branch_draw, int first_record, const Bounds& wood,
                         const Bounds& crown);
  // The tree's leaves' static data (LeafDraw::first_static, static_scale): one copy per
  // template, leaf kind and occlusion (issue 39), the first such tree's, appended by it.
  void add_leaf_static(const TreeToDraw& tree, const std::vector<boreas_leaf>& l,
                       std::vector<float>* leaf_static, LeafDraw* draw);
  void add_meadow(const MeadowToDraw& meadow, size_t* components, std::vector<float>* styles,
                  Bounds* bounds);
  void add_meadow_styles(const MeadowToDraw& meadow, int n, std::vector<float>* styles);
  void make_buffers(cl_context context, cl_command_queue queue, size_t branches, size_t leaves,
                    size_t components, const std::vector<float>& leaf_static,
                    const std::vector<float>& styles);
  // Reads the imported trees' rest poses and makes their buffers; grows bounds by them.
  void add_mesh_trees(const std::vector<boreas_mesh_tree_id>& ids, cl_context context,
                      cl_command_queue queue, Bounds* bounds);

  std::map<std::string, int> templates_;  // model -> its index in impostor_templates
  // (world template, leaf layer, crown occlusion, its transmittance, leaves) -> the first
  // static leaf of the first such tree, and its leaves' summed length (m): what the others
  // share, at their own scale.
  using StaticKey = std::tuple<int, int, bool, float, float, float, int>;
  std::map<StaticKey, std::pair<int, double>> leaf_statics_;
  size_t static_leaves_ = 0;
  std::vector<boreas_tree_id> trees_;
  std::vector<boreas_meadow_id> meadows_;
  std::vector<boreas_mesh_tree_id> mesh_trees_;
  std::vector<size_t> first_branch_, first_leaf_, first_component_;
  std::vector<size_t> first_mesh_trunk_, first_mesh_leaf_;  // vertices, per imported tree
  std::unique_ptr<interop::SharedBuffer> meadow_vertices_;
  std::unique_ptr<interop::SharedBuffer> mesh_trunk_positions_, mesh_leaf_vertices_;
  cl_mem strip_counts_ = nullptr;
  cl_context context_ = nullptr;
  cl_command_queue queue_ = nullptr;
  // The trees' records in one call a frame: branch, leaf and impostor records (capacity_
  // of each), ranges (one per tree), the indirect words (the call writes indirect_, a
  // device buffer whose needed counts the host reads without a wait, copied to
  // tree_indirect_, which GL draws from).
  std::unique_ptr<interop::SharedBuffer> branch_records_, leaf_records_, tree_impostors_;
  std::unique_ptr<interop::SharedBuffer> tree_ranges_, tree_indirect_;
  cl_mem indirect_ = nullptr;
  size_t capacity_[3] = {0, 0, 0};
  uint32_t tree_counts_[BOREAS_TREE_INDIRECT_UINTS] = {};
  bool every_tree_has_template_ = true;
  void make_tree_record_buffers(size_t branches, size_t leaves);
  void resize_tree_records(const size_t records[3]);
  void enqueue_tree_records(const boreas_tree_view_def& view);
  // Where the last read of the call's needed counts has landed and they pass the buffers,
  // grows them and returns true (read_in_flight: whether it has not yet, asked without a wait).
  bool grow_tree_records();
  bool read_in_flight();
  void read_needed(bool blocking);
  uint32_t needed_[4] = {};  // the indirect words' BOREAS_TREE_INDIRECT_NEEDED, as read
  cl_event needed_read_ = nullptr;  // the read into needed_, until seen complete
  bool needed_landed_ = false;      // needed_ holds a landed read not yet taken
  int64_t reads_enqueued_ = 0, blocking_reads_ = 0;
  // Every tree's branches and leaves; the bake's records: the templates' trees alone, one
  // after the other (ImpostorTemplate::rest_*_shift).
  size_t all_branches_ = 0, all_leaves_ = 0;
  std::unique_ptr<interop::SharedBuffer> rest_branch_records_, rest_leaf_records_;
  FrameGeometry rest_geometry_;
  GlObject leaf_static_, meadow_styles_;
  GlObject mesh_trunk_static_, mesh_trunk_indices_, mesh_leaf_static_, mesh_leaf_indices_;
  FrameGeometry geometry_;
};

}  // namespace boreas::render
