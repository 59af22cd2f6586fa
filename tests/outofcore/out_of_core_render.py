#!/usr/bin/env python3
"""render --geometry-budget end to end on a small unique park (4 spot sculptures and the lawn,
each its own file).

  out_of_core_render.py BIN_DIR SOURCE_DIR WORK_DIR [--quick]

--quick (the sanitizer build's case): two sculptures, one budget below the scene, both exact policies once, a
few roulette renders without the z-test, and the errors; every code path, little statistics.

Checks:
  - exact out-of-core images equal the in-core exact image bit for bit (R, G, B) at budgets of
    100 %, 60 % and just the largest mesh's load, both policies, one batch or one pass per batch, on one
    and two threads;
  - the report's loads, hits, evictions and bytes: at 100 % every mesh is loaded once; at smaller
    budgets meshes are evicted and loaded again, and the cache never holds more than its budget;
    proxies-exact queues fewer (segment, mesh) pairs than exact-batched;
  - proxies-roulette is unbiased, at a fixed q and with q learned from earlier batches: over 40
    seeds, the mean of the paired differences between its image mean and the in-core exact image
    mean of the same seed is within 3 standard errors (measured) of zero, and it skips some
    meshes' queues (the same estimator without its 1/q weights gave z = -13 here: the test can
    tell); the variance of those differences matches the closed form (1/q - 1) S^2 summed over
    the queues, which each render estimates from its traced queues;
  - errors exit 2 with one line and write nothing: a budget below the largest mesh, an original
    damaged on disk, --estimator roulette, --time, --data-parallel with a budget.
"""
import math
import re
import json
import os
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from image_diff import differing_pairs  # noqa: E402
from script_checks import fail, run  # noqa: E402
from unique_park import make_park  # noqa: E402

SIZE = ["--width", "96", "--height", "72", "--spp", "4", "--seed", "3"]


def image_means(paths):
    """The mean of R, G and B over each image (iinfo --stats, one process for all)."""
    p = run(["iinfo", "--stats", *paths])
    means = [float(sum(map(float, m.split()[:3])) / 3)
             for m in re.findall(r"Stats Avg: ([^(]*)\(", p.stdout)]
    if len(means) != len(paths):
        fail(f"iinfo gave {len(means)} means for {len(paths)} images")
    return means


