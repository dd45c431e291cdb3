// boreas images: the color map for wind speed. Viridis: perceptually uniform, readable by
// color-blind viewers and in grayscale, dark at zero so calm and solid cells stand out.
#pragma once

#include "image/image.h"

namespace boreas::render {

// t in [0, 1] (clamped) to a color; NaN maps to the color of 0.
Rgb viridis(float t);

// The color of speed (m/s) on a scale whose top is max_speed (> 0); faster clamps to the top.
Rgb speed_color(float speed, float max_speed);

}  // namespace boreas::render
