# mesh-info end to end: exit codes, the one-line error on stderr, report text and JSON keys.
#
# Included from tests/apps/CMakeLists.txt this registers the tests; run with `cmake -P` it is the
# driver of one test: runs EXE with ARGS, checks EXPECT_CODE and that stdout+stderr match
# OUTPUT_REGEX.
if(CMAKE_SCRIPT_MODE_FILE)
  separate_arguments(args NATIVE_COMMAND "${ARGS}")
  execute_process(COMMAND "${EXE}" ${args} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL EXPECT_CODE)
    message(FATAL_ERROR "exit code ${code}, expected ${EXPECT_CODE}\nstdout:\n${out}\nstderr:\n${err}")
  endif()
  if(NOT "${out}${err}" MATCHES "${OUTPUT_REGEX}")
    message(FATAL_ERROR "output does not match '${OUTPUT_REGEX}'\nstdout:\n${out}\nstderr:\n${err}")
  endif()
  return()
endif()

if(NOT TARGET mesh-info)
  return()
endif()
function(mesh_info_test name code regex)
  string(JOIN " " args ${ARGN})
  add_test(NAME app_mesh_info_${name}
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:mesh-info> "-DARGS=${args}"
      -DEXPECT_CODE=${code} "-DOUTPUT_REGEX=${regex}" -P ${CMAKE_CURRENT_LIST_FILE})
endfunction()
set(d ${PROXYVIS_DATA_DIR})
mesh_info_test(closed_genus 0 "triangles +6966.*closed +yes.*genus +0" ${d}/bunny.off)
mesh_info_test(dragon_genus 0 "triangles +100000.*genus +1" ${d}/dragon.drc)
mesh_info_test(open_teapot 0 "boundary edges +160.*non-manifold vertices +1.*closed +no" ${d}/teapot.obj)
mesh_info_test(self_intersections 0 "self-intersecting pairs +0" --self-intersections ${d}/bunny.off)
mesh_info_test(json_stdout 0 "\"genus\": 0.*\"volume\"" --json - --quiet ${d}/spot_triangulated.obj)
mesh_info_test(missing_file 2 "^[^\n]*mesh-info: error: [^\n]*nope\\.ply: file not found[^\n]*\n$" ${d}/nope.ply)
mesh_info_test(unknown_extension 2 "README\\.md: unknown mesh file extension" ${d}/README.md)
mesh_info_test(no_arguments 2 "required")
