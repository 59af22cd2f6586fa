# proxy-check end to end: exit codes, messages and JSON keys on tiny boxes written here (an
# original cube and proxies around it, inside it, far from it, open, empty).
#
# Included from tests/apps/CMakeLists.txt this writes the meshes and registers the tests; in
# script mode support/run_app.cmake includes it after its checks (exit code, OUTPUT_REGEX, written
# files) to check that JSON_FILE has every key and JSON_EXACT as its "exact" value.
if(CMAKE_SCRIPT_MODE_FILE)
  if(JSON_ONLY_STDOUT)
    # --json -: stdout is the JSON and nothing else (the report text went to stderr); it records
    # the hash of the error segments' file.
    expect_only_json_on_stdout("{" "}" "sampled class")
    expect_json_keys("stdout" "${json}" counts exact dump_errors)
    file(SHA256 "${DUMP_FILE}" actual)
    expect_json_value("stdout" "${json}" "${actual}" dump_errors sha256)
  else()
    file(READ "${JSON_FILE}" json)
    expect_json_keys("${JSON_FILE}" "${json}" counts V_avg f_hit f_miss intervals sampled_class
      exact cost_ratio seed rays seconds P_hit_proxy_given_miss_original
      P_miss_proxy_given_hit_original)
    expect_json_value("${JSON_FILE}" "${json}" "${JSON_EXACT}" exact)
  endif()
  return()
endif()


proxyvis_app_test_dir(pc_dir proxy_check)
# "NAME LO HI [FACES]": the box [LO, HI]^3 as NAME.off (11 faces: open).
foreach(box "cube 0 1" "around -0.5 1.5" "inner 0.25 0.75" "far 10 11" "open_around -0.5 1.5 11")
  separate_arguments(box)
  list(POP_FRONT box name)
  proxyvis_write_box_off(${pc_dir}/${name}.off ${box})
endforeach()
file(WRITE ${pc_dir}/empty.off "OFF\n0 0 0\n")

# pc_test(NAME CODE "ARGS" [JSON exact] [REGEX text] [FILE path])
function(pc_test name code args)
  cmake_parse_arguments(T "" "JSON;REGEX;FILE" "" ${ARGN})
  set(extra "")
  set(json "")
  if(T_JSON)
    set(json ${pc_dir}/${name}.json)
    set(args "${args} --json ${json}")
    set(extra CHECKS ${CMAKE_CURRENT_FUNCTION_LIST_FILE} DEFS -DJSON_FILE=${json}
      -DJSON_EXACT=${T_JSON})
  endif()
  proxyvis_app_test(app.proxy_check.${name} proxy-check ${code} "${args}" REGEX "${T_REGEX}"
    FILES ${T_FILE} ${json} TIMEOUT 60 ${extra})
endfunction()

set(q "--quiet --rays 20000 --seed 3")
pc_test(outside 0 "${pc_dir}/cube.off ${pc_dir}/around.off ${q} --expect outside"
  JSON contains REGEX "sampled class +outside")
pc_test(inside 0 "${pc_dir}/cube.off ${pc_dir}/inner.off ${q} --expect inside"
  JSON contained REGEX "sampled class +inside")
pc_test(inside_is_not_outside 1 "${pc_dir}/cube.off ${pc_dir}/inner.off ${q} --expect outside"
  REGEX "CONTRADICTED")
pc_test(far_away_is_disjoint 1 "${pc_dir}/cube.off ${pc_dir}/far.off ${q} --expect outside"
  JSON disjoint REGEX "mismatched pair")
pc_test(open_proxy_undecidable 0 "${pc_dir}/cube.off ${pc_dir}/open_around.off ${q}"
  JSON undecidable REGEX "not closed")
pc_test(empty_proxy 2 "${pc_dir}/cube.off ${pc_dir}/empty.off ${q}" REGEX "empty.off")
pc_test(missing_file 2 "${pc_dir}/cube.off ${pc_dir}/no_such_mesh.off ${q}" REGEX "no_such_mesh")
pc_test(bad_expect 2 "${pc_dir}/cube.off ${pc_dir}/around.off --expect sideways")
pc_test(no_arguments 2 "")
pc_test(one_mesh_is_not_a_scene 2 "${pc_dir}/cube.off" REGEX "scene")
pc_test(unwritable_json 3
  "${pc_dir}/cube.off ${pc_dir}/inner.off ${q} --json ${pc_dir}/cube.off/out.json"
  REGEX "out.json: cannot write output; .*cube.off' is not a folder")
# A missing folder is created (as for render-compare's --out).
pc_test(json_into_new_folder 0
  "${pc_dir}/cube.off ${pc_dir}/inner.off ${q} --json ${pc_dir}/new/folder/out.json"
  FILE ${pc_dir}/new/folder/out.json)
# --json - without --quiet: only JSON on stdout; it records the hash of the error segments.
proxyvis_app_test(app.proxy_check.json_stdout_only proxy-check 1
  "${pc_dir}/cube.off ${pc_dir}/inner.off --rays 20000 --seed 3 --expect outside --json - --dump-errors ${pc_dir}/stdout_errors.ply"
  CHECKS ${CMAKE_CURRENT_LIST_FILE} DEFS -DJSON_ONLY_STDOUT=1
  -DDUMP_FILE=${pc_dir}/stdout_errors.ply FILES ${pc_dir}/stdout_errors.ply TIMEOUT 60)
pc_test(dump_errors 0
  "${pc_dir}/cube.off ${pc_dir}/inner.off ${q} --dump-errors ${pc_dir}/errors.ply"
  FILE ${pc_dir}/errors.ply)

# Scene mode, scene distribution, a mesh placed only through instances: its segments are mapped
# into the instances' object space (camera hits on the floor to the light, past the cubes).
file(WRITE ${pc_dir}/floor.obj "v -5 -1 -5\nv 5 -1 -5\nv 5 -1 5\nv -5 -1 5\nf 1 3 2\nf 1 4 3\n")
file(WRITE ${pc_dir}/cubes.txt "cube 0 0 0\ncube 2 0 0.5\ncube -2 0 1\n")
file(WRITE ${pc_dir}/inst_scene.json [=[
{"camera": {"eye": [0.5, 8, 7], "look_at": [0.5, 0, 0.5], "fov_deg": 50, "resolution": [32, 32]},
 "lights": [{"type": "quad", "corner": [-1, 6, -1], "edge_u": [3, 0, 0], "edge_v": [0, 0, 3],
             "radiance": [5, 5, 5]}],
 "meshes": [{"name": "floor", "file": "floor.obj"},
            {"name": "cube", "file": "cube.off", "place": false,
             "proxies": [{"kind": "outside", "file": "around.off", "class": "outside"}]}],
 "instances": {"file": "cubes.txt"}}
]=])
pc_test(scene_instanced 0 "${pc_dir}/inst_scene.json --distribution scene ${q}"
  REGEX "scene distribution.*HH' +[1-9][0-9]* .*HM' +0 .*sampled class +outside.*exact +contains")
