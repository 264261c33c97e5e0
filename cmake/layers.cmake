# The layers, lowest first, and what each may use. This table is the one
# statement of the project's dependency order; the build and a test hold the
# code to it:
# - frustum_include_root() gives a library an include root that holds only
#   its own folder (a symbolic link in the build tree), so a target sees the
#   headers of the libraries it links and nothing else: "render/x.hpp" does
#   not resolve inside gl/ (before, gl/ exported the repository root).
# - frustum_check_layers() (the end of the top-level CMakeLists.txt) refuses,
#   at configure time, a layer library linking a layer it may not use.
# - The CTest `layers` (tests/layers/check_includes.cmake) reads every
#   #include of every folder below and fails on a layer that the folder's
#   row does not allow, and on "../" includes that step out of a folder.
#
# One row per folder: "<folder>:<layer> <layers it may include ...>". The
# layer name is the include prefix ("render/renderer.hpp"); <frustum/...>
# is the math library's own include root (frustum/include). The libraries'
# rows come first; a test folder's row starts with the layer it tests.
set(FRUSTUM_LAYERS
  "frustum:frustum"
  "image:image frustum"
  "gl:gl image frustum"
  "app/text:text"
  "app/scene:scene image text frustum"
  "app/plan:plan scene image frustum"
  "app/render:render plan scene gl image frustum"
  "app/reference:reference render plan scene gl image frustum"
  "app/window:window render plan scene gl image frustum"
  "app/vectors:vectors text frustum"
  "app/explain:explain frustum"
  "app/precision:precision plan scene image frustum"
  "app/demo:demo window reference render plan scene gl image frustum"
  "app/web:web window render plan scene gl image frustum"
  "tests/math:frustum support"
  "tests/package:frustum"
  "tests/cli:vectors frustum"
  "tests/plan:plan scene image frustum"
  "tests/scene:scene image frustum support"
  "tests/fuzz:scene vectors frustum"
  "tests/robustness:scene vectors gl image frustum support"
  "tests/gl:render reference precision plan scene gl image frustum support"
  "tests/bench:render reference plan scene gl image frustum"
  "tests/window:window demo render plan scene gl image frustum support"
  "tests/web:image frustum"
  "tests/support:support" # frustum_test_support: what the suites share
  "tests:tests") # tests/sample_files.hpp, shared by the suites as "../sample_files.hpp"

# Each layer's library: the target whose links frustum_check_layers() checks.
set(FRUSTUM_LAYER_TARGETS
  "frustum:frustum"
  "image:frustum_image"
  "gl:frustum_gl frustum_gl_window"
  "text:frustum_text"
  "scene:frustum_scene"
  "plan:frustum_plan"
  "render:frustum_render"
  "reference:frustum_reference"
  "window:frustum_window frustum_window_imgui"
  "vectors:frustum_vectors_lib"
  "demo:frustum_demo_cli"
  "precision:frustum_precision"
  "support:frustum_test_support")

# <target> sees "<layer>/..." as <folder>/... (PUBLIC: so do the targets
# that link it). The root holds nothing else.
function(frustum_include_root target layer folder)
  set(root ${CMAKE_BINARY_DIR}/include-roots/${target})
  file(MAKE_DIRECTORY ${root})
  file(REMOVE ${root}/${layer})
  file(CREATE_LINK ${folder} ${root}/${layer} SYMBOLIC)
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "INTERFACE_LIBRARY")
    target_include_directories(${target} INTERFACE ${root})
  elseif(type STREQUAL "EXECUTABLE")
    target_include_directories(${target} PRIVATE ${root})
  else()
    target_include_directories(${target} PUBLIC ${root})
  endif()
endfunction()

# One table row "<key>:<a b c>" -> <key> and the list a;b;c.
macro(frustum_layer_row row key_var names_var)
  string(REPLACE ":" ";" _row_parts "${row}")
  list(GET _row_parts 0 ${key_var})
  list(GET _row_parts 1 ${names_var})
  string(REPLACE " " ";" ${names_var} "${${names_var}}")
endmacro()

# The layer a target belongs to, or "" for targets outside the table.
function(_frustum_layer_of target out)
  set(found "")
  foreach(row IN LISTS FRUSTUM_LAYER_TARGETS)
    frustum_layer_row("${row}" layer targets)
    if(target IN_LIST targets)
      set(found ${layer})
    endif()
  endforeach()
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

# The layers a layer may use (its own included), from FRUSTUM_LAYERS.
function(_frustum_allowed_layers layer out)
  set(allowed "")
  foreach(row IN LISTS FRUSTUM_LAYERS)
    frustum_layer_row("${row}" folder names)
    list(GET names 0 own)
    if(own STREQUAL layer)
      set(allowed ${names})
      break() # the library's own row, before the tests' rows
    endif()
  endforeach()
  set(${out} "${allowed}" PARENT_SCOPE)
endfunction()

# Configure-time check: every layer library links only libraries of the
# layers its row allows, e.g.
# "frustum_gl (layer gl) links frustum_render (layer render); gl may use only: gl image frustum".
function(frustum_check_layers)
  foreach(row IN LISTS FRUSTUM_LAYER_TARGETS)
    frustum_layer_row("${row}" layer targets)
    _frustum_allowed_layers(${layer} allowed)
    foreach(target IN LISTS targets)
      if(NOT TARGET ${target})
        continue()
      endif()
      get_target_property(links ${target} LINK_LIBRARIES)
      if(NOT links)
        continue()
      endif()
      foreach(link IN LISTS links)
        if(NOT TARGET "${link}")
          continue()
        endif()
        get_target_property(real ${link} ALIASED_TARGET)
        if(real)
          set(link ${real})
        endif()
        _frustum_layer_of(${link} used)
        if(used AND NOT used IN_LIST allowed)
          string(REPLACE ";" " " allowed_text "${allowed}")
          message(FATAL_ERROR "${target} (layer ${layer}) links ${link} (layer ${used}); "
                              "${layer} may use only: ${allowed_text} (cmake/layers.cmake)")
        endif()
      endforeach()
    endforeach()
  endforeach()
endfunction()
