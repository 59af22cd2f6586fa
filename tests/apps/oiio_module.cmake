# OpenImageIO loaded on first use (lib/image/oiio_module.h): not linked by render and
# render-compare, never loaded by a plan or a unit, a missing module refused with one line.
# Not in a build that links the module into the programs (PROXYVIS_PRELOAD_OIIO_MODULE, the
# sanitizer build): there every process loads it at start, which is what this test rules out.
if(CMAKE_SCRIPT_MODE_FILE OR PROXYVIS_PRELOAD_OIIO_MODULE)
  return()
endif()
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME app.oiio_module
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/oiio_module.py $<TARGET_FILE:render>
          $<TARGET_FILE:render-compare> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/oiio_module)
set_tests_properties(app.oiio_module PROPERTIES TIMEOUT 300)
