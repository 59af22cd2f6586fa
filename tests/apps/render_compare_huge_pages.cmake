# render-compare re-executes itself once with glibc's huge-page malloc tunable, unless it is set.
if(CMAKE_SCRIPT_MODE_FILE)
  return()
endif()
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME app.render_compare.huge_pages
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/render_compare_huge_pages.py
          $<TARGET_FILE:render-compare>)
set_tests_properties(app.render_compare.huge_pages PROPERTIES TIMEOUT 60)
