# Outside proxies (proxies/outside): hull, wrap and convex parts on the bundled meshes, containment proven by
# the exact check, with and without a face budget.
proxyvis_add_test(proxy_outside_tests SOURCES ${CMAKE_CURRENT_LIST_DIR}/outside_test.cpp
  LIBS pv_proxy_pipeline pv_proxy_general pv_proxy_inside pv_proxy_outside pv_proxy_check pv_mesh
  LABELS slow TIMEOUT 600 SHARDS 4)
