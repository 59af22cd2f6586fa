# The QEM decimater's equivalence with OpenMesh's and its legality-test counts (the speed of
# proxy-gen's general proxies, checked without timing).
proxyvis_add_test(qem_decimater_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/qem_decimater_test.cpp
  LIBS pv_proxy_general pv_mesh OpenMeshCore OpenMeshTools)
proxyvis_add_test(distance_prune_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/distance_prune_test.cpp
  LIBS pv_proxy_check)
