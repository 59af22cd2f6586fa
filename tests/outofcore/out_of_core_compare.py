#!/usr/bin/env python3
"""render-compare --geometry-budget end to end on a small unique park (3 spot sculptures and the
lawn, each its own file).

  out_of_core_compare.py BIN_DIR SOURCE_DIR WORK_DIR

Checks:
  - the report (report.json, report.md, report.html, images) has a row per policy x batch with
    the contract's keys; the baseline is the most efficient exact-batched row, recomputed here
    from each row's MSE and seconds, as is every row's relative_efficiency;
  - exact-batched and proxies-exact give the same images (both exact, whole frame or a pass per
    batch) and the same MSE; proxies-exact queues fewer (segment, mesh) pairs;
  - loads: at the budget below the scene some mesh is loaded more than once per frame; the
    roulette rows skip queues; the ceiling is there, with its model;
  - errors exit 2 with one line and leave no report: --plan, --data-parallel, --equal-time and
    --estimators with a budget, a bad --load-q or --batch-passes, the study's flags without a
    budget.
"""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from image_diff import differing_pairs  # noqa: E402
from script_checks import fail, run  # noqa: E402
from unique_park import make_park  # noqa: E402

SIZE = ["--width", "64", "--height", "48", "--seed", "5", "--threads", "2"]
ROW_KEYS = ("policy", "geometry_budget_bytes", "loads_per_frame", "bytes_read", "load_seconds",
            "peak_rss_bytes", "relative_efficiency", "mse", "seconds", "spp", "batch_passes")


def check_rows(report):
    rows = report["rows"]
    policies = {"exact-batched", "proxies-exact", "proxies-roulette"}
    if {r["policy"] for r in rows} != policies or len(rows) != 6:
        fail(f"rows: {[(r['policy'], r['batch_passes']) for r in rows]}")
    for r in rows:
        missing = [k for k in ROW_KEYS if k not in r]
        if missing:
            fail(f"row {r['policy']} lacks {missing}")
        if r["geometry_budget_bytes"] != report["geometry_budget_bytes"]:
            fail("a row's budget is not the report's")
        if not (r["loads_per_frame"] > 0 and r["bytes_read"] > 0 and r["load_seconds"] > 0
                and r["peak_rss_bytes"] > 0 and r["mse"] > 0 and r["seconds"] > 0):
            fail(f"row {r['policy']}: a measured figure is not positive: {r}")
    exact = [r for r in rows if r["policy"] == "exact-batched"]
    best = max(exact, key=lambda r: 1 / (r["mse"] * r["seconds"]))
    base_eff = 1 / (best["mse"] * best["seconds"])
    if not best["baseline"] or sum(r["baseline"] for r in rows) != 1:
        fail("the baseline must be the most efficient exact-batched row, and only it")
    for r in rows:
        rel = 1 / (r["mse"] * r["seconds"]) / base_eff
        if abs(rel - r["relative_efficiency"]) > 1e-9 * max(1, rel):
            fail(f"{r['policy']}: relative_efficiency {r['relative_efficiency']}, recomputed {rel}")
    for batch in {r["batch_passes"] for r in rows}:
        by = {r["policy"]: r for r in rows if r["batch_passes"] == batch}
        if by["exact-batched"]["mse"] != by["proxies-exact"]["mse"]:
            fail(f"batch {batch}: exact-batched and proxies-exact MSE differ")
        if not by["proxies-exact"]["queued"] < by["exact-batched"]["queued"]:
            fail(f"batch {batch}: proxies-exact queued no fewer pairs")
    if sum(r["skipped_queues"] for r in rows if r["policy"] == "proxies-roulette") <= 0:
        fail("the roulette rows skipped no queue")
    return rows


def main():
    bin_dir, source, work = sys.argv[1:4]
    compare = os.path.join(bin_dir, "render-compare")
    scene = make_park(bin_dir, source, work, 3, "spot")
    meshes = len(json.load(open(scene))["meshes"])

    out = os.path.join(work, "report")
    p = run([compare, scene, *SIZE, "--geometry-budget", "60%", "--spp", "4", "--seeds", "2",
             "--reference-spp", "32", "--batch-passes", "0,1", "--out", out, "--quiet"])
    if "| exact-batched |" not in p.stdout or "HTML report:" not in p.stdout:
        fail(f"stdout lacks the table or the report's path:\n{p.stdout}")
    report = json.load(open(os.path.join(out, "report.json")))
    if report["mode"] != "out-of-core" or report["geometry_budget"] != "60%":
        fail(f"mode {report['mode']}, budget {report['geometry_budget']}")
    if not 0 < report["geometry_budget_bytes"] < report["in_core_bytes"]:
        fail("60 % must be a budget below the scene's in-core bytes")
    rows = check_rows(report)
    if max(r["loads_per_frame"] for r in rows) <= meshes:
        fail(f"at 60 % no row loaded a mesh twice: {[r['loads_per_frame'] for r in rows]}")
    c = report["ceiling"]
    if not c or not c["relative_efficiency"] > 0 or "model" not in c:
        fail(f"ceiling: {c}")
    for name in ("report.md", "report.html", "images/reference.png", "images/reference.exr"):
        if not os.path.exists(os.path.join(out, name)):
            fail(f"no {name}")
    html = open(os.path.join(out, "report.html")).read()
    if "Oracle ceiling" not in html or "exact-batched" not in html:
        fail("report.html lacks the table or the ceiling")
    # Both exact policies give the same image, in one batch or a pass per batch.
    pairs = [(os.path.join(out, "images", "exact-batched_4spp_frame.exr"),
              os.path.join(out, "images", f"{n}.exr"))
             for n in ("proxies-exact_4spp_frame", "proxies-exact_4spp_batch1",
                       "exact-batched_4spp_batch1")]
    bad = differing_pairs(pairs, channels="R,G,B")
    if bad:
        fail("exact images differ between policies or batches: " + str(bad[:2]))
    print(f"ok: {len(rows)} rows, ceiling {c['relative_efficiency']:.2f}x, exact images equal")

    # Errors: one line, exit 2, no report folder.
    bad_out = os.path.join(work, "refused")
    base = [compare, scene, *SIZE, "--spp", "2", "--out", bad_out, "--quiet"]
    cases = [
        (["--geometry-budget", "50%", "--plan", os.path.join(work, "plan")], "--plan"),
        (["--geometry-budget", "50%", "--data-parallel"], "--data-parallel"),
        (["--geometry-budget", "50%", "--equal-time", "1"], "--equal-time"),
        (["--geometry-budget", "50%", "--estimators", "exact"], "--estimators"),
        (["--geometry-budget", "50%", "--load-q", "2"], "--load-q"),
        (["--geometry-budget", "50%", "--batch-passes", "x"], "--batch-passes"),
        (["--geometry-budget", "lots"], "--geometry-budget"),
        (["--ooc-policies", "proxies-exact"], "--ooc-policies"),
        (["--cold-reads"], "--cold-reads"),
        (["--geometry-budget", "50%", "--ooc-policies", "fast"], "unknown policy"),
    ]
    for extra, words in cases:
        p = run(base + extra, expect=2)
        lines = [line for line in p.stderr.splitlines() if line.strip()]
        if len(lines) != 1 or words not in lines[0]:
            fail(f"{extra}: one line naming {words} expected, got {lines}")
        if os.path.exists(bad_out):
            fail(f"{extra}: a refused study left {bad_out}")
    print(f"ok: {len(cases)} refusals exit 2 with one line and write nothing")


if __name__ == "__main__":
    main()
