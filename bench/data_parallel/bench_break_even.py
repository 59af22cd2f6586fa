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
import math
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tests", "mpi"))
from mpi_support import mpi_env, mpirun_cmd  # noqa: E402

DEFAULT_ALPHAS = [0.5, 1.6, 5, 20, 50, 200, 500]
QUICK_ALPHAS = [0.5, 20, 500]
BASELINE = ("instance-boxes", "exact")
SERIES = [("instance-boxes", "roulette"), ("proxies", "exact"), ("proxies", "roulette")]


def break_even(alphas, values, threshold=1.0):
    """The break-even alpha of one series: the smallest alpha from which `values` (relative
    efficiency at each of the ascending `alphas`) is >= threshold and stays >= threshold for every
    larger alpha of the sweep.

    Returns (kind, alpha):
      ("always", alphas[0])  every value is >= threshold (break-even at or below the sweep);
      ("never", None)        the value at the largest alpha is < threshold;
      ("at", a)              otherwise: with i the last index whose value is < threshold, a is
                             where the straight line through (log alphas[i], values[i]) and
                             (log alphas[i+1], values[i+1]) crosses threshold (so
                             alphas[i] < a <= alphas[i+1]).
    A value of None (a missing run) counts as below the threshold."""
    if len(alphas) != len(values) or not alphas:
        raise ValueError("break_even: alphas and values must be non-empty and of equal length")
    if any(b <= a for a, b in zip(alphas, alphas[1:])):
        raise ValueError("break_even: alphas must ascend")
    below = [i for i, v in enumerate(values) if v is None or v < threshold]
    if not below:
        return "always", alphas[0]
    i = below[-1]
    if i == len(values) - 1:
        return "never", None
    v0, v1 = values[i], values[i + 1]
    if v0 is None:
        return "at", alphas[i + 1]
    t = (threshold - v0) / (v1 - v0)  # v1 >= threshold > v0, so 0 < t <= 1
    la = math.log(alphas[i]) + t * (math.log(alphas[i + 1]) - math.log(alphas[i]))
    return "at", math.exp(la)


def extrapolated_break_even(base, row):
    """The alpha at which `row` would break even with `base` in the alpha-beta model, from one
    run's figures of both (report.json rows: mse, network_alpha_us, modelled_compute_seconds,
    modelled_message_seconds, modelled_control_seconds): each row's modelled time is taken as
    c + alpha x k, with c its modelled compute and k its message and control seconds / alpha
    (the bytes / beta share counts in k: negligible at a large alpha, so pass the largest
    alpha's run). Forward counts are held at that run's (roulette's vary with alpha).

    Returns ("at", a), ("always", 0.0) when the row wins at every alpha >= 0, or ("never", None)
    when it loses at every alpha >= 0 (or wins only below some alpha)."""
    alpha = row["network_alpha_us"]

    def ck(r):
        return (r["modelled_compute_seconds"],
                (r["modelled_message_seconds"] + r["modelled_control_seconds"]) / alpha)
    c_b, k_b = ck(base)
    c_r, k_r = ck(row)
    n = row["mse"] * c_r - base["mse"] * c_b  # the row's excess cost at alpha 0
    d = base["mse"] * k_b - row["mse"] * k_r  # what the row saves per us of alpha
    if n <= 0 and d >= 0:
        return "always", 0.0
    if d <= 0:
        return "never", None
    return "at", n / d


def describe_break_even(result):
    kind, a = result
    if kind == "always":
        return f"always (<= {a:g} us)"
    if kind == "never":
        return "never (in the sweep)"
    return f"{a:.3g} us"


