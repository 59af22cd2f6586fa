# proxy-gen --shard i/n and --merge-shards on a small scene of bundled ecosys plants: the split is
# FNV-1a of the mesh name; shards of n = 1, 3 and more than the meshes, run shuffled and merged,
# equal the whole run byte for byte; a --plan of 3 shards run by submit.sh --local too
# (proxy_gen_shards.py says what each step checks).
if(CMAKE_SCRIPT_MODE_FILE)
  return()
endif()
proxyvis_python_test(app.proxy_gen_shards proxy_gen_shards.py
  $<TARGET_FILE_DIR:proxy-gen> ${PROXYVIS_DATA_DIR}
  ${CMAKE_CURRENT_BINARY_DIR}/proxy_gen_shards ${CMAKE_SOURCE_DIR}/scripts/slurm/submit.sh)
# not_sanitized: it runs proxy-gen some 25 times (6 minutes under ASan). The sanitizer build still runs
# the shard code: slurm.proxy_gen_cluster (3 shards and their merge) and the 17 bad_inputs.shard_*.
set_tests_properties(app.proxy_gen_shards PROPERTIES TIMEOUT 600 LABELS not_sanitized)
