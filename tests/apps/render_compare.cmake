# render-compare end to end on tiny renders: exit codes, the JSON contract on stdout (--json -),
# the report files, the reference cache, and bad input / unwritable output.
#
# Included from tests/apps/CMakeLists.txt this writes a tiny scene (a box on a ground quad under a
# quad light, with a box outside proxy) and registers the tests; in script mode
# support/run_app.cmake includes it after its checks (last exit code of RUNS runs, OUTPUT_REGEX,
# written files) to check that stdout is a JSON report of JSON_STDOUT rows carrying the contract
# keys.
if(CMAKE_SCRIPT_MODE_FILE AND RC_SEQUENCE)
  # Runs into one --out: a rerun leaves nothing of the previous report; a run killed by SIGTERM
  # leaves the previous report intact and no temporary; stale temporaries of dead runs (pid
  # 999999999 exceeds any pid_max) are removed by the next run.
  set(dir ${RC_DIR}/sequence)
  file(REMOVE_RECURSE ${dir})
  file(MAKE_DIRECTORY ${dir})
  set(common ${RC_SCENE} --out ${dir}/rep --width 8 --spp 1 --seeds 1 --reference-spp 16 --quiet)
  execute_process(COMMAND ${EXE} ${common} --height 8 --equal-time 0 --estimators exact,roulette
    RESULT_VARIABLE code ERROR_VARIABLE err)
  if(NOT code EQUAL 0 OR NOT EXISTS ${dir}/rep/roulette_1.png OR NOT EXISTS ${dir}/rep/manifest.json)
    message(FATAL_ERROR "first run: exit ${code}, no report\n${err}")
  endif()
  file(GLOB first_reference ${dir}/rep/reference-*.exr)
  file(MAKE_DIRECTORY ${dir}/.rep.tmp999999999_0)
  file(WRITE ${dir}/.rep.tmp999999999_0/exact_1.png "stale")
  file(WRITE ${dir}/.report.tmp999999999_1.json "stale")
  # The rerun renders another size: its reference has another cache key, so another file name;
  # the first run's reference, like its roulette images, must not stay beside the new report.
  execute_process(COMMAND ${EXE} ${common} --height 6 --equal-time 0 --estimators exact
    RESULT_VARIABLE code ERROR_VARIABLE err)
  if(NOT code EQUAL 0 OR EXISTS ${dir}/rep/roulette_1.png)
    message(FATAL_ERROR "rerun: exit ${code}; roulette_1.png of the first run must be gone\n${err}")
  endif()
  file(GLOB rerun_reference ${dir}/rep/reference-*.exr)
  list(LENGTH rerun_reference n_references)
  if(NOT n_references EQUAL 1 OR rerun_reference STREQUAL first_reference)
    message(FATAL_ERROR "rerun: references ${rerun_reference}; the first run's was ${first_reference}")
  endif()
  file(GLOB left LIST_DIRECTORIES true ${dir}/.*)
  if(left)
    message(FATAL_ERROR "stale temporaries of a dead run were not removed: ${left}")
  endif()
  file(SHA256 ${dir}/rep/report.json report_hash)
  # Killed while rendering (each equal-time cell takes 2 minutes), on one thread: the 4 s before
  # the signal need not keep both cores busy.
  execute_process(COMMAND timeout -s TERM 4 ${EXE} ${common} --height 8 --equal-time 120 --threads 1
    RESULT_VARIABLE code ERROR_VARIABLE err)
  if(NOT code EQUAL 124)
    message(FATAL_ERROR "the run to be killed ended with ${code} before SIGTERM\n${err}")
  endif()
  file(SHA256 ${dir}/rep/report.json after)
  if(NOT after STREQUAL report_hash)
    message(FATAL_ERROR "the killed run changed the previous report")
  endif()
  file(GLOB left LIST_DIRECTORIES true ${dir}/.* ${dir}/rep/.*)
  if(left)
    message(FATAL_ERROR "temporaries left behind: ${left}")
  endif()
  return()
