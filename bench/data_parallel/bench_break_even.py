#!/usr/bin/env python3
"""Break-even network latency of proxy forwarding and roulette in data-parallel rendering.

For each scene, sweep the network's per-message latency alpha (beta fixed) and run
render-compare --data-parallel under an emulated fabric (--emulate-network: the MPI exchange
really waits what the fabric charges, ranks on this one host), with the instance-box and proxy
forwarding policies and both estimators. Each run gives, per policy x estimator, the measured
wall-time efficiency under the emulated fabric relative to exact + instance boxes (the
baseline, same spp, also emulated) and the alpha-beta model's relative efficiency. The
break-even alpha of a policy x estimator is the smallest alpha from which its measured
relative efficiency is >= 1 and stays >= 1 over the rest of the sweep (interpolated in log
alpha between sweep points).

  bench/data_parallel/bench_break_even.py [--build build] [--out out/break_even] [--ranks 4]
      [--spp 16] [--seeds 2] [--reference-spp 256] [--alphas 0.5,1.6,5,20,50,200,500]
      [--beta-gbps 10] [--scenes park,park-low-sun,ecosys] [--plot-dir docs/images]
      [--resume] [--quick] [--self-test]

Scenes: names (park, park-low-sun: scenes/NAME.json; ecosys: scenes/ecosys.json with outside
proxies made by proxy-gen as docs/data_parallel.md "Measured" does, cached in
--ecosys-proxies) or paths of scene files. Writes OUT/break_even.md and OUT/break_even.json
(every row, the break-even alphas and the command lines), OUT/<scene>/alpha_<A>/ (each
render-compare report) and, with --plot-dir, PLOT_DIR/break_even_<scene>.png.

render-compare renders its exact reference again in every run (a data-parallel study has no
reference cache), with the same seed, so every alpha of a scene is scored against the same
image; the reference is rendered on shared memory, not under the emulated fabric, but its
time adds to every run: keep --reference-spp modest.

The alphas run in an interleaved order (smallest, largest, second smallest, ...) so that a
drift of the machine's load does not read as a trend in alpha. Timings on a shared machine are
noisy: a bench, not a test; it never fails on a figure."""
import argparse
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

from break_even_model import describe_break_even, self_test
from break_even_tables import (break_evens, fmt, have_matplotlib, oddities, plot, scene_table,
                               table_rows)
from proxyvis_tools.mpi import mpi_env, mpirun_cmd

DEFAULT_ALPHAS = [0.5, 1.6, 5, 20, 50, 200, 500]
QUICK_ALPHAS = [0.5, 20, 500]


def run(cmd, env=None, what=""):
    p = subprocess.run(cmd, capture_output=True, text=True, env=env)
    if p.returncode != 0:
        sys.exit(f"bench_break_even: {what}{' '.join(cmd)} failed (exit {p.returncode}):\n"
                 f"{p.stdout[-2000:]}\n{p.stderr[-4000:]}")
    return p


def ecosys_scene(args):
    """scenes/ecosys.json with outside proxies, made by proxy-gen as in docs/data_parallel.md
    ("Measured") unless already there."""
    scene = os.path.join(args.ecosys_proxies, "scene.json")
    if not os.path.exists(scene):
        proxy_gen = args.proxy_gen or os.path.join(args.build, "bin", "proxy-gen")
        if not os.path.exists(proxy_gen):
            print(f"bench_break_even: no {proxy_gen} to make ecosys' proxies: ecosys skipped "
                  "(--proxy-gen PATH names another)", flush=True)
            return None
        cmd = [proxy_gen, os.path.join(ROOT, "scenes", "ecosys.json"), "--kind", "outside",
               "--alpha", "0.03", "--offset", "0.003",
               "--out-dir", args.ecosys_proxies]
        print("making the ecosys proxies: " + " ".join(cmd), flush=True)
        t = time.time()
        run(cmd, env=os.environ)
        print(f"  {time.time() - t:.0f} s", flush=True)
        args.commands.append(" ".join(cmd))
    return scene


def resolve_scenes(args):
    """[(label, path)] for --scenes."""
    out = []
    for name in args.scenes.split(","):
        name = name.strip()
        if not name:
            continue
        if name == "ecosys":
            path = ecosys_scene(args)
            if path:
                out.append(("ecosys", path))
        elif os.path.exists(name):
            label = os.path.splitext(os.path.basename(name))[0]
            if label == "scene":  # a proxy-gen output folder's scene.json
                label = os.path.basename(os.path.dirname(os.path.abspath(name)))
            out.append((label, name))
        else:
            path = os.path.join(ROOT, "scenes", name + ".json")
            if os.path.exists(path):
                out.append((name, path))
            else:
                print(f"bench_break_even: no scene {name} ({path}): skipped", flush=True)
    return out


def interleaved(values):
    """Smallest, largest, second smallest, second largest, ..."""
    s = sorted(values)
    order = []
    while s:
        order.append(s.pop(0))
        if s:
            order.append(s.pop())
    return order


