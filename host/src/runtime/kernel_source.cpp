// boreas: include resolution over the embedded kernel table.
#include "runtime/kernel_source.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
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

using FileTable = std::vector<std::pair<const char*, const char*>>;

// Tables added by add_kernel_files, after the library's own.
std::mutex& extra_tables_mutex() {
  static std::mutex m;
  return m;
}
std::vector<const FileTable*>& extra_tables() {
  static std::vector<const FileTable*> tables;
  return tables;
}

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
  {
    std::lock_guard<std::mutex> lock(extra_tables_mutex());
    for (const FileTable* table : extra_tables()) {
      for (const auto& [file, text] : *table) {
        if (name == file) return text;
      }
    }
  }
  fail(BOREAS_ERROR_INTERNAL, "no embedded kernel file named " + name);
}

// The identifier after the blanks from line[at] on ("" if none); *end: the index past it.
std::string identifier_at(const std::string& line, size_t at, size_t* end) {
  at = std::min(line.find_first_not_of(" \t", at), line.size());
  *end = at;
  while (*end < line.size() &&
         (std::isalnum(static_cast<unsigned char>(line[*end])) || line[*end] == '_'))
    ++*end;
  return line.substr(at, *end - at);
}

// `#include NAME` follows NAME to the file of the last `#define NAME "file"` (the SIMD
// width's instantiation helper, cl/shared/width_instantiate.inc), as the preprocessor does.
void append_resolved(const std::string& name, std::set<std::string>& seen,
                     std::map<std::string, std::string>& file_names, std::string& out) {
  // Every header once, like #pragma once; a .inc file (a body instantiated once per SIMD
  // width, cl/shared/simd_width.h) at each #include, as the preprocessor would.
  const bool repeatable = name.size() > 4 && name.compare(name.size() - 4, 4, ".inc") == 0;
  if (!seen.insert(name).second && !repeatable) return;
  std::istringstream lines(read_file(name));
  std::string line;
  int number = 0;
  out += "#line 1 \"" + name + "\"\n";
  while (std::getline(lines, line)) {
    ++number;
    size_t hash = line.find_first_not_of(" \t");
    if (hash != std::string::npos && line.compare(hash, 7, "#define") == 0) {
      size_t end = 0;
      const std::string macro = identifier_at(line, hash + 7, &end);
      size_t open = line.find_first_not_of(" \t", end);
      size_t close = open == std::string::npos ? open : line.find('"', open + 1);
      if (!macro.empty() && close != std::string::npos && line[open] == '"')
        file_names[macro] = line.substr(open + 1, close - open - 1);
    }
    if (hash != std::string::npos && line.compare(hash, 8, "#include") == 0) {
      size_t open = line.find('"');
      size_t close = open == std::string::npos ? open : line.find('"', open + 1);
      std::string file;
      if (close != std::string::npos) {
        file = line.substr(open + 1, close - open - 1);
      } else {
        size_t end = 0;
        auto named = file_names.find(identifier_at(line, hash + 8, &end));
        if (named != file_names.end()) file = named->second;
      }
      if (!file.empty()) {
        append_resolved(file, seen, file_names, out);
        out += "#line " + std::to_string(number + 1) + " \"" + name + "\"\n";
        continue;
      }
    }
    out += line;
    out += '\n';
  }
}

}  // namespace

void add_kernel_files(const FileTable& files) {
  std::lock_guard<std::mutex> lock(extra_tables_mutex());
  std::vector<const FileTable*>& tables = extra_tables();
  if (std::find(tables.begin(), tables.end(), &files) == tables.end()) tables.push_back(&files);
}

std::string kernel_source(const std::string& file) {
  std::set<std::string> seen;
  std::map<std::string, std::string> file_names;
  std::string out;
  append_resolved(file, seen, file_names, out);
  return out;
}

}  // namespace boreas::impl
