# proxy-gen's proxy cache (proxies/pipeline/proxy_cache.h).
proxyvis_add_test(proxy_cache_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/proxy_cache_test.cpp
  LIBS pv_proxy_pipeline pv_util)
