# render-compare's ceiling (docs/report.md): `ceiling` and `of_ceiling` on every JSON row with
# of_ceiling == efficiency / ceiling, the per-light table in meta.ceiling, the Markdown and HTML
# sections; a scene whose meshes use no proxy has ceiling 1 and says "No proxies".
if(CMAKE_SCRIPT_MODE_FILE)
  return()
endif()
find_package(Python3 REQUIRED COMPONENTS Interpreter)

proxyvis_app_test_dir(ceil_dir render_compare_ceiling)
# The bunny (6,966 faces, scaled by 10) with a 12-face box as its outside proxy, on a ground
# quad under a quad light above the box: a proxy that render-compare uses.
proxyvis_write_box_off(${ceil_dir}/bunny_box.off -0.1 0.2)
set(ceil_scene [=[
{
  "camera": {"eye": [0, 3, 6], "look_at": [0, 0.8, 0], "fov_deg": 40, "resolution": [24, 16]},
  "lights": [{"type": "quad", "corner": [-1, 4, -1], "edge_u": [2, 0, 0], "edge_v": [0, 0, 2],
              "radiance": [8, 8, 8]}],
  "meshes": [
    {"name": "ground", "file": "@SCENES@/meshes/ground.obj", "transform": {"scale": 10}},
    {"name": "bunny", "file": "@DATA@/bunny.off", "transform": {"scale": 10},
     "proxies": [{"kind": "outside", "method": "box", "file": "bunny_box.off",
                  "class": "outside"}]}
  ]
}
]=])
string(REPLACE "@SCENES@" "${PROXYVIS_SCENES_DIR}" ceil_scene "${ceil_scene}")
string(REPLACE "@DATA@" "${CMAKE_SOURCE_DIR}/data" ceil_scene "${ceil_scene}")
file(WRITE ${ceil_dir}/bunny.json "${ceil_scene}")

# ceil_test(NAME SCENE [checker flags...])
function(ceil_test name scene)
  add_test(NAME app.render_compare.ceiling_${name}
    COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/render_compare_ceiling.py
            --out ${ceil_dir}/${name} ${ARGN}
            -- $<TARGET_FILE:render-compare> ${scene} --out ${ceil_dir}/${name} --spp 1,2
            --equal-time 0.05 --seeds 2 --reference-spp 64 --quiet --json -)
  set_tests_properties(app.render_compare.ceiling_${name} PROPERTIES TIMEOUT 300)
endfunction()

ceil_test(with_proxy ${ceil_dir}/bunny.json)
# The bunny without its proxy.
string(REPLACE "\"proxies\": [{\"kind\": \"outside\", \"method\": \"box\", \"file\": \"bunny_box.off\",\n                  \"class\": \"outside\"}]" "\"proxies\": []" ceil_plain "${ceil_scene}")
file(WRITE ${ceil_dir}/bunny_plain.json "${ceil_plain}")
ceil_test(no_proxies ${ceil_dir}/bunny_plain.json --ceiling-one --explanation "No proxies")
