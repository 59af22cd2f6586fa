# tests/proxies/pipeline/ mirrors proxies/pipeline/ (its own CMakeLists.txt).
add_subdirectory(${CMAKE_CURRENT_LIST_DIR}/pipeline)
