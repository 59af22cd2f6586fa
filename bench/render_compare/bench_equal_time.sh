#!/bin/sh
# Equal-time tables of all six estimators on dragon-plane and the foliage scene (equal-time
# targets), plus the oracle ceiling of docs/design.md, costs point 3 for each scene.
#   bench/render_compare/bench_equal_time.sh [BUILD_DIR] [OUT_DIR]
# Environment: SECONDS_PER_RENDER (default 4), SEEDS (3), KIND (outside), SPP (4,16),
# EXTRA (more render-compare flags, e.g. "--width 96 --height 96"), PROXY_FLAGS_<scene> (proxy-gen
# flags; foliage defaults to coarse proxies, --alpha 0.05 --ratio 0.1: the default wrap of a
# porous plant has about as many faces as the plant and cannot be cheaper).
# Prints Markdown; the HTML reports are in OUT_DIR/<scene>/report/report.html.
set -eu
build=${1:-build}
out=${2:-out/bench_equal_time}
bin=$build/bin
here=$(cd "$(dirname "$0")/../.." && pwd)
PROXY_FLAGS_dragon_plane=${PROXY_FLAGS_dragon_plane:-}
PROXY_FLAGS_foliage=${PROXY_FLAGS_foliage:---alpha 0.05 --ratio 0.1}
for scene in dragon-plane foliage; do
  dir=$out/$scene
  eval "proxy_flags=\$PROXY_FLAGS_$(echo "$scene" | tr - _)"
  mkdir -p "$dir"
  echo "# $scene" >&2
  "$bin/proxy-gen" "$here/scenes/$scene.json" --kind "${KIND:-outside}" --out-dir "$dir/proxies" \
    $proxy_flags --quiet --json "$dir/proxy-gen.json" >&2
  echo "## $scene: equal time, ${SECONDS_PER_RENDER:-4} s per render, ${SEEDS:-3} seeds"
  echo
  "$bin/render-compare" "$dir/proxies/scene.json" --out "$dir/report" --quiet \
    --spp "${SPP:-4,16}" --equal-time "${SECONDS_PER_RENDER:-4}" --seeds "${SEEDS:-3}" \
    ${EXTRA:-}
  echo
  if [ "$scene" = foliage ]; then
    # docs/design.md, costs point 2: both exact baselines; the table above uses --build auto
    # (flat here).
    echo "## $scene: exact with instanced BVHs (--build instanced), same budget"
    echo
    "$bin/render-compare" "$dir/proxies/scene.json" --out "$dir/report-instanced" --quiet \
      --estimators exact --build instanced --spp "${SPP:-4,16}" \
      --equal-time "${SECONDS_PER_RENDER:-4}" --seeds "${SEEDS:-3}" ${EXTRA:-}
    echo
  fi
  "$bin/bench_oracle_ceiling" "$dir/proxies/scene.json" --passes 16 --spp 64 ${EXTRA:-}
done
