# proxy-check's N classified segments per proxy (proxies/check/ray_classify.h).
proxyvis_add_test(check_attempts_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/check_attempts_test.cpp
  LIBS pv_proxy_check pv_trace)
