# The trust of a proxy's claimed class end to end: render-compare re-verifies a class whose
# recorded sha256 is missing or stale and downgrades a mislabelled proxy (warning + report), takes
# a matching hash as is; proxy-gen and proxy-check --write-scene record the hash.
#
# Included from tests/apps/CMakeLists.txt this writes the meshes and scenes and registers the
# tests; in script mode (run_app.cmake's APP_CHECKS) it checks the files named by TRUST_CHECK.
if(CMAKE_SCRIPT_MODE_FILE)
  # TRUST_REPORT: report.json whose only proxy must have class_status TRUST_STATUS and the scene
  # class TRUST_CLASS; report.md must say the status too.
  if(TRUST_REPORT)
    file(READ "${TRUST_REPORT}/report.json" json)
    string(JSON status GET "${json}" meta proxy_classes 0 class_status)
    string(JSON class GET "${json}" meta proxy_class)
    if(NOT status STREQUAL TRUST_STATUS OR NOT class STREQUAL TRUST_CLASS)
      message(FATAL_ERROR "class_status '${status}', class '${class}'; expected '${TRUST_STATUS}'"
        ", '${TRUST_CLASS}'\n${json}")
    endif()
    file(READ "${TRUST_REPORT}/report.md" md)
    if(NOT TRUST_STATUS STREQUAL "verified-by-hash" AND NOT md MATCHES "${TRUST_STATUS}")
      message(FATAL_ERROR "report.md does not say '${TRUST_STATUS}':\n${md}")
    endif()
    if(TRUST_STATUS STREQUAL "downgraded")
      string(REGEX MATCHALL "warning:[^\n]*downgraded" lines "${err}")
      list(LENGTH lines n)
      if(NOT n EQUAL 1)
        message(FATAL_ERROR "expected one downgrade warning on stderr, got ${n}:\n${err}")
      endif()
    elseif(err MATCHES "downgraded")
      message(FATAL_ERROR "unexpected downgrade:\n${err}")
    endif()
  endif()
  # TRUST_SCENE: a written scene whose proxy TRUST_PROXY_INDEX of mesh TRUST_MESH_INDEX must
  # claim TRUST_CLASS with the sha256 of TRUST_PROXY_FILE.
  if(TRUST_SCENE)
    file(READ "${TRUST_SCENE}" json)
    string(JSON class GET "${json}" meshes ${TRUST_MESH_INDEX} proxies 0 class)
    string(JSON hash GET "${json}" meshes ${TRUST_MESH_INDEX} proxies 0 sha256)
    file(SHA256 "${TRUST_PROXY_FILE}" expected)
    if(NOT class STREQUAL TRUST_CLASS OR NOT hash STREQUAL expected)
      message(FATAL_ERROR "class '${class}' sha256 ${hash}; expected '${TRUST_CLASS}' ${expected}"
        "\n${json}")
    endif()
  endif()
  return()
endif()


proxyvis_app_test_dir(tr_dir trust)
# The original: the box [-1, 1]^3 with a fan of 4 triangles per face (24 triangles), so a
# 12-triangle box proxy is cheaper and the renderer uses it.
file(WRITE ${tr_dir}/fanbox.off [=[OFF
14 24 0
-1 -1 -1
1 -1 -1
-1 1 -1
1 1 -1
-1 -1 1
1 -1 1
-1 1 1
1 1 1
0 0 -1
0 0 1
0 -1 0
0 1 0
-1 0 0
1 0 0
3 0 2 8
3 2 3 8
3 3 1 8
3 1 0 8
3 4 5 9
3 5 7 9
3 7 6 9
3 6 4 9
3 0 1 10
3 1 5 10
3 5 4 10
3 4 0 10
3 2 6 11
3 6 7 11
3 7 3 11
3 3 2 11
3 0 4 12
3 4 6 12
3 6 2 12
3 2 0 12
3 1 3 13
3 3 7 13
3 7 5 13
3 5 1 13
]=])
# The mislabelled proxy: the original shrunk by 50% (it lies inside, not outside).
proxyvis_write_box_off(${tr_dir}/shrunk.off -0.5 0.5)
# A true outside proxy, and a stale hash: that of an earlier version of the edited proxy.
proxyvis_write_box_off(${tr_dir}/outside.off -1.2 1.2)
file(SHA256 ${tr_dir}/outside.off tr_outside_hash)
proxyvis_write_box_off(${tr_dir}/edited.off -1.1 1.1)
file(SHA256 ${tr_dir}/edited.off tr_stale_hash)
proxyvis_write_box_off(${tr_dir}/edited.off -1.3 1.3)

