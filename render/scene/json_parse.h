// boreas scenes: strict JSON parsing for scene files. Syntax errors carry the line and
// column; a key given twice in one object is an error rather than silently "last wins".
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace boreas::render {

// Parses text; throws SceneError naming source (the file) on any problem.
nlohmann::json parse_scene_json(const std::string& text, const std::string& source);

// A JSON pointer segment for key: '~' and '/' escaped as RFC 6901 says.
std::string json_pointer_segment(const std::string& key);

}  // namespace boreas::render
