# proxy-check --precision float|double|both on a pair built so that the original's two readings
# disagree, and proxy-gen on it with and without a clearance (proxy_check_precision.py).
if(CMAKE_SCRIPT_MODE_FILE)
  return()
endif()
proxyvis_app_test_dir(precision_dir proxy_check_precision)
proxyvis_python_test(app.proxy_check.precision proxy_check_precision.py
  $<TARGET_FILE_DIR:proxy-check> ${precision_dir})
set_tests_properties(app.proxy_check.precision PROPERTIES TIMEOUT 600
  FAIL_REGULAR_EXPRESSION "FAIL:")
