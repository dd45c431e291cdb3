// boreas command: depth and label images as .npy (the format is in the header).
#include "sensors/depth_files.h"

#include <cstdint>
#include <fstream>
#include <stdexcept>

namespace boreas::render {

namespace {

void write_npy(const std::string& path, const std::string& header, const void* data, size_t bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(header.data(), std::streamsize(header.size()));
  out.write(static_cast<const char*>(data), std::streamsize(bytes));
  out.close();
  if (!out) throw std::runtime_error(path + ": cannot write the image");
}

}  // namespace

std::string npy_header(const std::string& descr, const std::vector<int>& shape) {
  std::string dict = "{'descr': '" + descr + "', 'fortran_order': False, 'shape': (";
  for (size_t i = 0; i < shape.size(); ++i) dict += (i ? ", " : "") + std::to_string(shape[i]);
  dict += shape.size() == 1 ? ",), }" : "), }";
  // Magic (6) + version (2) + length (2) + dict + newline, padded with spaces to 64.
  size_t total = 10 + dict.size() + 1;
  dict += std::string((64 - total % 64) % 64, ' ') + "\n";
  const uint16_t length = uint16_t(dict.size());
  std::string header("\x93NUMPY\x01\x00", 8);
  header += char(length & 0xff);
  header += char(length >> 8);
  return header + dict;
}

void write_depth_npy(const std::string& path, const std::vector<float>& depth, int width,
                     int height) {
  write_npy(path, npy_header("<f4", {height, width}), depth.data(), depth.size() * sizeof(float));
}

void write_labels_npy(const std::string& path, const std::vector<boreas_pixel_label>& labels,
                      int width, int height) {
  std::vector<int32_t> values;
  values.reserve(labels.size() * 3);
  for (const boreas_pixel_label& l : labels) {
    values.push_back(l.kind);
    values.push_back(int32_t(l.object.index));
    values.push_back(l.part);
  }
  write_npy(path, npy_header("<i4", {height, width, 3}), values.data(),
            values.size() * sizeof(int32_t));
}

}  // namespace boreas::render
