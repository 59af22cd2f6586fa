# The trust of a proxy's claimed class. A proxy labelled outside that is not must never give a
# silently biased table: render-compare re-verifies it (no recorded hash), downgrades it to
# general and still renders (exit 0; the warning and the report's class_status are checked in
# tests/apps/trust.cmake). Its report goes to the corpus folder, as @OUT@ must stay empty.
bad_input_test(trust_mislabelled_outside_proxy render-compare
  "@CORPUS@/trust/mislabelled.json --out @CORPUS@/trust/report_mislabelled --width 8 --height 8 --spp 1 --equal-time 0 --seeds 1 --reference-spp 16 --estimators exact,culling --quiet"
  CODE 0 INPUTS @CORPUS@/trust/mislabelled.json @CORPUS@/trust/shrunk.off
  @CORPUS@/trust/fanbox.off)
# An open proxy: containment cannot be decided, so its outside claim is dropped the same way.
bad_input_test(trust_open_outside_proxy render-compare
  "@CORPUS@/trust/open_proxy.json --out @CORPUS@/trust/report_open --width 8 --height 8 --spp 1 --equal-time 0 --seeds 1 --reference-spp 16 --estimators exact,culling --quiet"
  CODE 0 INPUTS @CORPUS@/trust/open_proxy.json @CORPUS@/trust/open.off)
# A corrupt proxy whose claim must be re-verified is an error naming the proxy, not a downgrade.
bad_input_test(trust_corrupt_claimed_proxy render-compare
  "@CORPUS@/trust/corrupt_proxy.json --out @OUT@/r --width 8 --height 8 --spp 1 --equal-time 0 --seeds 1 --quiet"
  REGEX "corrupt.off" INPUTS @CORPUS@/trust/corrupt_proxy.json @CORPUS@/trust/corrupt.off)
# A recorded hash that is not 64 lowercase hex digits: the scene's JSON path is named.
bad_input_test(trust_malformed_sha256 render-compare
  "@CORPUS@/trust/bad_hash.json --out @OUT@/r --quiet"
  REGEX "bad_hash.json.*proxies\\[0\\]\\.sha256" INPUTS @CORPUS@/trust/bad_hash.json)
bad_input_test(trust_malformed_sha256_check proxy-check "@CORPUS@/trust/bad_hash.json --rays 100"
  REGEX "bad_hash.json.*sha256" INPUTS @CORPUS@/trust/bad_hash.json)
# proxy-check --write-scene onto its own input scene: refused, the scene stays as it was.
bad_input_test(trust_write_scene_over_input proxy-check
  "@CORPUS@/trust/mislabelled.json --rays 100 --quiet --write-scene @CORPUS@/trust/mislabelled.json"
  REGEX "mislabelled.json.*(overwrite|destroy the input)" INPUTS @CORPUS@/trust/mislabelled.json)
