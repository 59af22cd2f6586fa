# proxy-gen: outside, inside and general proxies and their pipeline (proxies/outside, inside,
# general). The placement LP needs nothing else; the rest needs pv_mesh and pv_proxy_check.
proxyvis_add_test(proxy_lp_tests SOURCES ${CMAKE_CURRENT_LIST_DIR}/plane_lp_test.cpp LIBS pv_proxy_shared)
proxyvis_add_test(proxy_gen_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/outside_test.cpp ${CMAKE_CURRENT_LIST_DIR}/inside_test.cpp
          ${CMAKE_CURRENT_LIST_DIR}/general_test.cpp
  LIBS pv_proxy_pipeline pv_proxy_general pv_proxy_inside pv_proxy_outside pv_proxy_check pv_mesh
  LABELS slow TIMEOUT 600)