def compare_cmd(args, scene, alpha, out):
    return mpirun_cmd(args.ranks) + [
        os.path.join(args.build, "bin", "render-compare"), scene, "--data-parallel",
        "--forwarding", "instance-boxes,proxies", "--estimators", "exact,roulette",
        "--spp", str(args.spp), "--seeds", str(args.seeds),
        "--reference-spp", str(args.reference_spp), "--threads", str(args.threads),
        "--network", args.network, "--network-alpha-us", f"{alpha:g}",
        "--network-beta-gbps", f"{args.beta_gbps:g}", "--emulate-network",
        "--out", out, "--quiet"] + args.extra.split()


def report_matches(report, args, alpha):
    rows = report.get("rows", [])
    return (report.get("seeds") == args.seeds and report.get("reference_spp") == args.reference_spp
            and report.get("ranks") == args.ranks and rows
            and all(r.get("spp") == args.spp for r in rows)
            and abs(report.get("network_alpha_us", -1) - alpha) <= 1e-9 * alpha
            and abs(report.get("network_beta_gbps", -1) - args.beta_gbps) <= 1e-9 * args.beta_gbps)


def one_run(args, label, scene, alpha):
    """render-compare's report.json for one scene and alpha (reused with --resume)."""
    out = os.path.join(args.out, label, f"alpha_{alpha:g}")
    cmd = compare_cmd(args, scene, alpha, out)
    args.commands.append(" ".join(cmd))
    report_path = os.path.join(out, "report.json")
    if args.resume and os.path.exists(report_path):
        with open(report_path) as f:
            report = json.load(f)
        if report_matches(report, args, alpha):
            print(f"  {label} alpha {alpha:g} us: reused {report_path}", flush=True)
            return report, None
    t = time.time()
    run(cmd, env=mpi_env())
    wall = time.time() - t
    with open(report_path) as f:
        report = json.load(f)
    print(f"  {label} alpha {alpha:g} us: {wall:.1f} s (reference "
          f"{report.get('reference_seconds', 0):.2f} s)",
          flush=True)
    return report, wall


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="out/break_even")
    ap.add_argument("--ranks", type=int, default=4)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--spp", type=int, default=None, help="default 16 (--quick: 4)")
    ap.add_argument("--seeds", type=int, default=None, help="default 2 (--quick: 1)")
    ap.add_argument("--reference-spp", type=int, default=None, help="default 256 (--quick: 32)")
    ap.add_argument("--alphas", default=None,
                    help="µs, comma-separated (default %s; --quick: %s)" % (
                        ",".join(f"{a:g}" for a in DEFAULT_ALPHAS),
                        ",".join(f"{a:g}" for a in QUICK_ALPHAS)))
    ap.add_argument("--beta-gbps", type=float, default=10.0)
    ap.add_argument("--network", default="roce", help="the preset the custom fabric starts from")
    ap.add_argument("--scenes", default=None,
                    help="names or paths (default park,park-low-sun,ecosys; --quick: park)")
    ap.add_argument("--ecosys-proxies", default="out/dp/ecosys/proxies",
                    help="folder of ecosys' outside proxies (made by proxy-gen if missing)")
    ap.add_argument("--proxy-gen", default=None, help="default BUILD/bin/proxy-gen")
    ap.add_argument("--plot-dir", default=None, help="write break_even_<scene>.png here")
    ap.add_argument("--resume", action="store_true",
                    help="reuse a run's report.json in --out when its settings match")
    ap.add_argument("--quick", action="store_true", help="a smoke run: 1 scene, 3 alphas, 4 spp")
    ap.add_argument("--extra", default="", help="more render-compare flags")
    ap.add_argument("--self-test", action="store_true",
                    help="check the break-even computation on synthetic series and exit")
    args = ap.parse_args()
    q = args.quick
    args.spp = args.spp or (4 if q else 16)
    args.seeds = args.seeds or (1 if q else 2)
    args.reference_spp = args.reference_spp or (32 if q else 256)
    args.alphas = sorted(float(a) for a in args.alphas.split(",")) if args.alphas else (
        QUICK_ALPHAS if q else DEFAULT_ALPHAS)
    args.scenes = args.scenes or ("park" if q else "park,park-low-sun,ecosys")
    args.commands = []
    return args


