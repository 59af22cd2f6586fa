#!/usr/bin/env python3
"""render-compare starts itself once more with glibc.malloc.hugetlb=1 in GLIBC_TUNABLES
(apps/render-compare/huge_page_malloc.h), unless that tunable is already set: the dynamic
loader's log (LD_DEBUG=files) shows the program's libraries loaded by two program images, or by
one when the user set the tunable (or when it is set among other tunables).

  render_compare_huge_pages.py RENDER_COMPARE
"""
import os
import subprocess
import sys


def images(rc, tunables):
    """How many program images loaded libembree3 while running `rc --version`."""
    env = {k: v for k, v in os.environ.items() if k != "GLIBC_TUNABLES"}
    env["LD_DEBUG"] = "files"
    if tunables is not None:
        env["GLIBC_TUNABLES"] = tunables
    r = subprocess.run([rc, "--version"], capture_output=True, text=True, env=env, timeout=60)
    if r.returncode != 0 or not r.stdout.startswith("proxyvis "):
        print(f"FAIL: --version: exit {r.returncode}\n{r.stdout}{r.stderr[-2000:]}", file=sys.stderr)
        sys.exit(1)
    return sum(1 for line in r.stderr.splitlines()
               if "file=libembree3" in line and "needed by" in line)


def main():
    rc = sys.argv[1]
    cases = [(None, 2), ("glibc.malloc.check=0", 2), ("glibc.malloc.hugetlb=0", 1),
             ("glibc.malloc.check=0:glibc.malloc.hugetlb=1", 1)]
    for tunables, expected in cases:
        got = images(rc, tunables)
        if got != expected:
            print(f"FAIL: GLIBC_TUNABLES={tunables}: {got} program images, expected {expected}",
                  file=sys.stderr)
            sys.exit(1)
    print("render_compare_huge_pages: ok")


if __name__ == "__main__":
    main()
