# proxy-check --html (docs/report_3d.md): the page in headless Chromium with WebGL (the checks
# and the planted problems the checker must find are listed in proxy_check_view3d.py), and the
# flag's bad-input rules: exit 2 for a wrong use, 3 for an output that cannot be written, and no
# page left behind by a failed run. Exit 77 (skipped): Chromium is not installed.
if(CMAKE_SCRIPT_MODE_FILE)
  return()
endif()
proxyvis_python_test(app.proxy_check.view3d proxy_check_view3d.py
  $<TARGET_FILE_DIR:proxy-check> ${PROXYVIS_DATA_DIR}
  ${CMAKE_CURRENT_BINARY_DIR}/proxy_check_view3d)
# Labels long and browser: `./setup.sh test-long` runs it, `./setup.sh test` does not.
# Not under the sanitizers: what takes its time there is Chromium; the page's writer is sanitized
# in app.proxy_check.html_written.
set_tests_properties(app.proxy_check.view3d PROPERTIES TIMEOUT 300 SKIP_RETURN_CODE 77
  LABELS "long;browser;not_sanitized")

proxyvis_app_test_dir(v3d_dir proxy_check_view3d_inputs)
proxyvis_write_box_off(${v3d_dir}/cube.off 0 1)
proxyvis_write_box_off(${v3d_dir}/around.off -0.5 1.5)
file(WRITE ${v3d_dir}/empty.off "OFF\n0 0 0\n")
set(v3d_pair "${v3d_dir}/cube.off ${v3d_dir}/around.off --rays 20000 --quiet")
# A small pair writes its page (and the JSON records its hash: tests/apps/proxy_check_view3d.py).
proxyvis_app_test(app.proxy_check.html_written proxy-check 0
  "${v3d_pair} --expect outside --html ${v3d_dir}/new/folder/page.html"
  FILES ${v3d_dir}/new/folder/page.html TIMEOUT 60)
proxyvis_app_test(app.proxy_check.html_needs_pair proxy-check 2
  "${PROXYVIS_SCENES_DIR}/dragon-plane.json --html ${v3d_dir}/scene.html"
  REGEX "^proxy-check: error: --html needs a mesh pair[^\n]*\n$"
  NO_FILES ${v3d_dir}/scene.html TIMEOUT 60)
proxyvis_app_test(app.proxy_check.html_missing_path proxy-check 2 "${v3d_pair} --html"
  REGEX "--html: 1 required" TIMEOUT 60)
proxyvis_app_test(app.proxy_check.html_is_input proxy-check 2
  "${v3d_pair} --html ${v3d_dir}/around.off" REGEX "--html names the input" TIMEOUT 60)
proxyvis_app_test(app.proxy_check.html_same_as_json proxy-check 2
  "${v3d_pair} --html ${v3d_dir}/same.html --json ${v3d_dir}/same.html"
  REGEX "--html and --json name the same output" NO_FILES ${v3d_dir}/same.html TIMEOUT 60)
proxyvis_app_test(app.proxy_check.html_unwritable proxy-check 3
  "${v3d_pair} --html ${v3d_dir}/cube.off/page.html"
  REGEX "^proxy-check: error: [^\n]*page.html: cannot write output; [^\n]*cube.off' is not a folder[^\n]*\n$"
  TIMEOUT 60)
proxyvis_app_test(app.proxy_check.html_is_a_folder proxy-check 3
  "${v3d_pair} --html ${v3d_dir}" REGEX "it is a folder" TIMEOUT 60)
# A run that fails on its input leaves no page (nor its temporary) behind.
proxyvis_app_test(app.proxy_check.html_not_written_on_bad_input proxy-check 2
  "${v3d_dir}/cube.off ${v3d_dir}/empty.off --quiet --html ${v3d_dir}/bad_input.html"
  REGEX "empty.off" NO_FILES ${v3d_dir}/bad_input.html TIMEOUT 60)
