"""The image cases of data_parallel_test.py: data-parallel renders equal the single-process ones
(identical), roulette is unbiased (roulette), the alpha-beta fabric emulated and modelled
(network). Each takes the test's context (data_parallel_test.py)."""
import math
import os
import sys

from mpi_support import mpirun_cmd, read_json, rgb_equal, rgb_means, run
from image_diff import differing_pairs

FORWARDINGS = ["domain-bounds", "instance-boxes", "proxies"]


def identical(t):
    """Exact renders at 1 to 4 ranks, every policy, 1 and 2 threads, equal render's."""
    render, scene, work, dp = t.render, t.scene, t.work, t.dp
    # One render-compare job per rank count renders every policy in one MPI launch (its row
    # images are the first seed's, which is render's seed); render itself covers 2 threads.
    single = os.path.join(work, "single.exr")
    run([render, scene, "--estimator", "exact", "--spp", "8", "--seed", "5", "-o", single,
         "--quiet", "--threads", "2"])
    compare = os.path.join(os.path.dirname(render), "render-compare")

    def check_summary(s, ranks, fw, what):
        if s["ranks"] != ranks or s["forwarding"] != fw:
            sys.exit(f"FAIL: {what}: the summary says {s['ranks']} ranks, {s['forwarding']}")
        if ranks > 1 and s["forwards"] == 0:
            sys.exit(f"FAIL: {what}: no ray was forwarded; the scene does not exercise it")
        if ranks == 1 and s["forwards"] != 0:
            sys.exit(f"FAIL: {what}: one rank forwarded {s['forwards']} rays")
        for key in ("forwards_per_shadow_segment", "forward_bytes", "forward_messages",
                    "rank_peak_rss_bytes"):
            if key not in s:
                sys.exit(f"FAIL: {what}: the summary has no '{key}'")

    to_compare = []  # (image, what): compared with `single` at the end, in one process

    def check_image(out, what):
        to_compare.append((out, what))

    checked = 0
    for ranks in (1, 2, 3, 4):
        report = os.path.join(work, f"rc_{ranks}")
        run(mpirun_cmd(ranks) + [compare, scene, "--data-parallel", "--forwarding",
                                 ",".join(FORWARDINGS), "--estimators", "exact", "--spp", "8",
                                 "--seeds", "1", "--seed", "5", "--reference-spp", "8",
                                 "--passes-per-round", "3", "--threads", "1", "--quiet",
                                 "--out", report])
        rows = read_json(os.path.join(report, "report.json"))["rows"]
        if sorted(r["forwarding"] for r in rows) != sorted(FORWARDINGS):
            sys.exit(f"FAIL: {ranks} ranks: the report's rows are {rows}")
        for row in rows:
            what = f"{ranks} ranks, --forwarding {row['forwarding']}"
            check_summary(row, ranks, row["forwarding"], what)
            check_image(os.path.join(report, row["image"]), what)
            checked += 1
    for fw in FORWARDINGS:
        out = os.path.join(work, f"dp_2_{fw}_2threads.exr")
        dp(2, out, "--forwarding", fw, "--spp", "8", "--seed", "5", "--threads", "2",
           "--json", out + ".json")
        what = f"render, 2 ranks x 2 threads, --forwarding {fw}"
        s = read_json(out + ".json")
        check_summary(s, 2, fw, what)
        # Every request is 32 bytes and its answer 1.
        if s["forward_bytes"] != 33 * s["forwards"]:
            sys.exit(f"FAIL: {what}: {s['forward_bytes']} bytes for {s['forwards']} forwards")
        check_image(out, what)
        checked += 1
    whats = {out: what for out, what in to_compare}
    for _, out, text in differing_pairs(((single, out) for out, _ in to_compare), channels="R,G,B"):
        sys.exit(f"FAIL: {whats[out]}: the image differs from the single-process exact render\n"
                 f"{text}")
    print(f"ok: {checked} data-parallel renders equal the single-process exact render")

