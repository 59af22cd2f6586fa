#!/usr/bin/env python3
"""proxy-gen SCENE --shard i/n and --merge-shards on a small scene of bundled ecosys plants.

proxy_gen_shards.py BIN_DIR DATA_DIR WORK_DIR [SUBMIT_SH [--slurm REPO]]

Checks, each against facts fixed here (not produced by the code under test):
- the split is FNV-1a 64 of the mesh name mod n, computed here independently: each shard's
  manifest lists exactly those meshes and its folder holds only their proxies;
- for n in {1, 3, 9 (more shards than meshes)}, shards run in a shuffled order and merged give
  the whole run's files byte for byte (every proxy and sidecar, scene.json) and its report
  except the timing keys ("seconds");
- a mesh with "make_proxy": false and a 2-face ground are skipped in their shard as in the run;
- with the proxy cache (a fresh folder for the whole run and again for the shards), 2 shards
  merged give the whole run's files and report, its cache counts included;
- with SUBMIT_SH: --plan DIR --shards 3 run by submit.sh --local --jobs 2 gives the same files;
  after one unit's outputs and marker are deleted, submit.sh --resume --local runs it again and
  the merge gives them again.
- with --slurm REPO (instead of all of the above but the whole run): the same plan submitted to a
  real single-node Slurm (scripts/slurm/local_cluster.sh) as a job array with --wait gives the
  whole run's files; exit 77 (skip) only when Slurm cannot start here.
"""
import hashlib
import json
import pathlib
import random
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent / "support"))
from plant_scene import write_plant_scene  # noqa: E402

PLANTS = {"flower": "YELLOWFLOWER2.drc", "grass": "GRASS9.drc", "flower2": "YELLOWFLOWER7.drc",
          "bush": "BUSH13.drc", "nettle": "URTICADIOICA9.drc", "grass3": "GRASS3.drc"}
SETTINGS = ["--kind", "outside", "--no-cache", "--seed", "7"]


def fail(msg: str) -> None:
    print(f"FAIL: {msg}")
    sys.exit(1)


def run(args, expect=0):
    p = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=900)
    if p.returncode != expect:
        fail(f"{' '.join(map(str, args))}: exit {p.returncode}, expected {expect}\n"
             f"stdout:\n{p.stdout}\nstderr:\n{p.stderr}")
    return p


