// boreas: JSON text read with nlohmann for the library's file parsers (tree species,
// underbrush species), with the two inputs nlohmann gets wrong handled once: a NUL byte,
// which its lexer takes for the end of the input (a file cut there would read as the
// whole file), and a number past a double's range, which it throws as out_of_range with
// no position. Each parser words the error its own way.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace boreas::impl {

// Why and where a text is not JSON nlohmann can read.
struct JsonTextError {
  enum class Kind { kNulByte, kSyntax, kNumberOverflow };
  Kind kind = Kind::kSyntax;
  // The byte (from 0) of the NUL, of the character nlohmann stopped at, or of the first
  // place the overflowing number is written (0 when it is not found).
  size_t offset = 0;
  // What is wrong, without nlohmann's "[json.exception.*] " and "parse error at line L,
  // column C: " (its lines count a newline just read as the next line):
  // "a NUL byte (not a text file)", "syntax error while parsing value - ...",
  // "number overflow parsing '1e400'".
  std::string reason;
  std::string what;  // nlohmann's whole message ("" for a NUL byte)
};

// The line (from 1) that text's byte at offset is on; past the end, the last line.
int json_line_at(const std::string& text, size_t offset);

// Parses text into *out, or says why it is not JSON (and leaves *out as it was).
std::optional<JsonTextError> parse_json_text(const std::string& text, nlohmann::json* out);

}  // namespace boreas::impl