def roulette(t):
    """Roulette minus exact over seeds has mean zero; fixed costs: the same image at 2 threads."""
    render, scene, work, dp = t.render, t.scene, t.work, t.dp
    # Paired by seed: the light samples are the same, only forwarding differs, so
    # D = mean(roulette image) - mean(exact image) has expectation 0 exactly.
    pairs = []
    for seed in range(12):
        ex = os.path.join(work, f"exact_{seed}.exr")
        ro = os.path.join(work, f"roulette_{seed}.exr")
        # The data-parallel exact render equals the single-process one (case identical): no
        # MPI job needed for it.
        run([render, scene, "--estimator", "exact", "--spp", "4", "--seed", str(seed),
             "--threads", "1", "-o", ex, "--quiet"])
        dp(2, ro, "--forwarding", "proxies", "--estimator", "roulette", "--spp", "4", "--seed",
           str(seed), "--threads", "1", "--forward-cost-us", "200", "--local-cost-us", "1",
           "--json", ro + ".json", "--passes-per-round", "1")
        pairs.append((ex, ro))
        s = read_json(ro + ".json")
        if not (0 < s["mean_q"] < 1):
            sys.exit(f"FAIL: roulette forwarded with mean q {s['mean_q']}: not a roulette")
    means = rgb_means([f for pair in pairs for f in pair])
    diffs = [sum(means[2 * i + 1]) / 3 - sum(means[2 * i]) / 3 for i in range(len(pairs))]
    n = len(diffs)
    mean = sum(diffs) / n
    var = sum((d - mean) ** 2 for d in diffs) / (n - 1)
    z = mean / math.sqrt(var / n) if var > 0 else 0
    print(f"roulette - exact over {n} seeds: mean {mean:.3e}, sd {math.sqrt(var):.3e}, z {z:.2f}")
    if var == 0:
        sys.exit("FAIL: roulette and exact images are identical: nothing was left to chance")
    if abs(z) > 4:
        sys.exit(f"FAIL: |z| = {abs(z):.2f} > 4: roulette is biased")
    # With fixed costs its choices are a function of the seed: the same image at 2 threads.
    again = os.path.join(work, "roulette_0_threads2.exr")
    dp(2, again, "--forwarding", "proxies", "--estimator", "roulette", "--spp", "4", "--seed", "0",
       "--threads", "2", "--forward-cost-us", "200", "--local-cost-us", "1",
       "--passes-per-round", "1")
    same, text = rgb_equal(os.path.join(work, "roulette_0.exr"), again, work)
    if not same:
        sys.exit(f"FAIL: roulette with fixed costs differs between 1 and 2 threads\n{text}")
    print("ok: roulette is unbiased against exact (z-test)")