def self_test():
    cases = [
        # (alphas, values, expected kind, expected alpha)
        ([1, 10, 100, 1000], [0.5, 0.8, 1.2, 1.5], "at", math.sqrt(10 * 100)),
        ([1, 10, 100], [1.0, 1.1, 3.0], "always", 1),
        ([1, 10, 100], [1.5, 1.2, 0.9], "never", None),
        ([1, 10, 100, 1000], [1.2, 0.9, 1.1, 1.3], "at", 10 ** 1.5),  # a dip: after it
        ([1, 10, 100], [0.5, 1.0, 1.2], "at", 10),  # exactly 1 counts as break-even
        ([1, 100], [0.0, 2.0], "at", 10),  # halfway in log alpha
        ([1, 10, 100], [0.5, None, 1.5], "at", 100),  # a missing run is not >= 1
        ([0.5, 1.6, 5, 20, 50, 200, 500], [0.6, 0.62, 0.7, 0.9, 1.3, 2.5, 4], "at",
         math.exp(math.log(20) + 0.25 * math.log(50 / 20))),
    ]
    failed = 0
    for alphas, values, kind, alpha in cases:
        got = break_even(alphas, values)
        ok = got[0] == kind and (alpha is None and got[1] is None or
                                 alpha is not None and abs(got[1] - alpha) <= 1e-9 * alpha)
        if not ok:
            failed += 1
            print(f"FAIL: break_even({alphas}, {values}) = {got}, expected ({kind!r}, {alpha})")
    def row(mse, compute, per_alpha, alpha=100.0):
        return {"mse": mse, "network_alpha_us": alpha, "modelled_compute_seconds": compute,
                "modelled_message_seconds": per_alpha * alpha, "modelled_control_seconds": 0.0}
    base = row(1.0, 1.0, 0.01)
    for r, kind, alpha in ((row(1.0, 2.0, 0.0), "at", 100.0),  # 1 s more compute, 0.01 s/us less
                           (row(0.5, 1.5, 0.01), "always", 0.0),  # half the MSE: wins throughout
                           (row(1.0, 1.5, 0.02), "never", None),
                           (row(2.0, 1.0, 0.0), "at", 100.0)):  # 2 x MSE: 2 s against 1 + 0.01 a
        got = extrapolated_break_even(base, r)
        if got[0] != kind or (alpha is not None and abs(got[1] - alpha) > 1e-9):
            failed += 1
            print(f"FAIL: extrapolated_break_even = {got}, expected ({kind!r}, {alpha})")
    for bad in (([], []), ([1, 2], [1]), ([2, 1], [1, 1])):
        try:
            break_even(*bad)
            failed += 1
            print(f"FAIL: break_even{bad} did not raise")
        except ValueError:
            pass
    if failed:
        sys.exit(f"bench_break_even self-test: {failed} failure(s)")
    print(f"bench_break_even self-test: {len(cases) + 7} checks pass")


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


def table_rows(report, alpha):
    """The report's rows keyed by (forwarding, estimator, emulated)."""
    rows = {}
    for r in report["rows"]:
        rows[(r["forwarding"], r["estimator"], bool(r["emulated"]))] = dict(r, alpha=alpha)
    return rows


def fmt(v, spec):
    return "–" if v is None else format(v, spec)