def fnv1a64(text: str) -> int:
    h = 0xcbf29ce484222325
    for b in text.encode():
        h = ((h ^ b) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return h


def files(folder: pathlib.Path) -> dict:
    return {f.name: f.read_bytes() for f in sorted(folder.iterdir()) if f.is_file()}


def without_timing(report):
    if isinstance(report, dict):
        return {k: without_timing(v) for k, v in report.items() if k != "seconds"}
    if isinstance(report, list):
        return [without_timing(v) for v in report]
    return report


def write_scene(work: pathlib.Path) -> pathlib.Path:
    return write_plant_scene(work, DATA, PLANTS, "".join(
        f"{name} {k * 1.5} {k * 0.3} 0\n" for k, name in enumerate(PLANTS)))


def gen(scene, out, *extra, expect=0, settings=SETTINGS):
    return run([BIN / "proxy-gen", scene, *settings, "--out-dir", out, "-q", "--threads", "2",
                "--json", str(out) + ".json", *extra], expect)


def compare(single: pathlib.Path, out: pathlib.Path, label: str) -> None:
    a, b = files(single), files(out)
    if sorted(a) != sorted(b):
        fail(f"{label}: files {sorted(b)}, the whole run wrote {sorted(a)}")
    for name in a:
        if a[name] != b[name]:
            fail(f"{label}: {name} differs from the whole run's")
    ra = without_timing(json.loads(pathlib.Path(str(single) + ".json").read_text()))
    rb = without_timing(json.loads(pathlib.Path(str(out) + ".json").read_text()))
    if ra != rb:
        fail(f"{label}: the report differs from the whole run's:\n{json.dumps(rb)[:2000]}\n"
             f"vs\n{json.dumps(ra)[:2000]}")


def main() -> None:
    global BIN, DATA
    BIN, DATA, work = (pathlib.Path(a) for a in sys.argv[1:4])
    submit = sys.argv[4] if len(sys.argv) > 4 else None
    slurm_repo = sys.argv[6] if len(sys.argv) > 6 and sys.argv[5] == "--slurm" else None
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    scene = write_scene(work)
    names = ["ground", *PLANTS]
    out = work / "out"
    gen(scene, out)
    single = work / "single"
    out.rename(single)
    pathlib.Path(str(out) + ".json").rename(str(single) + ".json")
    report = json.loads(pathlib.Path(str(single) + ".json").read_text())
    got = {m["name"]: ("skipped" in m, "error" in m) for m in report["meshes"]}
    want = {n: (n in ("ground", "flower2"), False) for n in names}
    if got != want:
        fail(f"whole run: (skipped, failed) per mesh {got}, expected {want}")

    if slurm_repo:
        sys.exit(on_slurm(slurm_repo, scene, single, work / "out", submit))

    rng = random.Random(11)
    for n in (1, 3, 9):
        order = list(range(n))
        rng.shuffle(order)
        dirs = {}
        for i in order:
            d = work / f"shards{n}" / f"s{i}"
            gen(scene, d, "--shard", f"{i}/{n}")
            mine = {name for name in names if fnv1a64(name) % n == i}
            manifest = json.loads((d / "shard.json").read_text())
            listed = {m["name"] for m in manifest["meshes"]}
            if listed != mine:
                fail(f"shard {i}/{n}: lists {sorted(listed)}, FNV-1a says {sorted(mine)}")
            plys = {f.name.split(".")[0] for f in d.glob("*.ply")}
            if not plys <= mine - {"ground", "flower2"}:
                fail(f"shard {i}/{n}: wrote proxies of {sorted(plys)}, its meshes are {mine}")
            dirs[i] = d
        given = [dirs[i] for i in reversed(order)]  # not in shard order either
        shutil.rmtree(out, ignore_errors=True)
        run([BIN / "proxy-gen", scene, *SETTINGS, "--out-dir", out, "-q",
             "--json", str(out) + ".json", "--merge-shards", *given])
        compare(single, out, f"{n} shards")
        print(f"{n} shards (run in order {order}) merged == whole run")

    # The cache: same folder name, empty each time, so both generate every proxy.
    cache = work / "cache"
    cached = ["--kind", "outside", "--cache", str(cache), "--seed", "7"]
    shutil.rmtree(out, ignore_errors=True)
    gen(scene, out, settings=cached)
    single_cached = work / "single_cached"
    out.rename(single_cached)
    pathlib.Path(str(out) + ".json").rename(str(single_cached) + ".json")
    counts = json.loads(pathlib.Path(str(single_cached) + ".json").read_text())["cache"]
    # Every mesh but flower2 ("make_proxy": false never reaches the cache) is generated.
    if (counts["cached"], counts["generated"]) != (0, len(names) - 1):
        fail(f"whole run with a fresh cache: {counts}, expected 0 cached, "
             f"{len(names) - 1} generated")
    shutil.rmtree(cache)
    dirs = []
    for i in (1, 0):
        dirs.append(work / "cached_shards" / f"s{i}")
        gen(scene, dirs[-1], "--shard", f"{i}/2", settings=cached)
    run([BIN / "proxy-gen", scene, *cached, "--out-dir", out, "-q", "--json", str(out) + ".json",
         "--merge-shards", *dirs])
    compare(single_cached, out, "2 shards with the cache")
    print("2 shards with the proxy cache merged == whole run")

    if submit:
        plan = work / "plan"
        shutil.rmtree(out, ignore_errors=True)
        run([BIN / "proxy-gen", scene, *SETTINGS, "--out-dir", out, "--json", str(out) + ".json",
             "--threads", "1", "--plan", plan, "--shards", "3"])
        if out.exists():
            fail("--plan generated proxies; it must only write the plan")
        run(["bash", submit, plan, "--local", "--jobs", "2"])
        for k in range(3):
            if not (plan / "units" / f"{k}.done").is_file():
                fail(f"plan: units/{k}.done missing after submit.sh --local")
        compare(single, out, "plan of 3 shards via submit.sh --local")
        print("plan of 3 shards via submit.sh --local --jobs 2 == whole run")
        (plan / "units" / "1.done").unlink()
        shutil.rmtree(plan / "units" / "1.shard")
        shutil.rmtree(out)
        p = run(["bash", submit, plan, "--resume", "--local", "--jobs", "2"])
        if "1" not in p.stdout + p.stderr or not (plan / "units" / "1.done").is_file():
            fail(f"submit.sh --resume did not run unit 1 again:\n{p.stdout}\n{p.stderr}")
        compare(single, out, "plan resumed after unit 1 was lost")
        print("a lost unit run again by submit.sh --resume --local: merged == whole run")
    print("PASS")


def on_slurm(repo, scene, single, out, submit):
    """The 3-shard plan as a job array on a local Slurm cluster, merged by its dependent job."""
    sys.path.insert(0, str(pathlib.Path(repo) / "tests" / "slurm"))
    from cluster_support import SKIP, cluster, slurm_env, start_cluster
    # munged serves its socket only below folders anyone can search: a short folder in /tmp.
    cluster_dir = tempfile.mkdtemp(prefix="proxyvis-shards-cluster-")
    pathlib.Path(cluster_dir).chmod(0o755)
    try:
        if not start_cluster(repo, cluster_dir):
            return SKIP
        plan = out.parent / "plan-slurm"
        run([BIN / "proxy-gen", scene, *SETTINGS, "--out-dir", out, "--json", str(out) + ".json",
             "--threads", "1", "--plan", plan, "--shards", "3"])
        p = subprocess.run(["bash", submit, plan, "--wait", "--cpus-per-task", "1"],
                           capture_output=True, text=True, timeout=600,
                           env=slurm_env(cluster_dir))
        if p.returncode != 0:
            fail(f"submit.sh --wait: exit {p.returncode}\n{p.stdout}\n{p.stderr}")
        compare(single, out, "plan of 3 shards on Slurm")
        print("plan of 3 shards as a Slurm job array == whole run")
        print("PASS")
        return 0
    finally:
        cluster(repo, cluster_dir, "stop")
        shutil.rmtree(cluster_dir, ignore_errors=True)


if __name__ == "__main__":
    main()
