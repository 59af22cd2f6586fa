# render end to end: the image and its metadata (read back with OpenImageIO's iinfo), the JSON
# summary (only JSON on stdout with --json -), the same image at any thread count, PNG output and
# time budgets. Bad input and flags are in tests/bad_inputs/cases_render.cmake.
#
# Included from tests/apps/CMakeLists.txt this writes a small scene (the bunny on a ground quad,
# with a box around the bunny as its proxy: fewer triangles than the bunny, so estimators use it)
# and registers the tests; in script mode support/run_app.cmake includes it for RENDER_CHECK.
if(CMAKE_SCRIPT_MODE_FILE)
  if(RENDER_CHECK STREQUAL "json")
    expect_only_json_on_stdout("{" "}" "render: wrote")
    expect_json_keys("summary" "${json}" spp seconds rays estimator seed scene_name build version)
    string(JSON spp GET "${json}" spp)
    string(JSON estimator GET "${json}" estimator)
    if(NOT spp EQUAL 3 OR NOT estimator STREQUAL "paper-optimal")
      message(FATAL_ERROR "summary: spp ${spp}, estimator ${estimator}\n${json}")
    endif()
  elseif(RENDER_CHECK STREQUAL "metadata")
    find_program(IINFO iinfo REQUIRED)
    execute_process(COMMAND ${IINFO} -v ${RENDER_DIR}/meta.exr OUTPUT_VARIABLE info)
    foreach(expected "channel list: R, G, B, rays\\.original, rays\\.probe, rays\\.proxy, visibility\\.Y"
        "proxyvis:estimator: \"roulette\"" "proxyvis:spp: 5\n" "proxyvis:seed: \"77\""
        "proxyvis:scene: \"[^\"]*bunny_scene\\.json\"" "proxyvis:scene_name: \"bunny on a plane\""
        "proxyvis:camera: \"eye \\[0, 0\\.15, 0\\.5\\] look_at .* resolution 24x16\""
        "proxyvis:build: \"[^\"]+ [A-Za-z]+\"" "proxyvis:version: \"[0-9.]+\""
        "proxyvis:seconds: [0-9]" "Software: \"proxyvis [0-9.]+ render\"")
      if(NOT info MATCHES "${expected}")
        message(FATAL_ERROR "meta.exr: no '${expected}' in its metadata:\n${info}")
      endif()
    endforeach()
  elseif(RENDER_CHECK STREQUAL "threads")
    # Each estimator at 1 and 2 threads: the same pixels (idiff -fail 0) and the same ray counts.
    find_program(IDIFF idiff REQUIRED)
    foreach(estimator exact culling paper-optimal roulette)
      foreach(threads 1 2)
        execute_process(COMMAND ${EXE} ${RENDER_SCENE} -o ${RENDER_DIR}/${estimator}_${threads}.exr
          --estimator ${estimator} --spp 6 --seed 3 --threads ${threads} --quiet
          --roulette-costs 40,20,300,25,60 --json -
          RESULT_VARIABLE code OUTPUT_VARIABLE summary_${threads} ERROR_VARIABLE err)
        if(NOT code EQUAL 0)
          message(FATAL_ERROR "${estimator} at ${threads} threads: exit ${code}\n${err}")
        endif()
        string(JSON rays_${threads} GET "${summary_${threads}}" rays)
      endforeach()
      execute_process(COMMAND ${IDIFF} -fail 0 -failpercent 0 -warn 0
        ${RENDER_DIR}/${estimator}_1.exr ${RENDER_DIR}/${estimator}_2.exr
        RESULT_VARIABLE differ OUTPUT_VARIABLE diff_text)
      if(NOT differ EQUAL 0 OR NOT rays_1 STREQUAL rays_2)
        message(FATAL_ERROR "${estimator}: 1 and 2 threads differ\n${diff_text}\n${rays_1}\n${rays_2}")
      endif()
    endforeach()
  endif()
  return()
