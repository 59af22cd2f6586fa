# proxy-gen end to end: exit codes, messages, JSON keys and written files.
#
# Included from tests/apps/CMakeLists.txt this registers the tests; in script mode
# support/run_app.cmake includes it after its checks (exit code, OUTPUT_REGEX, EXPECT_FILE written
# or, for a failure, NO_FILE not) to check that stdout is JSON with the documented keys
# (JSON_KEYS, space-separated) and the expected "verified" value (JSON_VERIFIED).
if(CMAKE_SCRIPT_MODE_FILE)
  separate_arguments(keys UNIX_COMMAND "${JSON_KEYS}")
  expect_json_keys(stdout "${out}" ${keys})
  if(JSON_VERIFIED)
    string(JSON verified GET "${out}" verified)  # CMake reads JSON true as ON
    if(NOT verified STREQUAL JSON_VERIFIED)
      message(FATAL_ERROR "verified = ${verified}, expected ${JSON_VERIFIED}")
    endif()
  endif()
  return()
endif()


proxyvis_app_test_dir(pg_dir proxy_gen)
set(pg_data ${CMAKE_SOURCE_DIR}/data)  # bundled meshes: the tests need nothing outside the repository
set(pg_keys input kind method parameters faces volume_ratio hausdorff_proxy_to_original
  hausdorff_original_to_proxy verified seconds)

# pg_test(NAME CODE ARGS [REGEX r] [KEYS] [FILE f] [NO_FILE f] [VERIFIED v])
function(pg_test name code args)
  cmake_parse_arguments(T "KEYS" "REGEX;FILE;NO_FILE;VERIFIED" "" ${ARGN})
  set(checks "")
  if(T_KEYS)
    string(JOIN " " keys ${pg_keys})
    set(checks CHECKS ${CMAKE_CURRENT_FUNCTION_LIST_FILE} DEFS "-DJSON_KEYS=${keys}"
      "-DJSON_VERIFIED=${T_VERIFIED}")
  endif()
  proxyvis_app_test(proxy_gen_app.${name} proxy-gen ${code} "${args}" REGEX "${T_REGEX}"
    FILES ${T_FILE} NO_FILES ${T_NO_FILE} TIMEOUT 120 ${checks})
endfunction()

pg_test(outside_wrap_budget 0
  "${pg_data}/bunny.off --kind outside --max-faces 300 -o ${pg_dir}/bunny.outside.ply --json - -q"
  KEYS VERIFIED ON FILE ${pg_dir}/bunny.outside.ply)
pg_test(outside_hull 0 "${pg_data}/bunny.off --kind outside --method hull -o ${pg_dir}/bunny.hull.obj"
  REGEX "verified: +yes" FILE ${pg_dir}/bunny.hull.obj)
pg_test(general_meshopt 0
  "${pg_data}/spot_triangulated.obj --kind general --method meshopt --ratio 0.1 -o ${pg_dir}/spot.general.ply --json -"
  KEYS FILE ${pg_dir}/spot.general.ply)
pg_test(inside_open_input 2 "${pg_data}/bun_zipper.ply --kind inside -o ${pg_dir}/zipper.inside.ply"
  REGEX "223 boundary edges.*--fill-holes" NO_FILE ${pg_dir}/zipper.inside.ply)
pg_test(missing_input 2 "${pg_dir}/no_such_mesh.ply --kind outside -o ${pg_dir}/none.ply"
  NO_FILE ${pg_dir}/none.ply)
pg_test(unknown_method 2 "${pg_data}/bunny.off --kind inside --method hull -o ${pg_dir}/bad.ply"
  REGEX "unknown method" NO_FILE ${pg_dir}/bad.ply)
pg_test(bad_kind 2 "${pg_data}/bunny.off --kind sideways -o ${pg_dir}/bad2.ply" REGEX "kind")
# Scene mode: one proxy per mesh (open walls and the closed bunny), in parallel, plus the scene.
# The walls (2 and 6 faces) get no proxy: none could have fewer faces than they do.
pg_test(scene_outside 0
  "${CMAKE_SOURCE_DIR}/scenes/cornell-bunny.json --kind outside --out-dir ${pg_dir}/cornell -q --threads 2"
  REGEX "red: no proxy \\(2 faces.*== bunny.*verified: +yes.*scene with proxies"
  FILE ${pg_dir}/cornell/scene.json)
