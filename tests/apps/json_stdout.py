#!/usr/bin/env python3
"""Runs one program with `--json -` and fails unless its stdout is exactly one JSON value (Python's
json.loads of the whole of stdout, nothing before or after it) and the exit code is the expected
one. Optionally stderr must match a regex (the human report went there) and the JSON must hold
some top-level keys (of the object, or of the first element of an array).

    json_stdout.py [--code N] [--stderr REGEX] [--keys k1,k2] [--workdir DIR] -- PROGRAM ARGS...
"""
import argparse
import json
import os
import re
import subprocess
import sys


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--code", type=int, default=0)
    ap.add_argument("--stderr", default="")
    ap.add_argument("--keys", default="")
    ap.add_argument("--workdir", default="")
    ap.add_argument("command", nargs=argparse.REMAINDER)
    a = ap.parse_args()
    cmd = a.command[1:] if a.command[:1] == ["--"] else a.command
    if a.workdir:
        os.makedirs(a.workdir, exist_ok=True)
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300, cwd=a.workdir or None)
    context = f"\ncommand: {' '.join(cmd)}\nstdout:\n{p.stdout}\nstderr:\n{p.stderr}"
    if p.returncode != a.code:
        sys.exit(f"FAIL: exit code {p.returncode}, expected {a.code}{context}")
    try:
        value = json.loads(p.stdout)
    except json.JSONDecodeError as e:
        sys.exit(f"FAIL: stdout is not only JSON ({e}){context}")
    if a.stderr and not re.search(a.stderr, p.stderr, re.S):
        sys.exit(f"FAIL: stderr does not match '{a.stderr}'{context}")
    obj = value[0] if isinstance(value, list) and value else value
    for key in filter(None, a.keys.split(",")):
        if not isinstance(obj, dict) or key not in obj:
            sys.exit(f"FAIL: JSON key '{key}' missing{context}")
    print(f"OK: stdout is one JSON {type(value).__name__}, exit code {p.returncode}")


if __name__ == "__main__":
    main()
