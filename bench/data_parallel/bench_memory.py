#!/usr/bin/env python3
"""Peak resident memory of a data-parallel render per rank against one process, on a scene whose
geometry is unique (scenes/make_unique_park.py): where data-parallel rendering is needed.

  bench/data_parallel/bench_memory.py SCENE [--build build] [--ranks 2,4] [--spp 4]
      [--forwarding proxies] [--repeats 2]

Each configuration runs as its own process (or MPI job); the single process's peak RSS comes
from wait4() (ru_maxrss), each rank's from its own getrusage() in render's --json summary (the
same counter). Prints a Markdown table: ranks, largest rank's peak RSS, its ratio to the single
process, each rank's own triangles, and the render's time."""
import argparse
import json
import os
import subprocess
import sys
import tempfile

from proxyvis_tools.mpi import mpi_env, mpirun_cmd


def single(render, scene, spp, work):
    out = os.path.join(work, "single.exr")
    p = subprocess.Popen([render, scene, "--estimator", "exact", "--spp", str(spp), "-o", out,
                          "--quiet", "--json", out + ".json"], stdout=subprocess.DEVNULL)
    _, status, usage = os.wait4(p.pid, 0)
    if status != 0:
        sys.exit("bench_memory: the single-process render failed")
    with open(out + ".json") as f:
        seconds = json.load(f)["seconds"]
    return usage.ru_maxrss * 1024, seconds


def parallel(render, scene, spp, ranks, forwarding, work):
    out = os.path.join(work, f"dp{ranks}.exr")
    cmd = mpirun_cmd(ranks) + [render, scene, "--data-parallel", "--forwarding", forwarding,
                               "--spp", str(spp), "-o", out, "--quiet", "--json", out + ".json"]
    p = subprocess.run(cmd, capture_output=True, text=True, env=mpi_env())
    if p.returncode != 0:
        sys.exit(f"bench_memory: {' '.join(cmd)} failed:\n{p.stderr}")
    with open(out + ".json") as f:
        return json.load(f)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("scene")
    ap.add_argument("--build", default="build")
    ap.add_argument("--ranks", default="2,4")
    ap.add_argument("--spp", type=int, default=4)
    ap.add_argument("--forwarding", default="proxies")
    ap.add_argument("--repeats", type=int, default=2)
    a = ap.parse_args()
    render = os.path.join(a.build, "bin", "render")
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for rep in range(a.repeats):  # interleaved: single, then each rank count, per repeat
            rss, sec = single(render, a.scene, a.spp, work)
            rows.append(("1 (single process)", rss, None, sec, rep))
            for ranks in (int(r) for r in a.ranks.split(",")):
                s = parallel(render, a.scene, a.spp, ranks, a.forwarding, work)
                tris = ", ".join(f"{r['own_triangles'] / 1e6:.2f}" for r in s["per_rank"])
                rows.append((str(ranks), s["rank_peak_rss_bytes"], tris, s["seconds"], rep))
    singles = [r[1] for r in rows if r[2] is None]
    base = min(singles)
    print(f"scene {a.scene}, {a.spp} spp, --forwarding {a.forwarding}; single-process peak RSS "
          f"{min(singles) / 2**20:.0f}-{max(singles) / 2**20:.0f} MiB over {a.repeats} runs\n")
    print("| ranks | repeat | largest rank's peak RSS (MiB) | / single process (smallest) | "
          "own triangles per rank (M) | seconds |")
    print("|---|---:|---:|---:|---|---:|")
    for label, rss, tris, sec, rep in rows:
        print(f"| {label} | {rep} | {rss / 2**20:.0f} | {rss / base:.2f} | {tris or '-'} | "
              f"{sec:.2f} |")


if __name__ == "__main__":
    main()
