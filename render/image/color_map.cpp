// boreas images: viridis, as matplotlib's 11 evenly spaced samples, linearly interpolated.
#include "image/color_map.h"

#include <algorithm>
#include <cmath>

namespace boreas::render {

namespace {

constexpr unsigned kViridis[] = {0x440154, 0x482475, 0x414487, 0x355f8d, 0x2a788e, 0x21918c,
                                 0x22a884, 0x44bf70, 0x7ad151, 0xbddf26, 0xfde725};
constexpr int kStops = sizeof(kViridis) / sizeof(kViridis[0]);

Rgb from_hex(unsigned hex) {
  return {float((hex >> 16) & 0xff) / 255.0f, float((hex >> 8) & 0xff) / 255.0f,
          float(hex & 0xff) / 255.0f};
}

}  // namespace

Rgb viridis(float t) {
  if (!(t > 0.0f)) return from_hex(kViridis[0]);
  if (t >= 1.0f) return from_hex(kViridis[kStops - 1]);
  float x = t * float(kStops - 1);
  int i = std::min(int(std::floor(x)), kStops - 2);
  return mix(from_hex(kViridis[i]), from_hex(kViridis[i + 1]), x - float(i));
}

Rgb speed_color(float speed, float max_speed) { return viridis(speed / max_speed); }

}  // namespace boreas::render
