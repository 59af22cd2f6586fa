#!/usr/bin/env python3
"""Forwards per shadow segment and efficiency of data-parallel rendering, per scene and policy.

For each scene: render-compare --data-parallel on RANKS ranks with every forwarding policy and
both estimators, and once more with the inside proxies removed from the scene (outside proxies
only), then one Markdown table: forwards per shadow segment, its ratio to the instance-box
baseline, bytes, messages, per-rank peak RSS, and efficiency relative to exact with instance
boxes: measured on this machine's shared memory, measured under each emulated fabric of
--networks (render-compare --emulate-network: the exchange waits what the fabric charges), and
the alpha-beta model of that fabric from the same run's counts, with the ratio of emulated to
modelled time.

  bench/data_parallel/bench_forwarding.py [--build build] [--out out/bench_dp] [--ranks 4]
      [--spp 32] [--seeds 2] [--networks shm,ib-hdr,roce,10gbe-tcp] [--scenes scenes/park.json,...]
      [--repeats 3]

Repeats run the whole study again (the policies interleaved within each run), so the table
shows the spread of the timing columns as min-max over repeats; the counts do not vary with
timing for exact rows."""
import argparse
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

from proxyvis_tools.mpi import mpi_env, mpirun_cmd
from proxyvis_tools.scenes import load_scene_absolute


def without_inside(scene, out_dir):
    """The scene with only its outside proxies, written beside the original's paths."""
    s = load_scene_absolute(scene)
    for m in s["meshes"]:
        m["proxies"] = [p for p in m.get("proxies", []) if p["kind"] != "inside"]
    path = os.path.join(out_dir, os.path.basename(scene).replace(".json", ".outside-only.json"))
    with open(path, "w") as f:
        json.dump(s, f)
    return path


def study(args, scene, out, network):
    emulate = ["--emulate-network"] if network != "shm" else []
    cmd = mpirun_cmd(args.ranks) + [
        os.path.join(args.build, "bin", "render-compare"), scene, "--data-parallel",
        "--forwarding", args.forwarding, "--spp", str(args.spp),
        "--seeds", str(args.seeds), "--network", network, *emulate,
        "--passes-per-round", "2", "--threads", str(args.threads), "--out", out, "--quiet",
        "--reference-spp", str(args.reference_spp)] + args.extra.split()
    p = subprocess.run(cmd, capture_output=True, text=True, env=mpi_env())
    if p.returncode != 0:
        sys.exit(f"bench_forwarding: {' '.join(cmd)} failed:\n{p.stderr}")
    with open(os.path.join(out, "report.json")) as f:
        return json.load(f)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="out/bench_dp")
    ap.add_argument("--ranks", type=int, default=4)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--spp", type=int, default=32)
    ap.add_argument("--seeds", type=int, default=2)
    ap.add_argument("--reference-spp", type=int, default=1024)
    ap.add_argument("--networks", default="shm,ib-hdr,roce,10gbe-tcp",
                    help="fabrics: shm alone measures; any other is also emulated in the run")
    ap.add_argument("--forwarding", default="domain-bounds,instance-boxes,proxies")
    ap.add_argument("--repeats", type=int, default=1)
    ap.add_argument("--scenes", default="scenes/park.json,scenes/park-low-sun.json")
    ap.add_argument("--no-outside-only", action="store_true")
    ap.add_argument("--extra", default="", help="more render-compare flags")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    print(f"{args.ranks} ranks, {args.spp} spp x {args.seeds} seeds, fabrics {args.networks}, "
          f"{args.repeats} repeat(s); efficiency relative to exact with instance boxes on the "
          f"same fabric; min-max over repeats\n")
    print("| scene | proxies | estimator | forwarding | run on | forwards / segment | "
          "vs instance boxes | forward MB | messages | MSE | seconds | efficiency measured | "
          "efficiency modelled | emulated / modelled time |")
    print("|---|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for scene in args.scenes.split(","):
        variants = [("outside + inside", scene)]
        if not args.no_outside_only:
            variants.append(("outside only", without_inside(scene, args.out)))
        for label, path in variants:
            for network in args.networks.split(","):
                reports = [study(args, path, os.path.join(
                    args.out, f"{os.path.basename(path)}.{network}.{k}"), network)
                    for k in range(args.repeats)]
                rows = [r["rows"] for r in reports]
                base = next(r for r in rows[0] if r["estimator"] == "exact"
                            and r["forwarding"] == "instance-boxes")
                for i, row in enumerate(rows[0]):
                    if label == "outside only" and row["forwarding"] != "proxies":
                        continue  # the box policies do not use proxies: the same as above
                    if network != "shm" and not row["emulated"]:
                        continue  # the shared-memory rows of an emulated study: in the shm study

                    def spread(key, fmt="{:.2f}x"):
                        v = [rr[i][key] for rr in rows]
                        lo, hi = fmt.format(min(v)), fmt.format(max(v))
                        return lo if lo == hi else f"{lo}-{hi}"

                    ratios = [rr[i]["seconds"] / rr[i]["modelled_seconds"] for rr in rows]
                    run_on = f"emulated {network}" if row["emulated"] else "shm (measured)"
                    print(f"| {os.path.basename(scene)} | {label} | {row['estimator']} | "
                          f"{row['forwarding']} | {run_on} | "
                          f"{row['forwards_per_shadow_segment']:.4f} | "
                          f"{row['forwards_per_shadow_segment'] / base['forwards_per_shadow_segment']:.3f} | "
                          f"{row['forward_bytes'] / 1e6:.2f} | {row['forward_messages']} | "
                          f"{row['mse']:.3e} | {spread('seconds', '{:.3f}')} | "
                          f"{spread('relative_efficiency')} | "
                          f"{spread('modelled_relative_efficiency')} | "
                          f"{min(ratios):.2f}-{max(ratios):.2f} |")
                sys.stdout.flush()


if __name__ == "__main__":
    main()
