# The `render` program on bad input and bad flags: exit code 2 (3 for an output that cannot be
# written), one error line naming the file or flag, no image or JSON left, inputs intact.
# Corpus: corpus_render.py.
set(rs @CORPUS@/render_scene.json)
bad_input_test(render_missing_scene render "@CORPUS@/render_no_such.json -o @OUT@/x.exr"
  REGEX "render_no_such\\.json" OUTPUTS @OUT@/x.exr TIMEOUT 20)
bad_input_test(render_truncated_scene render "@CORPUS@/render_truncated.json -o @OUT@/x.exr"
  REGEX "render_truncated\\.json: invalid JSON" INPUTS @CORPUS@/render_truncated.json
  OUTPUTS @OUT@/x.exr TIMEOUT 20)
bad_input_test(render_garbage_mesh render "@CORPUS@/render_garbage_mesh.json -o @OUT@/x.exr --json @OUT@/x.json"
  REGEX "render_garbage\\.obj" INPUTS @CORPUS@/render_garbage_mesh.json @CORPUS@/render_garbage.obj
  OUTPUTS @OUT@/x.exr @OUT@/x.json TIMEOUT 20)
# Before any work: an image format render does not write, stdout as an image, the scene as output.
bad_input_test(render_tif_output render "${rs} -o @OUT@/x.tif" REGEX "x\\.tif: unsupported image format"
  INPUTS ${rs} OUTPUTS @OUT@/x.tif TIMEOUT 20)
bad_input_test(render_image_to_stdout render "${rs} -o -" REGEX "cannot be written to stdout"
  INPUTS ${rs} TIMEOUT 20)
bad_input_test(render_output_is_scene render "${rs} -o ${rs}" REGEX "names the input"
  INPUTS ${rs} TIMEOUT 20)
bad_input_test(render_output_under_a_file render "${rs} -o @CORPUS@/render_a_file/x.exr" CODE 3
  REGEX "x\\.exr: cannot write output" INPUTS ${rs} @CORPUS@/render_a_file TIMEOUT 20)
# Flags parsed strictly with their range.
bad_render_flags(render_spp_zero "--spp 0" "--spp: must be in" TIMEOUT 20)
bad_render_flags(render_spp_huge "--spp 99999999999" "--spp: must be in" TIMEOUT 20)
bad_render_flags(render_time_negative "--time -1" "--time" TIMEOUT 20)
bad_render_flags(render_spp_and_time "--spp 4 --time 1" "--spp excludes --time" TIMEOUT 20)
bad_render_flags(render_unknown_estimator "--estimator magic" "magic" TIMEOUT 20)
bad_render_flags(render_bad_roulette_costs "--roulette-costs 1,2,x" "--roulette-costs" TIMEOUT 20)
bad_render_flags(render_width_over_limit "--width 20000" "--width: must be in \\[1, 16384\\]" TIMEOUT 20)
