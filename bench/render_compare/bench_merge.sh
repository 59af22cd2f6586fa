#!/bin/sh
# Times `render-compare --merge` alone on a 64-unit study: cornell-bunny (outside hull proxies) at
# 512x512, exact/culling/roulette at 1-4 spp, 4 seeds, --reference-spp 15 (48 equal-spp units,
# the ceiling, 15 reference partials; about 250 MB of unit results).
#   bench/render_compare/bench_merge.sh [BUILD_DIR] [WORK_DIR]
# Environment: RUNS (merges timed, default 5; 0 only renders the units), SIZE (width = height,
# default 512), JOBS (units run at once, default 2), THREADS (the merge's --threads through
# SLURM_CPUS_PER_TASK; default: every core).
# The units are rendered once and kept in WORK_DIR/study; they are rendered again only when
# render-compare changed (a unit is refused by a merge of another build). Each merge runs under
# /usr/bin/time; prints one row per run and min / median / max of wall time, CPU time (user +
# sys) and peak RSS, with the load average before and after. To compare two builds, give each
# its own WORK_DIR and alternate their runs (the machine's load changes the figures).
set -eu
build=${1:-build}
work=${2:-out/bench_merge}
runs=${RUNS:-5}
size=${SIZE:-512}
bin=$(cd "$build/bin" && pwd)
here=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p "$work"
work=$(cd "$work" && pwd)
study=$work/study

# Proxies once (the hull is quick and does not depend on render-compare's build).
if [ ! -f "$work/proxies/scene.json" ]; then
  "$bin/proxy-gen" "$here/scenes/cornell-bunny.json" --kind outside --method hull \
    --out-dir "$work/proxies" --quiet > /dev/null
fi

# Units again when the binary changed: the build id in every unit is a hash of the executable.
stamp=$(sha256sum "$bin/render-compare" | cut -c1-64)
if [ ! -f "$study/binary.sha256" ] || [ "$(cat "$study/binary.sha256")" != "$stamp" ]; then
  rm -rf "$study"
  "$bin/render-compare" "$work/proxies/scene.json" --out "$work/report" --width "$size" \
    --height "$size" --estimators exact,culling,roulette --spp 1,2,3,4 --seeds 4 \
    --equal-time 0 --reference-spp 15 --quiet --plan "$study" >&2
  units=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["units"])' \
    "$study/plan.json")
  echo "bench_merge: rendering $units units, ${JOBS:-2} at a time" >&2
  start=$(date +%s)
  seq 0 $((units - 1)) |
    xargs -P "${JOBS:-2}" -I{} "$bin/render-compare" --run-unit "$study" {} --quiet
  echo "bench_merge: units took $(($(date +%s) - start)) s" >&2
  echo "$stamp" > "$study/binary.sha256"
fi
[ "$runs" -gt 0 ] || exit 0  # RUNS=0: only render the units

bytes=$(cat "$study"/units/*.result | wc -c)
echo "merge of $(find "$study/units" -name '*.result' | wc -l) units, $((bytes / 1000000)) MB, ${size}x${size}"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| run | wall s | user+sys s | peak RSS MB |"
echo "|---|---|---|---|"
times=$work/times.txt
: > "$times"
i=1
while [ "$i" -le "$runs" ]; do
  if [ -n "${THREADS:-}" ]; then export SLURM_CPUS_PER_TASK="$THREADS"; fi
  /usr/bin/time -f '%e %U %S %M' -o "$work/time.txt" \
    "$bin/render-compare" --merge "$study" --quiet > "$work/merge.out"
  read -r wall user sys rss < "$work/time.txt"
  cpu=$(echo "$user $sys" | awk '{printf "%.2f", $1 + $2}')
  rss=$(echo "$rss" | awk '{printf "%.0f", $1 / 1024}')
  echo "| $i | $wall | $cpu | $rss |"
  echo "$wall $cpu $rss" >> "$times"
  i=$((i + 1))
done
echo
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| | min | median | max |"
echo "|---|---|---|---|"
for col in 1 2 3; do
  name=$(echo "wall s|user+sys s|peak RSS MB" | cut -d'|' -f$col)
  cut -d' ' -f$col "$times" | sort -g | awk -v name="$name" '
    { v[NR] = $1 }
    END { m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
          printf "| %s | %s | %s | %s |\n", name, v[1], m, v[NR] }'
done
