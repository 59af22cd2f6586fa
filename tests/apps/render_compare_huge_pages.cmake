# render-compare re-executes itself once with glibc's huge-page malloc tunable, unless it is set.
if(CMAKE_SCRIPT_MODE_FILE)
  return()
endif()
proxyvis_python_test(app.render_compare.huge_pages render_compare_huge_pages.py
  $<TARGET_FILE:render-compare>)
set_tests_properties(app.render_compare.huge_pages PROPERTIES TIMEOUT 60)
