# render-compare end to end on tiny renders: exit codes, the JSON contract on stdout (--json -),
# the report files, the reference cache, and bad input / unwritable output.
#
# Two roles, as proxy_check.cmake: included from tests/apps/CMakeLists.txt it writes a tiny scene
# (a box on a ground quad under a quad light, with a box outside proxy) and registers the tests;
# run with `cmake -P` it drives one test: runs the program RUNS times (default 1), checks the last
# exit code, that stdout+stderr match OUTPUT_REGEX, that stdout is a JSON report whose rows carry
# the contract keys (JSON_STDOUT), and that EXPECT_FILE exists.
if(CMAKE_SCRIPT_MODE_FILE)
  separate_arguments(args NATIVE_COMMAND "${ARGS}")
  if(NOT RUNS)
    set(RUNS 1)
  endif()
  if(CLEAN_DIR)
    file(REMOVE_RECURSE "${CLEAN_DIR}")
  endif()
  foreach(run RANGE 1 ${RUNS})
    execute_process(COMMAND "${EXE}" ${args} RESULT_VARIABLE code OUTPUT_VARIABLE out
      ERROR_VARIABLE err)
  endforeach()
  if(NOT code EQUAL EXPECT_CODE)
    message(FATAL_ERROR "exit code ${code}, expected ${EXPECT_CODE}\nstdout:\n${out}\nstderr:\n${err}")
  endif()
  if(OUTPUT_REGEX AND NOT "${out}${err}" MATCHES "${OUTPUT_REGEX}")
    message(FATAL_ERROR "output does not match '${OUTPUT_REGEX}'\nstdout:\n${out}\nstderr:\n${err}")
  endif()
  if(JSON_STDOUT)
    string(JSON rows ERROR_VARIABLE bad GET "${out}" rows)
    if(bad)
      message(FATAL_ERROR "stdout is not a JSON report with rows: ${bad}\n${out}")
    endif()
    string(JSON n LENGTH "${rows}")
    if(NOT n EQUAL JSON_STDOUT)
      message(FATAL_ERROR "${n} rows, expected ${JSON_STDOUT}")
    endif()
    math(EXPR last "${n} - 1")
    foreach(i RANGE ${last})
      foreach(key estimator spp seconds mse relmse efficiency rays table mse_stderr)
        string(JSON value ERROR_VARIABLE missing GET "${rows}" ${i} ${key})
        if(missing)
          message(FATAL_ERROR "row ${i}: key '${key}' missing: ${missing}")
        endif()
      endforeach()
      string(JSON mse GET "${rows}" ${i} mse)
      if(NOT mse GREATER 0)
        message(FATAL_ERROR "row ${i}: MSE ${mse} is not positive")
      endif()
    endforeach()
  endif()
  foreach(f ${EXPECT_FILE})
    if(NOT EXISTS "${f}")
      message(FATAL_ERROR "${f} was not written")
    endif()
  endforeach()
  return()
endif()

if(NOT TARGET render-compare)
  return()
endif()

set(rc_dir ${CMAKE_CURRENT_BINARY_DIR}/render_compare)
file(MAKE_DIRECTORY ${rc_dir})
# Axis-aligned box [lo, hi]^3 as an OFF mesh (12 outward triangles).
function(rc_write_box name lo hi)
  set(text "OFF\n8 12 0\n")
  foreach(i RANGE 7)
    math(EXPR bx "${i} & 1")
    math(EXPR by "${i} & 2")
    math(EXPR bz "${i} & 4")
    set(p "")
    foreach(b ${bx} ${by} ${bz})
      if(b)
        string(APPEND p "${hi} ")
      else()
        string(APPEND p "${lo} ")
      endif()
    endforeach()
    string(APPEND text "${p}\n")
  endforeach()
  foreach(t "0 2 3" "0 3 1" "4 5 7" "4 7 6" "0 1 5" "0 5 4" "2 6 7" "2 7 3" "0 4 6" "0 6 2"
            "1 3 7" "1 7 5")
    string(APPEND text "3 ${t}\n")
  endforeach()
  file(WRITE ${rc_dir}/${name}.off "${text}")
