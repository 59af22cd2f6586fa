# proxy-gen on geometry that loads but that the generators cannot handle (corpus_generators.py),
# on sizes beyond their range, and with outputs that would replace inputs. Before the checks
# these crashed (SIGSEGV, SIGFPE in GMP, OpenMesh assertion), spun for minutes or grew memory
# without end, or overwrote the input.

# Every kind/method on every degenerate or extreme mesh: exit 2, one error line naming the mesh.
set(gen_methods "outside hull" "outside wrap" "inside wrap" "inside erode" "general qem"
  "general cgal-sms" "general meshopt")
set(gen_meshes gen_collinear_tetra gen_same_points gen_coords_3e38 gen_bunny_scaled_1e20
  gen_bunny_shifted_1e20 gen_bunny_y_1.7e38)
foreach(mesh ${gen_meshes})
  foreach(km ${gen_methods})
    separate_arguments(km)
    list(GET km 0 kind)
    list(GET km 1 method)
    string(REPLACE "." "_" case ${mesh})
    bad_input_test(${case}_${kind}_${method} proxy-gen
      "@CORPUS@/${mesh}.off --kind ${kind} --method ${method} -o @OUT@/p.ply --json @OUT@/p.json"
      INPUTS @CORPUS@/${mesh}.off TIMEOUT 30)
  endforeach()
endforeach()

# Sizes and budgets out of range are refused by the parser, with the range in the message.
bad_input_test(gen_offset_too_large proxy-gen "@DATA@/bunny.off --offset 10 -o @OUT@/p.ply"
  REGEX "--offset: must be in \\[0.0001, 1\\], got 10" TIMEOUT 20)
bad_input_test(gen_offset_huge proxy-gen "@DATA@/bunny.off --offset 1e9 -o @OUT@/p.ply"
  REGEX "--offset: must be in" TIMEOUT 20)
bad_input_test(gen_alpha_too_small proxy-gen "@DATA@/bunny.off --alpha 0.0005 -o @OUT@/p.ply"
  REGEX "--alpha: must be in \\[0.001, 1\\], got 0.0005" TIMEOUT 20)
bad_input_test(gen_max_faces_negative proxy-gen "@DATA@/bunny.off --max-faces -1 -o @OUT@/p.ply"
  REGEX "--max-faces.*got '-1'" TIMEOUT 20)
bad_input_test(gen_max_faces_huge proxy-gen
  "@DATA@/bunny.off --max-faces 99999999999999999999 -o @OUT@/p.ply" REGEX "--max-faces: must be in"
  TIMEOUT 20)
bad_input_test(gen_ratio_zero proxy-gen "@DATA@/bunny.off --kind general --ratio 0 -o @OUT@/p.ply"
  REGEX "--ratio: must be in" TIMEOUT 20)
bad_input_test(gen_erosion_too_large proxy-gen
  "@DATA@/bunny.off --kind inside --method erode --erosion 2 -o @OUT@/p.ply"
  REGEX "--erosion: must be in \\[0.001, 0.5\\]" TIMEOUT 20)
bad_input_test(gen_max_seconds_zero proxy-gen "@DATA@/bunny.off --max-seconds 0 -o @OUT@/p.ply"
  REGEX "--max-seconds: must be in" TIMEOUT 20)
bad_input_test(gen_unknown_kind proxy-gen "@DATA@/bunny.off --kind sideways -o @OUT@/p.ply"
  REGEX "--kind: sideways not in .outside,inside,general." TIMEOUT 20)
bad_input_test(gen_unknown_method proxy-gen "@DATA@/bunny.off --method simplest -o @OUT@/p.ply"
  REGEX "--method: simplest not in .*qem" TIMEOUT 20)

# A wrap too large to finish is refused before it starts (estimate), a running one is stopped by
# --max-seconds; neither leaves output.
bad_input_test(gen_wrap_estimate_too_large proxy-gen
  "@DATA@/bunny.off --alpha 0.001 --offset 1 -o @OUT@/p.ply"
  REGEX "bunny.off: the outside wrap with alpha 0.001 and offset 1 would have about" TIMEOUT 20)
bad_input_test(gen_wrap_stopped_by_max_seconds proxy-gen
  "@DATA@/dragon.drc --alpha 0.002 --max-seconds 1 -o @OUT@/p.ply --json @OUT@/p.json"
  REGEX "dragon.drc: stopped: the alpha wrap did not finish within 1 s" TIMEOUT 30)

# Outputs that are inputs are refused before any work; nothing is written, the input intact.
bad_input_test(gen_output_is_input proxy-gen
  "@CORPUS@/gen_scene_own_dir/tetra.off -o @CORPUS@/gen_scene_own_dir/tetra.off"
  INPUTS @CORPUS@/gen_scene_own_dir/tetra.off WATCH @CORPUS@/gen_scene_own_dir TIMEOUT 20)
bad_input_test(gen_json_is_input proxy-gen
  "@CORPUS@/gen_scene_own_dir/tetra.off -o @OUT@/p.ply --json @CORPUS@/gen_scene_own_dir/tetra.off"
  INPUTS @CORPUS@/gen_scene_own_dir/tetra.off WATCH @CORPUS@/gen_scene_own_dir TIMEOUT 20)
bad_input_test(gen_out_dir_is_scene_dir proxy-gen
  "@CORPUS@/gen_scene_own_dir/scene.json --out-dir @CORPUS@/gen_scene_own_dir"
  REGEX "gen_scene_own_dir/scene.json: --out-dir names the input"
  INPUTS @CORPUS@/gen_scene_own_dir/scene.json @CORPUS@/gen_scene_own_dir/tetra.off
  WATCH @CORPUS@/gen_scene_own_dir TIMEOUT 20)
