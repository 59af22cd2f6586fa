#!/usr/bin/env python3
"""The README's table of every closed bundled mesh at 2 % of its faces: proxy-gen's outside wrap,
outside convex parts and inside wrap at --ratio 0.02, and the two outside methods at 200 faces;
each cell the written volume ratio (every proxy proved, or the cell says its class).

    python3 bench/proxy_gen/closed_mesh_table.py [--bin build/bin] [--data data] [--threads 2]

Prints a Markdown table and the seconds each run took.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

MESHES = [("fandisk", "hard/fandisk.off"), ("dragon", "dragon.drc"), ("bunny", "bunny.off"),
          ("spot", "spot_triangulated.obj"), ("3holes (genus 3)", "hard/3holes.off"),
          ("cow (thin legs)", "hard/cow.off")]
CELLS = [("outside", "wrap", ["--ratio", "0.02"]), ("outside", "convex-parts", ["--ratio", "0.02"]),
         ("inside", "wrap", ["--ratio", "0.02"]), ("outside", "wrap", ["--max-faces", "200"]),
         ("outside", "convex-parts", ["--max-faces", "200"])]


def main():
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bin", default=os.path.join(root, "build", "bin"))
    ap.add_argument("--data", default=os.path.join(root, "data"))
    ap.add_argument("--threads", default="2")
    a = ap.parse_args()
    rows, seconds = [], 0.0
    with tempfile.TemporaryDirectory() as work:
        for label, rel in MESHES:
            cells, faces = [], None
            for kind, method, budget in CELLS:
                report = os.path.join(work, "r.json")
                t0 = time.monotonic()
                p = subprocess.run([os.path.join(a.bin, "proxy-gen"), os.path.join(a.data, rel),
                                    "--kind", kind, "--method", method, *budget, "-o",
                                    os.path.join(work, "p.ply"), "--json", report, "--quiet",
                                    "--threads", a.threads, "--no-cache"],
                                   capture_output=True, text=True)
                seconds += time.monotonic() - t0
                if p.returncode != 0:
                    cells.append(f"exit {p.returncode}")
                    continue
                r = json.load(open(report))
                if faces is None and budget[0] == "--ratio":
                    faces = r["faces"]
                ratio = f"{r['volume_ratio']:.3f}"
                cells.append(ratio if r["class"] == kind else f"{ratio} ({r['class']})")
            rows.append(f"| {label} | {faces} | {cells[0]} | {cells[1]} | {cells[2]} | "
                        f"{cells[3]} / {cells[4]} |")
            print(rows[-1], file=sys.stderr)
    print("| mesh | faces | outside wrap | outside convex parts | inside wrap | "
          "outside at 200 faces (wrap / convex parts) |")
    print("|---|---:|---:|---:|---:|---:|")
    print("\n".join(rows))
    print(f"\n{len(MESHES) * len(CELLS)} proxy-gen runs in {seconds:.0f} s")


if __name__ == "__main__":
    main()
