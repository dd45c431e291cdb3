# OpenImageIO as one interface target, boreas_openimageio, for render/ (frames, textures,
# and the terrain and nutrient images of scene files) and the tests that write images. The
# library (host/) never links it: it takes ground maps as pixel arrays.
#
# Debian's CMake package stops configuration with a fatal error unless openimageio-tools is
# installed too (its targets file insists on /usr/bin/iconvert and the other tools), so
# pkg-config, which needs only the library, is asked first.
find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
  pkg_check_modules(boreas_oiio QUIET IMPORTED_TARGET GLOBAL OpenImageIO)
endif()
add_library(boreas_openimageio INTERFACE)
if(TARGET PkgConfig::boreas_oiio)
  target_link_libraries(boreas_openimageio INTERFACE PkgConfig::boreas_oiio)
else()
  find_package(OpenImageIO CONFIG REQUIRED)
  target_link_libraries(boreas_openimageio INTERFACE OpenImageIO::OpenImageIO)
endif()