def roulette_unbiased(render, scene, work, seeds, budget):
    """proxies-roulette at a fixed q (0.5) and with q learned from earlier batches, each seed's
    image mean against the in-core exact image mean of the same seed (paired z-test)."""
    small = ["--width", "64", "--height", "48", "--spp", "8", "--threads", "2", "--quiet"]
    variants = {"fixed": "0.5", "learned": "learned"}
    exact, images, skipped, mean_q = [], {k: [] for k in variants}, dict.fromkeys(variants, 0), {}
    predicted = {}
    for seed in range(seeds):
        e = os.path.join(work, f"exact-{seed}.exr")
        run([render, scene, *small, "--seed", str(seed), "-o", e])
        exact.append(e)
        for name, q in variants.items():
            r = os.path.join(work, f"roulette-{name}-{seed}.exr")
            js = os.path.join(work, f"roulette-{name}-{seed}.json")
            run([render, scene, *small, "--seed", str(seed), "-o", r, "--geometry-budget", budget,
                 "--ooc-policy", "proxies-roulette", "--load-q", q, "--batch-passes", "1",
                 "--json", js])
            info = json.load(open(js))
            skipped[name] += info["skipped_queues"]
            predicted.setdefault(name, []).append(info["roulette_added_variance"])
            mean_q.setdefault(name, []).append(info["mean_load_q"])
            images[name].append(r)
    names = list(variants)
    means = image_means(exact + [p for n in names for p in images[n]])
    for k, name in enumerate(names):
        d = [means[seeds * (k + 1) + i] - means[i] for i in range(seeds)]
        mean = sum(d) / seeds
        sd = math.sqrt(sum((x - mean) ** 2 for x in d) / (seeds - 1))
        q = sum(mean_q[name]) / seeds
        if seeds < 10:
            print(f"ok: {seeds} {name} roulette renders ({skipped[name]} queues skipped, mean q "
                  f"{q:.2f}), no z-test with so few")
            continue
        if skipped[name] == 0 or sd == 0:
            fail(f"{name} roulette skipped {skipped[name]} queues, spread {sd}: the test cannot "
                 "tell anything")
        z = mean / (sd / math.sqrt(seeds))
        print(f"ok: {name} roulette - exact image mean over {seeds} seeds: {mean:.3e} +- "
              f"{sd / math.sqrt(seeds):.3e} (z = {z:.2f}), {skipped[name]} queues skipped, "
              f"mean q {q:.2f}")
        if abs(z) > 3.0:
            fail(f"proxies-roulette ({name} q) looks biased: z = {z:.2f}")
        # The variance of the paired differences (only the roulette's draws differ) against the
        # renders' closed-form estimate of it, (1/q - 1) S^2 summed over queues: the sample
        # variance of 40 seeds is within [0.45, 1.85] of the true one with probability 0.999
        # (chi-square, 39 degrees of freedom).
        closed = sum(predicted[name]) / seeds
        ratio = sd * sd / closed if closed > 0 else float("inf")
        print(f"ok: {name} roulette: measured variance {sd * sd:.3e}, closed form {closed:.3e} "
              f"(ratio {ratio:.2f})")
        if not 0.45 <= ratio <= 1.85:
            fail(f"{name} roulette: measured variance {sd * sd:.3e} is {ratio:.2f}x the closed "
                 f"form {closed:.3e}")
    if not 0 < sum(mean_q["learned"]) / seeds < 1:
        fail(f"the learned q never left 1: {mean_q['learned']}")


