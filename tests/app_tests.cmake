# Suites that need the app layers. Each links whatever app libraries exist.
set(_app_libs)
foreach(lib frustum_reference frustum_render frustum_plan frustum_scene frustum_gl frustum_image frustum_vectors_lib frustum_window frustum_precision)
  if(TARGET ${lib})
    list(APPEND _app_libs ${lib})
  endif()
endforeach()
# The loader alone (also what the fresh-clone test builds in its clone).
if(TARGET frustum_scene)
  frustum_test_suite(scene frustum_scene)
  frustum_corpus_test(corpus-samples-load scene corpus-samples)  # tests/scene/samples_test.cpp
  frustum_corpus_test(corpus-validator scene corpus-validator)   # tests/scene/validator_corpus_test.cpp
endif()
# The GL-free planning code alone: links no GL library, needs no context.
if(TARGET frustum_plan)
  frustum_test_suite(plan frustum_plan)
endif()
frustum_test_suite(gl frustum::frustum ${_app_libs})
frustum_corpus_test(corpus-samples-render gl corpus-samples)     # tests/gl/render_samples_test.cpp
# The gl suite again on an OpenGL ES 3.0 context (what WebGL 2 and older
# phones give), then also without GL_EXT_clip_control (the [-1, 1] path):
# Mesa's overrides; gles30_context_test.cpp checks they took effect.
add_test(NAME gl-es30 COMMAND test_gl --test-suite-exclude=corpus-*)
set_tests_properties(gl-es30 PROPERTIES LABELS gl SKIP_RETURN_CODE 77
                     ENVIRONMENT "MESA_GLES_VERSION_OVERRIDE=3.0;FRUSTUM_EXPECT_GLES=3.0")
add_test(NAME gl-es30-no-clip-control COMMAND test_gl --test-suite-exclude=corpus-*)
set_tests_properties(gl-es30-no-clip-control PROPERTIES LABELS gl SKIP_RETURN_CODE 77
                     ENVIRONMENT "MESA_GLES_VERSION_OVERRIDE=3.0;MESA_EXTENSION_OVERRIDE=-GL_EXT_clip_control;FRUSTUM_EXPECT_GLES=3.0-no-clip-control")
# The OpenGL ES 3.0 header: the entry-point table is checked against it.
find_file(FRUSTUM_GLES3_HEADER GLES3/gl3.h)
if(NOT FRUSTUM_GLES3_HEADER)
  message(FATAL_ERROR "GLES3/gl3.h not found (libgles-dev, scripts/install-deps.sh)")
endif()
target_compile_definitions(test_gl PRIVATE FRUSTUM_GLES3_HEADER="${FRUSTUM_GLES3_HEADER}")
# Issue 36's poster checks at full size (4096^2 in 512^2 tiles, 16384^2
# downsampled 4x, every effect): minutes on llvmpipe, so not in `make test`;
# built and run on demand: cmake --build build --target test_poster_slow && build/tests/test_poster_slow
add_executable(test_poster_slow EXCLUDE_FROM_ALL gl/poster_slow/main.cpp gl/poster_slow/poster_seams_slow_test.cpp)
target_link_libraries(test_poster_slow PRIVATE doctest::doctest frustum_test_support frustum::frustum ${_app_libs})
target_compile_definitions(test_poster_slow PRIVATE FRUSTUM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
frustum_test_suite(cli frustum::frustum ${_app_libs})
include(${CMAKE_CURRENT_SOURCE_DIR}/robustness/suite.cmake OPTIONAL) # frustum_test_suite(robustness ...) + tool paths
include(${CMAKE_CURRENT_SOURCE_DIR}/window/suite.cmake OPTIONAL) # frustum_test_suite(window ...) + frustum-demo's path
