# The "web" test (included from tests/CMakeLists.txt): the WebGL 2 page
# (app/web, built with emscripten by scripts/build-web.sh) screenshotted in
# headless Chromium and compared with `frustum-demo render` of the same view.
# Slow (an emscripten build and a browser per effect): `make test` leaves it
# out (-LE web); `make web` runs it. Skipped (exit 77) without emscripten or
# chromium.
if(TARGET frustum-demo AND TARGET frustum_image)
  add_executable(web_compare_pngs ${CMAKE_CURRENT_LIST_DIR}/compare_pngs.cpp)
  target_link_libraries(web_compare_pngs PRIVATE frustum_image)
  set(FRUSTUM_WEB_BUILD_DIR ${PROJECT_SOURCE_DIR}/build-web CACHE PATH
      "Where the web test builds the page (scripts/build-web.sh)")
  add_test(NAME web COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/run.sh ${PROJECT_SOURCE_DIR} ${FRUSTUM_WEB_BUILD_DIR}
                                 ${CMAKE_CURRENT_BINARY_DIR}/web-work $<TARGET_FILE:frustum-demo>
                                 $<TARGET_FILE:web_compare_pngs>)
  set_tests_properties(web PROPERTIES LABELS web SKIP_RETURN_CODE 77 TIMEOUT 1800)
endif()
