#!/usr/bin/env python3
"""render-compare as work units (docs/slurm.md): a study planned with --plan, its units run one
by one (shuffled, on one thread) and merged with --merge gives the images and tables of the
single-machine run bit for bit (timing fields aside).

  render_compare_units.py RENDER_COMPARE REPO_ROOT --local
      on cornell-bunny: sharded = single; a missing, corrupt or foreign unit (another seed, another
      scene) is refused at the merge with one error line naming it, nothing written; a unit killed
      midway leaves no result and `submit.sh --resume --local` runs it again and merges.
  render_compare_units.py RENDER_COMPARE REPO_ROOT --slurm
      a small dragon-plane study on a real single-node Slurm (local_cluster.sh), compared with the
      single run bit for bit; exits 77 (skipped) only when Slurm cannot start here.
"""
import json
import os
import random
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "slurm"))
from cluster_support import SKIP, cluster, start_cluster  # noqa: E402
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from image_diff import differing_pairs  # noqa: E402


class TestFailure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise TestFailure(message)


def run(argv, expect=0, env=None, timeout=600):
    r = subprocess.run(argv, capture_output=True, text=True, env=env, timeout=timeout)
    check(r.returncode == expect,
          f"{' '.join(map(shlex.quote, argv))}: exit {r.returncode}, expected {expect}\n"
          f"stdout: {r.stdout[-2000:]}\nstderr: {r.stderr[-2000:]}")
    return r


def unit_count(plan):
    with open(os.path.join(plan, "plan.json")) as f:
        return json.load(f)["units"]


# Keys of report.json that are measured times or derived from them: they differ run to run.
TIMING = re.compile(r"seconds|efficiency|ceiling|cpu|overshoot|threads")


def tables(report_path):
    """The report's rows and meta without timing fields."""
    with open(report_path) as f:
        report = json.load(f)

    def strip(x):
        if isinstance(x, dict):
            return {k: strip(v) for k, v in x.items() if not TIMING.search(k)}
        if isinstance(x, list):
            return [strip(v) for v in x]
        return x

    return strip(report["rows"]), strip(report["meta"])


def same_outputs(single, sharded):
    """Every image identical (EXR pixels through oiiotool, PNG byte for byte), the tables equal."""
    names = sorted(os.listdir(single))
    check(names == sorted(os.listdir(sharded)),
          f"different files: {names} vs {sorted(os.listdir(sharded))}")
    exrs = [n for n in names if n.endswith(".exr")]
    pngs = [n for n in names if n.endswith(".png")]
    check(len(exrs) >= 3 and len(pngs) >= 3, f"too few images: {names}")
    differ = differing_pairs((os.path.join(single, n), os.path.join(sharded, n)) for n in exrs)
    check(not differ, f"pixels differ between single and sharded: {differ}")
    for n in pngs:
        with open(os.path.join(single, n), "rb") as a, open(os.path.join(sharded, n), "rb") as b:
            check(a.read() == b.read(), f"{n}: differs between single and sharded")
    rows_a, meta_a = tables(os.path.join(single, "report.json"))
    rows_b, meta_b = tables(os.path.join(sharded, "report.json"))
    check(len(rows_a) > 0 and all("mse" in r for r in rows_a), "no MSE rows in the report")
    check(rows_a == rows_b, f"rows differ:\n{rows_a}\n{rows_b}")
    check(meta_a == meta_b, f"meta differs:\n{meta_a}\n{meta_b}")


def one_error_line(stderr, needle):
    lines = [l for l in stderr.splitlines() if l.strip()]
    check(len(lines) == 1 and lines[0].startswith("render-compare: error: ") and needle in lines[0],
          f"expected one error line naming {needle!r}, got: {stderr!r}")


