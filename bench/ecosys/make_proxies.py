#!/usr/bin/env python3
"""Builds one proxy variant for every plant prototype of a scene (the terrain and other placed
meshes get none) with proxy-gen, one mesh per call, and writes DIR/scene.json: the input scene
with each plant's proxy, its verified class and sha256 recorded. Meshes proxy-gen refuses (an
inside proxy of an open plant, say) keep no proxy and are listed in DIR/failed.txt.

usage: make_proxies.py PROXY_GEN SCENE DIR -- PROXY_GEN_ARGS...   (e.g. --kind outside --method hull)
"""
import concurrent.futures
import json
import os
import subprocess
import sys

from proxyvis_tools.meshes import sha256_file
from proxyvis_tools.scenes import load_scene_absolute


def main():
    if "--" not in sys.argv or sys.argv.index("--") != 4:
        sys.exit(__doc__)
    proxy_gen, scene_path, out_dir = sys.argv[1:4]
    args = sys.argv[5:]
    jobs = int(os.environ.get("JOBS", "2"))
    kind = args[args.index("--kind") + 1] if "--kind" in args else "outside"
    method = args[args.index("--method") + 1] if "--method" in args else (
        "qem" if kind == "general" else "wrap")
    os.makedirs(out_dir, exist_ok=True)
    scene = load_scene_absolute(scene_path)
    plants = [m for m in scene["meshes"] if m.get("place", True) is False]

    def build(mesh):
        out = os.path.join(out_dir, f"{mesh['name']}.{kind}.ply")
        report = os.path.join(out_dir, f"{mesh['name']}.json")
        if not (os.path.exists(out) and os.path.exists(report)):
            r = subprocess.run([proxy_gen, mesh["file"], "-o", out, "--json", report, "-q",
                                "--threads", "1", *args], capture_output=True, text=True)
            if r.returncode != 0:
                return mesh, None, r.stderr.strip().splitlines()[-1:] or ["exit %d" % r.returncode]
        with open(report) as f:
            rep = json.load(f)
        return mesh, (out, rep), None

    failed = []
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        for mesh, ok, err in pool.map(build, plants):
            if ok is None:
                failed.append(f"{mesh['name']}: {err[0] if err else ''}")
                mesh["proxies"] = []
                continue
            out, rep = ok
            proxy = {"kind": kind, "method": method, "file": os.path.abspath(out)}
            if rep.get("class"):  # an unverified (general) proxy records no class
                proxy.update({"class": rep["class"], "sha256": sha256_file(out)})
            mesh["proxies"] = [proxy]
    with open(os.path.join(out_dir, "scene.json"), "w") as f:
        json.dump(scene, f, indent=1)
    with open(os.path.join(out_dir, "failed.txt"), "w") as f:
        f.write("".join(line + "\n" for line in failed))
    print(f"{out_dir}: {len(plants) - len(failed)} of {len(plants)} plants have a proxy"
          + (f"; failed: {len(failed)} (see failed.txt)" if failed else ""))


if __name__ == "__main__":
    main()
