// boreas: JSON text for the library's file parsers (json_text.h).
#include "json_text.h"

#include <algorithm>

namespace boreas::impl {

namespace {

// nlohmann's message after its "[json.exception.parse_error.101] parse error at line L,
// column C: " (the first ": ").
std::string syntax_reason(const std::string& what) {
  const size_t colon = what.find(": ");
  return colon == std::string::npos ? what : what.substr(colon + 2);
}

// "number overflow parsing '1e400'" from "[json.exception.out_of_range.406] number ...",
// and where the number is first written.
JsonTextError overflow(const std::string& text, const std::string& what) {
  JsonTextError e{JsonTextError::Kind::kNumberOverflow, 0, what, what};
  const size_t close = what.find("] ");
  if (close != std::string::npos) e.reason = what.substr(close + 2);
  const size_t open = e.reason.find('\''), end = e.reason.rfind('\'');
  if (open != std::string::npos && end > open) {
    const size_t found = text.find(e.reason.substr(open + 1, end - open - 1));
    if (found != std::string::npos) e.offset = found;
  }
  return e;
}

}  // namespace

int json_line_at(const std::string& text, size_t offset) {
  const size_t end = std::min(offset, text.size());
  return 1 +
         static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(end), '\n'));
}

std::optional<JsonTextError> parse_json_text(const std::string& text, nlohmann::json* out) {
  if (const size_t nul = text.find('\0'); nul != std::string::npos)
    return JsonTextError{JsonTextError::Kind::kNulByte, nul, "a NUL byte (not a text file)", ""};
  try {
    *out = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte counts from 1 and points at the last character read.
    return JsonTextError{JsonTextError::Kind::kSyntax, e.byte > 0 ? e.byte - 1 : 0,
                         syntax_reason(e.what()), e.what()};
  } catch (const nlohmann::json::out_of_range& e) {
    return overflow(text, e.what());
  }
  return std::nullopt;
}

}  // namespace boreas::impl
