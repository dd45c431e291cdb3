// boreas scenes: strict JSON parsing (line numbers for syntax errors, no duplicate keys).
#include "scene/json_parse.h"

#include <set>
#include <vector>

#include "scene/scene_error.h"

namespace boreas::render {

namespace {

// One open object or array while parsing, for naming where a duplicate key sits.
struct OpenContainer {
  bool is_array = false;
  int index = -1;   // arrays: the element being read
  std::string key;  // objects: the member being read
  std::set<std::string> keys;
};

std::string pointer_to(const std::vector<OpenContainer>& open) {
  std::string path;
  // The innermost container is the one being read; each outer one names its child.
  for (size_t i = 0; i + 1 < open.size(); ++i) {
    path += "/" +
            (open[i].is_array ? std::to_string(open[i].index) : json_pointer_segment(open[i].key));
  }
  return path;
}

std::string text_position(const std::string& text, size_t byte) {
  // nlohmann counts byte from 1 at the character it stopped on.
  size_t end = std::min(byte > 0 ? byte - 1 : 0, text.size());
  int line = 1;
  size_t line_start = 0;
  for (size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(end - line_start + 1);
}

// nlohmann's message without its "[json.exception...] parse error at line L, column C: ".
std::string parse_reason(const std::string& what) {
  size_t at = what.find("parse error");
  size_t colon = at == std::string::npos ? std::string::npos : what.find(": ", at);
  return colon == std::string::npos ? what : what.substr(colon + 2);
}

}  // namespace

std::string json_pointer_segment(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

nlohmann::json parse_scene_json(const std::string& text, const std::string& source) {
  using Event = nlohmann::json::parse_event_t;
  std::vector<OpenContainer> open;
  auto track = [&](int /*depth*/, Event event, nlohmann::json& parsed) {
    bool starts_value =
        event == Event::value || event == Event::object_start || event == Event::array_start;
    if (starts_value && !open.empty() && open.back().is_array) ++open.back().index;
    switch (event) {
      case Event::object_start:
        open.push_back(OpenContainer{});
        break;
      case Event::array_start: {
        OpenContainer array;
        array.is_array = true;
        open.push_back(array);
        break;
      }
      case Event::object_end:
      case Event::array_end:
        open.pop_back();
        break;
      case Event::key: {
        std::string key = parsed.get<std::string>();
        if (!open.back().keys.insert(key).second) {
          throw SceneError(source, pointer_to(open) + "/" + json_pointer_segment(key),
                           "key given twice in the same object");
        }
        open.back().key = key;
        break;
      }
      case Event::value:
        break;
    }
    return true;
  };
  // nlohmann's lexer takes a NUL byte for the end of its input: a file cut there would read
  // as the whole file.
  if (const size_t nul = text.find('\0'); nul != std::string::npos)
    throw SceneError(source, text_position(text, nul + 1),
                     "parse error: a NUL byte (not a text file)");
  try {
    return nlohmann::json::parse(text, track);
  } catch (const nlohmann::json::parse_error& e) {
    throw SceneError(source, text_position(text, e.byte), "parse error: " + parse_reason(e.what()));
  } catch (const nlohmann::json::out_of_range& e) {
    // A number past a double's range ("number overflow parsing '1e400'") comes without a
    // position: the place is the first that holds that number.
    std::string what = e.what();
    const size_t close = what.find("] ");
    if (close != std::string::npos) what = what.substr(close + 2);
    const size_t open_quote = what.find('\''), end_quote = what.rfind('\'');
    size_t at = std::string::npos;
    if (open_quote != std::string::npos && end_quote > open_quote)
      at = text.find(what.substr(open_quote + 1, end_quote - open_quote - 1));
    throw SceneError(source, text_position(text, at == std::string::npos ? 0 : at + 1),
                     "parse error: " + what);
  }
}

}  // namespace boreas::render
