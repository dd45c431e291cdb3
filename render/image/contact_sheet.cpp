// boreas images: contact sheets. Frames are resized with OpenImageIO, then tiled and
// labelled on a canvas.
#include "image/contact_sheet.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <stdexcept>

#include "image/bitmap_font.h"

namespace boreas::render {

namespace {

const Rgb kBackground{0.12f, 0.12f, 0.12f};
constexpr int kGap = 4;  // pixels between tiles and around the sheet

Image shrink(const Image& frame, int width, int height) {
  if (width == frame.width() && height == frame.height()) return frame;
  OIIO::ImageSpec spec(frame.width(), frame.height(), 3, OIIO::TypeDesc::FLOAT);
  // ImageBuf wraps the pixels without copying; resize only reads them.
  OIIO::ImageBuf source(spec, const_cast<float*>(frame.data().data()));
  OIIO::ImageBuf resized;
  OIIO::ROI roi(0, width, 0, height, 0, 1, 0, 3);
  if (!OIIO::ImageBufAlgo::resize(resized, source, "", 0.0f, roi)) {
    throw std::runtime_error("contact sheet: resize failed: " + resized.geterror());
  }
  Image tile(width, height);
  resized.get_pixels(roi, OIIO::TypeDesc::FLOAT, tile.data().data());
  return tile;
}

}  // namespace

std::vector<int> contact_sheet_frames(int frame_count, int max_tiles) {
  std::vector<int> frames;
  int n = std::min(frame_count, max_tiles);
  for (int i = 0; i < n; ++i) {
    frames.push_back(n == 1 ? 0 : int((long long)i * (frame_count - 1) / (n - 1)));
  }
  return frames;
}

Image make_contact_sheet(const std::vector<SheetTile>& tiles, int columns, int tile_width,
                         const std::string& title) {
  if (tiles.empty() || columns < 1 || tile_width < 1) {
    throw std::invalid_argument("contact sheet: needs at least one tile, column and pixel");
  }
  const Image& first = *tiles.front().frame;
  int width = std::min(tile_width, first.width());
  int height = std::max(1, int((long long)first.height() * width / first.width()));
  int cols = std::min<int>(columns, int(tiles.size()));
  int rows = (int(tiles.size()) + cols - 1) / cols;
  int header = title.empty() ? 0 : kGlyphHeight + 2 * kGap;
  Image sheet(kGap + cols * (width + kGap), header + kGap + rows * (height + kGap), kBackground);
  if (!title.empty()) draw_text(sheet, kGap + 2, kGap + kGap / 2, title, 1, {1.0f, 1.0f, 1.0f});
  for (size_t i = 0; i < tiles.size(); ++i) {
    int x = kGap + int(i) % cols * (width + kGap);
    int y = header + kGap + int(i) / cols * (height + kGap);
    sheet.paste(shrink(*tiles[i].frame, width, height), x, y);
    if (!tiles[i].label.empty()) {
      sheet.fill_rect(x, y, x + text_width(tiles[i].label, 1) + 6, y + kGlyphHeight + 6,
                      {0.0f, 0.0f, 0.0f}, 0.6f);
      draw_text(sheet, x + 3, y + 3, tiles[i].label, 1, {1.0f, 1.0f, 1.0f});
    }
  }
  return sheet;
}

}  // namespace boreas::render