def scene_table(label, alphas, by_alpha):
    """Markdown table of one scene: one line per alpha x policy x estimator."""
    lines = [f"### {label}", "",
             "| alpha µs | forwarding | estimator | rel. eff. measured (emulated) | "
             "rel. eff. modelled | rel. eff. measured (shm) | seconds emulated | seconds "
             "modelled | emulated / modelled s | seconds shm | forwards / segment | mean q | "
             "MSE |",
             "|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for a in alphas:
        rows = by_alpha[a]
        for pol, est in [BASELINE] + SERIES:
            e = rows.get((pol, est, True))
            s = rows.get((pol, est, False))
            if e is None:
                continue
            ratio = e["seconds"] / e["modelled_seconds"] if e["modelled_seconds"] else None
            lines.append(
                f"| {a:g} | {pol} | {est} | {e['relative_efficiency']:.2f} | "
                f"{e['modelled_relative_efficiency']:.2f} | "
                f"{fmt(s and s['relative_efficiency'], '.2f')} | {e['seconds']:.3f} | "
                f"{e['modelled_seconds']:.3f} | {fmt(ratio, '.2f')} | "
                f"{fmt(s and s['seconds'], '.3f')} | {e['forwards_per_shadow_segment']:.4f} | "
                f"{e.get('mean_q', 1):.3f} | {e['mse']:.3e} |")
    return lines


def break_evens(alphas, by_alpha):
    """{(policy, estimator): {"measured": result, "modelled": result, "extrapolated": result}}
    (extrapolated: the model's from the largest alpha's run, extrapolated_break_even)."""
    out = {}
    top = by_alpha[alphas[-1]]
    for pol, est in SERIES:
        def series(key):
            vals = []
            for a in alphas:
                r = by_alpha[a].get((pol, est, True))
                vals.append(r[key] if r else None)
            return vals
        base, row = top.get(BASELINE + (True,)), top.get((pol, est, True))
        out[(pol, est)] = {"measured": break_even(alphas, series("relative_efficiency")),
                           "modelled": break_even(alphas, series("modelled_relative_efficiency")),
                           "extrapolated": extrapolated_break_even(base, row) if base and row
                           else ("never", None)}
    return out


def oddities(label, alphas, by_alpha, tolerance=0.10):
    """Emulated rows whose measured seconds differ from the modelled seconds by more than
    `tolerance`, and rows whose measured relative efficiency differs from the modelled one by
    more than `tolerance`."""
    out = []
    for a in alphas:
        for pol, est in [BASELINE] + SERIES:
            e = by_alpha[a].get((pol, est, True))
            if not e or not e["modelled_seconds"]:
                continue
            t = e["seconds"] / e["modelled_seconds"]
            m = e["modelled_relative_efficiency"]
            q = e["relative_efficiency"] / m if m else None
            if abs(t - 1) > tolerance or (q is not None and abs(q - 1) > tolerance):
                out.append({"scene": label, "alpha_us": a, "forwarding": pol, "estimator": est,
                            "seconds_emulated": e["seconds"], "seconds_modelled":
                            e["modelled_seconds"], "seconds_ratio": t,
                            "relative_measured": e["relative_efficiency"],
                            "relative_modelled": m, "relative_ratio": q})
    return out


def have_matplotlib():
    """True if this interpreter has matplotlib; else says how to get it."""
    try:
        import matplotlib  # noqa: F401
        return True
    except ImportError:
        print(f"bench_break_even: {sys.executable} has no matplotlib: no plots. ./setup.sh "
              "bench-deps installs Debian's python3-matplotlib, for /usr/bin/python3 (run this "
              "script with that interpreter when python3 on PATH is another one)", flush=True)
        return False


def plot(label, alphas, by_alpha, bes, args, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import FixedLocator, FuncFormatter, NullLocator

    fig, ax = plt.subplots(figsize=(7.5, 4.8), dpi=110)
    colours = {("instance-boxes", "roulette"): "tab:orange", ("proxies", "exact"): "tab:blue",
               ("proxies", "roulette"): "tab:green"}
    lo, hi = 1.0, 1.0
    for k, (pol, est) in enumerate(SERIES):
        c = colours[(pol, est)]
        for key, style, what in (("relative_efficiency", "-o", "measured (emulated)"),
                                 ("modelled_relative_efficiency", "--", "modelled")):
            xs, ys = [], []
            for a in alphas:
                r = by_alpha[a].get((pol, est, True))
                if r and r[key] > 0:
                    xs.append(a)
                    ys.append(r[key])
            if not xs:
                continue
            lo, hi = min(lo, *ys), max(hi, *ys)
            ax.plot(xs, ys, style, color=c, lw=1.6 if key == "relative_efficiency" else 1.0,
                    ms=4, alpha=1 if key == "relative_efficiency" else 0.7,
                    label=f"{pol} + {est}, {what}")
        kind, a = bes[(pol, est)]["measured"]
        if kind == "at":
            ax.plot([a], [1.0], marker="*", ms=14, color=c, mec="black", mew=0.6, zorder=5)
            ax.annotate(f"{a:,.0f} µs" if a >= 100 else f"{a:.3g} µs", (a, 1.0),
                        textcoords="offset points", xytext=(6, -14 - 11 * k), fontsize=8,
                        color=c)
        elif kind == "always":
            ax.plot([a], [1.0], marker="<", ms=9, color=c, mec="black", mew=0.6, zorder=5)
    ax.axhline(1.0, color="black", lw=0.8)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylim(lo / 1.15, hi * 1.15)
    fmt_fn = FuncFormatter(lambda v, _: f"{v:g}")
    ax.xaxis.set_major_formatter(fmt_fn)
    ticks = [t for t in (0.1, 0.2, 0.3, 0.5, 0.6, 0.7, 0.8, 0.9, 1, 1.2, 1.5, 2, 3, 5, 10, 20, 50)
             if lo / 1.15 <= t <= hi * 1.15]
    ax.yaxis.set_major_locator(FixedLocator(ticks))
    ax.yaxis.set_major_formatter(fmt_fn)
    ax.yaxis.set_minor_locator(NullLocator())
    ax.set_xlabel("network latency alpha (µs per message), beta %g GB/s" % args.beta_gbps)
    ax.set_ylabel("efficiency relative to exact + instance boxes")
    ax.set_title(f"{label}: {args.ranks} ranks, {args.spp} spp x {args.seeds} seeds, "
                 f"emulated fabric on one shared 2-core host", fontsize=9)
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    fig.text(0.01, 0.01, "star: break-even alpha of the measured (emulated) curve; dashed: "
             "alpha-beta model; wall times on a shared machine: each point is noisy",
             fontsize=7, color="dimgray")
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    fig.savefig(path)
    plt.close(fig)


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
