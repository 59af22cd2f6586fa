#!/usr/bin/env python3
"""scripts/proxy_budgets: the budget choice and the whole allocation on a small plant scene.

proxy_budget_allocation.py SCRIPTS_DIR BIN_DIR DATA_DIR WORK_DIR

Checks, each against facts fixed here or computed here independently of the code under test:
- budget_choice.choose finds the least value within the cap that brute force over every
  combination finds (random cases, fixed seed), never exceeds the cap, and says None when
  nothing fits;
- the allocation keeps the proxies within --share, counted per instance;
- a mesh's "proxy_max_faces" gives the same proxy, byte for byte, as --max-faces with that
  budget for the whole scene (the final proxies against the measured options);
- the choice has, on the segments it was chosen on, no more wasted hits per draw (MH') than any
  single budget for every mesh that fits the share;
- the printed result is measured on another seed, every final proxy proved outside;
- bad arguments exit 2 and an unreachable share exits 1, writing no allocation; options kept
  from a run with other settings are refused (exit 2), not reused.
"""
import hashlib
import itertools
import json
import pathlib
import random
import shutil
import subprocess
import sys

SCRIPTS = pathlib.Path(sys.argv[1]).resolve()
BIN = pathlib.Path(sys.argv[2]).resolve()
DATA = pathlib.Path(sys.argv[3]).resolve()
WORK = pathlib.Path(sys.argv[4]).resolve()
sys.path.insert(0, str(SCRIPTS))
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent / "support"))
from budget_choice import choose  # noqa: E402
from plant_scene import write_plant_scene  # noqa: E402

ALLOCATE = SCRIPTS / "allocate_proxy_budgets.py"
PLANTS = {"flower": "YELLOWFLOWER2.drc", "grass": "GRASS9.drc", "bush": "BUSH17.drc"}
INSTANCES = {"flower": 3, "grass": 2, "bush": 1}
BUDGETS = [16, 48]


def fail(msg):
    print(f"FAIL: {msg}")
    sys.exit(1)


def check_choice_against_brute_force():
    rng = random.Random(7)
    for case in range(300):
        items = [[(rng.randint(1, 40), rng.choice([0.0, rng.random()]))
                  for _ in range(rng.randint(1, 4))] for _ in range(rng.randint(1, 5))]
        cap = rng.randint(0, 100)
        best = None
        for combo in itertools.product(*[range(len(o)) for o in items]):
            cost = sum(items[i][k][0] for i, k in enumerate(combo))
            value = sum(items[i][k][1] for i, k in enumerate(combo))
            if cost <= cap and (best is None or value < best - 1e-12):
                best = value
        # Integer costs with one unit per triangle: no rounding, so the DP is exact.
        got = choose(items, cap, resolution=max(cap, 1))
        if best is None:
            if got is not None:
                fail(f"case {case}: nothing fits cap {cap}, choose gave {got}")
            continue
        if got is None:
            fail(f"case {case}: choose found nothing, brute force {best}")
        choice, value, cost = got
        if cost > cap or abs(value - best) > 1e-9:
            fail(f"case {case}: choose {value} at cost {cost}, brute force {best} within {cap}")
        if abs(sum(items[i][k][1] for i, k in enumerate(choice)) - value) > 1e-9:
            fail(f"case {case}: the returned value is not the sum of the choice")
        # Coarse units round costs up: the choice may be worse, never over the cap.
        coarse = choose(items, cap, resolution=7)
        if coarse is not None and coarse[2] > cap:
            fail(f"case {case}: coarse choice costs {coarse[2]} > {cap}")
    print("budget_choice: 300 random cases agree with brute force")


def ply_faces(path):
    for line in pathlib.Path(path).read_bytes().split(b"end_header")[0].decode().splitlines():
        if line.startswith("element face "):
            return int(line.split()[2])
    fail(f"{path}: no face count in its PLY header")


def sha(path):
    return hashlib.sha256(pathlib.Path(path).read_bytes()).hexdigest()


def allocate(scene, out, share, *extra, expect=0):
    args = [sys.executable, ALLOCATE, scene, "--share", share, "--out-dir", out, "--bin", BIN,
            "--budgets", ",".join(map(str, BUDGETS)), "--rays", "400", *extra, "--",
            "--threads", "2", "--no-cache"]
    p = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=900)
    if p.returncode != expect:
        fail(f"allocate --share {share} {extra}: exit {p.returncode}, expected {expect}\n"
             f"{p.stdout}\n{p.stderr}")
    return p


