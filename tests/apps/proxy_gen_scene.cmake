# proxy-gen on a small scene of bundled ecosys plants: make_proxy, the proxy cache (hit, misses on
# a changed setting or input, damaged entries regenerated, --no-cache) and proxy-check's N
# classified segments per prototype (proxy_gen_scene_cache.py says what each step checks).
if(CMAKE_SCRIPT_MODE_FILE)
  return()
endif()
proxyvis_python_test(app.proxy_gen_scene_cache proxy_gen_scene_cache.py
  $<TARGET_FILE_DIR:proxy-gen> ${PROXYVIS_DATA_DIR}
  ${CMAKE_CURRENT_BINARY_DIR}/proxy_gen_scene_cache)
set_tests_properties(app.proxy_gen_scene_cache PROPERTIES TIMEOUT 600)