def network(t):
    """Emulated fabrics: images, the model's keys, a slow fabric's waits, refused flags."""
    render, scene, work, dp = t.render, t.scene, t.work, t.dp
    single = os.path.join(work, "single.exr")
    run([render, scene, "--estimator", "exact", "--spp", "4", "--seed", "3", "-o", single,
         "--quiet", "--threads", "1"])
    outs = []
    for ranks, threads, net in ((2, 1, "ib-hdr"), (4, 2, "10gbe-tcp"), (2, 2, "unbatched-20us")):
        out = os.path.join(work, f"emulated_{ranks}_{threads}_{net}.exr")
        dp(ranks, out, "--forwarding", "proxies", "--spp", "4", "--seed", "3", "--threads",
           str(threads), "--network", net, "--emulate-network", "--json", out + ".json",
           "--passes-per-round", "2")
        s = read_json(out + ".json")
        what = f"{ranks} ranks x {threads} threads on emulated {net}"
        for key in ("network", "network_alpha_us", "network_beta_gbps", "emulated",
                    "modelled_seconds", "modelled_compute_seconds", "modelled_message_seconds",
                    "modelled_control_seconds", "seconds"):
            if key not in s:
                sys.exit(f"FAIL: {what}: the summary has no '{key}'")
        if s["network"] != net or not s["emulated"] or s["forwards"] == 0:
            sys.exit(f"FAIL: {what}: network {s['network']}, emulated {s['emulated']}, "
                     f"{s['forwards']} forwards")
        if net == "unbatched-20us":
            # The flat cost charges 20 us per forward: its messages cost at least that much.
            if s["modelled_message_seconds"] < 20e-6 * s["max_rank_forwards"] * 0.999:
                sys.exit(f"FAIL: {what}: {s['modelled_message_seconds']} s of messages for "
                         f"{s['max_rank_forwards']} forwards of the busiest rank")
            if not s["network_upper_bound"]:
                sys.exit(f"FAIL: {what}: the flat cost is not labelled an upper bound")
        outs.append((out, what))
    for out, what in outs:
        same, text = rgb_equal(single, out, work)
        if not same:
            sys.exit(f"FAIL: {what}: differs from the single-process exact render\n{text}")
    # A slow fabric: 20 ms per message. Every round's count exchange over 4 ranks waits 2 alpha
    # (ceil(log2 4)), so the emulated run takes at least rounds x 40 ms; the same run on shared
    # memory does not wait.
    slow = os.path.join(work, "slow.exr")
    dp(4, slow, "--forwarding", "instance-boxes", "--spp", "2", "--seed", "3", "--threads", "1",
       "--network", "roce", "--network-alpha-us", "20000", "--emulate-network", "--json",
       slow + ".json")
    s = read_json(slow + ".json")
    floor = s["forward_rounds"] * 2 * 0.020
    if s["network"] != "custom" or s["network_alpha_us"] != 20000 or s["network_beta_gbps"] != 11:
        sys.exit(f"FAIL: --network-alpha-us on roce gave {s['network']}, "
                 f"{s['network_alpha_us']} us, {s['network_beta_gbps']} GB/s")
    if s["seconds"] < floor or s["modelled_control_seconds"] < floor:
        sys.exit(f"FAIL: {s['forward_rounds']} rounds at 20 ms per message took {s['seconds']} s "
                 f"(modelled counts {s['modelled_control_seconds']} s), under {floor} s")
    fast = os.path.join(work, "fast.exr")
    dp(4, fast, "--forwarding", "instance-boxes", "--spp", "2", "--seed", "3", "--threads", "1",
       "--json", fast + ".json")
    f = read_json(fast + ".json")
    if f["emulated"] or f["network"] != "shm" or not f["network_beta_gbps"] > 0:
        sys.exit(f"FAIL: the default run is not on measured shared memory: {f['network']}, "
                 f"emulated {f['emulated']}, beta {f['network_beta_gbps']}")
    # render-compare: shared memory and emulated rows side by side, each with its baseline.
    compare = os.path.join(os.path.dirname(render), "render-compare")
    report = os.path.join(work, "rc")
    run(mpirun_cmd(2) + [compare, scene, "--data-parallel", "--forwarding",
                         "instance-boxes,proxies", "--estimators", "exact", "--spp", "2",
                         "--seeds", "1", "--reference-spp", "2", "--threads", "1", "--quiet",
                         "--network", "ib-hdr", "--emulate-network", "--out", report])
    rows = read_json(os.path.join(report, "report.json"))["rows"]
    kinds = sorted((r["forwarding"], r["emulated"]) for r in rows)
    if kinds != [("instance-boxes", False), ("instance-boxes", True), ("proxies", False),
                 ("proxies", True)]:
        sys.exit(f"FAIL: render-compare --emulate-network rows: {kinds}")
    for r in rows:
        if r["network"] != "ib-hdr" or "modelled_relative_efficiency" not in r:
            sys.exit(f"FAIL: a row without its fabric or model: {r}")
        if r["forwarding"] == "instance-boxes" and abs(r["relative_efficiency"] - 1) > 1e-9:
            sys.exit(f"FAIL: the baseline's relative efficiency is {r['relative_efficiency']}")
    # Bad flags: one line, exit 2, before anything is rendered.
    bad = os.path.join(work, "bad.exr")
    # Under mpirun every rank parses the flags: one line still (the one-rank cases of each bad
    # figure are in tests/bad_inputs).
    for flags, words in ((["--network", "infiniband"], "not a known fabric"),
                         (["--network-alpha-us", "-3"], "--network-alpha-us")):
        p = dp(2, bad, *flags, expect=2)
        lines = [l for l in p.stderr.splitlines() if l.strip()]
        if len(lines) != 1 or words not in lines[0] or os.path.exists(bad):
            sys.exit(f"FAIL: {flags}: expected one line with '{words}':\n{p.stderr}")
    for flag in (["--repeats", "2"],):
        p = run(mpirun_cmd(2) + [compare, scene, "--data-parallel", "--spp", "2", "--out",
                                 os.path.join(work, "never"), *flag], expect=2)
        lines = [l for l in p.stderr.splitlines() if l.strip()]
        if len(lines) != 1 or "not available with --data-parallel" not in lines[0] or \
                os.path.exists(os.path.join(work, "never")):
            sys.exit(f"FAIL: render-compare --data-parallel {flag}: expected one line:\n{p.stderr}")
    p = run([render, scene, "--network", "ib-hdr", "-o", bad, "--quiet"], expect=2)
    if "needs --data-parallel" not in p.stderr or os.path.exists(bad):
        sys.exit(f"FAIL: --network without --data-parallel:\n{p.stderr}")
    print(f"ok: {len(outs)} emulated renders equal the single-process render; 20 ms messages "
          f"took {s['seconds']:.2f} s for {s['forward_rounds']} rounds; bad flags exit 2")
