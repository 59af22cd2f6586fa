"""What bench_break_even.py writes from its runs: the per-scene Markdown table, the break-even
alphas of every series, the oddities (measured and modelled disagreeing) and the plot."""
import os
import sys

from break_even_model import BASELINE, SERIES, break_even, extrapolated_break_even


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
