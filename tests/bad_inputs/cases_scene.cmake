# Scene values out of the range the renderer's float arithmetic can take (scenes/FORMAT.md,
# "Value ranges"): render-compare and proxy-check refuse each at load with exit code 2 and one
# error line naming the scene file and the JSON path, and write nothing. Corpus: corpus_scene.py.

# scene_case(NAME SCENE REGEX): the scene through render-compare and proxy-check.
function(scene_case name scene regex)
  set(input @CORPUS@/${scene})
  bad_input_test(scene_${name}_render render-compare "${input} --out @OUT@/report --quiet"
    REGEX "${regex}" INPUTS ${input} @CORPUS@/scene_tri.obj OUTPUTS @OUT@/report)
  bad_input_test(scene_${name}_check proxy-check "${input} --json @OUT@/check.json --quiet"
    REGEX "${regex}" INPUTS ${input} @CORPUS@/scene_tri.obj OUTPUTS @OUT@/check.json)
endfunction()

# A light of radiance 1e38 rendered inf/NaN tables and exited 0.
scene_case(radiance_1e38 scene_radiance_1e38.json
  "scene_radiance_1e38.json: lights\\[0\\]\\.radiance: radiance 1e\\+38 out of range.*\\[0, 1e\\+06\\]")
# An eye at 1e30 was reported as "up is zero or parallel to the view direction".
scene_case(eye_1e30 scene_eye_1e30.json
  "scene_eye_1e30.json: camera\\.eye: eye coordinate 1e\\+30 out of range")
scene_case(eye_is_look_at scene_eye_is_look_at.json
  "scene_eye_is_look_at.json: camera: eye and look_at coincide")
scene_case(up_zero scene_up_zero.json "scene_up_zero.json: camera\\.up: length 0 out of range")
scene_case(up_parallel scene_up_parallel.json
  "scene_up_parallel.json: camera\\.up: up is parallel to the view direction")
scene_case(fov_179_9 scene_fov_179_9.json
  "scene_fov_179_9.json: camera\\.fov_deg: field of view 179\\.9 out of range")
scene_case(resolution_20000 scene_resolution_20000.json
  "scene_resolution_20000.json: camera\\.resolution: width and height must be in \\[1, 16384\\]")
scene_case(scale_1e30 scene_scale_1e30.json
  "scene_scale_1e30.json: meshes\\[0\\]\\.transform: transform scales by 1e\\+30")
scene_case(scale_1e-20 scene_scale_1e-20.json
  "scene_scale_1e-20.json: meshes\\[0\\]\\.transform: transform scales down by 1e\\+20")
scene_case(light_1e-8 scene_light_1e-8.json
  "scene_light_1e-8.json: lights\\[0\\]: light triangle of area .* \\(below 1e-12\\)")
scene_case(instances_1e7 scene_instances_1e7.json
  "scene_1e7\\.instances\\.txt:2: transform scales by 1e\\+07")
# The key is ESC [2J BEL: printed as \x1b[2J\x07 (the driver fails on any non-printable byte;
# '.' stands for the backslashes, which the driver's argument passing does not keep).
scene_case(escape_key scene_escape_key.json
  "scene_escape_key.json: camera..x1b.2J.x07: unknown key")

# --memory-budget (GiB for --build auto's flattened BVHs) is parsed strictly with its range: a
# negative, non-numeric or NaN budget is refused before any work, in both rendering programs.
bad_input_test(scene_memory_budget_negative render
  "@CORPUS@/scene_ok.json -o @OUT@/x.exr --memory-budget -1"
  REGEX "--memory-budget: must be in \\[0, 1048576\\], got -1" INPUTS @CORPUS@/scene_ok.json
  OUTPUTS @OUT@/x.exr TIMEOUT 20)
bad_input_test(scene_memory_budget_nan render-compare
  "@CORPUS@/scene_ok.json --out @OUT@/r --memory-budget nan"
  REGEX "--memory-budget: expected a number, got 'nan'" INPUTS @CORPUS@/scene_ok.json
  OUTPUTS @OUT@/r TIMEOUT 20)