# --ratio is a relative face budget for an outside proxy too (5 % of the bunny's 6966 faces).
pg_test(outside_ratio_budget 0
  "${pg_data}/bunny.off --kind outside --ratio 0.05 -o ${pg_dir}/bunny.ratio.ply"
  REGEX "budget: +348 faces \\(--ratio times the input's 6966\\), reached.*verified: +yes" FILE ${pg_dir}/bunny.ratio.ply)
# Usage errors are one line naming the program, the flag and the rule.
pg_test(negative_alpha 2 "${pg_data}/bunny.off --kind outside --alpha -1 -o ${pg_dir}/neg.ply"
  REGEX "proxy-gen: error: --alpha: must be in \\[0.001, 1\\], got -1" NO_FILE ${pg_dir}/neg.ply)

# Scene mode with one mesh no generator can handle (coordinates near the float limit) beside a
# good one: the bad mesh fails with its error on stderr, the good one gets its proxy, scene.json
# is still written, and the exit code says that something failed.
set(pg_tetra_faces "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
file(WRITE ${pg_dir}/extreme/huge.off
  "OFF\n4 4 0\n3e38 3e38 3e38\n-3e38 -3e38 3e38\n-3e38 3e38 -3e38\n3e38 -3e38 -3e38\n${pg_tetra_faces}")
set(pg_scene_head "{\"camera\": {\"eye\": [0, 0, 3], \"look_at\": [0, 0, 0]}, \"lights\": [{\"type\": \"quad\", \"corner\": [-1, 2, -1], \"edge_u\": [2, 0, 0], \"edge_v\": [0, 0, 2], \"radiance\": [5, 5, 5]}], \"meshes\": ")
file(WRITE ${pg_dir}/extreme/scene.json "${pg_scene_head}[{\"name\": \"huge\", \"file\": \"huge.off\"}, {\"name\": \"bunny\", \"file\": \"${pg_data}/bunny.off\"}]}\n")
pg_test(scene_one_mesh_fails 2
  "${pg_dir}/extreme/scene.json --kind outside --method hull --out-dir ${pg_dir}/extreme/out -q"
  REGEX "== huge: FAILED.*== bunny.*verified: +yes.*scene with proxies.*proxy-gen: error: [^\n]*huge.off: coordinates reach 3e\\+38"
  FILE "${pg_dir}/extreme/out/scene.json;${pg_dir}/extreme/out/bunny.outside.ply"
  NO_FILE ${pg_dir}/extreme/out/huge.outside.ply)
# A mesh name is not a path: "../../../x" becomes the file stem "_.._.._x" inside --out-dir.
file(WRITE ${pg_dir}/dotdot/scene.json "${pg_scene_head}[{\"name\": \"../../../x\", \"file\": \"${pg_data}/bunny.off\"}]}\n")
pg_test(scene_mesh_name_stays_in_out_dir 0
  "${pg_dir}/dotdot/scene.json --kind outside --method hull --out-dir ${pg_dir}/dotdot/p -q"
  FILE "${pg_dir}/dotdot/p/_.._.._x.outside.ply;${pg_dir}/dotdot/p/scene.json"
  NO_FILE ${CMAKE_CURRENT_BINARY_DIR}/x.outside.ply)

# The same proxy whatever the heap layout: CGAL's quickhull orders its output by address, which
# glibc's tcache setting changes (the two files differed before the hull was rebuilt in a
# canonical order).
add_test(NAME proxy_gen_app.hull_independent_of_heap_layout
  COMMAND sh -c "set -e
    args='${pg_data}/bunny.off --kind outside --method hull --max-faces 100 --threads 1 -q'
    $<TARGET_FILE:proxy-gen> $args -o ${pg_dir}/heap_a.ply
    GLIBC_TUNABLES=glibc.malloc.tcache_count=0 $<TARGET_FILE:proxy-gen> $args -o ${pg_dir}/heap_b.ply
    cmp ${pg_dir}/heap_a.ply ${pg_dir}/heap_b.ply")
