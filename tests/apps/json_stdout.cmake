# `--json -` puts only JSON on stdout, for every program: each test parses the whole of stdout with
# Python's json.loads (json_stdout.py) and fails on anything else. The runs are not --quiet, so the
# human report (and proxy-gen's --progress bar) must go to stderr, which is checked too.
if(CMAKE_SCRIPT_MODE_FILE)
  return()
endif()
find_package(Python3 REQUIRED COMPONENTS Interpreter)

proxyvis_app_test_dir(js_dir json_stdout)
set(js_data ${CMAKE_SOURCE_DIR}/data)

# js_test(NAME TARGET STDERR_REGEX KEYS ARGS...): TARGET ARGS... --json - must exit 0 with only
# JSON on stdout holding KEYS (comma-separated), and stderr matching STDERR_REGEX.
function(js_test name target stderr_regex keys)
  add_test(NAME app.json_stdout.${name}
    COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/json_stdout.py
            --stderr "${stderr_regex}" --keys "${keys}" --workdir ${js_dir}/${name}
            -- $<TARGET_FILE:${target}> ${ARGN} --json -)
  set_tests_properties(app.json_stdout.${name} PROPERTIES TIMEOUT 300)
endfunction()

js_test(mesh_info mesh-info "triangles" "faces,closed" ${js_data}/bunny.off ${js_data}/teapot.obj)
js_test(proxy_gen proxy-gen "proxy-gen \\[.*verified: +yes.*total" "faces,verified,hausdorff"
  ${js_data}/bunny.off --kind outside --method hull -o ${js_dir}/proxy_gen/bunny.hull.ply
  --progress)
# The generators that call OpenMesh (QEM) and CGAL (the inside wrap) print nothing on stdout either.
js_test(proxy_gen_qem proxy-gen "verified:" "faces,hausdorff"
  ${js_data}/bunny.off --kind general --method qem -o ${js_dir}/proxy_gen_qem/bunny.qem.ply)
js_test(proxy_gen_inside_wrap proxy-gen "verified: +yes" "faces,hausdorff"
  ${js_data}/hard/cow.off --kind inside -o ${js_dir}/proxy_gen_inside_wrap/cow.inside.ply)
js_test(proxy_gen_scene proxy-gen "== bunny.*scene with proxies" "meshes,scene_out"
  ${CMAKE_SOURCE_DIR}/scenes/cornell-bunny.json --kind outside --method hull
  --out-dir ${js_dir}/proxy_gen_scene/proxies)
js_test(proxy_check proxy-check "Verdicts" "counts,exact,hausdorff"
  ${js_data}/bunny.off ${js_data}/bunny.off --rays 20000)
js_test(render_compare render-compare "exact" "rows"
  ${CMAKE_SOURCE_DIR}/scenes/cornell-bunny.json --out ${js_dir}/render_compare/out --width 8
  --height 8 --spp 1 --equal-time 0 --seeds 1 --reference-spp 16 --estimators exact)
js_test(render render "render" "spp,seconds,estimator,seed"
  ${CMAKE_SOURCE_DIR}/scenes/cornell-bunny.json -o ${js_dir}/render/image.exr --width 8 --height 8
  --spp 2)
