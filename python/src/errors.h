// boreas for Python: errors. A failing boreas_status becomes the matching subclass of
// boreas.Error (with .status, .status_name and boreas_last_error()'s message); the C++
// exceptions here carry a failure out of code that runs without the GIL.
#pragma once

#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>

#include "boreas/boreas.h"

namespace boreas_py {

// A C call that failed: translated into the boreas.Error subclass for its status.
class StatusError : public std::runtime_error {
 public:
  StatusError(boreas_status status, const std::string& message)
      : std::runtime_error(message), status_(status) {}
  boreas_status status() const { return status_; }

 private:
  boreas_status status_;
};

// A failure of the Python layer itself (a closed world, a callback calling back into its
// world): translated into boreas.Error with status None.
class BindingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws StatusError with boreas_last_error()'s message unless status is BOREAS_OK. Call it
// on the thread that made the call, before any other boreas call (the message is per thread).
inline void check(boreas_status status) {
  if (status != BOREAS_OK) throw StatusError(status, boreas_last_error());
}

// Creates boreas.Error and its subclasses in m and translates the exceptions above.
void register_errors(pybind11::module_& m);

}  // namespace boreas_py