def main():
    args = parse_args()
    if args.self_test:
        self_test()
        return
    if not os.path.exists(os.path.join(args.build, "bin", "render-compare")):
        sys.exit(f"bench_break_even: no {args.build}/bin/render-compare (./setup.sh build)")
    os.makedirs(args.out, exist_ok=True)
    if args.plot_dir and not have_matplotlib():
        args.plot_dir = None
    start = time.time()
    scenes = resolve_scenes(args)
    print(f"{args.ranks} ranks, {args.spp} spp x {args.seeds} seeds, reference "
          f"{args.reference_spp} spp, --network {args.network} with beta {args.beta_gbps:g} "
          f"GB/s, alphas {', '.join(f'{a:g}' for a in args.alphas)} us, emulated\n", flush=True)
    md = ["# Break-even network latency (bench/data_parallel/bench_break_even.py)", "",
          f"{args.ranks} ranks on one host (`--emulate-network`), {args.spp} spp x {args.seeds} "
          f"seeds per cell, exact reference {args.reference_spp} spp, beta {args.beta_gbps:g} "
          "GB/s; relative efficiency = efficiency / that of exact + instance boxes at the same "
          "spp under the same (emulated) fabric. Measured on a shared machine: timings are "
          "noisy.", ""]
    result = {"ranks": args.ranks, "spp": args.spp, "seeds": args.seeds,
              "reference_spp": args.reference_spp, "beta_gbps": args.beta_gbps,
              "network": args.network, "alphas_us": args.alphas, "scenes": []}
    all_odd = []
    be_lines = ["| scene | forwarding | estimator | break-even alpha (measured, emulated) | "
                "break-even alpha (modelled) | modelled, extrapolated from the largest alpha's "
                "counts |", "|---|---|---|---|---|---|"]
    for label, scene in scenes:
        print(f"== {label} ({scene})", flush=True)
        by_alpha, walls, shm = {}, {}, None
        for a in interleaved(args.alphas):
            report, wall = one_run(args, label, scene, a)
            by_alpha[a] = table_rows(report, a)
            walls[a] = wall
            shm = (report.get("shm_alpha_us"), report.get("shm_beta_gbps"))
        bes = break_evens(args.alphas, by_alpha)
        lines = scene_table(label, args.alphas, by_alpha)
        if shm[0] is not None:
            lines += ["", f"This machine's shared memory (measured ping-pong): alpha "
                      f"{shm[0]:.2f} µs, beta {shm[1]:.2f} GB/s."]
        lines += [""]
        for (pol, est), be in bes.items():
            ext = be["extrapolated"]
            ext_text = ("always" if ext[0] == "always" else "never" if ext[0] == "never"
                        else f"{ext[1]:.3g} us")
            lines.append(f"- break-even alpha, {pol} + {est}: measured "
                         f"{describe_break_even(be['measured'])}, modelled "
                         f"{describe_break_even(be['modelled'])}, modelled extrapolated {ext_text}")
            be_lines.append(f"| {label} | {pol} | {est} | {describe_break_even(be['measured'])} "
                            f"| {describe_break_even(be['modelled'])} | {ext_text} |")
        odd = oddities(label, args.alphas, by_alpha)
        all_odd += odd
        lines.append("")
        print("\n".join(lines), flush=True)
        md += lines
        png = None
        if args.plot_dir:
            png = os.path.join(args.plot_dir, f"break_even_{label}.png")
            plot(label, args.alphas, by_alpha, bes, args, png)
            print(f"plot: {png}\n", flush=True)
        result["scenes"].append({
            "scene": label, "path": scene, "shm_alpha_us": shm[0], "shm_beta_gbps": shm[1],
            "run_seconds": {f"{a:g}": w for a, w in walls.items()}, "plot": png,
            "rows": [r for a in args.alphas for r in by_alpha[a].values()],
            "break_even": [{"forwarding": p, "estimator": e,
                            "measured": {"kind": b["measured"][0], "alpha_us": b["measured"][1]},
                            "modelled": {"kind": b["modelled"][0], "alpha_us": b["modelled"][1]},
                            "modelled_extrapolated": {"kind": b["extrapolated"][0],
                                                      "alpha_us": b["extrapolated"][1]}}
                           for (p, e), b in bes.items()]})
    md += ["## Break-even alphas", ""] + be_lines + [""]
    md += ["## Emulated rows more than 10 % from the model", "",
           "(seconds: measured wall time under the emulated fabric / modelled; relative: "
           "measured relative efficiency / modelled)", "",
           "| scene | alpha µs | forwarding | estimator | s emulated | s modelled | ratio | "
           "rel. measured | rel. modelled | ratio |",
           "|---|---:|---|---|---:|---:|---:|---:|---:|---:|"]
    for o in all_odd:
        md.append(f"| {o['scene']} | {o['alpha_us']:g} | {o['forwarding']} | {o['estimator']} | "
                  f"{o['seconds_emulated']:.3f} | {o['seconds_modelled']:.3f} | "
                  f"{o['seconds_ratio']:.2f} | {o['relative_measured']:.2f} | "
                  f"{o['relative_modelled']:.2f} | {fmt(o['relative_ratio'], '.2f')} |")
    elapsed = time.time() - start
    md += ["", f"Run time {elapsed / 60:.1f} min. Commands:", "", "```sh"] + args.commands
    md += ["```", ""]
    result.update({"oddities": all_odd, "commands": args.commands, "run_seconds": elapsed,
                   "argv": sys.argv})
    with open(os.path.join(args.out, "break_even.md"), "w") as f:
        f.write("\n".join(md))
    with open(os.path.join(args.out, "break_even.json"), "w") as f:
        json.dump(result, f, indent=1)
    print("\n".join(["## Break-even alphas", ""] + be_lines))
    print(f"\n{len(all_odd)} emulated row(s) more than 10 % from the model (see "
          f"{args.out}/break_even.md); run time {elapsed / 60:.1f} min")


if __name__ == "__main__":
    main()
