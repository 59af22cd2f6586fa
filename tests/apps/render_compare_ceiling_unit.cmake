# render-compare's ceiling unit renders nothing when the study has exact cells (the merge prices
# c_s with them) and its own short exact render otherwise.
if(CMAKE_SCRIPT_MODE_FILE)
  return()
endif()
proxyvis_python_test(app.render_compare.ceiling_unit render_compare_ceiling_unit.py
  $<TARGET_FILE:render-compare> ${CMAKE_SOURCE_DIR}
  ${CMAKE_CURRENT_BINARY_DIR}/render_compare_ceiling_unit)
set_tests_properties(app.render_compare.ceiling_unit PROPERTIES TIMEOUT 300)
