# tests/proxies/scene/ mirrors proxies/scene/ (its own CMakeLists.txt).
add_subdirectory(${CMAKE_CURRENT_LIST_DIR}/scene)
