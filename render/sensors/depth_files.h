// boreas command: a depth camera's images as NumPy .npy files (format version 1.0), which
// numpy.load reads as they are: the depth as float32 (height, width), m along the optical
// axis, inf where nothing lies within the camera's max_depth; the labels as int32
// (height, width, 3): per pixel the hit's kind (boreas_hit_kind, 0 for nothing), the index
// of the object's id (boreas_object_id.index, 0 for nothing) and the part (-1 for nothing).
#pragma once

#include <string>
#include <vector>

#include "boreas/boreas.h"

namespace boreas::render {

// The .npy header (magic, version 1.0, length, the dict padded to a multiple of 64 bytes)
// of a C-ordered little-endian array of descr ("<f4", "<i4") and shape.
std::string npy_header(const std::string& descr, const std::vector<int>& shape);

// Throw std::runtime_error naming the path when the file cannot be written.
void write_depth_npy(const std::string& path, const std::vector<float>& depth, int width,
                     int height);
void write_labels_npy(const std::string& path, const std::vector<boreas_pixel_label>& labels,
                      int width, int height);

}  // namespace boreas::render
