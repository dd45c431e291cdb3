// boreas command: its exit codes and the error that carries one up to main(), which
// prints "boreas: error: <message>" on stderr.
#pragma once

#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>

namespace boreas::render {

constexpr int kExitOk = 0;
constexpr int kExitBadInput = 1;  // bad options or scene file
constexpr int kExitNoDevice = 2;  // no OpenCL platform, or no device matches the request
constexpr int kExitFailure = 3;   // OpenCL or file output failed while running

class CliError : public std::runtime_error {
 public:
  CliError(int exit_code, const std::string& message)
      : std::runtime_error(message), exit_code_(exit_code) {}
  int exit_code() const noexcept { return exit_code_; }

 private:
  int exit_code_;
};

// Prints "boreas: error: <message>" on stderr; returns exit_code for `return report_error(...)`.
inline int report_error(const std::string& message, int exit_code = kExitBadInput) {
  std::fprintf(stderr, "boreas: error: %s\n", message.c_str());
  return exit_code;
}

// A number as the command's messages quote it (shortest stream form: 0.5, 1000, 1e+07).
inline std::string cli_number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

}  // namespace boreas::render
