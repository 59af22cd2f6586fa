#!/bin/sh
# The whole ecosys proxy comparison: makes every per-prototype proxy variant with proxy-gen
# (make_proxies.py; cached in OUT/<variant>/), runs bench_ecosys_ceiling on each and on the
# cluster-proxy variants, and prints one table (print_table.py). Results of docs/
# proxies_on_foliage.md. About 20 minutes on 2 idle cores the first time (most of it the default
# wraps), 5 minutes once the proxies exist.
#
# usage: bench/ecosys/run_comparison.sh [BUILD_DIR [OUT_DIR [PASSES]]]
#        (defaults: build, out/ecosys-proxies, 16); run from the repository root.
set -eu
build=${1:-build}
out=${2:-out/ecosys-proxies}
passes=${3:-16}
here=$(dirname "$0")
# make_proxies.py imports the shared scene and mesh formats from python/proxyvis_tools.
PYTHONPATH="$here/../../python${PYTHONPATH:+:$PYTHONPATH}"
export PYTHONPATH
scene=scenes/ecosys.json
bench="$build/bin/bench_ecosys_ceiling"
for exe in "$build/bin/proxy-gen" "$bench"; do
  [ -x "$exe" ] || { echo "run_comparison.sh: error: $exe: missing; build it first (cmake --build $build --target proxy-gen bench_ecosys_ceiling)" >&2; exit 2; }
done
mkdir -p "$out"
tsv="$out/results.tsv"
: > "$tsv"

variant() {  # NAME PROXY-GEN-ARGS...
  name=$1
  shift
  python3 "$here/make_proxies.py" "$build/bin/proxy-gen" "$scene" "$out/$name" -- "$@"
}
measure() {  # LABEL SCENE BENCH-ARGS...
  label=$1
  s=$2
  shift 2
  "$bench" "$s" --label "$label" --passes "$passes" --tsv "$tsv" "$@" > "$out/$(echo "$label" | tr ' ()' '___').md"
}

# Per-prototype proxies: outside (hull; wrap at the default and a coarser alpha/offset), general
# (QEM at 2 % and 10 % of the faces), inside (every ecosys plant is open: none is built).
variant hull --kind outside --method hull
variant wrap --kind outside
variant wrap-coarse --kind outside --alpha 0.05 --offset 0.005
variant qem-2pct --kind general --ratio 0.02
variant qem-10pct --kind general --ratio 0.1
variant inside --kind inside || true
variant inside-filled --kind inside --fill-holes --max-seconds 60 || true
for v in hull wrap wrap-coarse qem-2pct qem-10pct; do
  measure "$v" "$out/$v/scene.json"
done
measure "hull (4 px regions)" "$out/hull/scene.json" --tile 4

# Cluster proxies: one outside proxy per terrain cell (hull of the cell's instances' hulls, or an
# alpha wrap of their coarse wraps), traced with the cell self-shadowing rule; "fused" traces
# each cell's V' as one scene over shared BVHs.
for c in 10 5 2.5; do
  measure "cluster hull ${c}" "$out/hull/scene.json" --cluster-cell "$c" --cluster-method hull
done
measure "cluster wrap 5" "$out/wrap-coarse/scene.json" --cluster-cell 5 --cluster-method wrap \
  --cluster-alpha 0.5 --cluster-offset 0.05
for c in 5 2.5; do
  measure "cluster hull ${c} fused" "$out/hull/scene.json" --cluster-cell "$c" --cluster-method hull --cluster-fused
done

python3 "$here/print_table.py" "$tsv"
