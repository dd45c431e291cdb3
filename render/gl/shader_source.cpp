// boreas render: embedded GLSL sources and their includes (shader_source.h).
#include "gl/shader_source.h"

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

namespace boreas::embedded {
const std::vector<std::pair<const char*, const char*>>& shader_files();
}

namespace boreas::render {
namespace {

std::string raw_source(const std::string& name, const std::string& from) {
  if (const char* dir = std::getenv("BOREAS_SHADER_DIR")) {
    std::ifstream in(std::string(dir) + "/" + name, std::ios::binary);
    if (in) {
      std::ostringstream s;
      s << in.rdbuf();
      return s.str();
    }
  }
  for (const auto& [file, text] : embedded::shader_files())
    if (name == file) return text;
  throw ShaderError("no shader file '" + name + "'" + (from.empty() ? "" : " (included from " + from + ")"));
}

void expand(const std::string& name, const std::string& from, std::set<std::string>& seen, std::string& out) {
  if (!seen.insert(name).second) return;  // each file once
  std::istringstream in(raw_source(name, from));
  std::string line;
  while (std::getline(in, line)) {
    const std::string directive = "#include \"";
    if (line.rfind(directive, 0) == 0) {
      const size_t end = line.find('"', directive.size());
      if (end == std::string::npos) throw ShaderError(name + ": malformed #include line: " + line);
      expand(line.substr(directive.size(), end - directive.size()), name, seen, out);
      continue;
    }
    out += line;
    out += '\n';
  }
}

}  // namespace

std::string shader_source(const std::string& name) {
  std::set<std::string> seen;
  std::string out;
  expand(name, "", seen, out);
  return out;
}

}  // namespace boreas::render
