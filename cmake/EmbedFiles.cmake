# boreas_embed_files(): turns text files (OpenCL kernels, shaders, scenes) into a C++
# source holding a {name, text} table, regenerated whenever one of them changes.
#
#   boreas_embed_files(OUTPUT file.cpp FUNCTION ns::fn BASE_DIR dir FILES a.cl b.h ...)
#
# The generated function has the signature
#   const std::vector<std::pair<const char*, const char*>>& fn();
# and names are the files' paths relative to BASE_DIR.
function(boreas_embed_files)
  cmake_parse_arguments(E "" "OUTPUT;FUNCTION;BASE_DIR" "FILES" ${ARGN})
  set(abs_files "")
  foreach(f IN LISTS E_FILES)
    list(APPEND abs_files "${E_BASE_DIR}/${f}")
  endforeach()
  add_custom_command(
    OUTPUT "${E_OUTPUT}"
    COMMAND ${CMAKE_COMMAND}
            "-DOUTPUT=${E_OUTPUT}" "-DFUNCTION=${E_FUNCTION}" "-DBASE_DIR=${E_BASE_DIR}"
            "-DFILES=${E_FILES}"
            -P "${PROJECT_SOURCE_DIR}/cmake/EmbedFilesScript.cmake"
    DEPENDS ${abs_files} "${PROJECT_SOURCE_DIR}/cmake/EmbedFilesScript.cmake"
    COMMENT "Embedding ${E_FUNCTION}"
    VERBATIM)
endfunction()
