// boreas: boreas's own species format (host/species/*.json), read with nlohmann::json and
// checked against the parameter table (species.cpp):
//   {"format": "boreas-species-1", "name": "quaking_aspen", "source": "free text",
//    "params": {"Shape": 7, "1DownAngle": 60, "LeafShape": 0, ...}}
//
// Line numbers. A syntax error carries the byte position where nlohmann stopped; the line
// is one plus the newlines before it. nlohmann's tree keeps no positions, and it silently
// keeps the last of two equal keys, so once the text is known to be valid JSON a small
// scanner (find_keys) walks it again and records every object key with its line and the
// key of the object it sits in. Parameter errors use the line of the parameter's key, and
// the scanner's list (not the tree) drives the loop, so a repeated key is seen and refused.
#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "errors.h"
#include "json_text.h"
#include "trees/species.h"

namespace boreas::impl {

namespace {

using nlohmann::json;

constexpr const char* kFormat = "boreas-species-1";

struct KeyAt {
  std::string key;
  int depth = 0;       // 1: a key of the top-level object, 2: of an object inside it
  std::string parent;  // the key whose value holds this key's object ("" at the top)
  int line = 0;
};

// Every object key in `text`, in order. `text` must be valid JSON (nlohmann has parsed it),
// so the scanner only needs to tell strings apart from structure.
std::vector<KeyAt> find_keys(const std::string& text) {
  struct Frame {
    bool object;
    std::string key;  // the key this container is the value of
  };
  std::vector<Frame> stack;
  std::vector<KeyAt> keys;
  std::string last_key;
  int line = 1;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (c == '\n') {
      ++line;
    } else if (c == '"') {
      size_t end = i + 1;
      while (end < text.size() && text[end] != '"') end += text[end] == '\\' ? 2 : 1;
      size_t next = text.find_first_not_of(" \t\r\n", end + 1);
      if (!stack.empty() && stack.back().object && next != std::string::npos && text[next] == ':') {
        // Decode escapes the way nlohmann did: the raw key as a JSON string.
        last_key = json::parse(text.substr(i, end - i + 1)).get<std::string>();
        keys.push_back({last_key, static_cast<int>(stack.size()), stack.back().key, line});
      }
      i = end;
    } else if (c == '{' || c == '[') {
      bool in_object = !stack.empty() && stack.back().object;
      stack.push_back({c == '{', in_object ? last_key : std::string()});
    } else if (c == '}' || c == ']') {
      if (!stack.empty()) stack.pop_back();
    }
  }
  return keys;
}

std::string json_type(const json& v) {
  return v.is_string()    ? "a string"
         : v.is_boolean() ? "a boolean"
         : v.is_null()    ? "null"
         : v.is_array()   ? "an array"
         : v.is_object()  ? "an object"
                          : "a number";
}

}  // namespace

Species parse_species_json(const std::string& text, const std::string& file_name) {
  SpeciesBuilder b(file_name);

  // A NUL byte is refused before the key scan below could read on past it.
  json doc;
  if (const auto bad = parse_json_text(text, &doc))
    b.fail_at(json_line_at(text, bad->offset), "malformed JSON: " + bad->reason);
  if (!doc.is_object())
    b.fail_at(1, "expected a JSON object {\"format\": \"" + std::string(kFormat) + "\", ...}");

  std::vector<KeyAt> keys = find_keys(text);
  auto top_line = [&](const std::string& key) {
    for (const KeyAt& k : keys) {
      if (k.depth == 1 && k.key == key) return k.line;
    }
    return 1;
  };

  std::vector<std::string> seen;
  for (const KeyAt& k : keys) {
    if (k.depth != 1) continue;
    if (std::find(seen.begin(), seen.end(), k.key) != seen.end()) {
      b.fail_at(k.line, "key '" + k.key + "' given twice");
    }
    seen.push_back(k.key);
    if (k.key != "format" && k.key != "name" && k.key != "source" && k.key != "params") {
      b.fail_at(k.line, "unknown key '" + k.key + "' (expected format, name, source, params)");
    }
  }

  if (!doc.contains("format")) {
    b.fail_at(1, std::string("missing \"format\": \"") + kFormat + "\"");
  }
  if (doc["format"] != kFormat) {
    b.fail_at(top_line("format"),
              "format is " + doc["format"].dump() + ", expected \"" + kFormat + "\"");
  }
  if (!doc.contains("name") || !doc["name"].is_string() || doc["name"].get<std::string>().empty()) {
    b.fail_at(top_line("name"), "\"name\" must be a non-empty string");
  }
  b.set_name(doc["name"].get<std::string>());
  if (doc.contains("source") && !doc["source"].is_string()) {
    b.fail_at(top_line("source"), "\"source\" must be a string");
  }
  if (!doc.contains("params") || !doc["params"].is_object()) {
    b.fail_at(top_line("params"), "\"params\" must be an object of Arbaro parameters");
  }

  const json& params = doc["params"];
  for (const KeyAt& k : keys) {
    if (k.depth != 2 || k.parent != "params") continue;
    const SpeciesParam& p = b.find(k.key, k.line);
    const json& v = params[k.key];
    bool leaf_shape = p.is_leaf_shape();
    if (v.is_number()) {
      b.set_number(p, v.get<double>(), k.line);
    } else if (leaf_shape && v.is_string()) {
      b.set_text(p, v.get<std::string>(), k.line);
    } else {
      b.fail_param(k.line, k.key,
                   "value " + v.dump() + " is " + json_type(v) + ", expected a number" +
                       (leaf_shape ? " or a leaf shape name" : ""));
    }
  }
  return b.finish();
}

}  // namespace boreas::impl
