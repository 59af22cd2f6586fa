# Outputs: an output that is an input is refused before any work (exit 2) under every spelling
# (the same path, a symbolic link, a hard link, a detour through ..); devices are written in place
# (/dev/full: exit 3 "No space left on device"); an output that cannot be written fails at once
# (exit 3); numbers out of range and unknown names are usage errors (exit 2); a render whose
# radiance overflows fails naming the scene instead of printing inf tables.
set(io @CORPUS@/io)
set(pair "${io}/cube.off ${io}/around.off --rays 2000 --quiet")

# io_refused(NAME TARGET "ARGS" REGEX [bad_input_test options]): TARGET ARGS is refused (exit 2)
# with REGEX before any work, and writes nothing into the corpus's io folder.
function(io_refused name target args regex)
  bad_input_test(io_${name} ${target} "${args}" REGEX "${regex}" WATCH ${io} TIMEOUT 20 ${ARGN})
endfunction()

# Output equal to an input: -o under every spelling of the input's path (NAME:PATH in io/).
foreach(io_spelling "input:cube.off" "input_via_symlink:link_to_cube.off"
                    "input_via_hard_link:hard_cube.off" "input_via_dotdot:../io/./cube.off")
  string(REPLACE ":" ";" io_spelling ${io_spelling})
  list(GET io_spelling 0 io_name)
  list(GET io_spelling 1 io_path)
  get_filename_component(io_file ${io_path} NAME)
  io_refused(proxy_gen_output_is_${io_name} proxy-gen "${io}/cube.off -o ${io}/${io_path}"
    "${io_file}: -o names the input" INPUTS ${io}/cube.off ${io}/hard_cube.off)
endforeach()
io_refused(proxy_gen_json_is_input proxy-gen "${io}/cube.off -o @OUT@/p.ply --json ${io}/cube.off"
  "--json names the input" INPUTS ${io}/cube.off)
io_refused(mesh_info_json_is_input mesh-info "${io}/cube.off --json ${io}/link_to_cube.off"
  "--json names the input" INPUTS ${io}/cube.off)
io_refused(proxy_check_dump_errors_is_proxy proxy-check "${pair} --dump-errors ${io}/around.off"
  "--dump-errors names the input" INPUTS ${io}/around.off ${io}/cube.off)
io_refused(proxy_check_json_is_input proxy-check "${pair} --json ${io}/hard_cube.off"
  "--json names the input" INPUTS ${io}/cube.off)
io_refused(render_compare_json_is_scene render-compare
  "${io}/scene.json --out @OUT@/r --json ${io}/link_to_scene.json --quiet"
  "--json names the input" INPUTS ${io}/scene.json)
io_refused(render_compare_out_holds_scene render-compare "${io}/scene.json --out ${io} --quiet"
  "would contain the input" INPUTS ${io}/scene.json)
io_refused(render_compare_out_is_a_folder_of_other_files render-compare
  "${io}/scene.json --out @DATA@ --quiet"
  "holds other files" INPUTS ${io}/scene.json)
bad_input_test(io_two_outputs_one_file proxy-check "${pair} --json @OUT@/x --dump-errors @OUT@/x"
  REGEX "name the same output" TIMEOUT 20)

# A device behind a symbolic link is written in place: the link and /dev/null stay what they are.
bad_input_test(io_proxy_gen_output_to_dev_null_link proxy-gen
  "${io}/cube.off -o ${io}/null.ply --kind outside --method hull --quiet" CODE 0
  INPUTS ${io}/null.ply ${io}/cube.off WATCH ${io} TIMEOUT 60)
bad_input_test(io_mesh_info_json_to_dev_stdout mesh-info "${io}/cube.off --json /dev/stdout --quiet"
  CODE 0 INPUTS ${io}/cube.off WATCH ${io} TIMEOUT 20)

# Outputs that cannot be written: exit 3 before the work, with the system's reason.
bad_input_test(io_proxy_check_dump_errors_dev_full proxy-check "${pair} --dump-errors /dev/full"
  CODE 3 REGEX "/dev/full: cannot write output; No space left on device" WATCH ${io}
  TIMEOUT 30)
