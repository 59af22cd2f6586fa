# The glTF files proxyvis writes as three.js's GLTFLoader sees them in headless Chromium: the
# triangle count and bounds of mesh-info, plain and as Draco/meshopt copies (gltf_three.py says
# what it checks). three, playwright-core and the producers are tests/js's npm packages and
# Chromium a Debian package, all installed by setup.sh.
if(CMAKE_SCRIPT_MODE_FILE)
  return()
endif()
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME app.gltf_three
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/gltf_three.py
          $<TARGET_FILE_DIR:proxy-gen> ${PROXYVIS_DATA_DIR} ${CMAKE_SOURCE_DIR}/tests/js
          ${CMAKE_CURRENT_BINARY_DIR}/gltf_three)
# Labels long and browser: `./setup.sh test-long` runs it, `./setup.sh test` does not.
# Not under the sanitizers: what runs there is three.js in Node; the GLB writer it reads is
# sanitized in app.gltf_scene.
set_tests_properties(app.gltf_three PROPERTIES TIMEOUT 300 LABELS "long;browser;not_sanitized")
