// boreas scenes: key-by-key reading of JSON objects with typed, range-checked values.
#include "scene/json_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "scene/json_parse.h"
#include "scene/scene_error.h"

namespace boreas::render {

namespace {

std::string format_number(double v) {
  std::ostringstream out;
  out.precision(10);
  out << v;
  return out.str();
}

// "a string (\"3\")", "an array", ... for saying what was found instead.
std::string describe_value(const nlohmann::json& v) {
  switch (v.type()) {
    case nlohmann::json::value_t::null:
      return "null";
    case nlohmann::json::value_t::boolean:
      return std::string("a boolean (") + (v.get<bool>() ? "true" : "false") + ")";
    case nlohmann::json::value_t::string: {
      std::string text = v.dump();
      if (text.size() > 40) text = text.substr(0, 37) + "...";
      return "a string (" + text + ")";
    }
    case nlohmann::json::value_t::array:
      return "an array of " + std::to_string(v.size());
    case nlohmann::json::value_t::object:
      return "an object";
    default:
      return "a number (" + v.dump() + ")";
  }
}

// Levenshtein distance, to suggest the key a typo meant.
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// A near miss: close enough to closest that it is probably a typo of it.
bool near_miss(size_t distance, const std::string& closest) {
  return !closest.empty() && distance <= std::max<size_t>(2, closest.size() / 3);
}

}  // namespace

std::string did_you_mean(const std::string& got, const std::vector<std::string>& candidates) {
  std::string closest;
  size_t best = std::string::npos;
  for (const std::string& c : candidates) {
    size_t d = edit_distance(got, c);
    if (d < best) {
      best = d;
      closest = c;
    }
  }
  return near_miss(best, closest) ? "; did you mean \"" + closest + "\"?" : "";
}

const nlohmann::json JsonObjectReader::kEmptyObject = nlohmann::json::object();

bool NumberRule::allows(double v) const {
  bool above = lo_open ? v > lo : v >= lo;
  bool below = hi_open ? v < hi : v <= hi;
  return std::isfinite(v) && above && below;
}

std::string NumberRule::describe() const {
  bool has_lo = lo > -1e299;
  bool has_hi = hi < 1e299;
  if (has_lo && has_hi) {
    return std::string("in ") + (lo_open ? "(" : "[") + format_number(lo) + ", " +
           format_number(hi) + (hi_open ? ")" : "]");
  }
  if (has_lo) return std::string(lo_open ? "> " : ">= ") + format_number(lo);
  if (has_hi) return std::string(hi_open ? "< " : "<= ") + format_number(hi);
  return "a finite number";
}

std::string NumberRule::describe_violation(double v) const {
  bool below = lo_open ? !(v > lo) : !(v >= lo);
  bool above = hi_open ? !(v < hi) : !(v <= hi);
  if (below && !above && lo > -1e299)
    return std::string(lo_open ? "> " : ">= ") + format_number(lo);
  if (above && !below && hi < 1e299) return std::string(hi_open ? "< " : "<= ") + format_number(hi);
  return describe();
}

JsonObjectReader::JsonObjectReader(const nlohmann::json& value, std::string path,
                                   std::string source)
    : value_(value), path_(std::move(path)), source_(std::move(source)) {
  if (!value_.is_object()) {
    throw SceneError(source_, path_.empty() ? "/" : path_,
                     "expected an object, got " + describe_value(value_));
  }
}

std::string JsonObjectReader::path_of(const std::string& key) const {
  return key.empty() ? (path_.empty() ? "/" : path_) : path_ + "/" + json_pointer_segment(key);
}

void JsonObjectReader::fail(const std::string& key, const std::string& detail) const {
  throw SceneError(source_, path_of(key), detail);
}

const nlohmann::json* JsonObjectReader::find(const std::string& key) {
  known_.insert(key);
  auto it = value_.find(key);
  return it == value_.end() ? nullptr : &*it;
}

bool JsonObjectReader::has(const std::string& key) { return find(key) != nullptr; }

double JsonObjectReader::checked_number(const nlohmann::json& v, const std::string& path,
                                        NumberRule rule, bool want_integer) const {
  if (!v.is_number()) {
    throw SceneError(source_, path,
                     std::string("expected ") + (want_integer ? "an integer" : "a number") +
                         ", got " + describe_value(v));
  }
  double d = v.get<double>();
  if (!std::isfinite(d)) throw SceneError(source_, path, "must be finite (got " + v.dump() + ")");
  if (want_integer && std::floor(d) != d) {
    throw SceneError(source_, path, "must be an integer (got " + format_number(d) + ")");
  }
  if (!rule.allows(d)) {
    throw SceneError(source_, path,
                     "must be " + rule.describe_violation(d) + " (got " + format_number(d) + ")");
  }
  // Scene values end up in floats: a finite double beyond float range is not usable.
  if (std::fabs(d) > std::numeric_limits<float>::max()) {
    throw SceneError(source_, path, "is too large for a float (got " + format_number(d) + ")");
  }
  return d;
}

double JsonObjectReader::number(const std::string& key, double fallback, NumberRule rule) {
  const nlohmann::json* v = find(key);
  return v ? checked_number(*v, path_of(key), rule, false) : fallback;
}

int JsonObjectReader::integer(const std::string& key, int fallback, NumberRule rule) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  rule.lo = std::max(rule.lo, double(std::numeric_limits<int>::min()));
  rule.hi = std::min(rule.hi, double(std::numeric_limits<int>::max()));
  return static_cast<int>(checked_number(*v, path_of(key), rule, true));
}

