// boreas scenes: the error a scene file's problem raises. Its message names the file and
// where in it the problem is, e.g. "gusty.json: /wind/waves/2/wavelength: must be > 0 (got -1)".
#pragma once

#include <stdexcept>
#include <string>

namespace boreas::render {

class SceneError : public std::runtime_error {
 public:
  // where: a JSON pointer ("/wind/waves/2") or a text position ("line 7, column 3").
  SceneError(const std::string& source, const std::string& where, const std::string& detail)
      : std::runtime_error(source + ": " + (where.empty() ? "" : where + ": ") + detail),
        source_(source),
        where_(where),
        detail_(detail) {}

  const std::string& source() const noexcept { return source_; }
  const std::string& where() const noexcept { return where_; }
  const std::string& detail() const noexcept { return detail_; }

 private:
  std::string source_;
  std::string where_;
  std::string detail_;
};

}  // namespace boreas::render
