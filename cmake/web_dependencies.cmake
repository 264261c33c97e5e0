# The web build's header-only dependencies (FRUSTUM_BUILD_WEB, emscripten).
# GLM, tinygltf, nlohmann-json and stb are header-only in Debian, under the
# host's /usr/include; putting that folder on emscripten's include path would
# put the host's libc headers ahead of emscripten's sysroot. So the four are
# copied into the build folder and offered to find_package()/find_path()
# from there, and the rest of the CMake files stay as they are.
set(FRUSTUM_WEB_HOST_INCLUDE /usr/include CACHE PATH
    "Where the host's glm/, nlohmann/, stb/ and tiny_gltf.h are (copied for the web build)")
set(_web_headers ${CMAKE_BINARY_DIR}/web-headers)
foreach(_header glm nlohmann stb tiny_gltf.h)
  if(NOT EXISTS ${FRUSTUM_WEB_HOST_INCLUDE}/${_header})
    message(FATAL_ERROR "FRUSTUM_BUILD_WEB: ${FRUSTUM_WEB_HOST_INCLUDE}/${_header} not found; "
                        "run scripts/install-deps.sh --web (libglm-dev, nlohmann-json3-dev, libtinygltf-dev, libstb-dev)")
  endif()
  file(COPY ${FRUSTUM_WEB_HOST_INCLUDE}/${_header} DESTINATION ${_web_headers})
endforeach()

# Package configs that define the imported targets the CMake files link.
function(frustum_web_package name target)
  set(dir ${CMAKE_BINARY_DIR}/web-packages/${name})
  file(WRITE ${dir}/${name}Config.cmake
       "if(NOT TARGET ${target})\n"
       "  add_library(${target} INTERFACE IMPORTED)\n"
       "  set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES \"${_web_headers}\")\n"
       "endif()\n")
  set(${name}_DIR ${dir} CACHE PATH "web build: header-only ${name}" FORCE)
endfunction()
frustum_web_package(glm glm::glm)
frustum_web_package(TinyGLTF TinyGLTF::TinyGLTF)
frustum_web_package(nlohmann_json nlohmann_json::nlohmann_json)
set(STB_INCLUDE_DIR ${_web_headers} CACHE PATH "web build: stb/" FORCE)
set(STB_IMAGE_INCLUDE_DIR ${_web_headers}/stb CACHE PATH "web build: stb_image.h" FORCE)
set(STB_EASY_FONT_INCLUDE_DIR ${_web_headers} CACHE PATH "web build: stb/stb_easy_font.h" FORCE)
# tinygltf's and stb_image's code: compiled by app/web (frustum_web_stb), not
# Debian's libtinygltf.so and libstb.so.
set(STB_LIBRARY frustum_web_stb CACHE STRING "web build: stb_image implementation target" FORCE)
