# The relaxation after a bounded collapse (proxies/shared/internal/relax_toward_input.h) and the
# input test it relies on (internal/input_bound.h); the sanitizer build runs them too.
proxyvis_add_test(proxy_relax_tests SOURCES ${CMAKE_CURRENT_LIST_DIR}/relax_toward_input_test.cpp
  ${CMAKE_CURRENT_LIST_DIR}/input_bound_test.cpp
  LIBS pv_proxy_shared pv_proxy_check pv_mesh)
