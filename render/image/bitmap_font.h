// boreas images: a built-in 5x7 pixel font for frame titles and legend labels, so frames
// look the same on every machine without a font file. Upper case, digits and the
// punctuation labels need; lower case prints as upper case, anything else as '?'.
#pragma once

#include <string>

#include "image/image.h"

namespace boreas::render {

constexpr int kGlyphWidth = 5;    // pixels at scale 1
constexpr int kGlyphHeight = 7;   // pixels at scale 1
constexpr int kGlyphAdvance = 6;  // one blank column between letters

// Width in pixels of text drawn at scale (an integer magnification).
int text_width(const std::string& text, int scale);

// Draws text with its top-left corner at (x, y).
void draw_text(Image& image, int x, int y, const std::string& text, int scale, Rgb color);

}  // namespace boreas::render
