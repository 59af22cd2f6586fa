#!/usr/bin/env python3
"""What a render-compare plan's units hold and what the merge costs, for docs/film_scale.md.

For each case (image size, seeds) it plans a cornell-bunny study (exact, culling, roulette at
1 spp, --equal-time 0, --reference-spp 16: 3 x seeds equal-spp units + 1 ceiling + 16 reference
partials), runs its units with scripts/slurm/submit.sh --local --jobs 2 (one thread each), then
times `render-compare --merge` on its own --repeats times (wall, user + sys CPU, peak RSS; the
best of the repeats). Prints the unit result sizes per pixel by kind and the merge table.

  bench/film/merge_cost.py build out/film/merge [--cases 128x4,256x4,256x16,512x4,1024x4]
      [--repeats 3]
  bench/film/merge_cost.py build out/film/merge --tables-only   # again from merge_cost.json

Then fits merge CPU = c + a * units * pixels + b * pixels (reading the units grows with both;
writing the report's images with the pixels alone) by least squares.
"""
import argparse
import json
import os
import shutil
import struct
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def unit_kind(path):
    """The unit kind from a units/K.result header ("PVUNIT1\\n", 8-byte length, JSON)."""
    with open(path, "rb") as f:
        magic = f.read(8)
        if magic != b"PVUNIT1\n":
            raise SystemExit(f"merge_cost.py: error: {path}: not a unit result")
        (length,) = struct.unpack("<Q", f.read(8))
        header = json.loads(f.read(length))
    kind = header.get("kind", "?")
    return kind, header, length


def timed(argv):
    """Runs argv under /usr/bin/time; returns (wall s, CPU s, peak RSS KiB)."""
    fmt = "%e %U %S %M"
    r = subprocess.run(["/usr/bin/time", "-f", fmt] + argv, capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"merge_cost.py: error: {argv[0]}: exit {r.returncode}: {r.stderr[-400:]}")
    wall, user, sys_, rss = r.stderr.strip().splitlines()[-1].split()
    return float(wall), float(user) + float(sys_), int(rss)


def run_case(build, out, size, seeds, repeats):
    case_dir = os.path.join(out, f"{size}x{seeds}")
    shutil.rmtree(case_dir, ignore_errors=True)
    plan = os.path.join(case_dir, "plan")
    rc = os.path.join(build, "bin", "render-compare")
    subprocess.run([rc, os.path.join(ROOT, "scenes", "cornell-bunny.json"), "--out",
                    os.path.join(case_dir, "report"), "--estimators", "exact,culling,roulette",
                    "--spp", "1", "--seeds", str(seeds), "--equal-time", "0",
                    "--reference-spp", "16", "--width", str(size), "--height", str(size),
                    "--threads", "1", "--quiet", "--plan", plan], check=True)
    start = time.monotonic()
    subprocess.run([os.path.join(ROOT, "scripts", "slurm", "submit.sh"), plan, "--local",
                    "--jobs", "2"], check=True, stdout=subprocess.DEVNULL)
    units_wall = time.monotonic() - start
    by_kind = {}
    units = 0
    total = 0
    for name in os.listdir(os.path.join(plan, "units")):
        if not name.endswith(".result"):
            continue
        path = os.path.join(plan, "units", name)
        kind, header, header_len = unit_kind(path)
        size_b = os.path.getsize(path)
        units += 1
        total += size_b
        k = by_kind.setdefault(kind, {"n": 0, "min": 1e30, "max": 0, "header": 0})
        k["n"] += 1
        k["min"] = min(k["min"], size_b)
        k["max"] = max(k["max"], size_b)
        k["header"] = max(k["header"], header_len)
    merges = [timed([rc, "--merge", plan, "--quiet"]) for _ in range(repeats)]
    report = sum(os.path.getsize(os.path.join(dp, f))
                 for dp, _, fs in os.walk(os.path.join(case_dir, "report")) for f in fs)
    return {"size": size, "seeds": seeds, "units": units, "bytes": total, "kinds": by_kind,
            "units_wall": units_wall, "merge_wall": min(m[0] for m in merges),
            "merge_cpu": min(m[1] for m in merges), "merge_rss_kib": max(m[2] for m in merges),
            "merge_walls": [m[0] for m in merges], "report_bytes": report}


