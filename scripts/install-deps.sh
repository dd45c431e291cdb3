#!/usr/bin/env bash
# Installs the Debian packages boreas builds, tests and runs with.
# Idempotent: packages already installed are skipped, and nothing is fetched
# when all are present. Works as root, and through sudo otherwise.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake pkg-config
  # OpenCL: the ICD loader, headers, the Khronos C++ bindings and PoCL for CPUs
  ocl-icd-opencl-dev opencl-headers opencl-clhpp-headers pocl-opencl-icd clinfo
  # maths, windowing, GL loading, images
  libglm-dev libglfw3-dev libepoxy-dev libopenimageio-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev libomp-dev
  # the reference ray tracer the ray tests and BM_Rays compare with (never the library's)
  libembree-dev
  # formats, command line, logging
  nlohmann-json3-dev libcli11-dev libspdlog-dev libfmt-dev
  libtinyobjloader-dev libpugixml-dev libtinygltf-dev
  # the Python package (python/): interpreter headers, NumPy, pytest, pybind11, plots
  python3-dev python3-numpy python3-pytest pybind11-dev python3-matplotlib
  # datasets over many machines (python -m boreas.dataset): Dask's distributed scheduler
  python3-distributed
  # headless OpenGL for render tests: Xvfb and Mesa's llvmpipe
  xvfb xauth libgl1-mesa-dri libegl-mesa0
  # animated glTF checked by tools nobody here wrote (tests/web/, its npm packages by
  # `npm ci` in the tests' CMake step): Node for the Khronos validator and three.js,
  # Chromium to run three.js headless, Blender for its glTF importer; Blender also runs the
  # add-on (python/boreas/blender) and its headless tests (ctest -L blender)
  nodejs chromium blender
)
# `install-deps.sh --fuzz` (make fuzz): clang and its libFuzzer runtime too.
if [ "${1:-}" = "--fuzz" ]; then
  packages+=(clang libclang-rt-dev)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

# npm: Debian's package where no npm is on the machine. A Node.js that brings its own npm
# (NodeSource's nodejs does) conflicts with Debian's npm package, and its npm serves as well.
if ! command -v npm >/dev/null 2>&1; then
  missing+=(npm)
fi

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  sudo_cmd=()
elif command -v sudo >/dev/null 2>&1; then
  sudo_cmd=(sudo)
else
  echo "install-deps: missing packages (${missing[*]}) and neither root nor sudo is available" >&2
  exit 1
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
