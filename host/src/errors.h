// boreas: the error type every internal failure throws. The C API turns it into a
// boreas_status and the thread's last-error message; nothing else crosses the C ABI.
#pragma once

#include <stdexcept>
#include <string>

#include "boreas/boreas.h"

namespace boreas::impl {

class Error : public std::runtime_error {
 public:
  Error(boreas_status status, const std::string& message)
      : std::runtime_error(message), status_(status) {}
  boreas_status status() const { return status_; }

 private:
  boreas_status status_;
};

[[noreturn]] inline void fail(boreas_status status, const std::string& message) {
  throw Error(status, message);
}

[[noreturn]] inline void fail_argument(const std::string& message) {
  throw Error(BOREAS_ERROR_INVALID_ARGUMENT, message);
}

}  // namespace boreas::impl
