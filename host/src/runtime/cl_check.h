// boreas: the one checking helper every OpenCL call goes through. A failure throws with
// the call's text, the error's name, and the file and line it came from.
#pragma once

#define CL_HPP_TARGET_OPENCL_VERSION 120
#define CL_HPP_MINIMUM_OPENCL_VERSION 120
#include <CL/opencl.hpp>

namespace boreas::impl {

const char* cl_error_name(cl_int code);
void cl_check_failed(cl_int code, const char* call, const char* file, int line);

inline void cl_check(cl_int code, const char* call, const char* file, int line) {
  if (code != CL_SUCCESS) cl_check_failed(code, call, file, line);
}

}  // namespace boreas::impl

#define BOREAS_CL_CHECK(call) ::boreas::impl::cl_check((call), #call, __FILE__, __LINE__)
