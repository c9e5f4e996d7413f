# One wrapper around find_package that says what was found, so a build log answers
# "which OpenImageIO did this use?" without digging.
macro(sheaf_find name)
  find_package(${name} ${ARGN})
  if(${name}_FOUND)
    message(STATUS "Sheaf: found ${name} ${${name}_VERSION}")
  else()
    message(STATUS "Sheaf: ${name} not found")
  endif()
endmacro()

sheaf_find(TBB REQUIRED)
# XXH3 digests of the arrays a frame copies to the device (core/base/content_hash.cpp), used
# header-only (XXH_INLINE_ALL): nothing to link (Debian: libxxhash-dev).
find_path(SHEAF_XXHASH_INCLUDE_DIR xxhash.h)
if(NOT SHEAF_XXHASH_INCLUDE_DIR)
  message(FATAL_ERROR "Sheaf: xxhash.h not found (Debian: libxxhash-dev)")
endif()
message(STATUS "Sheaf: found xxHash (${SHEAF_XXHASH_INCLUDE_DIR}/xxhash.h)")
# Debian's OpenImageIO package config lists its command line tools (iconvert, ...) as imported
# targets and refuses to load when they are missing: the README installs openimageio-tools.
sheaf_find(OpenImageIO REQUIRED)
sheaf_find(pugixml REQUIRED)
# Debian installs OpenColorIO's package config straight into /usr/share/cmake, which
# find_package does not search by itself.
sheaf_find(OpenColorIO REQUIRED HINTS /usr/share/cmake)
sheaf_find(Threads REQUIRED)
# Mesh files (OBJ, PLY, glTF) for io/mesh. Its package config looks for draco itself.
sheaf_find(assimp REQUIRED)
# Subdivision (io/subdiv): OpenSubdiv's Far API in the CPU library osdCPU. Debian's package
# config (libosd-dev 3.5) names static libraries it does not ship and stops the configure, so
# it is not loaded here: the header and the shared library are found directly and given the
# config's target name, OpenSubdiv::osdCPU. A config that does load may define it first.
if(NOT TARGET OpenSubdiv::osdCPU)
  find_path(SHEAF_OPENSUBDIV_INCLUDE_DIR opensubdiv/version.h)
  find_library(SHEAF_OPENSUBDIV_OSDCPU_LIBRARY osdCPU)
  if(NOT SHEAF_OPENSUBDIV_INCLUDE_DIR OR NOT SHEAF_OPENSUBDIV_OSDCPU_LIBRARY)
    message(FATAL_ERROR "Sheaf: OpenSubdiv not found (opensubdiv/version.h and libosdCPU; "
                        "Debian: libosd-dev)")
  endif()
  file(STRINGS ${SHEAF_OPENSUBDIV_INCLUDE_DIR}/opensubdiv/version.h _sheaf_osd_version
       REGEX "#define OPENSUBDIV_VERSION_(MAJOR|MINOR|PATCH) ")
  string(REGEX REPLACE ".*MAJOR ([0-9]+).*MINOR ([0-9]+).*PATCH ([0-9]+).*" "\\1.\\2.\\3"
         OpenSubdiv_VERSION "${_sheaf_osd_version}")
  add_library(OpenSubdiv::osdCPU UNKNOWN IMPORTED)
  set_target_properties(OpenSubdiv::osdCPU PROPERTIES
    IMPORTED_LOCATION ${SHEAF_OPENSUBDIV_OSDCPU_LIBRARY}
    INTERFACE_INCLUDE_DIRECTORIES ${SHEAF_OPENSUBDIV_INCLUDE_DIR})
  message(STATUS "Sheaf: found OpenSubdiv ${OpenSubdiv_VERSION} (${SHEAF_OPENSUBDIV_OSDCPU_LIBRARY})")
endif()
if(SHEAF_BUILD_TESTS)
  sheaf_find(GTest REQUIRED)
endif()
if(SHEAF_BUILD_BENCHMARKS)
  sheaf_find(benchmark REQUIRED)
endif()
sheaf_find(CLI11 REQUIRED)
# Fonts for the text object (io/font): glyph outlines, advances and kerning (Debian:
# libfreetype-dev, which OpenImageIO's own package already pulls in).
sheaf_find(Freetype REQUIRED)
# Palette indices of PNG height fields (io/pov/height_fields.cpp), which OpenImageIO expands to
# colours (Debian: libpng-dev).
sheaf_find(PNG REQUIRED)

# Debian's package configs name include directories that do not exist: OpenImageIO lists
# /usr/include/opencv4 even without OpenCV's headers, and OpenColorIO's config, installed in
# /usr/share/cmake, computes its prefix as "/" and names "/include". CMake refuses imported
# targets with missing paths; keep the directories that exist (the headers are in /usr/include).
function(sheaf_drop_missing_include_dirs target)
  if(NOT TARGET ${target})
    return()
  endif()
  get_target_property(dirs ${target} INTERFACE_INCLUDE_DIRECTORIES)
  if(NOT dirs)
    return()
  endif()
  set(keep)
  foreach(dir IN LISTS dirs)
    if(EXISTS "${dir}" OR dir MATCHES "^\\$<")
      list(APPEND keep "${dir}")
    endif()
  endforeach()
  set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${keep}")
endfunction()
sheaf_drop_missing_include_dirs(OpenImageIO::OpenImageIO)
sheaf_drop_missing_include_dirs(OpenColorIO::OpenColorIO)
