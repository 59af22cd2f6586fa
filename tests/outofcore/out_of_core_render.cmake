if(CMAKE_SCRIPT_MODE_FILE)
  return()
endif()
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME app.render.out_of_core
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/out_of_core_render.py
          $<TARGET_FILE_DIR:render> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/out_of_core)
# The statistics (40 roulette seeds) are the Release suite's; under the sanitizers the quick case
# takes every code path once.
set_tests_properties(app.render.out_of_core PROPERTIES TIMEOUT 600
  FAIL_REGULAR_EXPRESSION "FAIL:" LABELS not_sanitized)
add_test(NAME app.render.out_of_core.quick
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/out_of_core_render.py
          $<TARGET_FILE_DIR:render> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/out_of_core_quick
          --quick)
set_tests_properties(app.render.out_of_core.quick PROPERTIES TIMEOUT 900
  FAIL_REGULAR_EXPRESSION "FAIL:")
add_test(NAME app.render_compare.out_of_core
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/out_of_core_compare.py
          $<TARGET_FILE_DIR:render-compare> ${CMAKE_SOURCE_DIR}
          ${CMAKE_CURRENT_BINARY_DIR}/out_of_core_compare)
set_tests_properties(app.render_compare.out_of_core PROPERTIES TIMEOUT 600
  FAIL_REGULAR_EXPRESSION "FAIL:")
# The render's measured peak RSS growth against budget + proxies + image + 10 %.
add_test(NAME app.render.out_of_core.memory
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/out_of_core_memory.py
          $<TARGET_FILE_DIR:render> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/out_of_core_memory)
# RSS under the sanitizers is theirs, not the renderer's.
set_tests_properties(app.render.out_of_core.memory PROPERTIES TIMEOUT 600
  FAIL_REGULAR_EXPRESSION "FAIL:" LABELS not_sanitized)
