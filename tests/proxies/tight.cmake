# Tightness at small budgets: outside/inside wraps at 2 % of the faces against the volume-ratio
# targets, and the input-bounded collapse (proxies/shared/bounded_simplify.h).
proxyvis_add_test(proxy_tight_tests SOURCES ${CMAKE_CURRENT_LIST_DIR}/tight_test.cpp
  LIBS pv_proxy_pipeline pv_proxy_general pv_proxy_inside pv_proxy_outside pv_proxy_check pv_mesh
  LABELS slow TIMEOUT 600)
