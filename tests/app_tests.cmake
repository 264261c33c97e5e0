# Suites that need the app layers. Each links whatever app libraries exist.
set(_app_libs)
foreach(lib frustum_reference frustum_render frustum_scene frustum_gl frustum_image frustum_vectors_lib frustum_window frustum_precision)
  if(TARGET ${lib})
    list(APPEND _app_libs ${lib})
  endif()
endforeach()
frustum_test_suite(scene frustum::frustum ${_app_libs})
frustum_test_suite(gl frustum::frustum ${_app_libs})
frustum_test_suite(cli frustum::frustum ${_app_libs})
include(${CMAKE_CURRENT_SOURCE_DIR}/robustness/suite.cmake OPTIONAL) # frustum_test_suite(robustness ...) + tool paths
include(${CMAKE_CURRENT_SOURCE_DIR}/window/suite.cmake OPTIONAL) # frustum_test_suite(window ...) + frustum-demo's path
