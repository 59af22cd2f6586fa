#!/usr/bin/env python3
"""One case of the hard-set matrix: proxy-gen on one mesh with one kind, method and budget, then
an independent check of what it wrote.

Whatever proxy-gen decides, the outcome must be one of:
  exit 0  the proxy file exists; its face count is within the budget (computed here from the
          input's face count as reported by mesh-info, not from proxy-gen's report); mesh-info
          finds it closed and manifold; for a written class outside/inside, proxy-check against
          the INPUT file confirms it (exact containment in the float and the double reading,
          zero HM' resp. MH' sampled rays), and so does independent_double_check (CGAL's own
          readers in double, no proxyvis code) when --independent names it; the report states
          the clearance and a measured separation of at least that.
  exit 1  (only with a budget) one line on stderr saying the budget was not met, no output.
  exit 2  only where the case allows a refusal (e.g. an inside proxy of a mesh with no
          interior): one line on stderr naming the input, no output.
Anything else (a crash, a signal, a timeout, several stderr lines, a leftover file) fails.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile


def run(cmd, timeout):
    try:
        return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        fail(f"timed out after {timeout} s: {' '.join(cmd)}")


def fail(msg):
    print(f"FAIL: {msg}")
    sys.exit(1)


def stderr_lines(p):
    return [line for line in p.stderr.splitlines() if line.strip()]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True, help="folder with proxy-gen, proxy-check, mesh-info")
    ap.add_argument("--mesh", required=True)
    ap.add_argument("--kind", required=True)
    ap.add_argument("--method", required=True)
    ap.add_argument("--ratio", type=float, default=0.0, help="0 = no budget")
    ap.add_argument("--max-faces", type=int, default=0, help="a face budget (instead of --ratio)")
    ap.add_argument("--fill-holes", action="store_true")
    ap.add_argument("--allow-refusal", default="",
                    help="regex: exit 2 is accepted when stderr matches it")
    ap.add_argument("--timeout", type=float, default=300)
    ap.add_argument("--rays", type=int, default=200000)
    ap.add_argument("--independent", default="",
                    help="independent_double_check: also check a written class with it")
    a = ap.parse_args()

    tool = lambda name: os.path.join(a.bin, name)
    info = run([tool("mesh-info"), a.mesh, "--json", "-", "-q"], 60)
    if info.returncode != 0:
        fail(f"mesh-info cannot read the input: {info.stderr.strip()}")
    input_faces = json.loads(info.stdout)[0]["faces"]
    budget = max(12, int(a.ratio * input_faces)) if a.ratio > 0 else None
    if a.max_faces > 0:
        budget = a.max_faces

    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "proxy.ply")
        report = os.path.join(work, "report.json")
        cmd = [tool("proxy-gen"), a.mesh, "--kind", a.kind, "--method", a.method, "-o", out,
               "--json", report, "-q", "--threads", "1"]
        if a.ratio > 0:
            cmd += ["--ratio", str(a.ratio)]
        if a.max_faces > 0:
            cmd += ["--max-faces", str(a.max_faces)]
        if a.fill_holes:
            cmd.append("--fill-holes")
        p = run(cmd, a.timeout)
        lines = stderr_lines(p)
        print(f"proxy-gen exit {p.returncode}; stderr: {lines}")
        if p.returncode not in (0, 1, 2):
            fail(f"proxy-gen ended with {p.returncode} (a crash or signal?)")
        if p.returncode != 0:
            if len(lines) != 1:
                fail(f"a failure must say one line on stderr, got {len(lines)}")
            left = sorted(os.listdir(work))
            if left:
                fail(f"a failed run left files behind: {left}")
            if p.returncode == 1:
                if budget is None:
                    fail("exit 1 without a budget: a guarantee failed")
                if "budget" not in lines[0]:
                    fail("exit 1 must say which budget was not met")
                print("OK: budget not met, the run failed cleanly")
                return
            import re
            if not a.allow_refusal or not re.search(a.allow_refusal, lines[0]):
                fail("refused (exit 2) where this case expects a proxy")
            if os.path.basename(a.mesh) not in lines[0]:
                fail("the refusal does not name the input file")
            print("OK: refused as allowed")
            return

        if not os.path.exists(out):
            fail("exit 0 but no proxy written")
        rep = json.load(open(report))
        cls = rep.get("class")
        faces = rep.get("faces")
        pinfo = run([tool("mesh-info"), out, "--json", "-", "-q"], 60)
        if pinfo.returncode != 0:
            fail(f"mesh-info cannot read the proxy: {pinfo.stderr.strip()}")
        pj = json.loads(pinfo.stdout)[0]
        print(f"class {cls}, {pj['faces']} faces (budget {budget}), "
              f"volume ratio {rep.get('volume_ratio')}")
        if pj["faces"] != faces:
            fail(f"the report says {faces} faces, the file has {pj['faces']}")
        if budget is not None and pj["faces"] > budget:
            fail(f"{pj['faces']} faces exceed the budget of {budget} and the run exited 0")
        if cls in ("outside", "inside"):
            if not (pj["closed"] and pj["manifold"]):
                fail(f"an {cls} proxy must be closed and manifold: {pj}")
            chk = run([tool("proxy-check"), a.mesh, out, "--expect", cls, "--rays",
                       str(a.rays), "--json", "-", "-q", "--seed", "7"], a.timeout)
            if chk.returncode != 0:
                fail(f"proxy-check --expect {cls} exit {chk.returncode}: {chk.stderr.strip()}")
            cj = json.loads(chk.stdout)
            want = "contains" if cls == "outside" else "contained"
            bad = "HM" if cls == "outside" else "MH"
            if cj["exact"] != want:
                fail(f"exact check says {cj['exact']}, the class needs {want}")
            if cj["counts"][bad] != 0:
                fail(f"{cj['counts'][bad]} {bad}' rays for an {cls} proxy")
            if cj["precision"] != "both" or cj.get("exact_double") != want:
                fail(f"double reading: {cj.get('exact_double')} ({cj.get('exact_double_detail')})")
            checks = rep["checks"]
            if not checks.get("clearance") or checks.get("separation", 0) < checks["clearance"]:
                fail(f"clearance {checks.get('clearance')}, separation {checks.get('separation')}")
            if a.independent:
                # CGAL reads OFF, OBJ and PLY: a Draco or glTF input (floats both ways) is handed
                # over as a binary PLY of the same floats.
                original = a.mesh
                if not original.lower().endswith((".off", ".obj", ".ply")):
                    original = os.path.join(work, "input.ply")
                    conv = run([tool("mesh-info"), a.mesh, "--save", original, "-q"], 120)
                    if conv.returncode != 0:
                        fail(f"mesh-info --save: {conv.stderr.strip()}")
                ind = run([a.independent, original, out, "--expect", cls], a.timeout)
                print(ind.stdout.strip())
                if ind.returncode != 0:
                    fail(f"independent_double_check: {ind.stdout.strip()} {ind.stderr.strip()}")
            print(f"OK: {cls} confirmed against the input ({cj['counts']})")
        elif cls == "general":
            if a.kind != "general" and not rep.get("class_reason"):
                fail(f"asked for {a.kind}, written as general without a reason")
            print("OK: general proxy")
        else:
            if a.kind != "general":
                fail(f"exit 0 with class {cls!r} for --kind {a.kind}")
            print("OK: general proxy (checks not all passed, reported as such)")


if __name__ == "__main__":
    main()
