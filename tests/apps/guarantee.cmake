# A class proxy-gen writes holds for the INPUT mesh, and proxy-check agrees with it:
#  - camelhead (an open cut) with --kind inside --fill-holes: written as class general with
#    class_reason and a note on stderr (exit 0); proxy-check --expect general passes while its
#    MH' count shows why inside would be wrong (--expect inside fails); scene mode records
#    "class": "general" in scene.json;
#  - cow (watertight, one edge with four faces): inside wrap and erode are class inside,
#    proxy-check --expect inside exits 0 with no MH' and exact "contained"; outside has a volume
#    ratio;
#  - two boxes sharing an edge: inside is class inside; a theta surface (odd edges) is refused
#    with advice that works.
# In script mode (APP_CHECKS) it checks that the file CLASS_FILE matches CLASS_REGEX.
if(CMAKE_SCRIPT_MODE_FILE)
  if(CLASS_FILE)
    file(READ "${CLASS_FILE}" text)
    if(NOT text MATCHES "${CLASS_REGEX}")
      message(FATAL_ERROR "${CLASS_FILE} does not match '${CLASS_REGEX}':\n${text}")
    endif()
  endif()
  return()
endif()


proxyvis_app_test_dir(gt_dir guarantee)
set(gt_hard ${CMAKE_SOURCE_DIR}/data/hard)

# gt_test(NAME TARGET CODE ARGS [REGEX r] [FILE f] [NO_FILE f] [SETUP fixture] [REQUIRES fixture]
#         [CLASS_FILE f CLASS_REGEX r])
function(gt_test name target code args)
  cmake_parse_arguments(T "" "REGEX;FILE;NO_FILE;SETUP;REQUIRES;CLASS_FILE;CLASS_REGEX" "" ${ARGN})
  set(checks "")
  if(T_CLASS_FILE)
    set(checks CHECKS ${CMAKE_CURRENT_FUNCTION_LIST_FILE} DEFS "-DCLASS_FILE=${T_CLASS_FILE}"
      "-DCLASS_REGEX=${T_CLASS_REGEX}")
  endif()
  proxyvis_app_test(guarantee_app.${name} ${target} ${code} "${args}" REGEX "${T_REGEX}"
    FILES ${T_FILE} NO_FILES ${T_NO_FILE} TIMEOUT 300 ${checks})
  if(T_SETUP)
    set_tests_properties(guarantee_app.${name} PROPERTIES FIXTURES_SETUP ${T_SETUP})
  endif()
  if(T_REQUIRES)
    set_tests_properties(guarantee_app.${name} PROPERTIES FIXTURES_REQUIRED ${T_REQUIRES})
  endif()
endfunction()

# camelhead: inside the hole-filled mesh, but not an inside proxy of the input.
gt_test(camelhead_fill_holes proxy-gen 0
  "${gt_hard}/camelhead.off --kind inside --fill-holes -o ${gt_dir}/camel.ply --json -"
  REGEX "\"class\": \"general\".*\"class_reason\": \"the input has 56 boundary edges.*proxy-gen: note: [^\n]*camelhead.off: written as class general, not inside"
  FILE ${gt_dir}/camel.ply SETUP guarantee_camel)
gt_test(camelhead_check_general proxy-check 0
  "${gt_hard}/camelhead.off ${gt_dir}/camel.ply --expect general --rays 200000 --seed 1"
  REGEX "MH' +[1-9][0-9]* .*expected +general: consistent" REQUIRES guarantee_camel)
gt_test(camelhead_check_inside_fails proxy-check 1
  "${gt_hard}/camelhead.off ${gt_dir}/camel.ply --expect inside --rays 200000 --seed 1"
  REGEX "expected +inside: CONTRADICTED \\([1-9][0-9]* MH' segments" REQUIRES guarantee_camel)

