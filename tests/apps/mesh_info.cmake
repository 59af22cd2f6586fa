# mesh-info end to end: exit codes, the one-line error on stderr, report text and JSON keys
# (support/run_app.cmake checks the exit code and that stdout+stderr match the regex).
if(CMAKE_SCRIPT_MODE_FILE)
  # --json -: stdout is the JSON and nothing else (the report text went to stderr).
  expect_only_json_on_stdout("[" "]" "triangles")
  return()
endif()

function(mesh_info_test name code regex)
  string(JOIN " " args ${ARGN})
  proxyvis_app_test(app_mesh_info_${name} mesh-info ${code} "${args}" REGEX "${regex}")
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
# Four collinear points closed up like a tetrahedron: every triangle has zero area.
set(collinear ${CMAKE_CURRENT_BINARY_DIR}/collinear_tetrahedron.off)
file(WRITE ${collinear} "OFF\n4 4 0\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
mesh_info_test(collinear_degenerate 0 "triangles +4\n.*degenerate triangles +4\n" ${collinear})
# --expect-sha256 with the right hash (either case) loads; --save leaves a sha256sum sidecar.
file(SHA256 ${collinear} collinear_sha256)
string(TOUPPER ${collinear_sha256} collinear_sha256_upper)
mesh_info_test(expect_sha256_match 0 "triangles +4" --expect-sha256 ${collinear_sha256_upper}
  ${collinear})
proxyvis_app_test(app_mesh_info_save_writes_sidecar mesh-info 0
  "--quiet --save ${CMAKE_CURRENT_BINARY_DIR}/saved_bunny.ply ${d}/bunny.off"
  FILES ${CMAKE_CURRENT_BINARY_DIR}/saved_bunny.ply ${CMAKE_CURRENT_BINARY_DIR}/saved_bunny.ply.sha256)
proxyvis_app_test(app_mesh_info_json_stdout_only mesh-info 0
  "--json - ${d}/bunny.off" CHECKS ${CMAKE_CURRENT_LIST_FILE})
# The converted mesh and the JSON describing it (with its hash), into folders that do not exist
# yet (created).
set(mi_dir ${CMAKE_CURRENT_BINARY_DIR}/mesh_info)
proxyvis_app_test(app_mesh_info_save_with_json mesh-info 0
  "${d}/bunny.off --quiet --save ${mi_dir}/new/bunny.ply --json ${mi_dir}/new/deeper/bunny.json"
  CLEAN ${mi_dir} FILES ${mi_dir}/new/bunny.ply ${mi_dir}/new/deeper/bunny.json
  REGEX "^$")
