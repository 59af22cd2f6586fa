# proxy-check's report: distances labelled with their unit (scene units and fractions of the
# original's diagonal), no volume for an open mesh and the reason why.
proxyvis_add_test(check_report_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/check_report_test.cpp
  LIBS pv_proxy_check pv_trace)