def local(rc, repo, work):
    scene = os.path.join(repo, "scenes", "cornell-bunny.json")
    flags = ["--width", "16", "--height", "16", "--seeds", "2", "--spp", "4", "--equal-time", "0",
             "--roulette-costs", "40,20,300,25,60", "--quiet"]
    single = os.path.join(work, "single")
    run([rc, scene, *flags, "--threads", "2", "--out", single])

    # Sharded: units in a shuffled order, each on one thread (as a 1-CPU Slurm task).
    plan, out = os.path.join(work, "plan"), os.path.join(work, "sharded")
    run([rc, scene, *flags, "--threads", "2", "--out", out, "--plan", plan])
    check(not os.path.exists(out), "--plan wrote the report folder")
    n = unit_count(plan)
    check(n == 6 * 2 + 1 + 16, f"units: {n}, expected 12 renders + ceiling + 16 partials")
    order = list(range(n))
    random.Random(7).shuffle(order)
    env = dict(os.environ, SLURM_CPUS_PER_TASK="1")
    for k in order:
        run([rc, "--run-unit", plan, str(k), "--quiet"], env=env)
        check(os.path.exists(os.path.join(plan, "units", f"{k}.done")), f"unit {k}: no marker")
    run([rc, "--merge", plan])
    same_outputs(single, out)
    print("sharded == single: OK")

    # A missing unit: refused, the report folder left as it was.
    before = sorted(os.listdir(out))
    os.rename(os.path.join(plan, "units", "3.done"), os.path.join(work, "3.done"))
    r = run([rc, "--merge", plan], expect=2)
    one_error_line(r.stderr, "units/3.result")
    check("has not finished" in r.stderr, f"missing unit: {r.stderr}")
    check(sorted(os.listdir(out)) == before, "a refused merge changed the report folder")
    os.rename(os.path.join(work, "3.done"), os.path.join(plan, "units", "3.done"))

    # A corrupt partial (one byte flipped in an image): the checksum refuses it.
    path = os.path.join(plan, "units", "5.result")
    with open(path, "rb") as f:
        good = f.read()
    bad = bytearray(good)
    bad[len(bad) // 2] ^= 0x40
    with open(path, "wb") as f:
        f.write(bad)
    r = run([rc, "--merge", plan], expect=2)
    one_error_line(r.stderr, "units/5.result")
    check("checksum" in r.stderr, f"corrupt unit: {r.stderr}")
    with open(path, "wb") as f:  # truncated
        f.write(good[:100])
    r = run([rc, "--merge", plan], expect=2)
    one_error_line(r.stderr, "units/5.result")
    with open(path, "wb") as f:
        f.write(good)

    # A unit of another seed, then of another scene, in place of unit 0.
    for name, other in (("seed", [scene, *flags, "--seed", "9"]),
                        ("scene hash", [os.path.join(repo, "scenes", "dragon-plane.json"), *flags])):
        other_plan = os.path.join(work, "other-" + name.replace(" ", "-"))
        run([rc, *other, "--out", os.path.join(work, "other-out"), "--plan", other_plan])
        run([rc, "--run-unit", other_plan, "0", "--quiet"])
        unit0 = os.path.join(plan, "units", "0.result")
        shutil.copy(unit0, os.path.join(work, "0.result"))
        shutil.copy(os.path.join(other_plan, "units", "0.result"), unit0)
        r = run([rc, "--merge", plan], expect=2)
        one_error_line(r.stderr, "units/0.result")
        check(f"its {name} is" in r.stderr, f"foreign unit ({name}): {r.stderr}")
        shutil.copy(os.path.join(work, "0.result"), unit0)
    run([rc, "--merge", plan])
    same_outputs(single, out)
    print("missing, corrupt and foreign units refused: OK")

    # A unit killed midway: no result, no marker; --resume --local runs it (and the rest).
    plan2, out2 = os.path.join(work, "plan-kill"), os.path.join(work, "out-kill")
    run([rc, scene, "--width", "16", "--height", "16", "--seeds", "1", "--spp", "4",
         "--estimators", "exact,roulette", "--equal-time", "1.5", "--reference-spp", "64",
         "--threads", "1", "--quiet", "--out", out2, "--plan", plan2])
    with open(os.path.join(plan2, "plan.json")) as f:
        kinds = [u["kind"] for u in json.load(f)["render_compare"]["unit_list"]]
    k = kinds.index("equal-time")
    p = subprocess.Popen([rc, "--run-unit", plan2, str(k), "--quiet"])
    time.sleep(1.0)
    check(p.poll() is None, "the equal-time unit ended before it could be killed")
    p.send_signal(signal.SIGKILL)
    p.wait()
    left = [f for f in os.listdir(os.path.join(plan2, "units")) if f.startswith(f"{k}.")]
    check(left == [], f"a killed unit left {left}")
    submit = os.path.join(repo, "scripts", "slurm", "submit.sh")
    r = run([submit, plan2, "--resume", "--local", "--jobs", "2"], timeout=600)
    check(os.path.exists(os.path.join(plan2, "units", f"{k}.done")), "the killed unit did not rerun")
    check(os.path.exists(os.path.join(out2, "report.json")), "no report after --resume --local")
    print("killed unit rerun by submit.sh --resume --local: OK")


def on_slurm(rc, repo, work):
    cluster_dir = os.path.join(work, "cluster")
    try:
        if not start_cluster(repo, cluster_dir):
            return SKIP
        env = dict(os.environ, SLURM_CONF=os.path.join(cluster_dir, "slurm.conf"))
        scene = os.path.join(repo, "scenes", "dragon-plane.json")
        flags = ["--width", "32", "--height", "24", "--seeds", "2", "--spp", "2,4",
                 "--estimators", "exact,culling,roulette", "--equal-time", "0",
                 "--reference-spp", "64", "--roulette-costs", "40,20,300,25,60", "--quiet"]
        single, plan, out = (os.path.join(work, n) for n in ("single", "plan", "sharded"))
        run([rc, scene, *flags, "--out", single])
        run([rc, scene, *flags, "--out", out, "--plan", plan])
        t0 = time.monotonic()
        run([os.path.join(repo, "scripts", "slurm", "submit.sh"), plan, "--wait",
             "--cpus-per-task", "1"], env=env, timeout=600)
        print(f"timing: {unit_count(plan)} units and the merge on the cluster: "
              f"{time.monotonic() - t0:.1f} s")
        same_outputs(single, out)
        print("dragon-plane on Slurm == single: OK")
        return 0
    finally:
        cluster(repo, cluster_dir, "stop")


def main():
    rc, repo, mode = sys.argv[1], sys.argv[2], sys.argv[3]
    work = tempfile.mkdtemp(prefix="proxyvis-units-test-")
    os.chmod(work, 0o755)  # munged serves its socket only below folders anyone can search
    try:
        status = local(rc, repo, work) if mode == "--local" else on_slurm(rc, repo, work)
        print("PASS" if not status else "")
        return status or 0
    except (TestFailure, subprocess.TimeoutExpired) as e:
        print(f"FAIL: {e}")
        return 1
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
