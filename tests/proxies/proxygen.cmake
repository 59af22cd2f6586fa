# proxy-gen's proxy cache (proxies/pipeline/proxy_cache.h) and proxy-check's N classified segments
# per proxy (proxies/check/ray_classify.h).
proxyvis_add_test(proxy_cache_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/proxy_cache_test.cpp
  LIBS pv_proxy_pipeline pv_util)
proxyvis_add_test(check_attempts_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/check_attempts_test.cpp
  LIBS pv_proxy_check pv_trace)
