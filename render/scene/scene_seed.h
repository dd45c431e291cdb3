// boreas scenes: a run's seed (`boreas run --seed`) laid over the seeds a scene file gives,
// so that one scene makes many different worlds, each reproducible from its seed.
#pragma once

#include <cstdint>

#include "scene/scene.h"

namespace boreas::render {

// The seed a scene's seed becomes under a run's seed: SplitMix64 of the two, so that
// distinct seeds in the file stay distinct (with overwhelming odds) and equal ones equal
// (trees that shared a template still share one).
uint64_t mix_seed(uint64_t run_seed, uint64_t scene_seed);

// Every seed of a loaded scene mixed with run_seed: the trees' (a forest's trees' template
// seeds among them), the imported trees', the meadows', the emitters' and the
// LiDARs'. A forest's own
// seed, which placed its trees, is mixed by the loader before it plants them.
void apply_run_seed(Scene& scene, uint64_t run_seed);

}  // namespace boreas::render
