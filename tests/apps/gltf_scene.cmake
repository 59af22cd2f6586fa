# glTF scenes both ways on dragon-plane: proxy-gen --gltf writes the scene with its proxies, the
# GLB renders the JSON scene's image bit for bit, and proxy-gen, proxy-check and render-compare
# run on it as a scene (gltf_scene.py says what each step checks).
if(CMAKE_SCRIPT_MODE_FILE)
  return()
endif()
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME app.gltf_scene
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/gltf_scene.py
          $<TARGET_FILE_DIR:proxy-gen> ${CMAKE_SOURCE_DIR} ${CMAKE_SOURCE_DIR}/tests/js
          ${CMAKE_CURRENT_BINARY_DIR}/gltf_scene)
# Under ASan it took 157 s: room for a loaded machine.
set_tests_properties(app.gltf_scene PROPERTIES TIMEOUT 900)
