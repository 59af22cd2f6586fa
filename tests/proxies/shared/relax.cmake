# The relaxation after a bounded collapse (proxies/shared/internal/relax_toward_input.h); the
# sanitizer build runs it too.
proxyvis_add_test(proxy_relax_tests SOURCES ${CMAKE_CURRENT_LIST_DIR}/relax_toward_input_test.cpp
  LIBS pv_proxy_shared pv_proxy_check pv_mesh)
