# Script behind Consumer.InstalledPackageBuildsAndRuns (cmake -P).
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
# A sanitized libboreas needs its runtime linked into the program first.
set(extra_flags "")
if(SANITIZE)
  set(extra_flags "-fsanitize=address,undefined")
endif()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")

# A lean core: the installed library loads at most 10 shared libraries besides the C and C++
# runtimes (OpenCL's loader, pugixml, ...), and the package files ask a consumer for nothing
# else (no image library: the library takes ground maps as pixel arrays).
file(GLOB_RECURSE installed_libs "${prefix}/*/libboreas.so")
list(GET installed_libs 0 installed_lib)
run(ldd "${installed_lib}")
string(REGEX MATCHALL "[^\n]+" ldd_lines "${last_output}")
set(runtime "^[ \t]*(linux-vdso|/lib64/ld-linux|ld-linux|libc\\.so|libm\\.so|libstdc\\+\\+|libgcc_s|libpthread|libdl|librt)")
set(others "")
foreach(line IN LISTS ldd_lines)
  if(NOT line MATCHES "${runtime}")
    string(STRIP "${line}" line)
    list(APPEND others "${line}")
  endif()
endforeach()
list(LENGTH others other_count)
message(STATUS "libboreas.so loads ${other_count} libraries besides the C/C++ runtime: ${others}")
if(other_count GREATER 10)
  message(FATAL_ERROR "libboreas.so loads ${other_count} libraries besides the C/C++ runtime (at most 10):\n${last_output}")
endif()
file(GLOB_RECURSE package_files "${prefix}/*/boreas.pc" "${prefix}/*/cmake/boreas/*.cmake")
foreach(f IN LISTS package_files)
  file(READ "${f}" text)
  if(text MATCHES "OpenImageIO|OIIO|pugixml|tinygltf|nlohmann")
    message(FATAL_ERROR "${f} asks a consumer for a private dependency (${CMAKE_MATCH_0})")
  endif()
endforeach()

# 1. CMake package
run(${CMAKE_COMMAND} -S "${PROJECT_DIR}" -B "${WORK_DIR}/cmake-build"
    "-DCMAKE_PREFIX_PATH=${prefix}" "-DCMAKE_C_COMPILER=${C_COMPILER}"
    "-DCMAKE_C_FLAGS=${extra_flags}")
run(${CMAKE_COMMAND} --build "${WORK_DIR}/cmake-build")
run("${WORK_DIR}/cmake-build/consumer")
message(STATUS "find_package consumer: ${last_output}")

# 2. pkg-config
file(GLOB_RECURSE pc_files "${prefix}/*/boreas.pc")
list(GET pc_files 0 pc_file)
get_filename_component(pc_dir "${pc_file}" DIRECTORY)
set(ENV{PKG_CONFIG_PATH} "${pc_dir}")
run(pkg-config --cflags --libs boreas)
string(STRIP "${last_output}" flags)
separate_arguments(flags UNIX_COMMAND "${flags}")
get_filename_component(libdir "${pc_dir}" DIRECTORY)
run("${C_COMPILER}" -std=c99 -Wall -Werror "${PROJECT_DIR}/main.c" -o "${WORK_DIR}/consumer-pc"
    ${flags} ${extra_flags} "-Wl,-rpath,${libdir}")
run("${WORK_DIR}/consumer-pc")
message(STATUS "pkg-config consumer: ${last_output}")
