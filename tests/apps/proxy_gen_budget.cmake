# proxy-gen face budgets (docs/budgets.md): a budget asked for is met by a verified proxy or the
# run fails with exit code 1, one error line and no output; --budget soft writes anyway; general
# proxies of a soup of closed parts meet their ratio with nothing from OpenMesh on stderr; an
# input without a consistent volume fails at once with advice that fits the method.
#
# In script mode (run_app.cmake includes this file after its own checks): ONE_ERROR_LINE = stderr
# is exactly one line; MAX_FACES = stdout is the JSON report of a verified proxy of at most that
# many faces with budget_reached REACHED; QUIET_STDERR = stderr holds no third-party warning;
# NOT_IN_OUTPUT = a regex the output must not match.
if(CMAKE_SCRIPT_MODE_FILE)
  if(ONE_ERROR_LINE)
    string(STRIP "${err}" e)
    string(REGEX MATCHALL "\n" newlines "${e}")
    list(LENGTH newlines n)
    if(NOT n EQUAL 0 OR NOT e MATCHES "^proxy-gen: error: ")
      message(FATAL_ERROR "expected one error line on stderr, got:\n${err}")
    endif()
  endif()
  if(MAX_FACES)
    string(JSON faces GET "${out}" faces)
    string(JSON reached GET "${out}" budget_reached)
    string(JSON verified GET "${out}" verified)
    if(faces GREATER MAX_FACES OR NOT reached STREQUAL REACHED)
      message(FATAL_ERROR "faces ${faces} (budget ${MAX_FACES}), budget_reached ${reached}")
    endif()
    if(VERIFIED AND NOT verified)
      message(FATAL_ERROR "the proxy is not verified:\n${out}")
    endif()
  endif()
  if(QUIET_STDERR AND err MATCHES "PolyMeshT|Decimater|complex (vertex|edge)|cannot \\(yet\\)")
    message(FATAL_ERROR "a third-party warning reached stderr:\n${err}")
  endif()
  if(NOT_IN_OUTPUT AND "${out}${err}" MATCHES "${NOT_IN_OUTPUT}")
    message(FATAL_ERROR "the output matches '${NOT_IN_OUTPUT}':\n${out}${err}")
  endif()
  return()
endif()


proxyvis_app_test_dir(pb_dir proxy_gen_budget)
set(pb_bunny ${CMAKE_SOURCE_DIR}/data/bunny.off)

# pb_test(NAME CODE ARGS [REGEX r] [FILE f] [NO_FILE f] [DEFS -Dk=v...] [TIMEOUT s])
function(pb_test name code args)
  cmake_parse_arguments(T "" "REGEX;FILE;NO_FILE;TIMEOUT" "DEFS" ${ARGN})
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 120)
  endif()
  proxyvis_app_test(proxy_gen_budget.${name} proxy-gen ${code} "${args}" REGEX "${T_REGEX}"
    FILES ${T_FILE} NO_FILES ${T_NO_FILE} TIMEOUT ${T_TIMEOUT}
    CHECKS ${CMAKE_CURRENT_FUNCTION_LIST_FILE} DEFS ${T_DEFS})
endfunction()

# No closed surface has 3 faces: exit 1, one line saying what was reached and why, no file.
pb_test(outside_3_faces_fails 1
  "${pb_bunny} --kind outside --max-faces 3 -o ${pb_dir}/b3.ply --json ${pb_dir}/b3.json -q"
  REGEX "bunny.off: budget of 3 faces not met: the smallest verified outside proxy has 4 faces; a closed surface needs at least 4 \\(use --max-faces 4 or more, or --budget soft"
  NO_FILE "${pb_dir}/b3.ply;${pb_dir}/b3.json" DEFS -DONE_ERROR_LINE=ON)
# 4 and 12 faces are met (the wrap cannot be collapsed that far: a tetrahedron, a box or the
# hull take over), verified by the exact containment check.
pb_test(outside_4_faces_met 0 "${pb_bunny} --kind outside --max-faces 4 -o ${pb_dir}/b4.ply --json -"
  FILE ${pb_dir}/b4.ply DEFS -DMAX_FACES=4 -DREACHED=ON -DVERIFIED=ON)
