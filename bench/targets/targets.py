#!/usr/bin/env python3
"""Prints the equal-time targets from run_targets.sh's reports: per scene, the ceiling, each
estimator's efficiency against exact with its run-to-run spread and its share of the ceiling,
the best non-exact estimator, and render-compare's peak RSS.
  targets.py OUT_DIR"""
import json
import os
import re
import sys


def peak_rss_mib(path):
    try:
        text = open(path).read()
    except OSError:
        return None
    m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
    return int(m.group(1)) / 1024 if m else None


def fmt(v, spec):
    return "n/a" if v is None else format(v, spec)


def main(out):
    print("| scene | build | ceiling | estimator | spp | efficiency [min-max] | of ceiling | peak RSS |")
    print("|---|---|---:|---|---:|---|---:|---:|")
    verdicts = []
    for scene in sorted(os.listdir(out)):
        path = os.path.join(out, scene, "report.json")
        if not os.path.exists(path):
            continue
        report = json.load(open(path))
        meta = report.get("meta", {})
        rows = [r for r in report["rows"] if r["table"] == "equal-time"]
        rss = peak_rss_mib(os.path.join(out, scene, "time.txt"))
        ceiling = rows[0].get("ceiling") if rows else None
        for r in rows:
            eff = r.get("efficiency")
            spread = ""
            if r.get("efficiency_min") is not None:
                spread = f" [{r['efficiency_min']:.2f}-{r['efficiency_max']:.2f}]"
            print(f"| {scene} | {meta.get('build', '?')} | {fmt(ceiling, '.3f')} | {r['estimator']} | "
                  f"{r['spp']:.0f} | {fmt(eff, '.3f')}{spread} | {fmt(r.get('of_ceiling'), '.2f')} | "
                  f"{fmt(rss, '.0f')} MiB |")
        others = [r for r in rows if r["estimator"] != "exact" and r.get("efficiency") is not None]
        if others:
            best = max(others, key=lambda r: r["efficiency"])
            verdicts.append(f"- {scene}: best non-exact {best['estimator']} {best['efficiency']:.3f}x exact "
                            f"(target >= 0.97: {'met' if best['efficiency'] >= 0.97 else 'NOT met'})")
        roulette = [r for r in rows if r["estimator"] == "roulette"]
        if roulette and roulette[0].get("of_ceiling") is not None and ceiling is not None:
            r = roulette[0]
            line = f"- {scene}: roulette {r['of_ceiling']:.2f} of the ceiling {ceiling:.3f}"
            if ceiling >= 1.1:
                line += f"; >= 1.05x exact where the ceiling is >= 1.1: {'met' if r['efficiency'] >= 1.05 else 'NOT met'}"
            verdicts.append(line)
        if rss is not None:
            verdicts.append(f"- {scene}: peak RSS {rss:.0f} MiB (target <= 4096 MiB on ecosys)")
    print()
    print("\n".join(verdicts))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
