#!/usr/bin/env bash
# A toy work unit for the Slurm tests: counts its runs, fails when told to, and writes its
# output the way a real unit must: to a temporary name, renamed into place, then units/K.done.
#   toy_unit.sh PLAN_DIR K TAG
set -eu
plan=$1 unit=$2 tag=$3
mkdir -p "$plan/runs"
echo run >>"$plan/runs/$unit.count"
if [ -e "$plan/fail/$unit" ]; then
  echo "toy unit $unit: failing as planted" >&2
  exit 7
fi
printf 'unit %d: %d %s\n' "$unit" $((unit * unit)) "$tag" >"$plan/units/$unit.txt.tmp"
mv "$plan/units/$unit.txt.tmp" "$plan/units/$unit.txt"
: >"$plan/units/$unit.done"