endfunction()
rc_write_box(box 0 1)
rc_write_box(box_outside -0.1 1.1)
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

set(rc_driver ${CMAKE_CURRENT_LIST_FILE})
# rc_test(NAME CODE "ARGS" [JSON rows] [REGEX text] [FILES paths...] [RUNS n] [CLEAN dir])
function(rc_test name code args)
  cmake_parse_arguments(T "" "JSON;REGEX;RUNS;CLEAN" "FILES" ${ARGN})
  set(defs -DEXE=$<TARGET_FILE:render-compare> -DEXPECT_CODE=${code} "-DARGS=${args}")
  foreach(v JSON_STDOUT:JSON OUTPUT_REGEX:REGEX RUNS:RUNS CLEAN_DIR:CLEAN)
    string(REPLACE ":" ";" pair ${v})
    list(GET pair 0 def)
    list(GET pair 1 arg)
    if(T_${arg})
      list(APPEND defs "-D${def}=${T_${arg}}")
    endif()
  endforeach()
  if(T_FILES)
    string(REPLACE ";" "\\;" files "${T_FILES}")
    list(APPEND defs "-DEXPECT_FILE=${files}")
  endif()
  add_test(NAME app.render_compare.${name} COMMAND ${CMAKE_COMMAND} ${defs} -P ${rc_driver})
  set_tests_properties(app.render_compare.${name} PROPERTIES TIMEOUT 120)
endfunction()

set(tiny "--width 16 --height 12 --spp 1,2 --equal-time 0.05 --seeds 2 --reference-spp 64")
# 6 estimators x (2 spp + equal time) = 18 rows.
rc_test(smoke 0 "${rc_dir}/tiny.json --out ${rc_dir}/smoke ${tiny} --quiet --json -"
  JSON 18 CLEAN ${rc_dir}/smoke
  FILES ${rc_dir}/smoke/report.html ${rc_dir}/smoke/report.csv ${rc_dir}/smoke/report.md
        ${rc_dir}/smoke/report.json ${rc_dir}/smoke/roulette_2.exr ${rc_dir}/smoke/roulette_2.png
        ${rc_dir}/smoke/exact_2_error.png ${rc_dir}/smoke/culling_equal-time_cost.png)
# The second run finds the reference in the cache.
rc_test(reference_cache 0
  "${rc_dir}/tiny.json --out ${rc_dir}/cache --width 8 --height 8 --spp 1 --equal-time 0 --seeds 1 --estimators exact,roulette --reference-spp 32"
  RUNS 2 CLEAN ${rc_dir}/cache REGEX "HTML report: .*cached")
if(EXISTS ${PROXYVIS_SCENES_DIR}/cornell-bunny.json AND EXISTS ${PROXYVIS_DATA_DIR}/bunny.off)
  rc_test(bundled_scene 0
    "${PROXYVIS_SCENES_DIR}/cornell-bunny.json --out ${rc_dir}/bundled --width 8 --height 8 --spp 1 --equal-time 0.05 --seeds 2 --reference-spp 32 --quiet --json -"
    JSON 12)
endif()
rc_test(unknown_scene_key 2 "${rc_dir}/bad_key.json --out ${rc_dir}/bad ${tiny} --quiet"
  REGEX "lens")
rc_test(missing_scene 2 "${rc_dir}/no_such_scene.json --out ${rc_dir}/bad ${tiny} --quiet"
  REGEX "no_such_scene")
rc_test(unknown_estimator 2 "${rc_dir}/tiny.json --out ${rc_dir}/bad --estimators exact,magic"
  REGEX "magic")
rc_test(bad_spp 2 "${rc_dir}/tiny.json --out ${rc_dir}/bad --spp 4,x" REGEX "spp")
rc_test(unwritable_out 3 "${rc_dir}/tiny.json --out ${rc_dir}/a_file/out ${tiny} --quiet")
