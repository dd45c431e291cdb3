// boreas scenes: builds the world a loaded scene describes, through the public API only.
#pragma once

#include <optional>
#include <string>

#include "boreas/boreas.hpp"
#include "scene/scene.h"

namespace boreas::render {

// device overrides the scene's own request when set. Throws boreas::Error from the library.
boreas::World make_world(const Scene& scene, const std::optional<std::string>& device);

}  // namespace boreas::render
