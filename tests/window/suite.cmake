# The "window" suite (tests/window/*.cpp), included from tests/app_tests.cmake.
# frustum-demo is run as a built binary: its path comes in as a compile
# definition, and the suite is built only when the target exists.
if(TARGET frustum-demo AND TARGET frustum_window)
  frustum_test_suite(window frustum::frustum ${_app_libs})
  target_compile_definitions(test_window PRIVATE FRUSTUM_DEMO_EXE="$<TARGET_FILE:frustum-demo>")
  add_dependencies(test_window frustum-demo)
endif()
# demo_options_test.cpp walks frustum-demo's option table in-process.
if(TARGET test_window AND TARGET frustum_demo_cli)
  target_link_libraries(test_window PRIVATE frustum_demo_cli)
endif()