endif()
if(CMAKE_SCRIPT_MODE_FILE)
  # Only JSON on stdout (text before or after it would make it unparsable for a consumer).
  string(STRIP "${out}" stripped)
  if(NOT stripped MATCHES "^{.*}$")
    message(FATAL_ERROR "stdout holds more than the JSON report:\n${out}")
  endif()
  string(JSON rows ERROR_VARIABLE bad GET "${out}" rows)
  if(bad)
    message(FATAL_ERROR "stdout is not a JSON report with rows: ${bad}\n${out}")
  endif()
  string(JSON n LENGTH "${rows}")
  if(NOT n EQUAL JSON_STDOUT)
    message(FATAL_ERROR "${n} rows, expected ${JSON_STDOUT}")
  endif()
  # The title names the scene (its "name", else the file's stem), never the file name.
  string(JSON title GET "${out}" title)
  if(NOT title MATCHES "^[^.]+: visibility estimators compared$")
    message(FATAL_ERROR "title '${title}' does not name the scene")
  endif()
  string(JSON meta GET "${out}" meta)
  expect_json_keys("meta" "${meta}" reference_spp reference_seconds reference_partials)
  if(NO_EXACT)
    # Without exact there is no baseline: efficiency is null, never a number such as 0.
    foreach(i RANGE 1)
      string(JSON type TYPE "${rows}" ${i} efficiency)
      if(NOT type STREQUAL "NULL")
        message(FATAL_ERROR "row ${i}: efficiency is ${type}, expected null")
      endif()
    endforeach()
    if(NOT err MATCHES "\\| n/a \\|")
      message(FATAL_ERROR "the table on stderr does not say n/a:\n${err}")
    endif()
    return()
  endif()
  math(EXPR last "${n} - 1")
  foreach(i RANGE ${last})
    string(JSON row GET "${rows}" ${i})
    expect_json_keys("row ${i}" "${row}" estimator spp seconds mse relmse efficiency rays table
      mse_stderr)
    string(JSON mse GET "${row}" mse)
    if(NOT mse GREATER 0)
      message(FATAL_ERROR "row ${i}: MSE ${mse} is not positive")
    endif()
  endforeach()
  return()
endif()


proxyvis_app_test_dir(rc_dir render_compare)
proxyvis_write_box_off(${rc_dir}/box.off 0 1)
proxyvis_write_box_off(${rc_dir}/box_outside.off -0.1 1.1)
# The light (y = 4) is outside the proxy, so the verified outside class holds (pitfall 2).
set(rc_scene_text [=[
{
  "camera": {"eye": [0, 3, 6], "look_at": [0, 0.5, 0], "fov_deg": 40, "resolution": [32, 32]},
  "lights": [{"type": "quad", "corner": [-1, 4, -1], "edge_u": [2, 0, 0], "edge_v": [0, 0, 2],
              "radiance": [8, 8, 8]}],
  "meshes": [
    {"name": "ground", "file": "@GROUND@", "transform": {"scale": 10}},
    {"name": "box", "file": "box.off", "transform": {"translate": [-0.5, 0, -0.5]},
     "proxies": [{"kind": "outside", "method": "box", "file": "box_outside.off",
                  "class": "outside"}]}
  ]
}
]=])
string(REPLACE "@GROUND@" "${PROXYVIS_SCENES_DIR}/meshes/ground.obj" rc_scene_text
  "${rc_scene_text}")
file(WRITE ${rc_dir}/tiny.json "${rc_scene_text}")
string(REPLACE "\"fov_deg\": 40" "\"fov_deg\": 40, \"lens\": 2" rc_bad_text "${rc_scene_text}")
file(WRITE ${rc_dir}/bad_key.json "${rc_bad_text}")
file(WRITE ${rc_dir}/a_file "not a directory")

# rc_test(NAME CODE "ARGS" [JSON rows] [NO_EXACT] [REGEX text] [FILES paths...] [RUNS n]
#         [CLEAN dir])
function(rc_test name code args)
  cmake_parse_arguments(T "NO_EXACT" "JSON;REGEX;RUNS;CLEAN" "FILES" ${ARGN})
  set(checks "")
  if(T_JSON)
    set(checks CHECKS ${CMAKE_CURRENT_FUNCTION_LIST_FILE} DEFS -DJSON_STDOUT=${T_JSON}
      -DNO_EXACT=${T_NO_EXACT})
  endif()
  proxyvis_app_test(app.render_compare.${name} render-compare ${code} "${args}" REGEX "${T_REGEX}"
    RUNS "${T_RUNS}" CLEAN "${T_CLEAN}" FILES ${T_FILES} TIMEOUT 120 ${checks})
endfunction()

