#!/usr/bin/env bash
# Runs the libFuzzer targets one after another, each on a fresh copy of its seed corpus, and
# prints a table: target, executions, exec/s, findings (crash/timeout/oom/leak files).
#   fuzz/run.sh [TARGET...] [-runs=N] [other libFuzzer flags]
# TARGET: fuzz_ply fuzz_obj ... (default: every fuzz_* executable built). -runs defaults to 100000.
# Build first with ./setup.sh fuzz (build-fuzz/; PROXYVIS_FUZZ_BUILD_DIR overrides). Runs at
# nice 10: the machine is shared. Work files: <build>/fuzz-work/<target>/{corpus,findings,log}.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${PROXYVIS_FUZZ_BUILD_DIR:-build-fuzz}
BIN=$BUILD_DIR/bin
WORK=$BUILD_DIR/fuzz-work

targets=() flags=() runs=100000
for arg in "$@"; do
  case "$arg" in
    -runs=*) runs=${arg#-runs=} ;;
    -*) flags+=("$arg") ;;
    *) targets+=("$arg") ;;
  esac
done
if [ ${#targets[@]} -eq 0 ]; then
  for exe in "$BIN"/fuzz_*; do [ -x "$exe" ] && targets+=("$(basename "$exe")"); done
fi
if [ ${#targets[@]} -eq 0 ]; then
  echo "run.sh: no fuzz targets in $BIN; build them with ./setup.sh fuzz" >&2
  exit 2
fi

# Seeds are written fresh (draco seeds are encoded by mesh-info when it was built).
mesh_info=()
[ -x "$BIN/mesh-info" ] && mesh_info=("$BIN/mesh-info")
python3 fuzz/make_seeds.py "$WORK/seeds" . "${mesh_info[@]}" >/dev/null

# Largest input per target: a bit above its largest seed (small inputs mutate much faster).
max_len_of() {
  case "$1" in
    fuzz_ply) echo 40000 ;;
    fuzz_draco) [ ${#mesh_info[@]} -gt 0 ] && echo 16384 || echo 100000 ;;
    fuzz_obj | fuzz_off | fuzz_glb | fuzz_gltf) echo 16384 ;;
    *) echo 8192 ;;
  esac
}

summary=()
for t in "${targets[@]}"; do
  exe=$BIN/$t
  [ -x "$exe" ] || { echo "run.sh: $exe not built" >&2; exit 2; }
  dir=$WORK/$t
  rm -rf "$dir" && mkdir -p "$dir/corpus" "$dir/findings"
  [ -d "$WORK/seeds/$t" ] && cp -r "$WORK/seeds/$t/." "$dir/corpus/"
  dict=()
  [ -f "fuzz/dict/${t#fuzz_}.dict" ] && dict=("-dict=fuzz/dict/${t#fuzz_}.dict")
  echo "== $t: $runs runs (log: $dir/log)"
  # A finding stops libFuzzer with a non-zero exit; the table still gets its row.
  nice -n 10 "$exe" "$dir/corpus" "-runs=$runs" -rss_limit_mb=2048 -malloc_limit_mb=2048 \
    -timeout=10 "-max_len=$(max_len_of "$t")" "-artifact_prefix=$dir/findings/" \
    -print_final_stats=1 "${dict[@]}" "${flags[@]}" >"$dir/log" 2>&1 || true
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$dir/log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$dir/log" | tail -1)
  found=$(find "$dir/findings" -type f \( -name 'crash-*' -o -name 'timeout-*' -o -name 'oom-*' \
    -o -name 'leak-*' \) | wc -l)
  summary+=("$(printf '%-20s %14s %10s %9s' "$t" "${execs:-?}" "${rate:-?}" "$found")")
  [ "$found" -eq 0 ] || echo "   findings in $dir/findings (reproduce: $exe FILE)"
done

{
  printf '%-20s %14s %10s %9s\n' target executions exec/s findings
  printf '%s\n' "${summary[@]}"
} | tee "$WORK/summary.txt"
