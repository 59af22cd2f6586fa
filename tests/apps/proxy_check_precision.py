#!/usr/bin/env python3
"""proxy-check --precision on a pair whose two readings disagree (docs/clearance.md).

  proxy_check_precision.py BIN_DIR WORK_DIR

The original is a unit box whose top is a fan around a dent vertex D = (0.25, 0.25, z): z is
written as the decimal 0.99999991655349731445, which rounds to float as 1 - 2^-24 and to double
as 1 - 1.4 * 2^-24. The inside proxy is the box inset by 1/256, its top split along the diagonal
through D at 1 - 2^-24 (corner (a, a)) and 1 - 2 * 2^-24 (corner (b, b)): at D it is about
1 - 1.25 * 2^-24, between the two readings of D. So the proxy is inside the float reading and
crosses the double one:
  --precision float   exact 'contained', --expect inside holds (exit 0)
  --precision double  exact 'intersecting', --expect inside is contradicted (exit 1)
  --precision both    (the default) both verdicts, precision_mismatch set, exit 1
and proxy-gen --clearance-ulps 0 on the same original gives an inside proxy only when it holds in
both readings (exit 0 with a clearance, or a failure naming the double reading).
"""
import json
import os
import subprocess
import sys

DENT = "0.99999991655349731445"
ULP = 2.0 ** -24


def fail(msg):
    print(f"FAIL: {msg}")
    sys.exit(1)


def write_original(path):
    with open(path, "w") as f:
        f.write("OFF\n9 14 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n")
        f.write(f"0.25 0.25 {DENT}\n")
        for t in ["0 2 1", "0 3 2", "0 1 5", "0 5 4", "1 2 6", "1 6 5", "2 3 7", "2 7 6",
                  "3 0 4", "3 4 7", "4 5 8", "5 6 8", "6 7 8", "7 4 8"]:
            f.write(f"3 {t}\n")


def write_proxy(path):
    a, b = 1.0 / 256, 1 - 1.0 / 256
    high, low = repr(1 - ULP), repr(1 - 2 * ULP)  # both floats: exact in any reading
    v = [(a, a, a), (b, a, a), (b, b, a), (a, b, a),
         (a, a, high), (b, a, high), (b, b, low), (a, b, high)]
    with open(path, "w") as f:
        f.write("OFF\n8 12 0\n")
        for x, y, z in v:
            f.write(f"{x!r} {y!r} {z}\n")
        for t in ["0 2 1", "0 3 2", "0 1 5", "0 5 4", "1 2 6", "1 6 5", "2 3 7", "2 7 6",
                  "3 0 4", "3 4 7", "4 5 6", "4 6 7"]:
            f.write(f"3 {t}\n")


def check(bin_dir, original, proxy, precision):
    cmd = [os.path.join(bin_dir, "proxy-check"), original, proxy, "--expect", "inside",
           "--rays", "2000", "--json", "-", "-q"]
    if precision:
        cmd += ["--precision", precision]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    if p.returncode not in (0, 1):
        fail(f"{' '.join(cmd)}: exit {p.returncode}: {p.stderr}")
    return p.returncode, json.loads(p.stdout)


def main():
    bin_dir, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    original, proxy = os.path.join(work, "dented_box.off"), os.path.join(work, "tight.off")
    write_original(original)
    write_proxy(proxy)

    code, j = check(bin_dir, original, proxy, "float")
    if code != 0 or j["exact"] != "contained" or j["precision"] != "float":
        fail(f"float reading: exit {code}, {j['exact']}, {j['exact_detail']}")
    code, j = check(bin_dir, original, proxy, "double")
    if code != 1 or j["exact"] == "contained" or j["precision"] != "double":
        fail(f"double reading: exit {code}, {j['exact']}")
    code, j = check(bin_dir, original, proxy, None)
    if (code != 1 or j["precision"] != "both" or j["exact"] != "contained"
            or j.get("exact_double") == "contained" or not j.get("precision_mismatch")):
        fail(f"both readings: exit {code}, {j['exact']} / {j.get('exact_double')}")
    print(f"OK: proxy-check tells the readings apart: {j['precision_mismatch']}")

    out = os.path.join(work, "gen.off")
    report = os.path.join(work, "gen.json")
    for ulps in ("8", "0"):
        if os.path.exists(out):
            os.remove(out)
        p = subprocess.run([os.path.join(bin_dir, "proxy-gen"), original, "--kind", "inside",
                            "--max-faces", "12", "--clearance-ulps", ulps, "-o", out,
                            "--json", report, "-q"], capture_output=True, text=True, timeout=300)
        if p.returncode == 0:
            r = json.load(open(report))
            c = r["checks"]
            if c.get("containment_double") != "contained" or c["containment"] != "contained":
                fail(f"--clearance-ulps {ulps}: written with {c}")
            code, j = check(bin_dir, original, out, None)
            if code != 0:
                fail(f"--clearance-ulps {ulps}: proxy-check says {j['exact']} / "
                     f"{j.get('exact_double')}")
        elif p.returncode == 1:
            if ulps != "0" or "double reading" not in p.stderr or os.path.exists(out):
                fail(f"--clearance-ulps {ulps}: exit 1: {p.stderr}")
        else:
            fail(f"--clearance-ulps {ulps}: exit {p.returncode}: {p.stderr}")
        print(f"OK: proxy-gen --clearance-ulps {ulps}: exit {p.returncode}")


if __name__ == "__main__":
    main()
