#!/usr/bin/env bash
# Runs render or render-compare data-parallel over N MPI ranks as one Slurm job (or here with
# mpirun): see data_parallel.py (the logic, Python standard library only) and docs/slurm.md.
command -v python3 >/dev/null 2>&1 || {
  echo "data_parallel.sh: error: python3: not found; the submitter is a Python script (install python3)" >&2
  exit 2
}
exec python3 "$(dirname "$0")/data_parallel.py" "$@"
