"""What the end-to-end test scripts share: a failure line ctest matches ("FAIL:") and running a
program with the exit code it must give."""
import subprocess
import sys


def fail(msg):
    print(f"FAIL: {msg}")
    sys.exit(1)


def run(args, expect=0, timeout=600):
    """Runs `args`; fails the test unless it exits with `expect`. Returns the CompletedProcess."""
    p = subprocess.run(args, capture_output=True, text=True, timeout=timeout)
    if p.returncode != expect:
        fail(f"{' '.join(args)}: exit {p.returncode}, expected {expect}\n{p.stdout}\n{p.stderr}")
    return p