uint64_t JsonObjectReader::unsigned_integer(const std::string& key, uint64_t fallback) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  if (v->is_number_unsigned()) return v->get<uint64_t>();
  if (!v->is_number()) fail(key, "expected an integer, got " + describe_value(*v));
  double d = v->get<double>();
  if (!std::isfinite(d)) fail(key, "must be finite (got " + v->dump() + ")");
  if (std::floor(d) != d) fail(key, "must be an integer (got " + format_number(d) + ")");
  if (d < 0.0) fail(key, "must be >= 0 (got " + format_number(d) + ")");
  constexpr double kExactLimit = 9007199254740992.0;  // 2^53
  if (d > kExactLimit) {
    fail(key, "must be written as a whole number without a fraction or exponent above 2^53 (got " +
                  format_number(d) + ")");
  }
  return static_cast<uint64_t>(d);
}

std::string JsonObjectReader::string(const std::string& key, const std::string& fallback) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  if (!v->is_string()) fail(key, "expected a string, got " + describe_value(*v));
  return v->get<std::string>();
}

std::optional<std::string> JsonObjectReader::optional_string(const std::string& key,
                                                             std::optional<std::string> fallback) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  if (v->is_null()) return std::nullopt;
  if (!v->is_string()) fail(key, "expected a string or null, got " + describe_value(*v));
  return v->get<std::string>();
}

double JsonObjectReader::number_or_null(const std::string& key, double fallback, NumberRule rule) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  if (v->is_null()) return 0.0;
  if (!v->is_number()) fail(key, "expected a number or null, got " + describe_value(*v));
  return checked_number(*v, path_of(key), rule, false);
}

bool JsonObjectReader::boolean(const std::string& key, bool fallback) {
  const nlohmann::json* v = find(key);
  if (!v) return fallback;
  if (!v->is_boolean()) fail(key, "expected a boolean (true or false), got " + describe_value(*v));
  return v->get<bool>();
}

void JsonObjectReader::numbers(const std::string& key, float* out, int count, NumberRule rule) {
  const nlohmann::json* v = find(key);
  if (!v) return;
  if (!v->is_array() || v->size() != size_t(count)) {
    fail(key,
         "expected an array of " + std::to_string(count) + " numbers, got " + describe_value(*v));
  }
  for (int i = 0; i < count; ++i) {
    out[i] = static_cast<float>(
        checked_number((*v)[size_t(i)], path_of(key) + "/" + std::to_string(i), rule, false));
  }
}

bool JsonObjectReader::numbers_or_null(const std::string& key, float* out, int count,
                                       NumberRule rule) {
  const nlohmann::json* v = find(key);
  if (!v || v->is_null()) return false;
  if (!v->is_array() || v->size() != size_t(count)) {
    fail(key, "expected an array of " + std::to_string(count) + " numbers or null, got " +
                  describe_value(*v));
  }
  numbers(key, out, count, rule);
  return true;
}

void JsonObjectReader::integers(const std::string& key, int* out, int count, NumberRule rule) {
  const nlohmann::json* v = find(key);
  if (!v) return;
  if (!v->is_array() || v->size() != size_t(count)) {
    fail(key,
         "expected an array of " + std::to_string(count) + " integers, got " + describe_value(*v));
  }
  rule.lo = std::max(rule.lo, double(std::numeric_limits<int>::min()));
  rule.hi = std::min(rule.hi, double(std::numeric_limits<int>::max()));
  for (int i = 0; i < count; ++i) {
    out[i] = static_cast<int>(
        checked_number((*v)[size_t(i)], path_of(key) + "/" + std::to_string(i), rule, true));
  }
}

std::vector<float> JsonObjectReader::number_list(const std::string& key, int min_count,
                                                 int max_count, NumberRule rule) {
  const nlohmann::json* v = find(key);
  if (!v) return {};
  if (!v->is_array() || v->size() < size_t(min_count) || v->size() > size_t(max_count)) {
    fail(key, "expected an array of " + std::to_string(min_count) + " to " +
                  std::to_string(max_count) + " numbers, got " + describe_value(*v));
  }
  std::vector<float> out(v->size());
  for (size_t i = 0; i < v->size(); ++i) {
    out[i] = static_cast<float>(
        checked_number((*v)[i], path_of(key) + "/" + std::to_string(i), rule, false));
  }
  return out;
}

JsonObjectReader JsonObjectReader::object(const std::string& key) {
  const nlohmann::json* v = find(key);
  return JsonObjectReader(v ? *v : kEmptyObject, path_of(key), source_);
}

int JsonObjectReader::objects(const std::string& key, int max_count,
                              const std::function<void(JsonObjectReader&)>& read) {
  const nlohmann::json* v = find(key);
  if (!v) return 0;
  if (!v->is_array()) fail(key, "expected an array of objects, got " + describe_value(*v));
  if (v->size() > size_t(max_count)) {
    fail(key, "at most " + std::to_string(max_count) + " entries are allowed (got " +
                  std::to_string(v->size()) + ")");
  }
  for (size_t i = 0; i < v->size(); ++i) {
    JsonObjectReader element((*v)[i], path_of(key) + "/" + std::to_string(i), source_);
    read(element);
    element.finish();
  }
  return static_cast<int>(v->size());
}

void JsonObjectReader::finish() const {
  for (const auto& item : value_.items()) {
    if (known_.count(item.key())) continue;
    std::string closest;
    size_t best = std::string::npos;
    for (const std::string& k : known_) {
      size_t d = edit_distance(item.key(), k);
      if (d < best) {
        best = d;
        closest = k;
      }
    }
    std::string hint;
    if (near_miss(best, closest)) {
      hint = "; did you mean \"" + closest + "\"?";
    } else {
      hint = "; known keys:";
      for (const std::string& k : known_) hint += " " + k;
    }
    fail(item.key(), "unknown key" + hint);
  }
}

}  // namespace boreas::render
