// boreas images: a contact sheet, a few frames of a run shrunk and tiled on one image so
// a run can be judged at a glance.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"

namespace boreas::render {

struct SheetTile {
  const Image* frame = nullptr;
  std::string label;  // drawn in the tile's top-left corner
};

// Tiles left to right, top to bottom, at most columns per row, each at most tile_width
// pixels wide (frames keep their aspect), under a one-line title (none when empty).
// Shrinking uses OpenImageIO's filtered resize.
Image make_contact_sheet(const std::vector<SheetTile>& tiles, int columns, int tile_width,
                         const std::string& title);

// Which of frame_count frames a sheet of at most max_tiles shows: evenly spaced, first and
// last included.
std::vector<int> contact_sheet_frames(int frame_count, int max_tiles);

}  // namespace boreas::render
