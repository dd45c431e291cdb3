// boreas: include resolution over the embedded kernel table.
#include "runtime/kernel_source.h"

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "errors.h"

namespace boreas::embedded {
const std::vector<std::pair<const char*, const char*>>& kernel_files();
}

namespace boreas::impl {

namespace {

std::string read_file(const std::string& name) {
  if (const char* dir = std::getenv("BOREAS_KERNEL_DIR"); dir && *dir) {
    std::string path = std::string(dir) + "/" + name;
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(BOREAS_ERROR_IO, "cannot read kernel file " + path + " (BOREAS_KERNEL_DIR)");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  for (const auto& [file, text] : embedded::kernel_files()) {
    if (name == file) return text;
  }
  fail(BOREAS_ERROR_INTERNAL, "no embedded kernel file named " + name);
}

void append_resolved(const std::string& name, std::set<std::string>& seen, std::string& out) {
  if (!seen.insert(name).second) return;  // every header once, like #pragma once
  std::istringstream lines(read_file(name));
  std::string line;
  int number = 0;
  out += "#line 1 \"" + name + "\"\n";
  while (std::getline(lines, line)) {
    ++number;
    size_t hash = line.find_first_not_of(" \t");
    if (hash != std::string::npos && line.compare(hash, 8, "#include") == 0) {
      size_t open = line.find('"');
      size_t close = open == std::string::npos ? open : line.find('"', open + 1);
      if (close != std::string::npos) {
        append_resolved(line.substr(open + 1, close - open - 1), seen, out);
        out += "#line " + std::to_string(number + 1) + " \"" + name + "\"\n";
        continue;
      }
    }
    out += line;
    out += '\n';
  }
}

}  // namespace

std::string kernel_source(const std::string& file) {
  std::set<std::string> seen;
  std::string out;
  append_resolved(file, seen, out);
  return out;
}

}  // namespace boreas::impl
