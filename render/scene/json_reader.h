// boreas scenes: reads one JSON object of a scene key by key, checking types and ranges and
// naming the file and the JSON pointer of any bad value. Keys that were never read are
// rejected by finish(), so a typo cannot be silently ignored.
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace boreas::render {

// The allowed range of a number, for checking it and for saying so.
struct NumberRule {
  double lo = -1e300;
  double hi = 1e300;
  bool lo_open = false;  // lo itself excluded
  bool hi_open = false;

  static NumberRule any() { return {}; }
  static NumberRule positive() { return {0.0, 1e300, true, false}; }
  static NumberRule non_negative() { return {0.0, 1e300, false, false}; }
  static NumberRule in(double lo, double hi) { return {lo, hi, false, false}; }
  static NumberRule above_at_most(double lo, double hi) { return {lo, hi, true, false}; }
  static NumberRule within(double magnitude) { return {-magnitude, magnitude, false, false}; }

  bool allows(double v) const;
  std::string describe() const;  // "> 0", "in [0, 1000]", ...
  // The side v breaks: "> 0" for -1 under (0, 1e7], "<= 1000" for 2000 under [0, 1000].
  std::string describe_violation(double v) const;
};

// "; did you mean \"name\"?" for the candidate closest to got when it is a near miss
// (the rule unknown keys use), else "".
std::string did_you_mean(const std::string& got, const std::vector<std::string>& candidates);

class JsonObjectReader {
 public:
  // value must be an object (checked here); path is its JSON pointer ("" for the root).
  JsonObjectReader(const nlohmann::json& value, std::string path, std::string source);

  bool has(const std::string& key);

  // Each returns fallback when the key is absent; a present value must fit its type and rule.
  double number(const std::string& key, double fallback, NumberRule rule = NumberRule::any());
  int integer(const std::string& key, int fallback, NumberRule rule = NumberRule::any());
  // A whole number in [0, 2^64 - 1] (seeds); written as a fraction or an exponent it must
  // be at most 2^53, where doubles stop holding every integer.
  uint64_t unsigned_integer(const std::string& key, uint64_t fallback);
  std::string string(const std::string& key, const std::string& fallback);
  // A string, or null for "not set"; absent gives fallback.
  std::optional<std::string> optional_string(const std::string& key,
                                             std::optional<std::string> fallback);
  // A number, or null for "not set" (returned as 0); absent gives fallback.
  double number_or_null(const std::string& key, double fallback, NumberRule rule);
  // true or false; absent gives fallback.
  bool boolean(const std::string& key, bool fallback);
  // A fixed-size array of numbers; out keeps its values when the key is absent.
  void numbers(const std::string& key, float* out, int count, NumberRule rule = NumberRule::any());
  // A fixed-size array of numbers, or null for "not set"; returns whether out was filled
  // (false, out untouched, for null or absent).
  bool numbers_or_null(const std::string& key, float* out, int count, NumberRule rule);
  void integers(const std::string& key, int* out, int count, NumberRule rule = NumberRule::any());
  // An array of min_count..max_count numbers (a LiDAR's channel angles); empty when absent.
  std::vector<float> number_list(const std::string& key, int min_count, int max_count,
                                 NumberRule rule = NumberRule::any());

  // The object under key (an empty one when absent).
  JsonObjectReader object(const std::string& key);
  // Calls read for each element of the array of objects under key, then that element's
  // finish(); returns the count.
  int objects(const std::string& key, int max_count,
              const std::function<void(JsonObjectReader&)>& read);

  // Throws for the first key no reader call asked about, suggesting the closest known key.
  void finish() const;

  // Throws a SceneError at this object's key (or at the object itself when key is empty).
  [[noreturn]] void fail(const std::string& key, const std::string& detail) const;
  std::string path_of(const std::string& key) const;
  const std::string& source() const { return source_; }

 private:
  const nlohmann::json* find(const std::string& key);
  double checked_number(const nlohmann::json& v, const std::string& path, NumberRule rule,
                        bool want_integer) const;

  const nlohmann::json& value_;
  std::string path_;
  std::string source_;
  std::set<std::string> known_;
  static const nlohmann::json kEmptyObject;
};

}  // namespace boreas::render
