#!/usr/bin/env python3
"""render-compare's ceiling in every report: runs render-compare with --json - and checks that
every row has `ceiling` and `of_ceiling` with of_ceiling == efficiency / ceiling (null where the
efficiency is), that meta.ceiling holds the per-light table and the explanation, and that the
Markdown and HTML reports show it. --ceiling-one also requires ceiling 1 and an explanation
starting with --explanation."""
import argparse
import json
import math
import os
import subprocess
import sys


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True, help="the --out folder given to render-compare")
    ap.add_argument("--ceiling-one", action="store_true")
    ap.add_argument("--explanation", default="")
    ap.add_argument("command", nargs=argparse.REMAINDER)
    a = ap.parse_args()
    cmd = a.command[1:] if a.command and a.command[0] == "--" else a.command
    run = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    if run.returncode != 0:
        fail(f"exit {run.returncode}\n{run.stderr}")
    report = json.loads(run.stdout)
    meta = report["meta"]["ceiling"]
    value = meta["value"]
    if not (isinstance(value, float) or isinstance(value, int)) or not value >= 1:
        fail(f"meta.ceiling.value {value} is not a number >= 1")
    for key in ("explanation", "model", "passes", "seconds", "run_share", "lights"):
        if key not in meta:
            fail(f"meta.ceiling has no {key}")
    # Two sentences.
    if meta["explanation"].count(". ") + meta["explanation"].endswith(".") != 2:
        fail(f"the explanation is not two sentences: {meta['explanation']}")
    lights = meta["lights"]
    if not lights or lights[-1]["light"] != "all" or lights[-1]["ceiling"] != value:
        fail(f"the per-light table does not end with the scene's line: {lights}")
    for line in lights:
        for key in ("segments", "p_proxy_blocked", "p_mh", "p_hm", "var_exact", "cost_proxy",
                    "cost_original", "cost_per_sample", "regions", "regions_roulette", "ceiling"):
            if key not in line:
                fail(f"light {line.get('light')} has no {key}")
    if a.ceiling_one and value != 1:
        fail(f"ceiling {value}, expected 1")
    if not meta["explanation"].startswith(a.explanation):
        fail(f"explanation does not start with '{a.explanation}': {meta['explanation']}")
    for i, row in enumerate(report["rows"]):
        if "ceiling" not in row or "of_ceiling" not in row:
            fail(f"row {i} lacks ceiling or of_ceiling: {sorted(row)}")
        if row["ceiling"] != value:
            fail(f"row {i}: ceiling {row['ceiling']} != the scene's {value}")
        eff = row["efficiency"]
        if eff is None:
            if row["of_ceiling"] is not None:
                fail(f"row {i}: of_ceiling {row['of_ceiling']} without an efficiency")
            continue
        if not math.isclose(row["of_ceiling"], eff / value, rel_tol=1e-12):
            fail(f"row {i}: of_ceiling {row['of_ceiling']} != {eff} / {value}")
    md = open(os.path.join(a.out, "report.md"), encoding="utf-8").read()
    html = open(os.path.join(a.out, "report.html"), encoding="utf-8").read()
    if "## Ceiling: " not in md or "| of ceiling |" not in md:
        fail("report.md has no ceiling section or column")
    if "<h2>Ceiling: " not in html or "<th>of ceiling</th>" not in html:
        fail("report.html has no ceiling section or column")
    print(f"ceiling {value}: {meta['explanation']}")


if __name__ == "__main__":
    main()
