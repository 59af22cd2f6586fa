# The pipeline's typed values (proxies/pipeline): the report's JSON round trip and its errors.
proxyvis_add_test(proxy_report_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/proxy_report_test.cpp
  LIBS pv_proxy_pipeline pv_util)
