"""Data-parallel rendering over MPI, end to end (label mpi). Cases:
  identical  exact renders equal the single-process exact render bit for bit (R, G, B) at 1, 2, 3
             and 4 ranks, every forwarding policy, 1 and 2 threads, from render and render-compare
  files      no rank opens another rank's original (strace of every rank's open calls)
  faults     a rank that cannot read its original ends the job with exit 2 and one line naming the
             rank and the file; a rank killed mid-job fails the job; no output replaces a good one
  refuse     a proxy whose recorded class does not hold for its file is refused before rendering
  flags      every flag render and render-compare share with the single-process renderer acts
             on the data-parallel one (--proxy-kind, --build, --memory-budget, --width,
             --height, --q-min) or is refused with exit 2 and one error line
  roulette   roulette is unbiased: over seeds, its image minus the same seed's exact image has
             mean zero (z-test); with fixed costs it is the same image at 1 and 2 threads
  network    the alpha-beta fabric: emulated exact renders equal the single-process render at 2 and
             4 ranks, 1 and 2 threads; an emulated fabric of 20 ms per message makes the run wait
             at least its rounds' count exchanges; every row carries the fabric and the model;
             render-compare --emulate-network gives shared-memory and emulated rows side by side;
             unknown presets, bad figures and network flags without --data-parallel exit 2, and
             so do render-compare's --equal-time and --repeats, which the study does not do
  readme     the mpirun commands of README.md's data-parallel section run as written, in a
             folder laid out like a new clone, and the exact render equals `render`'s
  make_proxies  the test scene's proxies, made once into WORK_DIR/../proxies for the other cases
             and tests/slurm's data-parallel tests (a ctest fixture: none of them makes its own)
usage: data_parallel_test.py CASE RENDER_EXE PROXY_GEN_EXE DATA_DIR SCENES_DIR WORK_DIR"""
import json
import math
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(__file__))
from mpi_support import make_unique_scene, mpi_env, mpirun_cmd, rgb_equal, rgb_means, run  # noqa: E402,E501
from image_diff import differing_pairs  # noqa: E402

case, render, proxy_gen, data_dir, scenes_dir, work = sys.argv[1:7]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
# Roulette's 25 renders are mostly program start and scene load: its 2 x 2 grid of sculptures
# (split over both ranks) loads in 0.7 s where the 3 x 3 grid takes 1.2 s.
SIDE = 2 if case == "roulette" else 3
scene = (make_unique_scene(work, data_dir, scenes_dir, proxy_gen, side=SIDE,
                           proxy_cache=os.path.join(os.path.dirname(work), "proxies"))
         if case != "readme" else None)
FORWARDINGS = ["domain-bounds", "instance-boxes", "proxies"]


def dp(ranks, out, *flags, expect=0, env=None):
    return run(mpirun_cmd(ranks) + [render, scene, "--data-parallel", "-o", out, "--quiet",
                                    *flags], expect=expect, env=env)


def summary(path):
    with open(path) as f:
        return json.load(f)


if case == "identical":
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
        rows = summary(os.path.join(report, "report.json"))["rows"]
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
        s = summary(out + ".json")
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

elif case == "files":
    # Every rank under strace; its opened files against the other ranks' originals. A machine
    # that forbids ptrace cannot run this check: skipped (exit 77), never passed.
    probe = subprocess.run(["strace", "-f", "-qq", "-o", os.devnull, "true"], capture_output=True,
                           text=True)
    if probe.returncode != 0:
        print(f"SKIP: strace cannot trace here: {probe.stderr.strip()}")
        sys.exit(77)
    trace = os.path.join(work, "trace")
    js = os.path.join(work, "files.json")
    cmd = mpirun_cmd(3) + [
        "sh", "-c", f'exec strace -f -qq -e trace=open,openat -o "{trace}.$OMPI_COMM_WORLD_RANK" '
        f'"$@"', "sh", render, scene, "--data-parallel", "--forwarding", "proxies", "--spp", "2",
        "-o", os.path.join(work, "files.exr"), "--json", js, "--quiet", "--threads", "1"]
    run(cmd)
    per_rank = summary(js)["per_rank"]
    owned = [set(r["originals_opened"]) for r in per_rank]
    everywhere = set.intersection(*owned)  # replicated: the ground
    for r in range(3):
        mine = owned[r] - everywhere
        if not mine:
            sys.exit(f"FAIL: rank {r} owns no original")
        for q in range(r + 1, 3):
            if mine & (owned[q] - everywhere):
                sys.exit(f"FAIL: ranks {r} and {q} both own {mine & owned[q]}")
    for r in range(3):
        with open(f"{trace}.{r}") as f:
            opened = f.read()
        if "meshes/m" not in opened:
            sys.exit(f"FAIL: rank {r}'s trace shows no mesh opened: is strace working?")
        for q in range(3):
            if q == r:
                continue
            for path in owned[q] - everywhere:
                if f'"{path}"' in opened:
                    sys.exit(f"FAIL: rank {r} opened {path}, an original of rank {q}")
        for path in owned[r] - everywhere:
            if f'"{path}"' not in opened:
                sys.exit(f"FAIL: rank {r} says it loaded {path} but strace saw no open of it")
    print("ok: each rank opened its own originals and no other rank's")

