# General proxies (proxies/general): every simplifier meets its budget; the QEM decimater's
# equivalence with OpenMesh's and its legality-test counts (the speed of proxy-gen's general
# proxies, checked without timing).
proxyvis_add_test(proxy_general_tests SOURCES ${CMAKE_CURRENT_LIST_DIR}/general_test.cpp
  LIBS pv_proxy_pipeline pv_proxy_general pv_proxy_inside pv_proxy_outside pv_proxy_check pv_mesh
  LABELS slow TIMEOUT 600)
proxyvis_add_test(qem_decimater_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/qem_decimater_test.cpp
  LIBS pv_proxy_general pv_mesh OpenMeshCore OpenMeshTools)