def solve3(rows, ys):
    """Least squares for 3 coefficients: the normal equations, Gauss-Jordan."""
    m = [[sum(r[i] * r[j] for r in rows) for j in range(3)] +
         [sum(r[i] * y for r, y in zip(rows, ys))] for i in range(3)]
    for c in range(3):
        p = max(range(c, 3), key=lambda r: abs(m[r][c]))
        m[c], m[p] = m[p], m[c]
        if abs(m[c][c]) < 1e-300:
            return None
        for r in range(3):
            if r != c:
                f = m[r][c] / m[c][c]
                m[r] = [a - f * b for a, b in zip(m[r], m[c])]
    return [m[i][3] / m[i][i] for i in range(3)]


def print_fit(results):
    if len(results) < 3:
        return
    # Columns scaled to about 1 (pixels ~1e6) before solving.
    rows = [(1.0, r["units"] * r["size"] ** 2 / 1e6, r["size"] ** 2 / 1e6) for r in results]
    fit = solve3(rows, [r["merge_cpu"] for r in results])
    if fit is None:
        print("\nmerge CPU: the cases do not determine the fit (vary units and size)")
        return
    c, a, b = fit
    worst = max(abs(r["merge_cpu"] - (c + a * u + b * p)) / r["merge_cpu"]
                for r, (_, u, p) in zip(results, rows))
    print(f"\nmerge CPU s = {c:.2f} + {a:.3f} us x unit x pixel + {b:.2f} us x pixel "
          f"(max residual {100 * worst:.0f} %)")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build")
    ap.add_argument("out")
    ap.add_argument("--cases", default="128x4,256x4,256x16,512x4,1024x4")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--tables-only", action="store_true",
                    help="print the tables of OUT/merge_cost.json; run nothing")
    a = ap.parse_args()
    if a.repeats < 1 or a.repeats > 20:
        raise SystemExit("merge_cost.py: error: --repeats: must be in [1, 20]")
    results = []
    if a.tables_only:
        with open(os.path.join(a.out, "merge_cost.json")) as f:
            results = json.load(f)
    for case in ([] if a.tables_only else a.cases.split(",")):
        size, seeds = (int(v) for v in case.split("x"))
        results.append(run_case(a.build, a.out, size, seeds, a.repeats))
        print(f"case {case} done", file=sys.stderr, flush=True)
    print("| size | units | unit kind | units of kind | bytes per unit | header bytes | "
          "bytes / pixel |")
    print("|---|---:|---|---:|---:|---:|---:|")
    for r in results:
        px = r["size"] ** 2
        for kind, k in sorted(r["kinds"].items()):
            span = (f"{k['min']:,}" if k["min"] == k["max"] else f"{k['min']:,}-{k['max']:,}")
            bpp = (f"{k['min'] / px:.2f}" if k["min"] == k["max"]
                   else f"{k['min'] / px:.2f}-{k['max'] / px:.2f}")
            print(f"| {r['size']}x{r['size']} | {r['units']} | {kind} | {k['n']} | {span} | "
                  f"{k['header']:,} | {bpp} |")
    print()
    print("| size | seeds | units | unit results MB | units wall s (2 jobs) | merge wall s (best; all) "
          "| merge CPU s | merge peak RSS MiB | report MB | merge CPU us / (unit x kpixel) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in results:
        kpx = r["size"] ** 2 / 1000
        walls = ", ".join(f"{w:.2f}" for w in r["merge_walls"])
        print(f"| {r['size']}x{r['size']} | {r['seeds']} | {r['units']} | {r['bytes'] / 1e6:.1f} | "
              f"{r['units_wall']:.1f} | {r['merge_wall']:.2f} ({walls}) | {r['merge_cpu']:.2f} | "
              f"{r['merge_rss_kib'] / 1024:.0f} | {r['report_bytes'] / 1e6:.1f} | "
              f"{1e6 * r['merge_cpu'] / (r['units'] * kpx):.1f} |")
    print_fit(results)
    if not a.tables_only:
        with open(os.path.join(a.out, "merge_cost.json"), "w") as f:
            json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
