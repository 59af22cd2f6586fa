# glTF against tools proxyvis did not write: the Khronos validator on every writer option, the
# class surviving the file (proxy-check --expect), and obj2gltf, gltf-pipeline and gltf-transform
# outputs loading as the OBJ they came from (gltf_tools.py says what each step checks). The npm
# packages are tests/js's, installed by setup.sh.
if(CMAKE_SCRIPT_MODE_FILE)
  return()
endif()
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME app.gltf_tools
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/gltf_tools.py
          $<TARGET_FILE_DIR:proxy-gen> ${PROXYVIS_DATA_DIR} ${CMAKE_SOURCE_DIR}/tests/js
          ${CMAKE_CURRENT_BINARY_DIR}/gltf_tools)
# Under ASan it took 230 s (proxy-gen a dozen times, node tools beside): room for a loaded machine.
set_tests_properties(app.gltf_tools PROPERTIES TIMEOUT 900)
