# proxy-gen end to end: exit codes, messages, JSON keys and written files.
#
# Included from tests/apps/CMakeLists.txt this registers the tests; run with `cmake -P` it is the
# driver of one test: it runs the program, checks the exit code, that stdout+stderr match
# OUTPUT_REGEX, that stdout (JSON_STDOUT) parses with the documented keys, and that
# EXPECT_FILE was (or, for a failure, NO_FILE was not) written.
if(CMAKE_SCRIPT_MODE_FILE)
  separate_arguments(args NATIVE_COMMAND "${ARGS}")
  foreach(f ${EXPECT_FILE} ${NO_FILE})
    file(REMOVE "${f}")
  endforeach()
  execute_process(COMMAND "${EXE}" ${args} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL EXPECT_CODE)
    message(FATAL_ERROR "exit code ${code}, expected ${EXPECT_CODE}\nstdout:\n${out}\nstderr:\n${err}")
  endif()
  if(OUTPUT_REGEX AND NOT "${out}${err}" MATCHES "${OUTPUT_REGEX}")
    message(FATAL_ERROR "output does not match '${OUTPUT_REGEX}'\nstdout:\n${out}\nstderr:\n${err}")
  endif()
  if(JSON_KEYS)
    foreach(key ${JSON_KEYS})
      string(JSON value ERROR_VARIABLE missing GET "${out}" ${key})
      if(missing)
        message(FATAL_ERROR "JSON key '${key}' missing: ${missing}\nstdout:\n${out}")
      endif()
    endforeach()
    if(JSON_VERIFIED)
      string(JSON verified GET "${out}" verified)  # CMake reads JSON true as ON
      if(NOT verified STREQUAL JSON_VERIFIED)
        message(FATAL_ERROR "verified = ${verified}, expected ${JSON_VERIFIED}")
      endif()
    endif()
  endif()
  if(EXPECT_FILE AND NOT EXISTS "${EXPECT_FILE}")
    message(FATAL_ERROR "${EXPECT_FILE} was not written")
  endif()
  if(NO_FILE AND EXISTS "${NO_FILE}")
    message(FATAL_ERROR "${NO_FILE} was written although the run failed")
  endif()
  return()
endif()

if(NOT TARGET proxy-gen)
  return()
endif()

set(pg_dir ${CMAKE_CURRENT_BINARY_DIR}/proxy_gen)
file(MAKE_DIRECTORY ${pg_dir})
set(pg_data ${CMAKE_SOURCE_DIR}/data/meshes)
if(NOT EXISTS ${pg_data}/bunny.off)
  set(pg_data ${CMAKE_SOURCE_DIR}/../shared/data/meshes)
endif()
set(pg_keys input kind method parameters faces volume_ratio hausdorff_proxy_to_original
  hausdorff_original_to_proxy verified seconds)

# pg_test(NAME CODE ARGS [REGEX r] [KEYS] [FILE f] [NO_FILE f] [VERIFIED v])
function(pg_test name code args)
  cmake_parse_arguments(T "KEYS" "REGEX;FILE;NO_FILE;VERIFIED" "" ${ARGN})
  set(keys "")
  if(T_KEYS)
    set(keys "${pg_keys}")
  endif()
  add_test(NAME proxy_gen_app.${name}
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:proxy-gen> "-DARGS=${args}" -DEXPECT_CODE=${code}
      "-DOUTPUT_REGEX=${T_REGEX}" "-DJSON_KEYS=${keys}" "-DEXPECT_FILE=${T_FILE}" "-DNO_FILE=${T_NO_FILE}"
      "-DJSON_VERIFIED=${T_VERIFIED}" -P ${CMAKE_CURRENT_LIST_FILE})
  set_tests_properties(proxy_gen_app.${name} PROPERTIES TIMEOUT 120)
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
pg_test(scene_outside 0
  "${CMAKE_SOURCE_DIR}/scenes/cornell-bunny.json --kind outside --out-dir ${pg_dir}/cornell -q --threads 2"
  REGEX "scene with proxies" FILE ${pg_dir}/cornell/scene.json)
