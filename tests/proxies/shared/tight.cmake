# Tightness at small budgets: outside/inside wraps at 2 % of the faces against the volume-ratio
# targets, and the input-bounded collapse (proxies/shared/bounded_simplify.h). not_sanitized: the
# targets are numbers, and the suite took 170 s under ASan; the collapse and the relaxation run
# there in proxy_budget_tests and the proxy_gen_budget cases.
proxyvis_add_test(proxy_tight_tests SOURCES ${CMAKE_CURRENT_LIST_DIR}/tight_test.cpp
  LIBS pv_proxy_pipeline pv_proxy_general pv_proxy_inside pv_proxy_outside pv_proxy_check pv_mesh
  LABELS slow not_sanitized TIMEOUT 600)
