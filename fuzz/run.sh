#!/usr/bin/env bash
# Runs the libFuzzer targets one after another and prints a table: target, executions, exec/s,
# findings (crash/timeout/oom/leak files).
#   fuzz/run.sh [TARGET...] [-runs=N] [other libFuzzer flags]
#     each target on a fresh copy of its seed corpus; -runs defaults to 100000.
#   fuzz/run.sh --minutes N [TARGET...] [libFuzzer flags]
#     each target N minutes, resuming from the committed corpus fuzz/corpus/<target>.tar.xz (plus
#     the seeds); what it finds new is merged into it (libFuzzer -merge=1 keeps only inputs that
#     add coverage; the archive is packed reproducibly) and the run is added to
#     fuzz/corpus/ledger.tsv, whose totals per target (executions across all runs) are printed at
#     the end and quoted in fuzz/README.md.
# TARGET: fuzz_ply fuzz_obj ... (default: every fuzz_* executable built).
# Build first with ./setup.sh fuzz (build-fuzz/; PROXYVIS_FUZZ_BUILD_DIR overrides). Runs at
# nice 10: the machine is shared. Work files: <build>/fuzz-work/<target>/{corpus,findings,log}.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${PROXYVIS_FUZZ_BUILD_DIR:-build-fuzz}
BIN=$BUILD_DIR/bin
WORK=$BUILD_DIR/fuzz-work

targets=() flags=() runs=100000 minutes=""
while [ $# -gt 0 ]; do
  case "$1" in
    --minutes)
      minutes=${2:-}
      [[ "$minutes" =~ ^[0-9]+$ ]] && [ "$minutes" -gt 0 ] || {
        echo "run.sh: --minutes needs a whole number of minutes above 0" >&2
        exit 2
      }
      shift ;;
    -runs=*) runs=${1#-runs=} ;;
    -*) flags+=("$1") ;;
    *) targets+=("$1") ;;
  esac
  shift
done
CORPUS=fuzz/corpus
LEDGER=$CORPUS/ledger.tsv
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
  limit=("-runs=$runs")
  if [ -n "$minutes" ]; then
    limit=("-runs=-1" "-max_total_time=$((minutes * 60))")
    [ -f "$CORPUS/$t.tar.xz" ] && tar -xJf "$CORPUS/$t.tar.xz" -C "$dir/corpus"
  fi
  dict=()
  [ -f "fuzz/dict/${t#fuzz_}.dict" ] && dict=("-dict=fuzz/dict/${t#fuzz_}.dict")
  what="$runs runs"
  [ -z "$minutes" ] || what="$minutes min from $CORPUS/$t.tar.xz"
  echo "== $t: $what (log: $dir/log)"
  # A finding stops libFuzzer with a non-zero exit; the table still gets its row.
  nice -n 10 "$exe" "$dir/corpus" "${limit[@]}" -rss_limit_mb=2048 -malloc_limit_mb=2048 \
    -timeout=10 "-max_len=$(max_len_of "$t")" "-artifact_prefix=$dir/findings/" \
    -print_final_stats=1 "${dict[@]}" "${flags[@]}" >"$dir/log" 2>&1 || true
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$dir/log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$dir/log" | tail -1)
  found=$(find "$dir/findings" -type f \( -name 'crash-*' -o -name 'timeout-*' -o -name 'oom-*' \
    -o -name 'leak-*' \) | wc -l)
  summary+=("$(printf '%-20s %14s %10s %9s' "$t" "${execs:-?}" "${rate:-?}" "$found")")
  [ "$found" -eq 0 ] || echo "   findings in $dir/findings (reproduce: $exe FILE)"
  if [ -n "$minutes" ]; then
    # Keep only the inputs that add coverage to what is committed, then book the run.
    mkdir -p "$dir/merged"
    [ -f "$CORPUS/$t.tar.xz" ] && tar -xJf "$CORPUS/$t.tar.xz" -C "$dir/merged"
    if nice -n 10 "$exe" -merge=1 "-max_len=$(max_len_of "$t")" "$dir/merged" "$dir/corpus" \
      >"$dir/merge.log" 2>&1; then
      tar --sort=name --mtime=@0 --owner=0 --group=0 --numeric-owner -C "$dir/merged" -cf - . |
        xz -9 >"$CORPUS/$t.tar.xz.tmp" && mv "$CORPUS/$t.tar.xz.tmp" "$CORPUS/$t.tar.xz"
    else
      echo "   merge into $CORPUS/$t.tar.xz failed (see $dir/merge.log)"
    fi
    [ -f "$LEDGER" ] || printf 'date\ttarget\tminutes\texecutions\tfindings\n' >"$LEDGER"
    printf '%s\t%s\t%s\t%s\t%s\n' "$(date -u +%Y-%m-%d)" "$t" "$minutes" "${execs:-0}" "$found" \
      >>"$LEDGER"
  fi
done

{
  printf '%-20s %14s %10s %9s\n' target executions exec/s findings
  printf '%s\n' "${summary[@]}"
} | tee "$WORK/summary.txt"
if [ -n "$minutes" ] && [ -f "$LEDGER" ]; then
  echo
  echo "executions across all runs ($LEDGER):"
  awk -F '\t' 'NR > 1 { e[$2] += $4; f[$2] += $5; n[$2]++ }
    END { for (t in e) printf "%-20s %14d executions in %d runs, %d findings\n", t, e[t], n[t], f[t] }' \
    "$LEDGER" | sort
fi
