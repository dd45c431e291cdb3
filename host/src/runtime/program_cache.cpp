// boreas: program building with an in-memory and an on-disk binary cache.
//
// A cache file is: magic "BOREASCL", the 64-bit key, the payload size, a 64-bit FNV-1a
// hash of the payload, then the device binary. Anything that does not match (a truncated
// or corrupt file, another key, a binary the driver refuses) is ignored and rebuilt from
// source, and the file is rewritten.
#include "runtime/program_cache.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <system_error>
#include <vector>

#include "errors.h"
#include "fnv1a.h"
#include "runtime/kernel_source.h"

namespace boreas::impl {

namespace {

constexpr char kMagic[8] = {'B', 'O', 'R', 'E', 'A', 'S', 'C', 'L'};

std::string hex(unsigned long long v) {
  char buffer[17];
  std::snprintf(buffer, sizeof buffer, "%016llx", v);
  return buffer;
}

}  // namespace

std::string default_cache_dir() {
  if (const char* env = std::getenv("BOREAS_CACHE_DIR")) return env;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return std::string(xdg) + "/boreas";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::string(home) + "/.cache/boreas";
  return "";
}

ProgramCache::ProgramCache(cl::Context context, const Device& device, std::string cache_dir)
    : context_(std::move(context)), device_(device), cache_dir_(std::move(cache_dir)) {
  simd_width_ = device_.simd_width();
  std::ostringstream prelude;
  prelude << "/* boreas device prelude for " << device_.name << " */\n"
          << "#define BOREAS_FAST_MATH " << (device_.uses_fast_math() ? 1 : 0) << "\n"
          << "#define BOREAS_DEVICE_GPU " << (device_.is_gpu() ? 1 : 0) << "\n"
          << "#define BOREAS_DEVICE_W " << simd_width_ << "\n";
  prelude_ = prelude.str();
  options_ = "-cl-std=CL1.2";
}

cl::Program ProgramCache::get(const std::string& file, const std::string& extra_defines) {
  std::string memory_key = file + '\n' + extra_defines;
  if (auto it = programs_.find(memory_key); it != programs_.end()) return it->second;
  cl::Program program = build(file, prelude_ + extra_defines + kernel_source(file));
  programs_.emplace(memory_key, program);
  return program;
}

void ProgramCache::release(const std::string& file, const std::string& extra_defines) {
  programs_.erase(file + '\n' + extra_defines);
}

cl::Program ProgramCache::build_source(const std::string& label, const std::string& source) {
  return build(label, prelude_ + source);
}

cl::Program ProgramCache::build(const std::string& label, const std::string& source) {
  Fnv1a64 hash;
  hash.add(source.data(), source.size());
  for (const std::string& part : {device_.platform_name, device_.platform_version, device_.name,
                                  device_.version, device_.driver_version, options_}) {
    hash.add(part.data(), part.size()).add("\n", 1);
  }
  const unsigned long long key = hash.value();
  std::string path;
  if (!cache_dir_.empty()) {
    path = cache_dir_ + "/" + hex(key) + ".bin";
    if (cl::Program cached = load_binary(path, key); cached() != nullptr) {
      ++disk_hits_;
      return cached;
    }
  }

  cl_int err = CL_SUCCESS;
  cl::Program program(context_, source, false, &err);
  BOREAS_CL_CHECK(err);
  ++compiles_;
  err = program.build({device_.device}, options_.c_str());
  if (err != CL_SUCCESS) {
    std::string log;
    program.getBuildInfo(device_.device, CL_PROGRAM_BUILD_LOG, &log);
    if (err == CL_BUILD_PROGRAM_FAILURE || err == CL_INVALID_BUILD_OPTIONS) {
      fail(BOREAS_ERROR_KERNEL_BUILD, "building OpenCL program " + label + " for " + device_.name +
                                          " failed (" + cl_error_name(err) + "); compiler log:\n" +
                                          log);
    }
    BOREAS_CL_CHECK(err);
  }
  if (!path.empty()) store_binary(path, key, program);
  return program;
}

cl::Program ProgramCache::load_binary(const std::string& path, unsigned long long key) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return cl::Program();
  char magic[8];
  unsigned long long header[3];  // key, size, payload hash
  if (!in.read(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof magic) != 0 ||
      !in.read(reinterpret_cast<char*>(header), sizeof header) || header[0] != key ||
      header[1] == 0 || header[1] > (1ull << 30)) {
    return cl::Program();
  }
  std::vector<unsigned char> binary(header[1]);
  if (!in.read(reinterpret_cast<char*>(binary.data()),
               static_cast<std::streamsize>(binary.size())) ||
      fnv1a64(binary.data(), binary.size()) != header[2]) {
    return cl::Program();
  }
  cl_int err = CL_SUCCESS;
  cl_int binary_status = CL_SUCCESS;
  const unsigned char* data = binary.data();
  size_t size = binary.size();
  cl_device_id id = device_.device();
  cl_program raw =
      clCreateProgramWithBinary(context_(), 1, &id, &size, &data, &binary_status, &err);
  if (err != CL_SUCCESS || binary_status != CL_SUCCESS || raw == nullptr) {
    if (raw) clReleaseProgram(raw);
    return cl::Program();
  }
  cl::Program program(raw);  // takes ownership
  if (program.build({device_.device}, options_.c_str()) != CL_SUCCESS) return cl::Program();
  return program;
}

void ProgramCache::store_binary(const std::string& path, unsigned long long key,
                                const cl::Program& program) {
  // The disk cache is an optimisation: any failure here leaves the run unaffected.
  std::vector<std::vector<unsigned char>> binaries;
  if (program.getInfo(CL_PROGRAM_BINARIES, &binaries) != CL_SUCCESS || binaries.size() != 1 ||
      binaries[0].empty()) {
    return;
  }
  std::error_code ec;
  std::filesystem::create_directories(cache_dir_, ec);
  if (ec) return;
  const std::vector<unsigned char>& binary = binaries[0];
  unsigned long long header[3] = {key, binary.size(), fnv1a64(binary.data(), binary.size())};
  // A name no other process or thread writing the same entry can share.
  std::random_device entropy;
  std::string tmp = path + ".tmp" + std::to_string(getpid()) + "-" + std::to_string(entropy()) +
                    std::to_string(entropy());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) return;
    out.write(kMagic, sizeof kMagic);
    out.write(reinterpret_cast<const char*>(header), sizeof header);
    out.write(reinterpret_cast<const char*>(binary.data()),
              static_cast<std::streamsize>(binary.size()));
    if (!out) {
      out.close();
      std::filesystem::remove(tmp, ec);
      return;
    }
  }
  std::filesystem::rename(tmp, path, ec);  // atomic: readers never see half a file
  if (ec) std::filesystem::remove(tmp, ec);
}

}  // namespace boreas::impl