bad_input_test(io_mesh_info_json_dev_full mesh-info "${io}/cube.off --json /dev/full --quiet"
  CODE 3 REGEX "/dev/full: cannot write output; No space left on device" TIMEOUT 20)
bad_input_test(io_json_is_a_folder mesh-info "${io}/cube.off --json ${io}/a_folder --quiet"
  CODE 3 REGEX "a_folder: cannot write output; it is a folder" WATCH ${io} TIMEOUT 20)
bad_input_test(io_json_under_a_file proxy-gen "${io}/cube.off -o @OUT@/p.ply --json ${io}/a_file/r.json"
  CODE 3 REGEX "r.json: cannot write output; '.*a_file' is not a folder" WATCH ${io} TIMEOUT 20)
bad_input_test(io_render_compare_out_under_a_file render-compare
  "${io}/scene.json --out ${io}/a_file/r --quiet" CODE 3 REGEX "a_file" WATCH ${io} TIMEOUT 20)

# Numbers parsed strictly with their range; names checked against the allowed list.
bad_input_test(io_rays_max_uint64 proxy-check "${pair} --rays 18446744073709551615"
  REGEX "--rays: must be in \\[1, 10000000000\\]" TIMEOUT 20)
bad_input_test(io_rays_two_to_64 proxy-check "${pair} --rays 18446744073709551616"
  REGEX "--rays" TIMEOUT 20)
bad_input_test(io_width_over_scene_limit render-compare
  "${io}/scene.json --out @OUT@/r --width 20000" REGEX "--width: must be in \\[1, 16384\\]"
  TIMEOUT 20)
bad_input_test(io_height_zero render-compare "${io}/scene.json --out @OUT@/r --height 0"
  REGEX "--height" TIMEOUT 20)
bad_input_test(io_proxy_kind_bogus render-compare
  "${io}/scene.json --out @OUT@/r --proxy-kind bogus" REGEX "--proxy-kind.*bogus" TIMEOUT 20)
bad_input_test(io_seeds_zero render-compare "${io}/scene.json --out @OUT@/r --seeds 0"
  REGEX "--seeds" TIMEOUT 20)
bad_input_test(io_seeds_fraction render-compare "${io}/scene.json --out @OUT@/r --seeds 1.5"
  REGEX "--seeds" TIMEOUT 20)
bad_input_test(io_equal_time_negative render-compare
  "${io}/scene.json --out @OUT@/r --equal-time -1" REGEX "--equal-time" TIMEOUT 20)
bad_input_test(io_equal_time_huge render-compare
  "${io}/scene.json --out @OUT@/r --equal-time 1e300" REGEX "--equal-time" TIMEOUT 20)
bad_input_test(io_reference_spp_huge render-compare
  "${io}/scene.json --out @OUT@/r --reference-spp 4294967296" REGEX "--reference-spp" TIMEOUT 20)
bad_input_test(io_spp_huge render-compare "${io}/scene.json --out @OUT@/r --spp 4,99999999999"
  REGEX "--spp: must be in" TIMEOUT 20)
bad_input_test(io_spp_signed render-compare "${io}/scene.json --out @OUT@/r --spp +4"
  REGEX "--spp" TIMEOUT 20)
bad_input_test(io_probes_zero render-compare "${io}/scene.json --out @OUT@/r --probes 0"
  REGEX "--probes" TIMEOUT 20)
bad_input_test(io_draco_bits_over mesh-info "${io}/cube.off --save @OUT@/c.drc --draco-bits 31"
  REGEX "--draco-bits" TIMEOUT 20)

# A radiance that overflows: no inf/NaN table with exit 0, but one error naming the scene.
bad_input_test(io_render_compare_radiance_overflows render-compare
  "${io}/huge_radiance.json --out @OUT@/r --spp 1 --equal-time 0 --seeds 1 --reference-spp 16 --estimators exact,roulette --quiet"
  REGEX "huge_radiance.json: .*(non-finite|radiance)" INPUTS ${io}/huge_radiance.json WATCH ${io} TIMEOUT 60)
