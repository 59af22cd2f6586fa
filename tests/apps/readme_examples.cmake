# The README's examples run verbatim on a fresh layout (readme_examples.py): `-o out/...` and
# `--out-dir out/...` must work before out/ exists. render-compare's example renders for a minute
# or more and is left out here (it is run by hand when the README changes).
if(CMAKE_SCRIPT_MODE_FILE)
  return()
endif()
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME app.readme_examples
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/readme_examples.py
          ${CMAKE_SOURCE_DIR}/README.md $<TARGET_FILE_DIR:proxy-gen> ${CMAKE_SOURCE_DIR}
          ${CMAKE_CURRENT_BINARY_DIR}/readme_examples --skip render-compare)
set_tests_properties(app.readme_examples PROPERTIES TIMEOUT 900 LABELS not_sanitized)
