// boreas: OpenCL device enumeration and choice.
#include "runtime/device.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <sstream>

#include "errors.h"

namespace boreas::impl {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == '\0' || std::isspace(static_cast<unsigned char>(s.back()))))
    s.pop_back();
  size_t start = 0;
  while (start < s.size() && std::isspace(static_cast<unsigned char>(s[start]))) ++start;
  return s.substr(start);
}

std::string describe(const std::vector<Device>& devices) {
  std::ostringstream out;
  for (const Device& d : devices) {
    out << "\n  " << d.platform_index << ":" << d.device_index << "  " << d.name << " ("
        << d.platform_name << ", " << (d.is_gpu() ? "GPU" : "CPU") << ")";
  }
  return out.str();
}

int score(const Device& d) {
  int kind = d.is_gpu() ? 2 : ((d.type & CL_DEVICE_TYPE_ACCELERATOR) ? 1 : 0);
  return kind * 100000 + std::min(d.compute_units, 99999);
}

const char kNoDriverHelp[] =
    "install an OpenCL driver: on Debian, 'apt-get install pocl-opencl-icd' for CPUs, or "
    "your GPU vendor's ICD (e.g. nvidia-opencl-icd, mesa-opencl-icd, intel-opencl-icd)";

}  // namespace

bool Device::has_extension(const std::string& ext) const {
  std::istringstream words(extensions);
  std::string word;
  while (words >> word) {
    if (word == ext) return true;
  }
  return false;
}

bool Device::uses_fast_math() const {
  if (const char* env = std::getenv("BOREAS_FAST_MATH")) {
    if (std::string(env) == "0") return false;
    if (std::string(env) == "1") return true;
  }
  return !is_gpu();
}

int Device::simd_width() const {
  if (const char* env = std::getenv("BOREAS_SIMD_WIDTH")) {
    for (int w : {1, 2, 4, 8, 16})
      if (std::string(env) == std::to_string(w)) return w;
  }
  if (is_gpu() || !uses_fast_math()) return 1;
  int w = 1;
  while (w * 2 <= std::min(native_float_width, 16)) w *= 2;
  return w;
}

std::vector<Device> list_devices() {
  std::vector<cl::Platform> platforms;
  cl_int err = cl::Platform::get(&platforms);
  if (err == -1001 /* CL_PLATFORM_NOT_FOUND_KHR */ || platforms.empty()) {
    fail(BOREAS_ERROR_NO_DEVICE, std::string("no OpenCL platform found: ") + kNoDriverHelp);
  }
  BOREAS_CL_CHECK(err);

  std::vector<Device> devices;
  for (size_t p = 0; p < platforms.size(); ++p) {
    std::vector<cl::Device> platform_devices;
    err = platforms[p].getDevices(CL_DEVICE_TYPE_ALL, &platform_devices);
    if (err == CL_DEVICE_NOT_FOUND) continue;
    BOREAS_CL_CHECK(err);
    for (size_t d = 0; d < platform_devices.size(); ++d) {
      Device dev;
      dev.platform_index = static_cast<int>(p);
      dev.device_index = static_cast<int>(d);
      dev.platform = platforms[p];
      dev.device = platform_devices[d];
      dev.platform_name = trim(platforms[p].getInfo<CL_PLATFORM_NAME>());
      dev.platform_version = trim(platforms[p].getInfo<CL_PLATFORM_VERSION>());
      dev.name = trim(dev.device.getInfo<CL_DEVICE_NAME>());
      dev.version = trim(dev.device.getInfo<CL_DEVICE_VERSION>());
      dev.driver_version = trim(dev.device.getInfo<CL_DRIVER_VERSION>());
      dev.native_float_width =
          static_cast<int>(dev.device.getInfo<CL_DEVICE_NATIVE_VECTOR_WIDTH_FLOAT>());
      dev.extensions = dev.device.getInfo<CL_DEVICE_EXTENSIONS>();
      dev.type = dev.device.getInfo<CL_DEVICE_TYPE>();
      dev.compute_units = static_cast<int>(dev.device.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>());
      dev.global_memory = dev.device.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
      devices.push_back(std::move(dev));
    }
  }
  if (devices.empty()) {
    fail(BOREAS_ERROR_NO_DEVICE,
         "OpenCL platforms exist but offer no device: " + std::string(kNoDriverHelp));
  }
  return devices;
}

int choose_device(const std::vector<Device>& devices, const std::string& requested) {
  std::string request = trim(requested);
  std::string source = "the device request";
  if (request.empty()) {
    if (const char* env = std::getenv("BOREAS_DEVICE")) {
      request = trim(env);
      source = "BOREAS_DEVICE";
    }
  }
  if (request.empty()) {
    int best = 0;
    for (size_t i = 1; i < devices.size(); ++i) {
      if (score(devices[i]) > score(devices[static_cast<size_t>(best)])) best = static_cast<int>(i);
    }
    return best;
  }

  std::string want = lower(request);
  auto pick_type = [&](bool gpu) -> int {
    int best = -1;
    for (size_t i = 0; i < devices.size(); ++i) {
      bool cpu = (devices[i].type & CL_DEVICE_TYPE_CPU) != 0;
      if (gpu ? !devices[i].is_gpu() : !cpu) continue;
      if (best < 0 || score(devices[i]) > score(devices[static_cast<size_t>(best)]))
        best = static_cast<int>(i);
    }
    return best;
  };
  int found = -1;
  if (want == "gpu" || want == "cpu") {
    found = pick_type(want == "gpu");
  } else if (size_t colon = want.find(':');
             colon != std::string::npos && colon > 0 &&
             want.find_first_not_of("0123456789:") == std::string::npos) {
    int p = std::atoi(want.substr(0, colon).c_str());
    int d = std::atoi(want.substr(colon + 1).c_str());
    for (size_t i = 0; i < devices.size(); ++i) {
      if (devices[i].platform_index == p && devices[i].device_index == d)
        found = static_cast<int>(i);
    }
  } else {
    for (size_t i = 0; i < devices.size() && found < 0; ++i) {
      if (lower(devices[i].name).find(want) != std::string::npos ||
          lower(devices[i].platform_name).find(want) != std::string::npos)
        found = static_cast<int>(i);
    }
  }
  if (found < 0) {
    fail(BOREAS_ERROR_NO_DEVICE, source + " '" + request +
                                     "' matches no OpenCL device (use gpu, cpu, P:D or part "
                                     "of a name); available:" +
                                     describe(devices));
  }
  return found;
}

}  // namespace boreas::impl
