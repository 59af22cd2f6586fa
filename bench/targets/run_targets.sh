#!/bin/sh
# The equal-time targets on every bundled scene, in one run per scene (estimators interleaved by
# render-compare itself): each scene's proxies (proxy-gen, cached), then render-compare with
# every estimator at equal time under /usr/bin/time -v (peak RSS), then one table.
#   bench/targets/run_targets.sh [BUILD_DIR] [OUT_DIR]
# Environment: SECONDS_PER_RENDER (default 2), SEEDS (2), REPEATS (2), SPP (16),
# SCENES (default: dragon-plane cornell-bunny foliage ecosys), BUILD (auto), EXTRA (more
# render-compare flags). Prints Markdown (targets.py); reports in OUT_DIR/<scene>/report/.
set -eu
build=${1:-build}
out=${2:-out/bench_targets}
bin=$build/bin
here=$(cd "$(dirname "$0")/../.." && pwd)
for scene in ${SCENES:-dragon-plane cornell-bunny foliage ecosys}; do
  dir=$out/$scene
  mkdir -p "$dir"
  echo "# $scene" >&2
  # foliage: coarse wraps (the default wrap of a porous plant is not cheaper than the plant).
  flags=""
  [ "$scene" = foliage ] && flags="--alpha 0.05 --ratio 0.1"
  "$bin/proxy-gen" "$here/scenes/$scene.json" --kind outside --out-dir "$dir/proxies" $flags \
    --quiet --json "$dir/proxy-gen.json" >&2
  /usr/bin/time -v -o "$dir/time.txt" "$bin/render-compare" "$dir/proxies/scene.json" \
    --out "$dir/report" --quiet --spp "${SPP:-16}" --equal-time "${SECONDS_PER_RENDER:-2}" \
    --seeds "${SEEDS:-2}" --repeats "${REPEATS:-2}" --build "${BUILD:-auto}" \
    --json "$dir/report.json" ${EXTRA:-} >/dev/null
done
python3 "$here/bench/targets/targets.py" "$out"
