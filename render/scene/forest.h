// boreas scenes: a "forests" entry expanded into trees — where each stands, its species,
// seed (template), rotation and scale, all fixed by the entry's seed.
#pragma once

#include <vector>

#include "scene/scene.h"

namespace boreas::render {

// The trees of a stand: a lattice of ceil(sqrt(count * x/z)) columns over the rectangle,
// filled row by row, each tree jittered within its cell by up to 35 % of the cell (so no
// two trunks are closer than 30 % of the spacing); species drawn by weight; seed one of
// `templates` per species; rotation uniform in [0, 2 pi); scale uniform in the range.
std::vector<SceneTree> plant_forest(const SceneForest& forest);

}  // namespace boreas::render
