# proxy-gen on scenes (proxies/scene): the shard manifest's and the run report's JSON.
proxyvis_add_test(proxy_scene_records_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/scene_records_test.cpp
  LIBS pv_proxy_scene pv_util)
