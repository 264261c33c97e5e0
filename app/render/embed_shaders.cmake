# Run with cmake -P at build time: turns each GLSL file into a C++ string
# constant, shaders/scene.vert -> render::shaders::scene_vert (in the
# namespace of the layer that embeds it), so the binaries need no shader
# files at run time.
#   -DSHADERS=a.vert|b.frag   input files ('|'-separated: ';' would split the command line)
#   -DOUTPUT=.../embedded_shaders.hpp
#   -DNAMESPACE=render        the layer's namespace (render, reference)
string(REPLACE "|" ";" shader_files "${SHADERS}")
set(text "// Generated from shaders/ by app/render/embed_shaders.cmake: do not edit.\n")
string(APPEND text "#pragma once\n\n#include <string_view>\n\nnamespace ${NAMESPACE}::shaders {\n")
foreach(path IN LISTS shader_files)
  file(READ "${path}" source)
  if(source MATCHES "\\)glsl\"")
    message(FATAL_ERROR "${path} contains ')glsl\"', which ends the raw string literal")
  endif()
  get_filename_component(name "${path}" NAME)
  string(MAKE_C_IDENTIFIER "${name}" identifier)
  string(APPEND text "\n// shaders/${name}\ninline constexpr std::string_view ${identifier} = R\"glsl(${source})glsl\";\n")
endforeach()
string(APPEND text "\n} // namespace ${NAMESPACE}::shaders\n")
# Rewrite only on change, so an unrelated re-run recompiles nothing.
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" previous)
endif()
if(NOT previous STREQUAL text)
  file(WRITE "${OUTPUT}" "${text}")
endif()
