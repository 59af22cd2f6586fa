#!/usr/bin/env bash
# Runs a plan's work units as a Slurm job array and its merge as a dependent job: see submit.py
# (the logic, Python standard library only) and docs/slurm.md (the plan format).
command -v python3 >/dev/null 2>&1 || {
  echo "submit.sh: error: python3: not found; the submitter is a Python script (install python3)" >&2
  exit 2
}
exec python3 "$(dirname "$0")/submit.py" "$@"