def main():
    bin_dir, source, work = sys.argv[1:4]
    quick = "--quick" in sys.argv[4:]
    render = os.path.join(bin_dir, "render")
    scene = make_park(bin_dir, source, work, 2 if quick else 4, "spot")
    park = os.path.dirname(scene)

    ref = os.path.join(work, "ref.exr")
    run([render, scene, *SIZE, "-o", ref, "--quiet", "--threads", "2"])
    probe = os.path.join(work, "probe.json")
    run([render, scene, *SIZE, "--geometry-budget", "100%", "-o",
         os.path.join(work, "probe.exr"), "--json", probe, "--quiet"])
    info = json.load(open(probe))
    in_core = info["in_core_bytes"]
    meshes = len(json.load(open(scene))["meshes"])  # the sculptures and the lawn
    if info["loads"] != meshes or info["evictions"] != 0:
        fail(f"at 100 % every mesh loads once: {info['loads']} loads, {info['evictions']} evictions")
    # The largest mesh alone, from the error message of a budget of one byte.
    p = run([render, scene, *SIZE, "--geometry-budget", "1", "-o", os.path.join(work, "no.exr"),
             "--quiet"], expect=2)
    lines = [l for l in p.stderr.splitlines() if l.strip()]
    if len(lines) != 1 or "smaller than mesh" not in lines[0]:
        fail(f"a budget below the largest mesh: {lines}")
    if os.path.exists(os.path.join(work, "no.exr")):
        fail("a refused render wrote its image")
    largest = int(lines[0].split("give at least ")[1].split(" bytes")[0])
    if not 0 < largest < in_core:
        fail(f"largest mesh {largest} bytes against {in_core} in core")

    pairs, queued = [], {}
    # A mesh's load needs its build scratch beside the resident ones (kLoadPeakOverBuilt x its
    # built bytes): these budgets are above that, below the scene.
    budgets = ("75%",) if quick else ("100%", "60%", str(largest))
    runs = (("1", "2"),) if quick else (("0", "2"), ("1", "1"))
    for budget in budgets:
        for policy in ("exact-batched", "proxies-exact"):
            for batch, threads in runs:
                name = f"{policy}-{budget.rstrip('%')}-{batch}-{threads}"
                out = os.path.join(work, name + ".exr")
                js = os.path.join(work, name + ".json")
                run([render, scene, *SIZE, "--geometry-budget", budget, "--ooc-policy", policy,
                     "--batch-passes", batch, "--threads", threads, "-o", out, "--json", js,
                     "--quiet"])
                r = json.load(open(js))
                pairs.append((ref, out))
                if r["peak_cache_bytes"] > r["geometry_budget_bytes"]:
                    fail(f"{name}: cache peak {r['peak_cache_bytes']} over the budget")
                if budget != "100%" and r["evictions"] == 0:
                    fail(f"{name}: a budget below the scene evicted nothing")
                if r["original_traces"] <= 0 or r["original_traces"] > r["queued"]:
                    fail(f"{name}: {r['original_traces']} traces of {r['queued']} queued pairs")
                if r["loads"] < meshes or r["bytes_read"] <= 0 or r["load_seconds"] <= 0:
                    fail(f"{name}: loads {r['loads']}, bytes {r['bytes_read']}")
                for key in ("loads_per_frame", "peak_rss_bytes", "queued", "original_traces"):
                    if key not in r:
                        fail(f"{name}: no {key} in the report")
                queued[(policy, budget, batch)] = r["queued"]
                print(f"ok: {name}: {r['loads']} loads, {r['evictions']} evictions, "
                      f"{r['queued']} queued")
    for (policy, budget, batch), q in queued.items():
        if policy == "proxies-exact" and not q < queued[("exact-batched", budget, batch)]:
            fail(f"proxies-exact queued {q}, exact-batched {queued[('exact-batched', budget, batch)]}")
    bad = differing_pairs(pairs, channels="R,G,B")
    if bad:
        fail("out-of-core images differ from the in-core one:\n" +
             "\n".join(f"{b}: {r}" for _, b, r in bad[:3]))
    print(f"ok: {len(pairs)} out-of-core images equal the in-core one bit for bit")

    roulette_unbiased(render, scene, work, 3 if quick else 40, budgets[-1] if quick else "60%")

    # A damaged original: exit 2 naming it, nothing written.
    broken = os.path.join(work, "broken")
    shutil.copytree(park, broken, symlinks=True)
    victim = sorted(f for f in os.listdir(os.path.join(broken, "meshes"))
                    if not f.endswith(".json"))[0]
    path = os.path.join(broken, "meshes", victim)
    with open(path, "r+b") as f:
        f.truncate(os.path.getsize(path) // 3)
    out = os.path.join(work, "broken.exr")
    p = run([render, os.path.join(broken, "unique-park.json"), *SIZE, "--geometry-budget", "60%",
             "-o", out, "--quiet"], expect=2)
    lines = [l for l in p.stderr.splitlines() if l.strip()]
    if len(lines) != 1 or victim not in lines[0]:
        fail(f"a damaged original must be named in one line: {lines}")
    if os.path.exists(out):
        fail("a refused render wrote its image")
    for extra, words in ((["--estimator", "roulette"], "--estimator roulette"),
                         (["--time", "1"], "--time"),
                         (["--data-parallel"], "not available with --data-parallel")):
        args = [render, scene, "--geometry-budget", "60%", "-o", out, "--quiet", *extra]
        if "--time" not in extra:
            args += ["--spp", "1"]
        p = run(args, expect=2)
        if words not in p.stderr or os.path.exists(out):
            fail(f"{extra}: {p.stderr}")
    # The out-of-core flags without a budget would act on nothing: refused.
    for flag in (["--ooc-policy", "proxies-exact"], ["--load-q", "0.3"], ["--cold-reads"]):
        p = run([render, scene, "--spp", "1", "-o", out, "--quiet", *flag], expect=2)
        if "needs --geometry-budget" not in p.stderr or os.path.exists(out):
            fail(f"{flag} without a budget: {p.stderr}")
    print("ok: errors exit 2 with one line and write nothing")


if __name__ == "__main__":
    main()