# trust_scene(NAME PROXY HASH): a scene of the fan box on a ground quad under a quad light (far
# above every proxy, so the light check keeps the class) whose proxy PROXY claims "outside".
function(trust_scene name proxy hash)
  set(h "")
  if(hash)
    set(h ", \"sha256\": \"${hash}\"")
  endif()
  file(WRITE ${tr_dir}/${name}.json "{
  \"camera\": {\"eye\": [0, 4, 7], \"look_at\": [0, 0, 0], \"fov_deg\": 40, \"resolution\": [8, 8]},
  \"lights\": [{\"type\": \"quad\", \"corner\": [-1, 5, -1], \"edge_u\": [2, 0, 0],
              \"edge_v\": [0, 0, 2], \"radiance\": [8, 8, 8]}],
  \"meshes\": [
    {\"name\": \"ground\", \"file\": \"${PROXYVIS_SCENES_DIR}/meshes/ground.obj\",
     \"transform\": {\"translate\": [0, -1, 0], \"scale\": 10}},
    {\"name\": \"fanbox\", \"file\": \"fanbox.off\", \"transform\": {\"translate\": [0.2, 0, 0]},
     \"proxies\": [{\"kind\": \"outside\", \"file\": \"${proxy}\", \"class\": \"outside\"${h}}]}
  ]
}
")
endfunction()
trust_scene(mislabelled shrunk.off "")
trust_scene(edited edited.off ${tr_stale_hash})
trust_scene(hashed outside.off ${tr_outside_hash})
trust_scene(unhashed outside.off "")

set(tr_tiny "--width 8 --height 8 --spp 1 --equal-time 0 --seeds 1 --reference-spp 16 --estimators exact,culling,paper-equal")
function(trust_rc_test name scene status class)
  proxyvis_app_test(app.trust.${name} render-compare 0
    "${tr_dir}/${scene}.json --out ${tr_dir}/${name} ${tr_tiny}" CLEAN ${tr_dir}/${name}
    CHECKS ${CMAKE_CURRENT_LIST_FILE} TIMEOUT 120
    DEFS -DTRUST_REPORT=${tr_dir}/${name} -DTRUST_STATUS=${status} -DTRUST_CLASS=${class})
endfunction()
# A 50%-shrunk proxy labelled outside: one warning, the scene is rendered as general and the
# report says downgraded.
trust_rc_test(mislabelled_downgraded mislabelled downgraded general)
# A true outside proxy edited after its hash was recorded: proven again, the class stands.
trust_rc_test(edited_reverified edited re-verified outside)
# The hash matches: the fast path, no containment check.
trust_rc_test(hash_fast_path hashed verified-by-hash outside)

# proxy-check --write-scene records the proven class with the proxy's hash (paths relative to the
# new file); the mislabelled proxy is recorded as what it is (inside), with exit 1 for the
# contradicted claim.
proxyvis_app_test(app.trust.check_writes_hash proxy-check 0
  "${tr_dir}/unhashed.json --rays 2000 --write-scene ${tr_dir}/checked.json --quiet"
  FILES ${tr_dir}/checked.json CHECKS ${CMAKE_CURRENT_LIST_FILE}
  DEFS -DTRUST_SCENE=${tr_dir}/checked.json -DTRUST_MESH_INDEX=1 -DTRUST_CLASS=outside
       -DTRUST_PROXY_FILE=${tr_dir}/outside.off)
proxyvis_app_test(app.trust.check_records_true_class proxy-check 1
  "${tr_dir}/mislabelled.json --rays 2000 --write-scene ${tr_dir}/checked2.json --quiet"
  FILES ${tr_dir}/checked2.json CHECKS ${CMAKE_CURRENT_LIST_FILE}
  DEFS -DTRUST_SCENE=${tr_dir}/checked2.json -DTRUST_MESH_INDEX=1 -DTRUST_CLASS=inside
       -DTRUST_PROXY_FILE=${tr_dir}/shrunk.off)
proxyvis_app_test(app.trust.check_write_scene_needs_scene proxy-check 2
  "${tr_dir}/fanbox.off ${tr_dir}/outside.off --write-scene ${tr_dir}/x.json" REGEX "needs a scene"
  NO_FILES ${tr_dir}/x.json)
# proxy-gen's scene mode records the hash of each proxy whose class it verified (the hull of the
# fan box is a 12-triangle box, cheaper than the original; the ground quad gets none).
proxyvis_app_test(app.trust.gen_writes_hash proxy-gen 0
  "${tr_dir}/unhashed.json --kind outside --method hull --out-dir ${tr_dir}/gen --quiet"
  CLEAN ${tr_dir}/gen CHECKS ${CMAKE_CURRENT_LIST_FILE} TIMEOUT 120
  DEFS -DTRUST_SCENE=${tr_dir}/gen/scene.json -DTRUST_MESH_INDEX=1 -DTRUST_CLASS=outside
       -DTRUST_PROXY_FILE=${tr_dir}/gen/fanbox.outside.ply)
