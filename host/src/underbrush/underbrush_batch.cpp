// boreas: the meadows of a world on the device — layout, upload, the step, readbacks.
#include "underbrush/underbrush_batch.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "errors.h"
#include "shared/underbrush_math.h"
#include "wind/wind_params.h"

namespace boreas::impl {
namespace {

constexpr int kStrip = 2 * BOREAS_UB_JOINTS;

// Padding that does nothing: far away, no reach, no momentum.
BoreasGpuCollider silent_collider() { return BoreasGpuCollider{1e18f, 1e18f, 1e18f, 0.0f}; }
BoreasGpuImpulse silent_impulse() { return BoreasGpuImpulse{1e18f, 1e18f, 1e18f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f}; }

}  // namespace

UnderbrushBatch::UnderbrushBatch(Runtime& runtime) : runtime_(runtime) {}

const UnderbrushBatch::Placed& UnderbrushBatch::placed(uint64_t key) const {
  for (const Placed& p : meadows_)
    if (p.meadow->key == key) return p;
  fail(BOREAS_ERROR_INTERNAL, "underbrush batch has no meadow with key " + std::to_string(key));
}

int UnderbrushBatch::first(uint64_t key) const { return placed(key).first; }

void UnderbrushBatch::add(std::shared_ptr<const MeadowInstance> meadow) {
  std::vector<std::shared_ptr<const MeadowInstance>> next;
  for (const Placed& p : meadows_) next.push_back(p.meadow);
  next.push_back(std::move(meadow));
  rebuild(std::move(next));
}

void UnderbrushBatch::remove(uint64_t key) {
  std::vector<std::shared_ptr<const MeadowInstance>> next;
  for (const Placed& p : meadows_)
    if (p.meadow->key != key) next.push_back(p.meadow);
  rebuild(std::move(next));
}

std::vector<float> UnderbrushBatch::read_state() {
  std::vector<float> out(size_t(BOREAS_UB_STATE_PLANES) * std::max(n_, 1));
  if (n_ > 0)
    BOREAS_CL_CHECK(runtime_.queue().enqueueReadBuffer(state_[current_], CL_TRUE, 0, out.size() * sizeof(float),
                                                       out.data()));
  return out;
}

void UnderbrushBatch::rebuild(std::vector<std::shared_ptr<const MeadowInstance>> meadows) {
  // The current state of the meadows that stay, read before anything changes.
  std::vector<float> old_state;
  if (n_ > 0) old_state = read_state();
  const int old_n = n_;
  std::vector<Placed> placed;
  int n = 0, parts = 0;
  size_t table_size = 0;
  for (const auto& m : meadows) {
    placed.push_back({m, n, parts});
    n += m->meadow.count;
    parts += static_cast<int>(m->meadow.parts.size());
    table_size += m->meadow.tables.size();
  }
  const int stride = std::max(n, 1);
  std::vector<float> frame(size_t(BOREAS_UB_FRAME_PLANES) * stride, 0.0f);
  std::vector<int32_t> index(size_t(BOREAS_UB_INDEX_PLANES) * stride, 0);
  std::vector<float> state(size_t(BOREAS_UB_STATE_PLANES) * stride, 0.0f);
  std::vector<float> tables;
  tables.reserve(table_size);
  std::vector<BoreasGpuPart> records;
  for (const Placed& p : placed) {
    const Meadow& m = p.meadow->meadow;
    const int table_offset = static_cast<int>(tables.size());
    tables.insert(tables.end(), m.tables.begin(), m.tables.end());
    for (const MeadowPart& mp : m.parts) {
      BoreasGpuPart g = mp.gpu;
      g.forward += table_offset;
      g.inverse += table_offset;
      g.breaking += table_offset;
      g.widths += table_offset;
      records.push_back(g);
    }
    // Where the meadow's state comes from: the old batch if it was there, else rest.
    const float* source = m.rest_state.data();
    int source_stride = m.count, source_first = 0;
    for (const Placed& o : meadows_)
      if (o.meadow->key == p.meadow->key) {
        source = old_state.data();
        source_stride = old_n;
        source_first = o.first;
      }
    for (int c = 0; c < m.count; ++c) {
      const size_t to = size_t(p.first + c);
      for (int k = 0; k < BOREAS_UB_FRAME_PLANES; ++k) frame[size_t(k) * stride + to] = m.frame[size_t(k) * m.count + c];
      index[size_t(BOREAS_UB_INDEX_PART) * stride + to] = m.index[size_t(BOREAS_UB_INDEX_PART) * m.count + c] + p.first_part;
      index[size_t(BOREAS_UB_INDEX_PARENT) * stride + to] = m.index[size_t(BOREAS_UB_INDEX_PARENT) * m.count + c] + p.first;
      for (int k = 0; k < BOREAS_UB_STATE_PLANES; ++k)
        state[size_t(k) * stride + to] = source[size_t(k) * source_stride + source_first + c];
    }
  }
  if (tables.empty()) tables.push_back(0.0f);
  if (records.empty()) records.push_back(BoreasGpuPart{});

  // New buffers first; the batch changes only once all of them exist.
  cl::Buffer next_state[2] = {runtime_.buffer(CL_MEM_READ_WRITE, state.size() * sizeof(float)),
                              runtime_.buffer(CL_MEM_READ_WRITE, state.size() * sizeof(float))};
  cl::Buffer next_frame = runtime_.buffer(CL_MEM_READ_ONLY, frame.size() * sizeof(float));
  cl::Buffer next_index = runtime_.buffer(CL_MEM_READ_ONLY, index.size() * sizeof(int32_t));
  cl::Buffer next_parts = runtime_.buffer(CL_MEM_READ_ONLY, records.size() * sizeof(BoreasGpuPart));
  cl::Buffer next_tables = runtime_.buffer(CL_MEM_READ_ONLY, tables.size() * sizeof(float));
  runtime_.upload(next_state[0], state);
  runtime_.upload(next_state[1], state);
  runtime_.upload(next_frame, frame);
  runtime_.upload(next_index, index);
  runtime_.upload(next_parts, records);
  runtime_.upload(next_tables, tables);

  meadows_ = std::move(placed);
  n_ = n;
  current_ = 0;
  state_[0] = next_state[0];
  state_[1] = next_state[1];
  frame_ = next_frame;
  index_ = next_index;
  parts_ = next_parts;
  tables_ = next_tables;
  parts_host_ = std::move(records);
  parts_dt_ = -1.0;
}

void UnderbrushBatch::upload_parts(double dt) {
  if (dt == parts_dt_) return;
  for (BoreasGpuPart& g : parts_host_) g.decay = static_cast<float>(std::exp(-dt / double(g.tau)));
  runtime_.upload(parts_, parts_host_);
  parts_dt_ = dt;
}

void UnderbrushBatch::enqueue_step(double dt, const TreeWindInput& wind, const std::vector<BoreasGpuCollider>& colliders,
                                   const std::vector<BoreasGpuImpulse>& impulses) {
  if (n_ == 0) return;
  upload_parts(dt);
  std::vector<BoreasGpuCollider>& c = collider_staging_;
  std::vector<BoreasGpuImpulse>& m = impulse_staging_;
  c = colliders;
  m = impulses;
  int collider_slots = pad_to_slots(c, silent_collider());
  int impulse_slots = pad_to_slots(m, silent_impulse());
  if (c.empty()) c.push_back(silent_collider());  // a valid buffer even with no colliders
  if (m.empty()) m.push_back(silent_impulse());
  if (c.size() > collider_capacity_) {
    collider_capacity_ = std::max<size_t>(c.size(), 16);
    colliders_ = runtime_.buffer(CL_MEM_READ_ONLY, collider_capacity_ * sizeof(BoreasGpuCollider));
  }
  if (m.size() > impulse_capacity_) {
    impulse_capacity_ = std::max<size_t>(m.size(), 16);
    impulses_ = runtime_.buffer(CL_MEM_READ_ONLY, impulse_capacity_ * sizeof(BoreasGpuImpulse));
  }
  runtime_.upload_async(colliders_, c);
  runtime_.upload_async(impulses_, m);
  std::string defines = slot_define("BOREAS_WAVE_SLOTS", wind.wave_slots) +
                        slot_define("BOREAS_COLLIDER_SLOTS", collider_slots) +
                        slot_define("BOREAS_IMPULSE_SLOTS", impulse_slots);
  cl::Kernel& k = runtime_.kernel("underbrush_step.cl", "boreas_underbrush_step", defines);
  const int next = 1 - current_;
  int arg = 0;
  BOREAS_CL_CHECK(k.setArg(arg++, state_[current_]));
  BOREAS_CL_CHECK(k.setArg(arg++, state_[next]));
  BOREAS_CL_CHECK(k.setArg(arg++, frame_));
  BOREAS_CL_CHECK(k.setArg(arg++, index_));
  BOREAS_CL_CHECK(k.setArg(arg++, parts_));
  BOREAS_CL_CHECK(k.setArg(arg++, tables_));
  BOREAS_CL_CHECK(k.setArg(arg++, n_));
  BOREAS_CL_CHECK(k.setArg(arg++, static_cast<float>(dt)));
  BOREAS_CL_CHECK(k.setArg(arg++, static_cast<float>(kGravity)));
  BOREAS_CL_CHECK(k.setArg(arg++, *wind.waves));
  BOREAS_CL_CHECK(k.setArg(arg++, wind.wave_count));
  BOREAS_CL_CHECK(k.setArg(arg++, *wind.grid));
  BOREAS_CL_CHECK(k.setArg(arg++, wind.grid_layout));
  BOREAS_CL_CHECK(k.setArg(arg++, colliders_));
  BOREAS_CL_CHECK(k.setArg(arg++, static_cast<int>(colliders.size())));
  BOREAS_CL_CHECK(k.setArg(arg++, impulses_));
  BOREAS_CL_CHECK(k.setArg(arg++, static_cast<int>(impulses.size())));
  runtime_.launch(k, size_t(n_));
}

void UnderbrushBatch::enqueue_vertices(uint64_t key, const float* camera, const cl::Buffer& out, const cl::Buffer& counts,
                                       size_t out_first) {
  const Placed& p = placed(key);
  const int count = p.meadow->meadow.count;
  if (count == 0) return;
  const std::array<float, 3>& lod = p.meadow->meadow.params.lod;
  cl::Kernel& k = runtime_.kernel("underbrush_vertices.cl", "boreas_underbrush_vertices");
  // No camera: everything at full detail.
  const float far = 3e38f;
  float cam[3] = {0.0f, 0.0f, 0.0f};
  if (camera)
    for (int a = 0; a < 3; ++a) cam[a] = camera[a];
  int arg = 0;
  BOREAS_CL_CHECK(k.setArg(arg++, state_[current_]));
  BOREAS_CL_CHECK(k.setArg(arg++, frame_));
  BOREAS_CL_CHECK(k.setArg(arg++, index_));
  BOREAS_CL_CHECK(k.setArg(arg++, parts_));
  BOREAS_CL_CHECK(k.setArg(arg++, tables_));
  BOREAS_CL_CHECK(k.setArg(arg++, n_));
  for (int a = 0; a < 3; ++a) BOREAS_CL_CHECK(k.setArg(arg++, cam[a]));
  for (int a = 0; a < 3; ++a) BOREAS_CL_CHECK(k.setArg(arg++, camera ? lod[a] : far));
  BOREAS_CL_CHECK(k.setArg(arg++, out));
  BOREAS_CL_CHECK(k.setArg(arg++, counts));
  BOREAS_CL_CHECK(k.setArg(arg++, p.first));
  BOREAS_CL_CHECK(k.setArg(arg++, count));
  BOREAS_CL_CHECK(k.setArg(arg++, static_cast<int>(out_first)));
  runtime_.launch(k, size_t(count));
}

void UnderbrushBatch::vertices(uint64_t key, const float* camera, std::vector<float>* vertices,
                               std::vector<int32_t>* counts) {
  const Placed& p = placed(key);
  const int count = p.meadow->meadow.count;
  vertices->assign(size_t(count) * kStrip * 8, 0.0f);
  counts->assign(size_t(count), 0);
  if (count == 0) return;
  cl::Buffer out = runtime_.buffer(CL_MEM_WRITE_ONLY, size_t(count) * kStrip * 8 * sizeof(float));
  cl::Buffer cnt = runtime_.buffer(CL_MEM_WRITE_ONLY, size_t(count) * sizeof(int32_t));
  enqueue_vertices(key, camera, out, cnt, 0);
  cl::CommandQueue& q = runtime_.queue();
  BOREAS_CL_CHECK(q.enqueueReadBuffer(out, CL_TRUE, 0, vertices->size() * sizeof(float), vertices->data()));
  BOREAS_CL_CHECK(q.enqueueReadBuffer(cnt, CL_TRUE, 0, counts->size() * sizeof(int32_t), counts->data()));
}

std::vector<boreas_component> UnderbrushBatch::components(uint64_t key) {
  const Placed& p = placed(key);
  const Meadow& m = p.meadow->meadow;
  std::vector<float> state = read_state();
  const size_t n = size_t(std::max(n_, 1));
  std::vector<boreas_component> out(size_t(m.count));
  for (int c = 0; c < m.count; ++c) {
    const size_t i = size_t(p.first + c);
    boreas_component& o = out[size_t(c)];
    int parent = m.index[size_t(BOREAS_UB_INDEX_PARENT) * m.count + c];
    for (int a = 0; a < 3; ++a) {
      o.base[a] = state[size_t(BOREAS_UB_STATE_BASE + a) * n + i];
      o.center_of_mass[a] = state[size_t(BOREAS_UB_STATE_X + a) * n + i];
      o.velocity[a] = state[size_t(BOREAS_UB_STATE_V + a) * n + i];
      o.rest_center_of_mass[a] = m.frame[size_t(BOREAS_UB_FRAME_REST + a) * m.count + c];
    }
    o.broken = static_cast<int32_t>(state[size_t(BOREAS_UB_STATE_BROKEN) * n + i]);
    o.species = m.species_of[size_t(c)];
    o.part = m.parts[size_t(m.index[size_t(BOREAS_UB_INDEX_PART) * m.count + c])].part;
    o.parent = parent == c ? -1 : parent;
  }
  return out;
}

}  // namespace boreas::impl
