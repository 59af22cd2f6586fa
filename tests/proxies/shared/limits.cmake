# proxies/shared: the input geometry checks and the time budget, and the pipeline refusing such
# inputs for every kind and method before CGAL or OpenMesh run.
proxyvis_add_test(proxy_limits_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/input_geometry_test.cpp
  LIBS pv_proxy_pipeline pv_proxy_shared pv_mesh TIMEOUT 120)
