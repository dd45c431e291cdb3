// boreas command: LiDAR points over a frame, colored by surface.
#include "view/lidar_overlay.h"

#include <cmath>

#include "image/bitmap_font.h"
#include "view/motion_trails.h"

namespace boreas::render {

namespace {

// Whole 8-bit values, so that a point's pixel is written as exactly its color.
constexpr Rgb bytes(int r, int g, int b) { return {r / 255.0f, g / 255.0f, b / 255.0f}; }
const Rgb kSurfaceColors[BOREAS_LIDAR_SURFACES] = {
    bytes(255, 140, 24),   // bark
    bytes(24, 230, 255),   // leaf
    bytes(255, 242, 50),   // grass
    bytes(242, 76, 230),   // ground
    bytes(255, 255, 255),  // solid
};


}  // namespace

Rgb lidar_surface_color(int hit_kind) { return kSurfaceColors[boreas_lidar_surface_of(hit_kind)]; }

int draw_lidar_points(Image& image, const std::vector<boreas_lidar_point>& points,
                      const glm::mat4& view_proj) {
  const int size = image.width() > 640 ? 3 : 2;
  int drawn = 0;
  for (const boreas_lidar_point& p : points) {
    float x = 0.0f, y = 0.0f;
    if (!project_to_image(view_proj, image.width(), image.height(), glm::vec3(p.x, p.y, p.z), x,
                          y)) {
      continue;
    }
    const int x0 = int(std::floor(x - 0.5f * float(size - 1)));
    const int y0 = int(std::floor(y - 0.5f * float(size - 1)));
    if (x0 + size <= 0 || y0 + size <= 0 || x0 >= image.width() || y0 >= image.height()) continue;
    image.fill_rect(x0, y0, x0 + size, y0 + size, lidar_surface_color(p.kind));
    ++drawn;
  }
  return drawn;
}

void draw_lidar_legend(Image& image) {
  static const char* const kNames[BOREAS_LIDAR_SURFACES] = {"BARK", "LEAF", "GRASS", "GROUND",
                                                            "SOLID"};
  const int line = 10;
  image.fill_rect(2, 2, 64, 4 + line * BOREAS_LIDAR_SURFACES, Rgb{0.0f, 0.0f, 0.0f}, 0.55f);
  for (int s = 0; s < BOREAS_LIDAR_SURFACES; ++s) {
    const int y = 4 + s * line;
    image.fill_rect(5, y + 1, 11, y + 7, kSurfaceColors[s]);
    draw_text(image, 14, y, kNames[s], 1, kSurfaceColors[s]);
  }
}

}  // namespace boreas::render
