# proxy-check: exact containment and the ray-sampled classification.
proxyvis_add_test(containment_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/containment_test.cpp
  LIBS pv_proxy_check)
