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
sheaf_find(OpenImageIO REQUIRED)
sheaf_find(pugixml REQUIRED)
sheaf_find(Threads REQUIRED)
if(SHEAF_BUILD_TESTS)
  sheaf_find(GTest REQUIRED)
endif()
if(SHEAF_BUILD_BENCHMARKS)
  sheaf_find(benchmark REQUIRED)
endif()
sheaf_find(CLI11 REQUIRED)

# Debian's OpenImageIO config names /usr/include/opencv4 among its include directories even
# when OpenCV's headers are not installed; CMake refuses imported targets with missing paths.
# Keep only the directories that exist rather than pulling in OpenCV.
if(TARGET OpenImageIO::OpenImageIO)
  get_target_property(_oiio_inc OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
  if(_oiio_inc)
    set(_oiio_keep)
    foreach(_dir IN LISTS _oiio_inc)
      if(EXISTS "${_dir}" OR _dir MATCHES "^\\$<")
        list(APPEND _oiio_keep "${_dir}")
      endif()
    endforeach()
    set_target_properties(OpenImageIO::OpenImageIO PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_oiio_keep}")
  endif()
endif()
