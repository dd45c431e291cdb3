// boreas render bench: the benchmarks of boreas_render_bench (render_benchmarks.cpp).
#pragma once

namespace boreas::render::bench {

// Registers BM_FrameStages, BM_InteropUpdate and BM_RenderOnly, in the order they run.
void register_benchmarks();

// Frees what the benchmarks keep between runs (worlds, buffers, renderers); call before
// release_gl_context().
void release_benchmarks();

}  // namespace boreas::render::bench