def wasted_hits(checks):
    """Segments per draw that hit an outside proxy and miss its original (the default
    objective), from proxy-check's counts."""
    return sum(c["counts"]["MH"] / c["attempts"] for c in checks)


def main():
    check_choice_against_brute_force()
    if WORK.exists():
        shutil.rmtree(WORK)
    WORK.mkdir(parents=True)
    lines = "".join(f"{n} {i * 1.3:.1f} {0.4 * k:.1f} 0\n" for k, n in enumerate(INSTANCES)
                    for i in range(INSTANCES[n]))
    scene = write_plant_scene(WORK, DATA, PLANTS, lines, no_proxy=())
    # The options alone: a share between the smallest and the largest uniform budget.
    out = WORK / "alloc"
    allocate(scene, out, "1")
    options = {b: json.loads((out / "options" / f"b{b}.check.json").read_text())["checks"]
               for b in [0] + BUDGETS}
    original = sum(c["original"]["faces"] * INSTANCES[c["label"].split(" / ")[0]]
                   for c in options[0])
    totals = {b: sum(c["proxy"]["faces"] * INSTANCES[c["label"].split(" / ")[0]] for c in cs)
              for b, cs in options.items()}
    share = (totals[16] + totals[48]) / 2 / original
    shutil.rmtree(out / "final")
    p = allocate(scene, out, f"{share:.6f}")
    report = json.loads((out / "allocation.json").read_text())

    final = json.loads((out / "final" / "scene.json").read_text())
    budget_scene = json.loads((out / "budgets.json").read_text())
    triangles = 0
    for m in final["meshes"]:
        if m["name"] not in PLANTS:
            continue
        budget = report["meshes"][m["name"]]["budget"]
        bm = next(x for x in budget_scene["meshes"] if x["name"] == m["name"])
        if bm.get("proxy_max_faces") != budget:
            fail(f"{m['name']}: budgets.json has {bm.get('proxy_max_faces')}, chose {budget}")
        (proxy,) = m["proxies"]
        proxy_file = out / "final" / proxy["file"]  # relative to the scene
        if proxy["class"] != "outside":
            fail(f"{m['name']}: final proxy class {proxy['class']}")
        option = json.loads((out / "options" / f"b{budget}" / "scene.json").read_text())
        (want,) = next(x for x in option["meshes"] if x["name"] == m["name"])["proxies"]
        if proxy["sha256"] != want["sha256"] or sha(proxy_file) != want["sha256"]:
            fail(f"{m['name']}: proxy_max_faces {budget} gave other bytes than --max-faces")
        f = ply_faces(proxy_file)
        if budget and f > budget:
            fail(f"{m['name']}: {f} faces over its budget {budget}")
        triangles += f * INSTANCES[m["name"]]
    if triangles > share * original:
        fail(f"the proxies take {triangles} triangles, more than {share} of {original}")

    chosen = {n: report["meshes"][n]["budget"] for n in PLANTS}
    picked = [c for b in options for c in options[b]
              if chosen[c["label"].split(" / ")[0]] == b]
    chosen_hits = wasted_hits(picked)
    for b, cs in options.items():
        if totals[b] <= share * original and wasted_hits(cs) < chosen_hits - 1e-12:
            fail(f"budget {b} for every mesh fits and wastes fewer hits than the choice")
    rows = {r["label"]: r for r in report["rows"]}
    if abs(rows["chosen (seed 0, the segments it was chosen on)"]["wasted_hits_per_draw"]
           - chosen_hits) > 1e-9:
        fail("the reported wasted hits on seed 0 are not the options' of the choice")
    held = json.loads((out / "final.check.json").read_text())
    if held["seed"] != 1 or any(c["counts"]["HM"] != 0 or c["exact"] != "contains"
                                for c in held["checks"]):
        fail("the held-out check is not seed 1 or a final proxy is not proved outside")
    if "scene with proxies:" not in p.stdout or "| chosen (seed 1) |" not in p.stdout:
        fail(f"no result table:\n{p.stdout}")

    # Bad arguments and an unreachable share: nothing written.
    bad = WORK / "bad"
    allocate(scene, bad, "0", expect=2)
    allocate(scene, bad, "0.5", "--check-seed", "0", expect=2)
    allocate(scene, bad, "0.5", "--budgets", "3", expect=2)
    allocate(scene, bad, "1e-6", expect=1)
    allocate(scene, bad, "0.5", "--seed", "5", expect=2)  # options measured with seed 0
    if (bad / "allocation.json").exists() or (bad / "budgets.json").exists():
        fail("a failed allocation left its outputs")
    print(f"allocation within {share:.4f}: {triangles} of {original} triangles")


if __name__ == "__main__":
    main()
