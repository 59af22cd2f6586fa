# proxy-check: exact containment, class statistics and the ray-sampled classification.
proxyvis_add_test(containment_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/containment_test.cpp
  LIBS pv_proxy_check)
proxyvis_add_test(check_stats_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/check_stats_test.cpp
  LIBS pv_proxy_check)
proxyvis_add_test(check_distance_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/check_distance_test.cpp
  LIBS pv_proxy_check)
proxyvis_add_test(check_rays_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/check_rays_test.cpp
  LIBS pv_proxy_check pv_trace)
proxyvis_add_test(check_data_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/check_data_test.cpp
  LIBS pv_proxy_check pv_trace pv_mesh pv_proxy_outside)
proxyvis_add_test(scene_pair_space_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/scene_pair_space_test.cpp
  LIBS pv_proxy_check pv_scene pv_mesh)