elif case == "faults":
    good = os.path.join(work, "good.exr")
    dp(2, good, "--spp", "2", "--json", good + ".json")
    before = open(good, "rb").read()
    owned = summary(good + ".json")["per_rank"][1]["originals_opened"]
    victim = next(p for p in owned if "/meshes/m" in p)
    with open(victim, "r+b") as f:
        f.truncate(os.path.getsize(victim) // 2)
    # Rank 0 reports 3 s late, as under load: the other rank must not end the job before it.
    slow = mpi_env()
    slow["PROXYVIS_TEST_SLOW_ERROR"] = "3"
    p = dp(2, good, "--spp", "2", expect=2, env=slow)
    lines = [l for l in p.stderr.splitlines() if "error" in l]
    if len(lines) != 1 or "rank 1" not in lines[0] or os.path.basename(victim) not in lines[0]:
        sys.exit(f"FAIL: expected one error line naming rank 1 and {victim}:\n{p.stderr}")
    if open(good, "rb").read() != before:
        sys.exit("FAIL: the failed job replaced the good output")
    shutil.copyfile(os.path.join(data_dir, "bunny.off" if victim.endswith(".off")
                                 else "spot_triangulated.obj"), victim)
    env = mpi_env()
    env["PROXYVIS_TEST_KILL_RANK"] = "1"
    p = dp(2, good, "--spp", "2", expect=None, env=env)
    if p.returncode == 0:
        sys.exit("FAIL: a job whose rank 1 was killed exited 0")
    if open(good, "rb").read() != before:
        sys.exit("FAIL: the killed job replaced the good output")
    leftovers = [f for f in os.listdir(work) if f.startswith("good") and f not in
                 ("good.exr", "good.exr.json")]
    if leftovers:
        sys.exit(f"FAIL: the killed job left {leftovers}")
    print(f"ok: unreadable original -> exit 2 naming rank 1; killed rank -> exit "
          f"{p.returncode}; the good output untouched")

elif case == "refuse":
    with open(scene) as f:
        s = json.load(f)
    s["meshes"][1]["proxies"][0]["sha256"] = "0" * 64
    bad = os.path.join(work, "bad.json")
    with open(bad, "w") as f:
        json.dump(s, f)
    out = os.path.join(work, "refused.exr")
    p = run(mpirun_cmd(2) + [render, bad, "--data-parallel", "--forwarding", "proxies", "-o", out,
                             "--quiet"], expect=2)
    if "not proved for this file" not in p.stderr or os.path.exists(out):
        sys.exit(f"FAIL: a proxy with a wrong sha256 was not refused:\n{p.stderr}")
    # Without proxies to rely on, the box baseline still renders it.
    dp(2, out, "--forwarding", "instance-boxes", "--spp", "1")
    print("ok: a proxy whose class is not proved for its file is refused before rendering")

elif case == "flags":
    def dp_json(name, *flags):
        out = os.path.join(work, name + ".exr")
        dp(2, out, "--seed", "3", "--threads", "1", *flags, "--json", out + ".json")
        return summary(out + ".json"), out

    def single(name, scene_file, *flags):
        out = os.path.join(work, name + ".exr")
        run([render, scene_file, "--seed", "3", "--threads", "1", "-o", out, "--quiet",
             "--json", out + ".json", *flags])
        return summary(out + ".json"), out

    def same_image(a, b, what):
        same, text = rgb_equal(a, b, work)
        if not same:
            sys.exit(f"FAIL: {what}: the data-parallel image differs from render's\n{text}")

    # --proxy-kind outside: forwarding relies on the outside proxies alone, so no segment is
    # decided by an inside proxy and more are forwarded; the image stays render's own.
    both, _ = dp_json("both", "--spp", "4")
    outside, outside_exr = dp_json("outside", "--spp", "4", "--proxy-kind", "outside")
    if both["blocked_by_inside_proxy"] == 0:
        sys.exit("FAIL: no segment was decided by an inside proxy: the scene does not exercise it")
    if outside["blocked_by_inside_proxy"] != 0 or outside["forwards"] <= both["forwards"]:
        sys.exit(f"FAIL: --proxy-kind outside did not act: {outside['blocked_by_inside_proxy']} "
                 f"blocked by inside proxies, {outside['forwards']} forwards against "
                 f"{both['forwards']} with both kinds")
    held = [sum(r["proxy_triangles"] for r in x["per_rank"]) for x in (both, outside)]
    if not held[1] < held[0]:
        sys.exit(f"FAIL: --proxy-kind outside: the ranks hold {held[1]} proxy triangles, with "
                 f"both kinds {held[0]}: the inside proxies were loaded for nothing")
    _, single_outside = single("single_outside", scene, "--spp", "4", "--proxy-kind", "outside")
    same_image(single_outside, outside_exr, "--proxy-kind outside")

    # --width and --height: the image's size.
    small, _ = dp_json("small", "--spp", "1", "--width", "20", "--height", "10")
    if (small["width"], small["height"]) != (20, 10):
        sys.exit(f"FAIL: --width 20 --height 10 rendered {small['width']} x {small['height']}")

    # --build and --memory-budget on an instanced copy of the scene: the data-parallel build is
    # the single-process one for the same flags, and so is the image.
    with open(scene) as f:
        inst = json.load(f)
    lines = []
    for m in inst["meshes"][1:]:
        m["place"] = False
        t = m.pop("transform")
        lines.append(" ".join([m["name"]] + [repr(float(v)) for v in t]))
    with open(os.path.join(work, "inst.instances.txt"), "w") as f:
        f.write("\n".join(lines) + "\n")
    inst["instances"] = {"file": "inst.instances.txt"}
    for m in inst["meshes"]:
        for p in m.get("proxies", []):
            p["file"] = os.path.join(os.path.dirname(scene), p["file"])
        if not os.path.isabs(m["file"]):
            m["file"] = os.path.join(os.path.dirname(scene), m["file"])
    inst_scene = os.path.join(work, "inst.json")
    with open(inst_scene, "w") as f:
        json.dump(inst, f)
    for flags, expect in ((["--build", "flat"], "flat"), (["--build", "instanced"], "instanced"),
                          (["--build", "auto", "--memory-budget", "0"], "instanced"),
                          (["--build", "auto"], "flat")):
        what = " ".join(flags)
        out = os.path.join(work, f"inst_{'_'.join(flags)}.exr")
        run(mpirun_cmd(2) + [render, inst_scene, "--data-parallel", "-o", out, "--quiet",
                             "--spp", "2", "--seed", "3", "--threads", "1", "--json",
                             out + ".json", *flags])
        got = summary(out + ".json")["scene_build"]
        ref, ref_exr = single(f"inst_single_{'_'.join(flags)}", inst_scene, "--spp", "2", *flags)
        if got != expect or ref["scene_build"] != expect:
            sys.exit(f"FAIL: {what}: data-parallel build {got}, render's {ref['scene_build']}, "
                     f"expected {expect}")
        same_image(ref_exr, out, what)

    # --q-min 1 leaves roulette no choice: it forwards every undecided segment.
    roulette = ["--estimator", "roulette", "--spp", "4", "--forward-cost-us", "200",
                "--local-cost-us", "1", "--passes-per-round", "1"]
    free, _ = dp_json("q_free", *roulette)
    pinned, _ = dp_json("q_pinned", *roulette, "--q-min", "1")
    if not free["mean_q"] < 1 or pinned["mean_q"] != 1:
        sys.exit(f"FAIL: --q-min 1 did not act: mean q {pinned['mean_q']} (without it "
                 f"{free['mean_q']})")

    # Refused: exit 2, one error line naming the flag, no output.
    compare = os.path.join(os.path.dirname(render), "render-compare")
    refused = os.path.join(work, "refused.exr")
    # Two of them under mpirun (one line from two ranks); the others, and these, are one-rank
    # cases in tests/bad_inputs/cases_data_parallel.cmake.
    cases = [
        (["--proxy-kind", "inside"], "--proxy-kind inside"),
        (["--probes", "8"], "--probes"),
    ]
    for flags, name in cases:
        p = dp(2, refused, *flags, expect=2)
        errors = [l for l in p.stderr.splitlines() if "error" in l]
        if len(errors) != 1 or name not in errors[0] or os.path.exists(refused):
            sys.exit(f"FAIL: {' '.join(flags)} was not refused with one line naming it:\n"
                     f"{p.stderr}")
    report = os.path.join(work, "rc_refused")
    p = run(mpirun_cmd(2) + [compare, scene, "--data-parallel", "--spp", "1", "--seeds", "1",
                             "--reference-spp", "16", "--quiet", "--out", report, "--probes",
                             "8"], expect=2)
    if len([l for l in p.stderr.splitlines() if "error" in l and "--probes" in l]) != 1:
        sys.exit(f"FAIL: render-compare --data-parallel --probes was not refused:\n{p.stderr}")
    # render-compare passes --proxy-kind on too.
    report = os.path.join(work, "rc_outside")
    run(mpirun_cmd(2) + [compare, scene, "--data-parallel", "--spp", "2", "--seeds", "1",
                         "--reference-spp", "16", "--estimators", "exact", "--quiet", "--out",
                         report, "--proxy-kind", "outside"])
    rows = summary(os.path.join(report, "report.json"))["rows"]
    if not rows or any(r["blocked_by_inside_proxy"] != 0 for r in rows):
        sys.exit(f"FAIL: render-compare --proxy-kind outside did not act: {rows}")
    print(f"ok: --proxy-kind, --width, --height, --build, --memory-budget and --q-min act on the "
          f"data-parallel renderer; {len(cases) + 1} other uses are refused")

elif case == "roulette":
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
        s = summary(ro + ".json")
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
elif case == "network":
    single = os.path.join(work, "single.exr")
    run([render, scene, "--estimator", "exact", "--spp", "4", "--seed", "3", "-o", single,
         "--quiet", "--threads", "1"])
    outs = []
    for ranks, threads, net in ((2, 1, "ib-hdr"), (4, 2, "10gbe-tcp"), (2, 2, "unbatched-20us")):
        out = os.path.join(work, f"emulated_{ranks}_{threads}_{net}.exr")
        dp(ranks, out, "--forwarding", "proxies", "--spp", "4", "--seed", "3", "--threads",
           str(threads), "--network", net, "--emulate-network", "--json", out + ".json",
           "--passes-per-round", "2")
        s = summary(out + ".json")
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
    s = summary(slow + ".json")
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
    f = summary(fast + ".json")
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
    rows = summary(os.path.join(report, "report.json"))["rows"]
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
elif case == "make_proxies":
    print(f"ok: the test scene's proxies are in {os.path.join(os.path.dirname(work), 'proxies')}")
elif case == "readme":
    import re
    import shlex
    root = os.path.dirname(os.path.abspath(scenes_dir))
    text = open(os.path.join(root, "README.md"), encoding="utf-8").read()
    section = text.split("## Data-parallel rendering over MPI", 1)[1].split("\n## ", 1)[0]
    block = re.search(r"```sh\n(.*?)```", section, re.S).group(1)
    block = re.sub(r"\\\n\s*", "", block)
    lines = [l.strip() for l in block.splitlines() if l.strip().startswith("mpirun")]
    if len(lines) < 2:
        sys.exit(f"FAIL: {len(lines)} mpirun lines in README's data-parallel section")
    os.makedirs(os.path.join(work, "build"))
    for name in ("data", "scenes"):
        os.symlink(os.path.join(root, name), os.path.join(work, name))
    os.symlink(os.path.dirname(os.path.abspath(render)), os.path.join(work, "build", "bin"))
    for line in lines:
        p = subprocess.run(shlex.split(line, comments=True), cwd=work, capture_output=True,
                           text=True, env=mpi_env(), timeout=500)
        if p.returncode != 0:
            sys.exit(f"FAIL: $ {line}\nexit {p.returncode}\n{p.stdout}\n{p.stderr}")
        print(f"ok: {line}")
    exr = os.path.join(work, "out", "park.exr")
    single = os.path.join(work, "single.exr")
    spp = re.search(r"--spp (\d+)", lines[0]).group(1)
    run([render, os.path.join(root, "scenes", "park.json"), "--spp", spp, "-o", single, "--quiet"])
    same, text = rgb_equal(single, exr, work)
    if not same:
        sys.exit(f"FAIL: README's data-parallel render differs from render's\n{text}")
    report = summary(os.path.join(work, "out", "park-dp", "report.json"))
    policies = {r["forwarding"] for r in report["rows"]}
    if policies != {"domain-bounds", "instance-boxes", "proxies"}:
        sys.exit(f"FAIL: the report's rows cover {policies}")
    print("ok: README's data-parallel commands run and the render equals render's")
else:
    sys.exit(f"unknown case {case}")
