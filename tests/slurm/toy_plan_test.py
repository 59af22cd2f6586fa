#!/usr/bin/env python3
"""End-to-end test of scripts/slurm/submit.sh on a toy plan of 8 units.

  toy_plan_test.py REPO_ROOT --slurm   a real single-node Slurm (local_cluster.sh) in a temporary
                                       folder; exits 77 (skipped) only when Slurm cannot start
  toy_plan_test.py REPO_ROOT --local   the same plan run with submit.sh --local (no Slurm)

Each unit writes "unit K: K² TAG" atomically and counts its runs in runs/K.count; the merge
concatenates the units in order. The test runs the plan, then removes one unit's output and
plants a failure in another: --resume must re-run exactly those two, fail without merging,
and after the failure is cleared re-run only the failed unit and merge.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

from cluster_support import (SKIP, TestFailure, check, clean_up, cluster, start_cluster,
                             stop_checked)

UNITS = 8
# Passed through the generated job scripts unchanged: spaces, quotes, $ and a glob.
TAG = "a $HOME \"q\" 'b' *"


def expected_merge():
    return "".join(f"unit {k}: {k * k} {TAG}\n" for k in range(UNITS))


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def run_counts(plan):
    counts = {}
    for k in list(range(UNITS)) + ["merge"]:
        path = os.path.join(plan, "runs", f"{k}.count")
        counts[k] = len(read(path).splitlines()) if os.path.exists(path) else 0
    return counts


def write_plan(plan, tests_dir):
    os.makedirs(os.path.join(plan, "units"))
    with open(os.path.join(plan, "plan.json"), "w") as f:
        json.dump({
            "version": 1,
            "name": "toy",
            "units": UNITS,
            "run_unit": ["bash", os.path.join(tests_dir, "toy_unit.sh"), "{plan_dir}", "{unit}",
                         TAG],
            "merge": ["bash", os.path.join(tests_dir, "toy_merge.sh"), "{plan_dir}", str(UNITS)],
        }, f)


class Runner:
    """Runs submit.sh in one mode and checks its exit status and error line."""

    def __init__(self, repo, mode, env):
        self.submit = os.path.join(repo, "scripts", "slurm", "submit.sh")
        self.mode = mode
        self.env = env

    def __call__(self, plan, *extra, expect=0):
        argv = [self.submit, plan] + list(extra)
        argv += ["--local", "--jobs", "2"] if self.mode == "--local" else ["--wait"]
        t0 = time.monotonic()
        r = subprocess.run(argv, capture_output=True, text=True, env=self.env, timeout=120)
        seconds = time.monotonic() - t0
        sys.stdout.write(r.stdout)
        sys.stdout.write(r.stderr)
        check(r.returncode == expect,
              f"{' '.join(extra) or 'first run'}: exit {r.returncode}, expected {expect}")
        errors = r.stderr.strip().splitlines()
        if expect == 0:
            check(not errors, f"unexpected stderr: {r.stderr!r}")
        else:
            check(len(errors) == 1 and errors[0].startswith("submit.sh: error: "),
                  f"expected one error line, got {r.stderr!r}")
        return r.stderr, seconds


def scenario(repo, mode, run, work):
    tests_dir = os.path.join(repo, "tests", "slurm")
    plan = os.path.join(work, "toy plan")  # a space: the scripts must quote it
    write_plan(plan, tests_dir)
    merged = os.path.join(plan, "merged.txt")

    if mode == "--slurm":
        # sbatch refuses: one error line with its reason, no unit runs.
        err, _ = run(plan, "--partition", "nosuch", expect=1)
        check("sbatch: cannot submit 8 units; " in err and "partition" in err,
              f"sbatch's refusal: {err!r}")
        check(run_counts(plan)[0] == 0, "a refused submission ran units")

    _, seconds = run(plan)
    print(f"timing: {UNITS} toy units + merge ({mode}): {seconds:.1f} s")
    check(read(merged) == expected_merge(), f"merged.txt wrong: {read(merged)!r}")
    check(run_counts(plan) == {**{k: 1 for k in range(UNITS)}, "merge": 1},
          f"first run: run counts {run_counts(plan)}")

    # A second plain submission would mix runs: refused, nothing runs.
    err, _ = run(plan, expect=2)
    check("--resume" in err and os.path.join(plan, "units") in err, f"refusal: {err!r}")
    check(run_counts(plan)[0] == 1, "a refused submission ran units")

    # Unit 3 lost its output, unit 6 fails: both re-run, the merge must not.
    for name in ("3.txt", "3.done"):
        os.unlink(os.path.join(plan, "units", name))
    os.unlink(merged)
    os.makedirs(os.path.join(plan, "fail"))
    open(os.path.join(plan, "fail", "6"), "w").close()
    for name in ("6.txt", "6.done"):
        os.unlink(os.path.join(plan, "units", name))
    err, _ = run(plan, "--resume", expect=1)
    check("unit 6 did not finish" in err, f"failure message does not name unit 6: {err!r}")
    check(not os.path.exists(merged), "merged.txt written although unit 6 failed")
    check(os.path.exists(os.path.join(plan, "units", "3.done")), "unit 3 not re-run")
    want = {**{k: 1 for k in range(UNITS)}, 3: 2, 6: 2, "merge": 1}
    check(run_counts(plan) == want, f"resume with a failure: run counts {run_counts(plan)}, "
          f"expected {want}")
    log = read(os.path.join(plan, "slurm", "logs", "unit-6.out"))
    check("failing as planted" in log, f"unit 6's log lacks its error: {log!r}")

    # Failure cleared: only unit 6 runs again, then the merge.
    os.unlink(os.path.join(plan, "fail", "6"))
    _, seconds = run(plan, "--resume")
    print(f"timing: resume of 1 unit + merge ({mode}): {seconds:.1f} s")
    check(read(merged) == expected_merge(), f"merged.txt after resume wrong: {read(merged)!r}")
    want = {**{k: 1 for k in range(UNITS)}, 3: 2, 6: 3, "merge": 2}
    check(run_counts(plan) == want, f"second resume: run counts {run_counts(plan)}, "
          f"expected {want}")
    log = read(os.path.join(plan, "slurm", "logs", "unit-6.out"))
    check(log.count("unit 6: started on") == 3 and "failing as planted" in log,
          f"unit 6's log does not keep its three attempts: {log!r}")

    # Everything done: --resume runs the merge alone.
    os.unlink(merged)
    run(plan, "--resume")
    check(read(merged) == expected_merge(), "merge-only resume: merged.txt wrong")
    want["merge"] = 3
    check(run_counts(plan) == want, f"merge-only resume: run counts {run_counts(plan)}")


def refuse_second_submission(repo, env, work):
    """While a plan's jobs are queued or running, even --resume is refused."""
    plan = os.path.join(work, "slow plan")
    os.makedirs(os.path.join(plan, "units"))
    with open(os.path.join(plan, "plan.json"), "w") as f:
        json.dump({"units": 2, "run_unit": ["sleep", "30", "{unit}"], "merge": ["true"]}, f)
    submit = os.path.join(repo, "scripts", "slurm", "submit.sh")
    r = subprocess.run([submit, plan], capture_output=True, text=True, env=env, timeout=60)
    check(r.returncode == 0, f"slow plan: exit {r.returncode}: {r.stderr}")
    r = subprocess.run([submit, plan, "--resume"], capture_output=True, text=True, env=env,
                       timeout=60)
    sys.stdout.write(r.stderr)
    lines = r.stderr.strip().splitlines()
    check(r.returncode == 2 and len(lines) == 1 and "still queued or running" in lines[0],
          f"second submission while running: exit {r.returncode}: {r.stderr!r}")
    # stop cancels the sleeping units


def main():
    repo, mode = sys.argv[1], sys.argv[2]
    work = tempfile.mkdtemp(prefix="proxyvis-slurm-test-")
    os.chmod(work, 0o755)  # munged serves its socket only below folders anyone can search
    env = dict(os.environ)
    cluster_dir = os.path.join(work, "cluster")
    started = False
    try:
        if mode == "--slurm":
            if not start_cluster(repo, cluster_dir):
                return SKIP
            started = True
            env["SLURM_CONF"] = os.path.join(cluster_dir, "slurm.conf")
            status = cluster(repo, cluster_dir, "status")
            check(status.returncode == 0 and "idle" in status.stdout,
                  f"status after start: {status.stdout}{status.stderr}")
        scenario(repo, mode, Runner(repo, mode, env), work)
        if started:
            refuse_second_submission(repo, env, work)
            stop_checked(repo, cluster_dir)
            started = False
        print("PASS")
        return 0
    except (TestFailure, subprocess.TimeoutExpired) as e:
        print(f"FAIL: {e}")
        return 1
    finally:
        clean_up(repo, cluster_dir, started, work)


if __name__ == "__main__":
    sys.exit(main())
