# frustum_gl for the web build (included from app/web/CMakeLists.txt): the
# same GL layer as gl/CMakeLists.txt minus the EGL, OSMesa and GLFW
# backends, plus gl::WebGlContext (web_context.hpp). frustum_gl_window is
# the default-framebuffer part the window painter uses (the canvas is
# framebuffer 0). Keep the shared file list in step with gl/CMakeLists.txt.
set(_gl ${PROJECT_SOURCE_DIR}/gl)
add_library(frustum_gl STATIC
  ${_gl}/context.cpp
  ${_gl}/debug_output.cpp
  ${_gl}/functions.cpp
  ${_gl}/errors.cpp
  ${_gl}/objects.cpp
  ${_gl}/offscreen_target.cpp
  ${_gl}/clip_control.cpp
  ${_gl}/web_context.cpp)    # gl::Context backend: the browser's WebGL 2 canvas
frustum_include_root(frustum_gl gl ${PROJECT_SOURCE_DIR}/gl) # "gl/..." and nothing else
target_compile_definitions(frustum_gl PUBLIC GL_GLES_PROTOTYPES=0)
target_link_libraries(frustum_gl PUBLIC frustum::frustum frustum_image)
target_compile_features(frustum_gl PUBLIC cxx_std_17)

add_library(frustum_gl_window STATIC ${_gl}/window_framebuffer.cpp)
target_link_libraries(frustum_gl_window PUBLIC frustum_gl)
target_compile_features(frustum_gl_window PUBLIC cxx_std_17)
