#!/usr/bin/env python3
"""render-compare's ceiling unit measures only: with exact among --estimators it renders nothing
and the merge prices c_s with the exact cells' renders; without exact it makes its own short exact
render (docs/slurm.md, "The ceiling"). Either way the merged report has a ceiling >= 1 with a
positive shading cost c_s.

  render_compare_ceiling_unit.py RENDER_COMPARE REPO_ROOT WORK_DIR
"""
import json
import os
import shutil
import struct
import subprocess
import sys


def check(cond, msg):
    if not cond:
        print("FAIL:", msg, file=sys.stderr)
        sys.exit(1)


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    check(r.returncode == 0, f"{' '.join(cmd)}: exit {r.returncode}\n{r.stderr[-3000:]}")
    return r


def unit_header(path):
    """The JSON header of a unit result (lib/plan/unit_file.h: magic, length, JSON)."""
    with open(path, "rb") as f:
        check(f.read(8) == b"PVUNIT1\n", f"{path}: not a unit result")
        (length,) = struct.unpack("<Q", f.read(8))
        return json.loads(f.read(length))


def study(rc, scene, work, name, estimators):
    plan, out = os.path.join(work, name + "-plan"), os.path.join(work, name + "-report")
    run([rc, scene, "--width", "16", "--height", "16", "--seeds", "1", "--spp", "2",
         "--estimators", estimators, "--equal-time", "0", "--reference-spp", "1",
         "--threads", "1", "--quiet", "--out", out, "--plan", plan])
    with open(os.path.join(plan, "plan.json")) as f:
        units = json.load(f)["render_compare"]["unit_list"]
    for k in range(len(units)):
        run([rc, "--run-unit", plan, str(k), "--quiet"])
    run([rc, "--merge", plan])
    ceiling_unit = [k for k, u in enumerate(units) if u["kind"] == "ceiling"]
    check(len(ceiling_unit) == 1, f"{name}: {len(ceiling_unit)} ceiling units")
    header = unit_header(os.path.join(plan, "units", f"{ceiling_unit[0]}.result"))
    measured = header["ceiling"]
    check(measured["passes"] >= 2 and measured["regions"], f"{name}: no measurement: {measured}")
    with open(os.path.join(out, "report.json")) as f:
        ceiling = json.load(f)["meta"]["ceiling"]
    check(ceiling["value"] >= 1, f"{name}: ceiling {ceiling['value']}")
    check(ceiling["lights"][-1]["cost_per_sample"] > 0,
          f"{name}: c_s not priced: {ceiling['lights'][-1]}")
    return header["renders"]


def main():
    rc, repo, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    scene = os.path.join(repo, "scenes", "cornell-bunny.json")
    renders = study(rc, scene, work, "with-exact", "exact,roulette")
    check(renders == [], f"with exact cells the ceiling unit rendered {len(renders)} images")
    renders = study(rc, scene, work, "without-exact", "culling,roulette")
    check(len(renders) == 1 and renders[0]["spp"] == 4,
          f"without exact cells the ceiling unit must make one 4-spp exact render: {renders}")
    print("render_compare_ceiling_unit: ok")


if __name__ == "__main__":
    main()