# Scene mode: scene.json records the class written, general.
file(WRITE ${gt_dir}/scene/scene.json "{\"camera\": {\"eye\": [0, 0, 3], \"look_at\": [0, 0, 0]}, \"lights\": [{\"type\": \"quad\", \"corner\": [-1, 2, -1], \"edge_u\": [2, 0, 0], \"edge_v\": [0, 0, 2], \"radiance\": [5, 5, 5]}], \"meshes\": [{\"name\": \"camel\", \"file\": \"${gt_hard}/camelhead.off\"}]}\n")
gt_test(camelhead_scene proxy-gen 0
  "${gt_dir}/scene/scene.json --kind inside --fill-holes --out-dir ${gt_dir}/scene/out -q"
  REGEX "proxy-gen: note: [^\n]*camelhead.off: written as class general"
  FILE ${gt_dir}/scene/out/scene.json
  CLASS_FILE ${gt_dir}/scene/out/scene.json CLASS_REGEX "\"kind\": \"inside\"[^}]*\"class\": \"general\"|\"class\": \"general\"[^}]*\"kind\": \"inside\"")

# cow: watertight with one edge of four faces: an inside proxy by ray parity.
foreach(method wrap erode)
  gt_test(cow_inside_${method} proxy-gen 0
    "${gt_hard}/cow.off --kind inside --method ${method} -o ${gt_dir}/cow.${method}.ply --json -"
    REGEX "\"containment\": \"contained\".*\"class\": \"inside\".*\"volume_ratio\": 0\\.[0-9]"
    FILE ${gt_dir}/cow.${method}.ply SETUP guarantee_cow_${method})
  gt_test(cow_check_inside_${method} proxy-check 0
    "${gt_hard}/cow.off ${gt_dir}/cow.${method}.ply --expect inside --rays 500000"
    REGEX "MH' +0 .*exact +contained .*expected +inside: consistent"
    REQUIRES guarantee_cow_${method})
endforeach()
gt_test(cow_outside proxy-gen 0 "${gt_hard}/cow.off --kind outside -o ${gt_dir}/cow.outside.ply"
  REGEX "watertight, non-manifold.*volume ratio: 1\\.[0-9]+.*verified: +yes"
  FILE ${gt_dir}/cow.outside.ply)

# Two unit boxes sharing one edge (the second box's corners at +1 in x and y).
set(gt_boxes "OFF\n16 24 0\n")
foreach(shift 0 1)
  foreach(i RANGE 7)
    math(EXPR x "(${i} & 1) + ${shift}")
    math(EXPR y "((${i} >> 1) & 1) + ${shift}")
    math(EXPR z "(${i} >> 2) & 1")
    string(APPEND gt_boxes "${x} ${y} ${z}\n")
  endforeach()
endforeach()
foreach(base 0 8)
  foreach(t "0 2 3" "0 3 1" "4 5 7" "4 7 6" "0 1 5" "0 5 4" "2 6 7" "2 7 3" "0 4 6" "0 6 2"
            "1 3 7" "1 7 5")
    separate_arguments(t)
    set(line "3")
    foreach(v ${t})
      math(EXPR v "${v} + ${base}")
      string(APPEND line " ${v}")
    endforeach()
    string(APPEND gt_boxes "${line}\n")
  endforeach()
endforeach()
file(WRITE ${gt_dir}/two_boxes.off "${gt_boxes}")
gt_test(two_boxes_inside proxy-gen 0
  "${gt_dir}/two_boxes.off --kind inside --max-faces 100000 -o ${gt_dir}/two_boxes.inside.ply"
  REGEX "watertight, non-manifold.*verified: +yes \\(exact containment check: [^\n]*the proxy lies inside the original"
  FILE ${gt_dir}/two_boxes.inside.ply)

# Three fans over one triangle loop: odd edges, no inside; the advice names what works.
file(WRITE ${gt_dir}/theta.off "OFF\n6 9 0\n0 0 0\n1 0 0\n0 1 0\n0.3 0.3 -1\n0.3 0.3 0.5\n0.3 0.3 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n3 0 1 4\n3 1 2 4\n3 2 0 4\n3 0 1 5\n3 1 2 5\n3 2 0 5\n")
gt_test(theta_inside_refused proxy-gen 2 "${gt_dir}/theta.off --kind inside -o ${gt_dir}/theta.inside.ply"
  REGEX "3 edges with an odd number .*--kind outside or --kind general"
  NO_FILE ${gt_dir}/theta.inside.ply)
gt_test(theta_outside_works proxy-gen 0 "${gt_dir}/theta.off --kind outside -o ${gt_dir}/theta.outside.ply"
  REGEX "verified: +yes" FILE ${gt_dir}/theta.outside.ply)
