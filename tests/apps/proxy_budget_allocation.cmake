# scripts/proxy_budgets: the budget choice against brute force, and the whole allocation on a
# small plant scene (proxy_budget_allocation.py says what each step checks).
if(CMAKE_SCRIPT_MODE_FILE)
  return()
endif()
proxyvis_python_test(app.proxy_budget_allocation proxy_budget_allocation.py
  ${CMAKE_SOURCE_DIR}/scripts/proxy_budgets $<TARGET_FILE_DIR:proxy-gen> ${PROXYVIS_DATA_DIR}
  ${CMAKE_CURRENT_BINARY_DIR}/proxy_budget_allocation)
# not_sanitized: it runs proxy-gen and proxy-check 12 times; the scene key it adds is parsed in
# scene_tests, which the sanitizer build runs.
set_tests_properties(app.proxy_budget_allocation PROPERTIES TIMEOUT 600 LABELS not_sanitized)
