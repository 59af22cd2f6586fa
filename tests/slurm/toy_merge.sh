#!/usr/bin/env bash
# The toy plan's merge: concatenates units/0.txt .. units/(K-1).txt in unit order into
# merged.txt (temporary name, then rename) and counts its runs.
#   toy_merge.sh PLAN_DIR K
set -eu
plan=$1 units=$2
echo run >>"$plan/runs/merge.count"
for ((k = 0; k < units; k++)); do
  cat "$plan/units/$k.txt"
done >"$plan/merged.txt.tmp"
mv "$plan/merged.txt.tmp" "$plan/merged.txt"
