#!/usr/bin/env python3
"""Runs the command lines of README.md's "Using the programs" block verbatim, in order, in a fresh
folder laid out like a new clone (data/ and scenes/ linked, build/bin/ linked to the built
programs, no out/ yet), and fails unless each exits 0 and says nothing on stderr but progress
and notes. A README example that a new user cannot run as written is a bug in the README or in
the program.

    readme_examples.py README BIN_DIR SOURCE_DIR WORK_DIR [--skip PROGRAM ...]

--skip leaves out the lines of a program (render-compare's example renders for minutes).
"""
import argparse
import os
import re
import shlex
import shutil
import subprocess
import sys


def example_lines(readme: str) -> list:
    text = open(readme, encoding="utf-8").read()
    section = text.split("## Using the programs", 1)[1]
    block = re.search(r"```sh\n(.*?)```", section, re.S).group(1)
    block = re.sub(r"\\\n\s*", "", block)  # a command continued over lines with a backslash
    return [line.strip() for line in block.splitlines() if line.strip().startswith("build/bin/")]


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("readme")
    ap.add_argument("bin_dir")
    ap.add_argument("source_dir")
    ap.add_argument("work_dir")
    ap.add_argument("--skip", nargs="*", default=[])
    a = ap.parse_args()
    lines = example_lines(a.readme)
    if len(lines) < 3:
        sys.exit(f"FAIL: found only {len(lines)} example lines in {a.readme}")
    shutil.rmtree(a.work_dir, ignore_errors=True)
    os.makedirs(os.path.join(a.work_dir, "build"))
    for name in ("data", "scenes"):
        os.symlink(os.path.join(a.source_dir, name), os.path.join(a.work_dir, name))
    os.symlink(os.path.abspath(a.bin_dir), os.path.join(a.work_dir, "build", "bin"))
    ran = 0
    for line in lines:
        args = shlex.split(line, comments=True)
        program = os.path.basename(args[0])
        if program in a.skip:
            print(f"skipped: {line}")
            continue
        p = subprocess.run(args, cwd=a.work_dir, capture_output=True, text=True, timeout=600)
        context = f"\n$ {line}\nexit {p.returncode}\nstdout:\n{p.stdout}\nstderr:\n{p.stderr}"
        if p.returncode != 0:
            sys.exit(f"FAIL: a README example does not run{context}")
        unexpected = [l for l in p.stderr.splitlines() if l and not re.match(
            rf"^({re.escape(program)}: note: |{re.escape(program)} \[|Classifying segments \[)", l)]
        if unexpected:
            sys.exit(f"FAIL: unexpected lines on stderr: {unexpected}{context}")
        print(f"ok: {line}")
        ran += 1
    print(f"OK: {ran} README examples ran")
    return 0


if __name__ == "__main__":
    sys.exit(main())
