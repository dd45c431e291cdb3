// boreas scenes: builds the world a loaded scene describes, through the public API only.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "boreas/boreas.hpp"
#include "scene/scene.h"

namespace boreas::render {

// device overrides the scene's own request when set. Throws boreas::Error from the library;
// a tree the library rejects (a bad species file) keeps its status, and its message, which
// names the species file, line and parameter, is prefixed with the scene and the tree's JSON
// path. tree_ids, when given, receives the id of each of scene.trees in order.
boreas::World make_world(const Scene& scene, const std::optional<std::string>& device,
                         std::vector<boreas_id>* tree_ids = nullptr);

}  // namespace boreas::render
