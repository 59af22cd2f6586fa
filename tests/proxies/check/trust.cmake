# The trust of a proxy's claimed class: the decision, its use on scene files, and that a downgrade
# reaches the renderer's class.
proxyvis_add_test(class_trust_test SOURCES ${CMAKE_CURRENT_LIST_DIR}/class_trust_test.cpp
  LIBS pv_proxy_check pv_render pv_mesh pv_scene)