set(tiny "--width 16 --height 12 --spp 1,2 --equal-time 0.05 --seeds 2 --reference-spp 64")
# 6 estimators x (2 spp + equal time) = 18 rows.
rc_test(smoke 0 "${rc_dir}/tiny.json --out ${rc_dir}/smoke ${tiny} --quiet --json -"
  JSON 18 CLEAN ${rc_dir}/smoke
  FILES ${rc_dir}/smoke/report.html ${rc_dir}/smoke/report.csv ${rc_dir}/smoke/report.md
        ${rc_dir}/smoke/report.json ${rc_dir}/smoke/roulette_2.exr ${rc_dir}/smoke/roulette_2.png
        ${rc_dir}/smoke/roulette_2_aov.exr
        ${rc_dir}/smoke/exact_2_error.png ${rc_dir}/smoke/culling_equal-time_cost.png)
# The second run finds the reference in the cache.
rc_test(reference_cache 0
  "${rc_dir}/tiny.json --out ${rc_dir}/cache --width 8 --height 8 --spp 1 --equal-time 0 --seeds 1 --estimators exact,roulette --reference-spp 32"
  RUNS 2 CLEAN ${rc_dir}/cache REGEX "HTML report: .*cached")
rc_test(bundled_scene 0
  "${PROXYVIS_SCENES_DIR}/cornell-bunny.json --out ${rc_dir}/bundled --width 8 --height 8 --spp 1 --equal-time 0.05 --seeds 2 --reference-spp 32 --quiet --json -"
  JSON 12)
rc_test(unknown_scene_key 2 "${rc_dir}/bad_key.json --out ${rc_dir}/bad ${tiny} --quiet"
  REGEX "lens")
rc_test(missing_scene 2 "${rc_dir}/no_such_scene.json --out ${rc_dir}/bad ${tiny} --quiet"
  REGEX "no_such_scene")
rc_test(unknown_estimator 2 "${rc_dir}/tiny.json --out ${rc_dir}/bad --estimators exact,magic"
  REGEX "magic")
rc_test(bad_spp 2 "${rc_dir}/tiny.json --out ${rc_dir}/bad --spp 4,x" REGEX "spp")
rc_test(bad_build 2 "${rc_dir}/tiny.json --out ${rc_dir}/bad --build sideways" REGEX "build")
rc_test(bad_roulette_costs 2 "${rc_dir}/tiny.json --out ${rc_dir}/bad --roulette-costs 1,2,x"
  REGEX "roulette-costs")
# Fixed roulette costs and a flattened build run end to end.
rc_test(fixed_costs_flat 0
  "${rc_dir}/tiny.json --out ${rc_dir}/fixed ${tiny} --estimators exact,roulette --roulette-costs 10,10,40,40,20 --build flat --quiet --json -"
  JSON 6 CLEAN ${rc_dir}/fixed)
# Without exact among the estimators: efficiency n/a in the table, null in the JSON.
rc_test(no_exact_efficiency_na 0
  "${rc_dir}/tiny.json --out ${rc_dir}/no_exact --width 8 --height 8 --spp 1 --equal-time 0 --seeds 1 --estimators roulette,culling --reference-spp 16 --json -"
  JSON 2 NO_EXACT CLEAN ${rc_dir}/no_exact)
# On the terminal: a scene whose meshes use no proxy (the box proxy is not cheaper than the box)
# is said in one warning line, and the reference's samples, partial renders and time.
rc_test(terminal_notes 0
  "${rc_dir}/tiny.json --out ${rc_dir}/notes --width 8 --height 8 --spp 1 --equal-time 0 --seeds 1 --estimators exact --reference-spp 16"
  CLEAN ${rc_dir}/notes
  REGEX "render-compare: warning: tiny\\.json: no mesh of this scene has a proxy[^\n]*\n.*reference [^\n]*exact, 16 spp in 16 partial renders, [0-9.]+ s")
rc_test(unwritable_out 3 "${rc_dir}/tiny.json --out ${rc_dir}/a_file/out ${tiny} --quiet")
# --json - without --quiet: still only the JSON on stdout, the tables go to stderr.
rc_test(json_stdout_only 0
  "${rc_dir}/tiny.json --out ${rc_dir}/stdout_only ${tiny} --estimators exact,roulette --json -"
  JSON 6 CLEAN ${rc_dir}/stdout_only)
add_test(NAME app.render_compare.rerun_and_sigterm COMMAND ${CMAKE_COMMAND}
  -DEXE=$<TARGET_FILE:render-compare> -DRC_SEQUENCE=1 -DRC_DIR=${rc_dir}
  -DRC_SCENE=${rc_dir}/tiny.json -P ${CMAKE_CURRENT_LIST_FILE})
set_tests_properties(app.render_compare.rerun_and_sigterm PROPERTIES TIMEOUT 180)
