# Header-only dependencies (GLM, doctest, nlohmann-json) for cross builds.
# Debian installs them for the host under /usr/include; adding that folder to
# a cross compiler's include path would put the host's libc and libstdc++
# headers ahead of the target sysroot's. Instead each header folder is
# linked into <build>/host-headers (which holds nothing else) and offered to
# find_package() through a small package config, so the project's CMake
# files stay as they are. Included at project() by the toolchain files in
# this folder (CMAKE_PROJECT_INCLUDE).
set(FRUSTUM_HOST_INCLUDE_DIR /usr/include CACHE PATH
    "Where the host's glm/, doctest/ and nlohmann/ header folders are (linked for cross builds)")
set(_frustum_headers ${CMAKE_BINARY_DIR}/host-headers)
file(MAKE_DIRECTORY ${_frustum_headers})

# frustum_header_package(<package> <target> <header folder> <version header> <version macro prefix>)
function(frustum_header_package package target folder version_header prefix)
  set(source ${FRUSTUM_HOST_INCLUDE_DIR}/${folder})
  if(NOT EXISTS ${source}/${version_header})
    message(FATAL_ERROR "cross build: ${source}/${version_header} not found (install ${package}'s Debian "
                        "package, see scripts/install-deps.sh, or set FRUSTUM_HOST_INCLUDE_DIR)")
  endif()
  if(NOT EXISTS ${_frustum_headers}/${folder})
    file(CREATE_LINK ${source} ${_frustum_headers}/${folder} SYMBOLIC)
  endif()
  set(version "")
  foreach(part MAJOR MINOR PATCH)
    file(STRINGS ${source}/${version_header} line REGEX "#define ${prefix}_${part}[ \t]+[0-9]+")
    string(REGEX MATCH "[0-9]+[ \t]*(//.*)?$" number "${line}")
    string(REGEX MATCH "^[0-9]+" number "${number}")
    list(APPEND version ${number})
  endforeach()
  list(JOIN version "." version)
  set(dir ${CMAKE_BINARY_DIR}/host-header-packages/${package})
  file(WRITE ${dir}/${package}Config.cmake
       "if(NOT TARGET ${target})\n"
       "  add_library(${target} INTERFACE IMPORTED)\n"
       "  set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES \"${_frustum_headers}\")\n"
       "endif()\n")
  file(WRITE ${dir}/${package}ConfigVersion.cmake
       "set(PACKAGE_VERSION ${version})\n"
       "if(PACKAGE_FIND_VERSION AND PACKAGE_VERSION VERSION_LESS PACKAGE_FIND_VERSION)\n"
       "  set(PACKAGE_VERSION_COMPATIBLE FALSE)\n"
       "else()\n"
       "  set(PACKAGE_VERSION_COMPATIBLE TRUE)\n"
       "endif()\n")
  set(${package}_DIR ${dir} CACHE PATH "cross build: header-only ${package} (cmake/toolchains)" FORCE)
endfunction()

frustum_header_package(glm glm::glm glm detail/setup.hpp GLM_VERSION)
frustum_header_package(doctest doctest::doctest doctest doctest.h DOCTEST_VERSION)
frustum_header_package(nlohmann_json nlohmann_json::nlohmann_json nlohmann detail/abi_macros.hpp NLOHMANN_JSON_VERSION)
