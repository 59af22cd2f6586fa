#!/usr/bin/env python3
"""Side by side: our proved outside proxies (proxy-gen --method wrap, --method hull, one convex
piece, and --method convex-parts, a union of convex pieces) and V-HACD's convex decomposition (npm vhacd-js, a WebAssembly build, run by
vhacd_run.mjs) on the same meshes at the same face budgets. Prints a Markdown table: faces, volume ratio, seconds and
containment. Ours are proved by proxy-gen's exact check; V-HACD's are not, so for every row the
share of the input's volume left outside the output is measured by Monte Carlo (bench_cover: the
same seeded points for every row, 1 M by default, with its standard error).

  bench/vhacd_compare/bench_vhacd.py [--bin build/bin] [--mesh FILE ...] [--samples N]
                                     [--row wrap|hull|convex-parts|vhacd|vhacd-64 ...]
                                     [--json OUT.json]

Needs `npm ci` in bench/vhacd_compare (./setup.sh bench-deps does it). Never fails on a figure.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DEFAULT_MESHES = ["data/hard/3holes.off", "data/hard/fandisk.off", "data/hard/cow.off",
                  "data/bunny.off", "data/spot_triangulated.obj", "data/dragon.drc"]


ROWS = ["wrap", "hull", "convex-parts", "vhacd", "vhacd-64"]


def run(cmd):
    t0 = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} exited {p.returncode}: {p.stderr.strip()}")
    return p.stdout, time.perf_counter() - t0


def input_faces(bin_dir, mesh):
    out, _ = run([os.path.join(bin_dir, "mesh-info"), mesh, "--json", "-", "-q"])
    return json.loads(out)[0]["faces"]


def cover(bin_dir, mesh, mode, other, samples):
    out, _ = run([os.path.join(bin_dir, "bench_cover"), mesh, mode, other,
                  "--samples", str(samples)])
    return json.loads(out)


def ours(bin_dir, mesh, method, budget, work, samples):
    out = os.path.join(work, f"{method}.ply")
    report = os.path.join(work, f"{method}.json")
    _, seconds = run([os.path.join(bin_dir, "proxy-gen"), mesh, "--kind", "outside", "--method",
                      method, "--max-faces", str(budget), "-o", out, "--json", report, "-q"])
    r = json.load(open(report))
    c = cover(bin_dir, mesh, "--solid", out, samples)
    return {"method": method, "faces": r["faces"], "volume_ratio": r["volume_ratio"],
            "mc_volume_ratio": c["volume_ratio"], "uncovered_share": c["uncovered_share"],
            "uncovered_stderr": c["uncovered_share_stderr"], "seconds": seconds,
            "proved": r["class"] == "outside" and r["verified"], "pieces": r.get("parts", 1)}


def vhacd(bin_dir, mesh, budget, work, samples, verts=None):
    # About 12 faces per piece, and vertices per hull so that the total face count (a hull of V
    # vertices has 2V - 4 faces) meets the budget; or `verts` per hull (V-HACD's default is 64),
    # to show what its hulls cover when the budget does not bind them.
    hulls = min(32, max(2, budget // 12))
    verts = verts or max(4, (budget // hulls + 4) // 2)
    obj = os.path.join(work, "mesh.obj")
    if not mesh.endswith(".obj"):
        run([os.path.join(bin_dir, "mesh-info"), mesh, "--save", obj, "-q"])
    else:
        obj = mesh
    out = os.path.join(work, "vhacd.obj")
    stdout, wall = run(["node", os.path.join(HERE, "vhacd_run.mjs"), "--in", obj, "--out", out,
                        "--max-hulls", str(hulls), "--max-vertices-per-hull", str(verts)])
    r = json.loads(stdout)
    c = cover(bin_dir, mesh, "--hulls", out, samples)
    return {"method": f"V-HACD ({verts} vertices/hull)", "faces": r["faces"], "volume_ratio": None,
            "mc_volume_ratio": c["volume_ratio"], "uncovered_share": c["uncovered_share"],
            "uncovered_stderr": c["uncovered_share_stderr"], "seconds": r["seconds"],
            "wall_seconds": wall, "proved": False, "pieces": r["hulls"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"))
    ap.add_argument("--mesh", action="append", help="default: the hard set's closed meshes and "
                    "the bundled bunny, spot and dragon")
    ap.add_argument("--samples", type=int, default=1_000_000)
    ap.add_argument("--row", action="append", choices=ROWS,
                    help="only these rows (repeatable); default: all")
    ap.add_argument("--json", help="also write the rows as JSON")
    a = ap.parse_args()
    meshes = a.mesh or [os.path.join(ROOT, m) for m in DEFAULT_MESHES]
    rows = []
    print("| mesh | budget | method | pieces | faces | volume ratio | input volume outside "
          "(MC) | seconds | proved |")
    print("|---|---|---|---:|---:|---:|---:|---:|---|")
    for mesh in meshes:
        n = input_faces(a.bin, mesh)
        for label, budget in (("2 %", max(12, int(0.02 * n))), ("200", 200)):
            with tempfile.TemporaryDirectory() as work:
                makers = {
                    "wrap": lambda: ours(a.bin, mesh, "wrap", budget, work, a.samples),
                    "hull": lambda: ours(a.bin, mesh, "hull", budget, work, a.samples),
                    "convex-parts":
                        lambda: ours(a.bin, mesh, "convex-parts", budget, work, a.samples),
                    "vhacd": lambda: vhacd(a.bin, mesh, budget, work, a.samples),
                    "vhacd-64": lambda: vhacd(a.bin, mesh, budget, work, a.samples, 64)}
                for make in (makers[r] for r in (a.row or ROWS)):
                    try:
                        row = make()
                    except RuntimeError as e:
                        print(f"| {os.path.basename(mesh)} | {label} | error: {e} |||||||")
                        continue
                    row.update(mesh=os.path.basename(mesh), budget=budget, budget_label=label)
                    rows.append(row)
                    ratio = row["volume_ratio"] if row["volume_ratio"] else row["mc_volume_ratio"]
                    outside = (f"{100 * row['uncovered_share']:.3f} % ± "
                               f"{100 * row['uncovered_stderr']:.3f}")
                    print(f"| {row['mesh']} | {label} ({budget}) | {row['method']} | "
                          f"{row['pieces'] or ''} | {row['faces']} | {ratio:.3f} | {outside} | "
                          f"{row['seconds']:.2f} | {'yes' if row['proved'] else 'no'} |",
                          flush=True)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
