# A written class holds for the input mesh: ray-parity solids (watertight non-manifold meshes have
# an inside), the exact check against the input, and the downgrade to general for --fill-holes.
proxyvis_add_test(proxy_guarantee_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/guarantee_test.cpp
  LIBS pv_proxy_pipeline pv_proxy_general pv_proxy_inside pv_proxy_outside pv_proxy_check
       pv_proxy_shared pv_mesh pv_trace
  LABELS slow TIMEOUT 600 SHARDS 2)
