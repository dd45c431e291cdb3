// boreas render: a world's trees and meadows as the renderer's buffers. The kernels write
// the branch records, leaf records and underbrush strips into interop buffers (one of
// each, every tree and meadow at its own offset) after each step; what does not move
// (leaf sizes and occlusion, the components' colors) is uploaded once.
//
// A frame:  update(camera)  (the world has stepped)  ->  Renderer::draw(..., geometry())
//           ->  end_draw()  (after the last GL command that reads them).
#pragma once

#include <memory>
#include <vector>

#include <CL/cl.h>
#include <glm/vec3.hpp>

#include "boreas/boreas.h"
#include "gl/gl_objects.h"
#include "gl/renderer.h"
#include "interop/shared_buffer.h"

namespace boreas::render {

struct TreeToDraw {
  boreas_id id{};
  boreas_tree_level_def levels[4];  // the tree's def: rings and sides of each level's grid
};

struct MeadowToDraw {
  boreas_id id{};
  // 6 floats per component (linear albedo, transmittance), in component order.
  std::vector<float> styles;
};

class WorldBuffers {
 public:
  // Reads the trees' and meadows' static data once; the world must outlive this object
  // and its context must suit the strategy (gl_sharing: made from the current GL context).
  WorldBuffers(boreas_world world, interop::Strategy strategy, const std::vector<TreeToDraw>& trees,
               const std::vector<MeadowToDraw>& meadows);
  ~WorldBuffers();
  WorldBuffers(const WorldBuffers&) = delete;
  WorldBuffers& operator=(const WorldBuffers&) = delete;

  interop::Strategy strategy() const { return strategy_; }
  // Whether zero-copy buffers are the GL mapping itself (no copy anywhere).
  bool maps_in_place() const;
  // The world's state as of its last step into the buffers; camera (m) sets the meadows'
  // level of detail. Returns once GL may draw them.
  void update(const glm::vec3& camera);
  void end_draw();
  const FrameGeometry& geometry() const { return geometry_; }
  // Bytes the kernels write per frame.
  size_t bytes_per_frame() const;

 private:
  std::vector<interop::SharedBuffer*> shared() const;

  boreas_world world_;
  interop::Strategy strategy_;
  std::vector<boreas_id> trees_, meadows_;
  std::vector<size_t> first_branch_, first_leaf_, first_component_;
  std::unique_ptr<interop::SharedBuffer> branch_records_, leaf_records_, meadow_vertices_;
  cl_mem strip_counts_ = nullptr;
  GlObject leaf_static_, meadow_styles_;
  FrameGeometry geometry_;
};

}  // namespace boreas::render
