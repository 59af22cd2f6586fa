# proxy-gen --shard i/n and --merge-shards (docs/proxy_gen_shards.md): a merge refuses shards of
# another scene, other settings, another build or another split, a missing or repeated shard, a
# truncated manifest or proxy, and an output folder that is a shard's; bad --shard values and a
# --shard on a single mesh are refused. Exit 2, one error line naming the file, nothing written.
# Corpus: corpus_shard.py (its scene; the shards come from bad_inputs.shard_corpus, which runs it
# with this build's proxy-gen, since a merge accepts only shards of its own build).
add_test(NAME bad_inputs.shard_corpus
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/corpus_shard.py
          $<TARGET_FILE:proxy-gen> ${BAD_INPUTS_CORPUS})
set_tests_properties(bad_inputs.shard_corpus PROPERTIES FIXTURES_REQUIRED bad_inputs_corpus
  FIXTURES_SETUP bad_inputs_shard TIMEOUT 120)

set(shard_merge "@CORPUS@/shard/scene.json --kind outside --method hull --no-cache --out-dir @OUT@/merged --merge-shards")
set(shard_cases "")
macro(shard_case name args)
  bad_input_test(${name} proxy-gen "${args}" ${ARGN} TIMEOUT 30)
  list(APPEND shard_cases bad_inputs.${name})
endmacro()

# merge_refused(NAME SHARD MESSAGE [INPUTS...]): merging shard s2_0 with the corpus's shard folder
# SHARD is refused with "SHARD/shard.json: MESSAGE", SHARD's manifest untouched.
macro(merge_refused name shard message)
  shard_case(${name} "${shard_merge} @CORPUS@/shard/s2_0 @CORPUS@/shard/${shard}"
    REGEX "${shard}/shard\\.json: ${message}" INPUTS @CORPUS@/shard/${shard}/shard.json ${ARGN})
endmacro()
merge_refused(shard_merge_other_scene other_1 "a shard of another scene" @CORPUS@/shard/scene.json)
merge_refused(shard_merge_other_settings seed_1 "a shard made with other settings")
merge_refused(shard_merge_other_build build_1 "a shard of another build")
merge_refused(shard_merge_other_split s3_1 "shard 1/3 of another split")
shard_case(shard_merge_missing "${shard_merge} @CORPUS@/shard/s2_1"
  REGEX "shard/scene\\.json: shard 0/2 is missing from the merge"
  INPUTS @CORPUS@/shard/s2_1/shard.json)
shard_case(shard_merge_duplicate
  "${shard_merge} @CORPUS@/shard/s2_0 @CORPUS@/shard/s2_1 @CORPUS@/shard/s2_0"
  REGEX "s2_0/shard\\.json: shard 0/2 given twice"
  INPUTS @CORPUS@/shard/s2_0/shard.json)
merge_refused(shard_merge_truncated_manifest trunc_manifest_1 "not a proxy-gen shard manifest")
shard_case(shard_merge_truncated_proxy
  "${shard_merge} @CORPUS@/shard/s2_0 @CORPUS@/shard/trunc_proxy_1"
  REGEX "trunc_proxy_1/b\\.outside\\.ply: not the proxy its shard wrote"
  INPUTS @CORPUS@/shard/trunc_proxy_1/b.outside.ply @CORPUS@/shard/trunc_proxy_1/shard.json)
shard_case(shard_merge_missing_manifest "${shard_merge} @CORPUS@/shard/s2_0 @CORPUS@/shard"
  REGEX "shard/shard\\.json")
# The merge may not write into a shard it reads (its scene.json, its proxies).
shard_case(shard_merge_into_a_shard
  "@CORPUS@/shard/scene.json --kind outside --method hull --no-cache --out-dir @CORPUS@/shard/s2_0 --merge-shards @CORPUS@/shard/s2_0 @CORPUS@/shard/s2_1"
  REGEX "s2_0/"
  INPUTS @CORPUS@/shard/s2_0/shard.json @CORPUS@/shard/s2_0/scene.json
         @CORPUS@/shard/s2_0/a.outside.ply)
shard_case(shard_index_out_of_range
  "@CORPUS@/shard/scene.json --no-cache --out-dir @OUT@/s --shard 2/2" REGEX "--shard: must be i/n")
shard_case(shard_zero_shards
  "@CORPUS@/shard/scene.json --no-cache --out-dir @OUT@/s --shard 0/0" REGEX "--shard: must be i/n")
shard_case(shard_negative
  "@CORPUS@/shard/scene.json --no-cache --out-dir @OUT@/s --shard -1/2" REGEX "--shard")
shard_case(shard_of_a_mesh "@CORPUS@/shard/bunny.off -o @OUT@/p.ply --shard 0/2"
  REGEX "bunny\\.off: --shard, --merge-shards and --plan split a scene")
shard_case(shard_plan_too_many
  "@CORPUS@/shard/scene.json --no-cache --out-dir @OUT@/m --plan @OUT@/plan --shards 1001"
  REGEX "--shards")
shard_case(shard_plan_over_finished_units
  "@CORPUS@/shard/scene.json --no-cache --out-dir @OUT@/m --plan @CORPUS@/shard/plan_done --shards 2"
  REGEX "plan_done: the plan folder already holds finished units"
  INPUTS @CORPUS@/shard/plan_done/units/0.done WATCH @CORPUS@/shard/plan_done
         @CORPUS@/shard/plan_done/units)
shard_case(shard_shards_without_plan
  "@CORPUS@/shard/scene.json --no-cache --out-dir @OUT@/m --shards 2" REGEX "--shards")
set_tests_properties(${shard_cases} PROPERTIES FIXTURES_REQUIRED "bad_inputs_corpus;bad_inputs_shard")
