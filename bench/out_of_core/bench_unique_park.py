#!/usr/bin/env python3
"""The out-of-core comparison on the unique sculpture park: render-compare --geometry-budget at
each budget, the policies interleaved seed by seed inside each run, one table per budget
(time, loads, bytes, peak RSS, the render's RSS growth + proxies against budget + proxies + image
+ 10 %, MSE, efficiency 1/(MSE x time) relative to the best batched exact)
and the oracle ceiling. Never fails on speed.

  bench_unique_park.py [--count 100] [--budgets 10%,25%,50%] [--spp 8] [--seeds 3]
                       [--batch-passes 0,2] [--load-q learned] [--cold-reads]
                       [--size 320x240] [--work out/bench-ooc] [--bin build/bin]

The park (scenes/make_unique_park.py: every sculpture its own Draco file, with outside and
inside proxies at 2 %) is made once in WORK and reused.
"""
import argparse
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--count", type=int, default=100)
    ap.add_argument("--budgets", default="10%,25%,50%")
    ap.add_argument("--spp", default="8")
    ap.add_argument("--seeds", default="3")
    ap.add_argument("--batch-passes", default="0,2")
    ap.add_argument("--load-q", default="learned")
    ap.add_argument("--cold-reads", action="store_true")
    ap.add_argument("--size", default="320x240")
    ap.add_argument("--reference-spp", default="256")
    ap.add_argument("--work", default=os.path.join(ROOT, "out", "bench-ooc"))
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"))
    a = ap.parse_args()
    park = os.path.join(a.work, f"park-{a.count}")
    scene = os.path.join(park, "unique-park.json")
    if not os.path.exists(scene):
        subprocess.run([sys.executable, os.path.join(ROOT, "scenes", "make_unique_park.py"),
                        "--count", str(a.count), "--out", park,
                        "--proxy-gen", os.path.join(a.bin, "proxy-gen"),
                        "--mesh-info", os.path.join(a.bin, "mesh-info")], check=True)
    width, height = a.size.split("x")
    for budget in a.budgets.split(","):
        out = os.path.join(a.work, f"report-{a.count}-{budget.rstrip('%')}")
        args = [os.path.join(a.bin, "render-compare"), scene, "--geometry-budget", budget,
                "--width", width, "--height", height, "--spp", a.spp, "--seeds", a.seeds,
                "--batch-passes", a.batch_passes, "--load-q", a.load_q,
                "--reference-spp", a.reference_spp, "--threads", "2", "--out", out, "--quiet"]
        if a.cold_reads:
            args.append("--cold-reads")
        subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
        report = json.load(open(os.path.join(out, "report.json")))
        mib = 1 << 20
        print(f"\n## {a.count} sculptures, budget {budget} = "
              f"{report['geometry_budget_bytes'] / mib:.1f} of {report['in_core_bytes'] / mib:.1f}"
              f" MiB, proxies {report['proxy_bytes'] / mib:.1f} MiB, {a.size}, {a.spp} spp, "
              f"{report['seeds']} seeds (scan {report['scan_seconds']:.1f} s)\n")
        print("| policy | batch | cache | q | loads | MB read | load s | peak RSS MiB | "
              "held / bound MiB | time s | rays/s | MSE | efficiency |")
        print("|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        for r in report["rows"]:
            rays = r["shadow_segments"] / r["seconds"] if r.get("shadow_segments") else 0
            print(f"| {r['policy']} | {r['batch_passes'] or 'frame'} | {r['page_cache']} | "
                  f"{r['load_q']} ({r['mean_load_q']:.2f}) | {r['loads_per_frame']:.1f} | "
                  f"{r['bytes_read'] / 1e6:.1f} | {r['load_seconds']:.2f} | "
                  f"{r['peak_rss_bytes'] / mib:.0f} | {r['bounded_peak_bytes'] / mib:.1f} / "
                  f"{r['rss_bound_bytes'] / mib:.1f}{'' if r['within_rss_bound'] else ' (over)'} | "
                  f"{r['seconds']:.2f} | {rays:.3g} | "
                  f"{r['mse']:.3e} | {r['relative_efficiency']:.2f}x"
                  f"{' (baseline)' if r['baseline'] else ''} |")
        c = report["ceiling"]
        if c:
            print(f"\noracle ceiling (modelled): {c['relative_efficiency']:.2f}x, mean q "
                  f"{c['mean_q']:.2f}, {c['queues_skipped_per_frame']:.1f} of "
                  f"{c['queues_per_frame']:.1f} queues skipped outright")
        print(f"report: {os.path.join(out, 'report.html')}")


if __name__ == "__main__":
    main()
