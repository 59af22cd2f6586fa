# Outputs checked before the work: an output that cannot be written (here: its folder would be a
# plain file) fails with exit 3 and one line naming it before the input is even loaded. The runs
# would take many seconds on the dragon if the check came after the work (as it once did for
# proxy-gen's -o), so the short TIMEOUT is part of the assertion.
set(px @CORPUS@/proxyux)
set(px_dragon @DATA@/dragon.drc)
set(px_slow_wrap "--kind outside --alpha 0.004 --offset 0.0005")

bad_input_test(proxyux_proxy_gen_output_unwritable_fails_before_work proxy-gen
  "${px_dragon} ${px_slow_wrap} -o ${px}/a_file/dragon.ply"
  CODE 3 REGEX "a_file/dragon.ply: cannot write output; .*a_file' is not a folder"
  INPUTS ${px_dragon} WATCH ${px} TIMEOUT 3)
bad_input_test(proxyux_proxy_gen_json_unwritable_fails_before_work proxy-gen
  "${px_dragon} ${px_slow_wrap} -o @OUT@/dragon.ply --json ${px}/a_file/dragon.json"
  CODE 3 REGEX "a_file/dragon.json: cannot write output" OUTPUTS @OUT@/dragon.ply
  INPUTS ${px_dragon} WATCH ${px} TIMEOUT 3)
bad_input_test(proxyux_proxy_gen_out_dir_unwritable_fails_before_work proxy-gen
  "@DATA@/../scenes/dragon-plane.json ${px_slow_wrap} --out-dir ${px}/a_file/proxies"
  CODE 3 REGEX "a_file/proxies/.*: cannot write output" WATCH ${px} TIMEOUT 3)
bad_input_test(proxyux_proxy_check_dump_errors_unwritable_fails_before_work proxy-check
  "${px_dragon} ${px_dragon} --rays 100000000 --dump-errors ${px}/a_file/errors.ply"
  CODE 3 REGEX "a_file/errors.ply: cannot write output" INPUTS ${px_dragon} WATCH ${px}
  TIMEOUT 3)
# Five self-intersection counts of the dragon take about 10 s.
string(REPEAT "${px_dragon} " 5 px_five_dragons)
bad_input_test(proxyux_mesh_info_json_unwritable_fails_before_work mesh-info
  "${px_five_dragons} --self-intersections --json ${px}/a_file/dragon.json"
  CODE 3 REGEX "a_file/dragon.json: cannot write output" INPUTS ${px_dragon} WATCH ${px} TIMEOUT 3)
