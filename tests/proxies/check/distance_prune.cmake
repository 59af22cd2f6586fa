# The pruned mesh distance against a brute force (proxies/check/mesh_distance.h).
proxyvis_add_test(distance_prune_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/distance_prune_test.cpp
  LIBS pv_proxy_check)
