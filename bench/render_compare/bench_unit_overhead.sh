#!/bin/sh
# The fixed cost of render-compare's work units (docs/slurm.md, "Measured"): the same study run
# single (one process) and planned (--plan, every unit one after the other, --merge), alternately,
# N times. CPU time is user + sys of each process (GNU time). Prints a Markdown table: the single
# run's CPU, the planned run's CPU per phase (plan, each unit by kind, merge), its total and the
# difference and ratio to the single run, each as the median with min and max over the N rounds.
#   bench/render_compare/bench_unit_overhead.sh [BUILD_DIR] [OUT_DIR]
# Environment: N (rounds, default 3); SCENE (default: dragon-plane with outside proxies made by
# proxy-gen in OUT_DIR); FLAGS (the study, default: exact and roulette at
# 256 spp, one seed, no equal-time table, a 1-spp reference, 512x512, one thread).
set -eu
build=${1:-build}
out=${2:-out/bench_unit_overhead}
bin=$(cd "$build/bin" && pwd)
here=$(cd "$(dirname "$0")/../.." && pwd)
N=${N:-3}
FLAGS=${FLAGS:---estimators exact,roulette --spp 256 --seeds 1 --equal-time 0 --reference-spp 1 --width 512 --height 512 -q --threads 1}
command -v /usr/bin/time >/dev/null || { echo "bench_unit_overhead: needs GNU time (/usr/bin/time)" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
if [ -z "${SCENE:-}" ]; then
  SCENE=$out/proxies/scene.json
  [ -f "$SCENE" ] || "$bin/proxy-gen" "$here/scenes/dragon-plane.json" --kind outside \
    --out-dir "$out/proxies" --quiet >&2
fi
log=$out/cpu.tsv
: >"$log"
# cpu ROUND MODE PHASE CMD...: runs CMD, appends its user + sys seconds to the log.
cpu() {
  round=$1 mode=$2 phase=$3
  shift 3
  /usr/bin/time -o "$out/time.txt" -f "%U %S" "$@" >/dev/null
  awk -v r="$round" -v m="$mode" -v p="$phase" '{ printf "%s\t%s\t%s\t%.3f\n", r, m, p, $1 + $2 }' \
    "$out/time.txt" >>"$log"
}
# FLAGS is a list of words on purpose.
# shellcheck disable=SC2086
for round in $(seq 1 "$N"); do
  echo "round $round of $N" >&2
  cpu "$round" single all "$bin/render-compare" "$SCENE" --out "$out/single" $FLAGS
  rm -rf "$out/plan"
  cpu "$round" planned plan "$bin/render-compare" "$SCENE" --out "$out/planned" --plan "$out/plan" $FLAGS
  units=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["units"])' "$out/plan/plan.json")
  k=0
  while [ "$k" -lt "$units" ]; do
    kind=$(python3 -c 'import json, sys
u = json.load(open(sys.argv[1]))["render_compare"]["unit_list"][int(sys.argv[2])]
print(u["kind"] + ("" if u["kind"] != "equal-spp" else " " + u["estimator"] + " " + str(u["spp"])))' \
      "$out/plan/plan.json" "$k")
    cpu "$round" planned "unit $k ($kind)" "$bin/render-compare" --run-unit "$out/plan" "$k" --quiet
    k=$((k + 1))
  done
  cpu "$round" planned merge "$bin/render-compare" --merge "$out/plan"
done
python3 - "$log" <<'PY'
import collections, statistics, sys
rows = [line.rstrip("\n").split("\t") for line in open(sys.argv[1])]
by = collections.OrderedDict()
totals = collections.defaultdict(float)
single = {}
for r, mode, phase, s in rows:
    by.setdefault((mode, phase), []).append(float(s))
    if mode == "planned":
        totals[r] += float(s)
    else:
        single[r] = float(s)
by[("planned", "total")] = [totals[r] for r in single]
by[("planned - single", "fixed cost of planning")] = [totals[r] - single[r] for r in single]
by[("planned / single", "ratio")] = [totals[r] / single[r] for r in single]
def cell(v):
    return f"{statistics.median(v):.2f} ({min(v):.2f}-{max(v):.2f})"
print(f"| run | phase | CPU s, median (min-max) of {len(single)} |")
print("|---|---|---|")
for (mode, phase), v in by.items():
    print(f"| {mode} | {phase} | {cell(v)} |")
PY