endif()

proxyvis_app_test_dir(render_dir render)
# A box around the bunny (its bounding box grown by a margin): an outside proxy of 12 triangles.
proxyvis_write_box_off(${render_dir}/bunny_box.off -0.1 0.19)
set(render_scene_text [=[
{
  "name": "bunny on a plane",
  "camera": {"eye": [0, 0.15, 0.5], "look_at": [0, 0.1, 0], "fov_deg": 40, "resolution": [24, 16]},
  "lights": [{"type": "quad", "corner": [-0.2, 0.6, -0.2], "edge_u": [0.4, 0, 0],
              "edge_v": [0, 0, 0.4], "radiance": [8, 8, 8]}],
  "meshes": [
    {"name": "ground", "file": "@GROUND@", "transform": {"translate": [0, 0.033, 0], "scale": 2}},
    {"name": "bunny", "file": "@BUNNY@",
     "proxies": [{"kind": "outside", "method": "box", "file": "bunny_box.off"}]}
  ]
}
]=])
string(REPLACE "@GROUND@" "${PROXYVIS_SCENES_DIR}/meshes/ground.obj" render_scene_text
  "${render_scene_text}")
string(REPLACE "@BUNNY@" "${PROXYVIS_DATA_DIR}/bunny.off" render_scene_text "${render_scene_text}")
set(render_scene ${render_dir}/bunny_scene.json)
file(WRITE ${render_scene} "${render_scene_text}")

# render_test(NAME CODE "ARGS" [REGEX r] [FILES paths...] [NO_FILES paths...] [CHECK what])
function(render_test name code args)
  cmake_parse_arguments(T "" "REGEX;CHECK" "FILES;NO_FILES" ${ARGN})
  set(checks "")
  if(T_CHECK)
    set(checks CHECKS ${CMAKE_CURRENT_FUNCTION_LIST_FILE} DEFS -DRENDER_CHECK=${T_CHECK}
      -DRENDER_DIR=${render_dir} -DRENDER_SCENE=${render_scene})
  endif()
  proxyvis_app_test(app.render.${name} render ${code} "${args}" REGEX "${T_REGEX}"
    FILES ${T_FILES} NO_FILES ${T_NO_FILES} TIMEOUT 120 ${checks})
endfunction()

# An EXR into a folder that does not exist yet, with the summary beside it.
render_test(exr_and_json 0
  "${render_scene} -o ${render_dir}/new/folder/image.exr --spp 4 --json ${render_dir}/new/image.json --quiet"
  REGEX "render: wrote .*image\\.exr: exact, 4 spp"
  FILES ${render_dir}/new/folder/image.exr ${render_dir}/new/image.json)
render_test(metadata 0
  "${render_scene} -o ${render_dir}/meta.exr --estimator roulette --spp 5 --seed 77 --quiet"
  FILES ${render_dir}/meta.exr CHECK metadata)
render_test(json_stdout_only 0
  "${render_scene} -o ${render_dir}/json.png --estimator paper-optimal --spp 3 --json -"
  FILES ${render_dir}/json.png CHECK json)
render_test(same_image_any_thread_count 0
  "${render_scene} -o ${render_dir}/warmup.exr --spp 1 --quiet" CHECK threads)
# A time budget: as many samples as fit, the progress bar's mode without a sample count.
render_test(time_budget 0
  "${render_scene} -o ${render_dir}/timed.png --estimator roulette --time 0.3 --quiet"
  REGEX "roulette, [0-9]+ spp in 0\\.[0-9]+ s" FILES ${render_dir}/timed.png)
# No proxy in the scene: a roulette render says it only traces the originals.
render_test(no_proxies_warning 0
  "${PROXYVIS_SCENES_DIR}/cornell-bunny.json -o ${render_dir}/plain.png --estimator roulette --spp 1 --width 8 --height 8"
  REGEX "render: warning: cornell-bunny\\.json: no mesh of this scene has a proxy")
