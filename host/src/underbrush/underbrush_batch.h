// boreas: every meadow of a world on the device as one set of component planes
// (cl/shared/underbrush_types.h), stepped by one launch (underbrush_step.cl); the vertex
// kernel (underbrush_vertices.cl) writes the strips on request.
//
// Adding or removing a meadow rebuilds the buffers, carrying the current state of the
// meadows that stay. The step writes the other half of a ping-pong state, visible only
// after commit(), so a failed step leaves the batch as it was.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "runtime/runtime.h"
#include "trees/tree_batch.h"
#include "underbrush/meadow.h"

namespace boreas::impl {

struct MeadowInstance {
  uint64_t key = 0;
  Meadow meadow;
};

class UnderbrushBatch {
 public:
  explicit UnderbrushBatch(Runtime& runtime);

  bool empty() const { return meadows_.empty(); }
  int component_count() const { return n_; }

  void add(std::shared_ptr<const MeadowInstance> meadow);
  void remove(uint64_t key);

  // Enqueues one step; colliders and impulses as the kernel reads them (unpadded). Their
  // upload does not wait: the queue must finish before the next enqueue_step (World::step
  // does), as they are copied from this batch's staging vectors.
  void enqueue_step(double dt, const TreeWindInput& wind, const std::vector<BoreasGpuCollider>& colliders,
                    const std::vector<BoreasGpuImpulse>& impulses);
  void commit() { current_ = 1 - current_; }

  // Blocking readbacks of one meadow (as of the last commit).
  std::vector<boreas_component> components(uint64_t key);
  // Its strips (BOREAS_UB_JOINTS * 2 vertices of 8 floats per component) and counts, LOD
  // from the camera (NULL: full detail).
  void vertices(uint64_t key, const float* camera, std::vector<float>* vertices, std::vector<int32_t>* counts);

  // For tests and benchmarks: the whole batch.
  std::vector<float> read_state();
  int first(uint64_t key) const;  // index of the meadow's first component
  const cl::Buffer& state_buffer() const { return state_[current_]; }
  // Enqueues the vertex kernel over one meadow (at its LOD distances) into the given
  // buffers, its first component's strip at component slot out_first (boreas_cl.h).
  void enqueue_vertices(uint64_t key, const float* camera, const cl::Buffer& out, const cl::Buffer& counts,
                        size_t out_first);

 private:
  struct Placed {
    std::shared_ptr<const MeadowInstance> meadow;
    int first = 0;       // first component
    int first_part = 0;  // first part record
  };
  const Placed& placed(uint64_t key) const;
  void rebuild(std::vector<std::shared_ptr<const MeadowInstance>> meadows);
  void upload_parts(double dt);

  Runtime& runtime_;
  std::vector<Placed> meadows_;
  int n_ = 0;
  int current_ = 0;
  std::vector<BoreasGpuPart> parts_host_;
  double parts_dt_ = -1.0;  // dt the device's part records' decay was written for
  cl::Buffer state_[2], frame_, index_, parts_, tables_;
  cl::Buffer colliders_, impulses_;
  std::vector<BoreasGpuCollider> collider_staging_;  // read by the step's upload_async
  std::vector<BoreasGpuImpulse> impulse_staging_;
  size_t collider_capacity_ = 0, impulse_capacity_ = 0;
};

}  // namespace boreas::impl
