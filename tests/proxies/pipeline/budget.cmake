# The face budget's fallbacks and policy (proxies/pipeline/budget_*, openmesh_faces.h).
proxyvis_add_test(proxy_budget_tests SOURCES ${CMAKE_CURRENT_LIST_DIR}/budget_test.cpp
  LIBS pv_proxy_pipeline pv_proxy_general pv_proxy_inside pv_proxy_outside pv_proxy_check pv_mesh
       OpenMeshCore
  TIMEOUT 300)
