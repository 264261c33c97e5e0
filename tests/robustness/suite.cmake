# The "robustness" suite (tests/robustness/*.cpp), included from
# tests/app_tests.cmake. The command-line tools are run as built binaries:
# their paths come in as compile definitions, one per target that exists,
# and the suite skips the tools it is not given.
frustum_test_suite(robustness frustum::frustum ${_app_libs})
if(TARGET test_robustness)
  foreach(tool vectors demo explain)
    if(TARGET frustum-${tool})
      string(TOUPPER ${tool} upper)
      target_compile_definitions(test_robustness PRIVATE FRUSTUM_${upper}_EXE="$<TARGET_FILE:frustum-${tool}>")
      add_dependencies(test_robustness frustum-${tool})
    endif()
  endforeach()
  # The fuzzers' inputs (corpus, regressions) and their folder layout.
  target_compile_definitions(test_robustness PRIVATE FRUSTUM_FUZZ_DIR="${PROJECT_SOURCE_DIR}/tests/fuzz")
  target_include_directories(test_robustness PRIVATE ${PROJECT_SOURCE_DIR}/tests/fuzz)
endif()