pb_test(outside_12_faces_met 0
  "${pb_bunny} --kind outside --max-faces 12 -o ${pb_dir}/b12.ply --json -"
  FILE ${pb_dir}/b12.ply DEFS -DMAX_FACES=12 -DREACHED=ON -DVERIFIED=ON)
# --budget soft writes the smallest verified proxy and says the budget was not reached.
pb_test(outside_soft_budget_writes 0
  "${pb_bunny} --kind outside --method hull --max-faces 3 --budget soft -o ${pb_dir}/soft.ply --json -"
  FILE ${pb_dir}/soft.ply DEFS -DMAX_FACES=1000000 -DREACHED=OFF -DVERIFIED=ON)
# Flat inputs: the hull fallback cannot be built for them (skipped, not an error), CGAL's
# oriented box needs 4 points (a single triangle keeps the axes, nothing printed).
file(WRITE ${pb_dir}/quad.off "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n")
file(WRITE ${pb_dir}/tri.off "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
pb_test(flat_quad_4_faces_met 0 "${pb_dir}/quad.off --kind outside --max-faces 4 -o ${pb_dir}/quad4.ply --json -"
  FILE ${pb_dir}/quad4.ply DEFS -DMAX_FACES=4 -DREACHED=ON -DVERIFIED=ON)
pb_test(one_triangle_12_faces_quiet 0
  "${pb_dir}/tri.off --kind outside --max-faces 12 -o ${pb_dir}/tri12.ply --json -"
  FILE ${pb_dir}/tri12.ply DEFS -DMAX_FACES=12 -DREACHED=ON -DVERIFIED=ON -DQUIET_STDERR=ON)
pb_test(bad_budget_mode 2 "${pb_bunny} --budget maybe -o ${pb_dir}/bad.ply"
  REGEX "--budget: maybe not in" NO_FILE ${pb_dir}/bad.ply)
# Inside by erosion at 2 %: the voxel surface (40 k faces) collapses to the budget only with
# self-intersections, so a coarser grid takes over; the budget is met, or the run fails.
pb_test(inside_erode_2_percent 0
  "${pb_bunny} --kind inside --method erode --ratio 0.02 -o ${pb_dir}/erode.ply --json -"
  FILE ${pb_dir}/erode.ply DEFS -DMAX_FACES=139 -DREACHED=ON -DVERIFIED=ON TIMEOUT 600)

# A soup of 50 closed boxes (one pair sharing an edge: a non-manifold edge OpenMesh calls
# complex): qem cannot go below 4 faces per box, meshoptimizer meets 2 % (12 faces); nothing
# from OpenMesh reaches stderr.
set(pb_soup "")
set(pb_soup_faces "")
foreach(k RANGE 49)
  math(EXPR x "3 * ${k}")
  math(EXPR base "8 * ${k}")
  foreach(c RANGE 7)
    math(EXPR dx "${x} + (${c} & 1)")
    math(EXPR dy "(${c} >> 1) & 1")
    math(EXPR dz "(${c} >> 2) & 1")
    if(k EQUAL 49)  # the last box touches the first one along the edge x = 1, y = 1
      math(EXPR dx "1 + (${c} & 1)")
      math(EXPR dy "1 + ((${c} >> 1) & 1)")
    endif()
    string(APPEND pb_soup "${dx} ${dy} ${dz}\n")
  endforeach()
  foreach(t "0 2 3" "0 3 1" "4 5 7" "4 7 6" "0 1 5" "0 5 4" "2 6 7" "2 7 3" "0 4 6" "0 6 2"
            "1 3 7" "1 7 5")
    separate_arguments(t)
    list(TRANSFORM t PREPEND "${base}+")
    set(ids "")
    foreach(e ${t})
      math(EXPR i "${e}")
      string(APPEND ids " ${i}")
    endforeach()
    string(APPEND pb_soup_faces "3${ids}\n")
  endforeach()
endforeach()
file(WRITE ${pb_dir}/soup.off "OFF\n400 600 0\n${pb_soup}${pb_soup_faces}")
pb_test(general_soup_meets_ratio 0
  "${pb_dir}/soup.off --kind general --ratio 0.02 -o ${pb_dir}/soup.qem.ply --json -"
  FILE ${pb_dir}/soup.qem.ply DEFS -DMAX_FACES=12 -DREACHED=ON -DQUIET_STDERR=ON)

# A tetrahedron with a fin on one edge (a non-manifold edge, two boundary edges): eroded after
# filling its hole it is written as class general (a ray through the hole could reach it), in
# seconds, not after half a minute of collapses, and nothing on the terminal names a wrap flag.
file(WRITE ${pb_dir}/tet_fin.off "OFF\n5 5 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 0.5\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 1 4 2\n")
pb_test(erode_non_manifold_fin_is_general 0
  "${pb_dir}/tet_fin.off --kind inside --method erode --fill-holes -o ${pb_dir}/fin.ply"
  REGEX "class: +general" FILE ${pb_dir}/fin.ply DEFS "-DNOT_IN_OUTPUT=--alpha|--offset" TIMEOUT 120)
# A surface with no inside (three sheets on one loop: odd edges) is refused at once for erode,
# with advice that names no wrap flag.
file(WRITE ${pb_dir}/theta.off "OFF\n6 9 0\n0 0 0\n1 0 0\n0 1 0\n0.3 0.3 -1\n0.3 0.3 0.5\n0.3 0.3 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n3 0 1 4\n3 1 2 4\n3 2 0 4\n3 0 1 5\n3 1 2 5\n3 2 0 5\n")
pb_test(erode_no_interior_fails_fast 2
  "${pb_dir}/theta.off --kind inside --method erode -o ${pb_dir}/theta.ply"
  REGEX "theta.off: 3 edges with an odd number" NO_FILE ${pb_dir}/theta.ply
  DEFS -DONE_ERROR_LINE=ON "-DNOT_IN_OUTPUT=--alpha|--offset" TIMEOUT 20)

# Scene mode: every mesh that misses a hard budget fails on its own line, scene.json is still
# written, the exit code is 1.
file(WRITE ${pb_dir}/scene/scene.json "{\"camera\": {\"eye\": [0, 0, 3], \"look_at\": [0, 0, 0]}, \"lights\": [{\"type\": \"quad\", \"corner\": [-1, 2, -1], \"edge_u\": [2, 0, 0], \"edge_v\": [0, 0, 2], \"radiance\": [5, 5, 5]}], \"meshes\": [{\"name\": \"fin\", \"file\": \"${pb_dir}/tet_fin.off\"}, {\"name\": \"soup\", \"file\": \"${pb_dir}/soup.off\"}]}\n")
pb_test(scene_budget_fails_per_mesh 1
  "${pb_dir}/scene/scene.json --kind outside --method hull --max-faces 3 --out-dir ${pb_dir}/scene/out -q"
  REGEX "proxy-gen: error: [^\n]*tet_fin.off: budget of 3 faces not met.*proxy-gen: error: [^\n]*soup.off: budget of 3 faces not met"
  FILE ${pb_dir}/scene/out/scene.json NO_FILE ${pb_dir}/scene/out/soup.outside.ply)
# One mesh fails (the theta surface has no inside: refused, exit 2), the other meets its 2 %
# budget and is written; the run's exit code is the failure's.
file(WRITE ${pb_dir}/scene2/scene.json "{\"camera\": {\"eye\": [0, 0, 3], \"look_at\": [0, 0, 0]}, \"lights\": [{\"type\": \"quad\", \"corner\": [-1, 2, -1], \"edge_u\": [2, 0, 0], \"edge_v\": [0, 0, 2], \"radiance\": [5, 5, 5]}], \"meshes\": [{\"name\": \"theta\", \"file\": \"${pb_dir}/theta.off\"}, {\"name\": \"bunny\", \"file\": \"${pb_bunny}\"}]}\n")
pb_test(scene_one_fails_others_go_on 2
  "${pb_dir}/scene2/scene.json --kind inside --method erode --fill-holes --ratio 0.02 --out-dir ${pb_dir}/scene2/out -q"
  REGEX "== theta: FAILED.*== bunny.*verified: +yes.*proxy-gen: error: [^\n]*theta.off: 3 edges with an odd number"
  FILE "${pb_dir}/scene2/out/scene.json;${pb_dir}/scene2/out/bunny.inside.ply"
  NO_FILE ${pb_dir}/scene2/out/theta.inside.ply TIMEOUT 300)
