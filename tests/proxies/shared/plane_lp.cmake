# The placement LP of the box and tetrahedron fallbacks (proxies/shared/plane_lp.h).
proxyvis_add_test(proxy_lp_tests SOURCES ${CMAKE_CURRENT_LIST_DIR}/plane_lp_test.cpp
  LIBS pv_proxy_shared)
