"""The input and flag cases of data_parallel_test.py: which files each rank opens (files), a rank
that fails (faults), an unproved proxy (refuse), the flags shared with the single-process renderer
(flags) and README's commands (readme). Each takes the test's context (data_parallel_test.py)."""
import json
import os
import re
import shlex
import shutil
import subprocess
import sys

from mpi_support import mpi_env, mpirun_cmd, read_json, rgb_equal, run


def files(t):
    """No rank opens another rank's original (strace of every rank)."""
    render, scene, work = t.render, t.scene, t.work
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
    per_rank = read_json(js)["per_rank"]
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

def faults(t):
    """An unreadable original or a killed rank fails the job; the good output stays."""
    work, dp, data_dir = t.work, t.dp, t.data_dir
    good = os.path.join(work, "good.exr")
    dp(2, good, "--spp", "2", "--json", good + ".json")
    before = open(good, "rb").read()
    owned = read_json(good + ".json")["per_rank"][1]["originals_opened"]
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

def refuse(t):
    """A proxy whose class is not proved for its file is refused before rendering."""
    render, scene, work, dp = t.render, t.scene, t.work, t.dp
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

def dp_json(t, name, *flags):
    out = os.path.join(t.work, name + ".exr")
    t.dp(2, out, "--seed", "3", "--threads", "1", *flags, "--json", out + ".json")
    return read_json(out + ".json"), out


def single(t, name, scene_file, *flags):
    out = os.path.join(t.work, name + ".exr")
    run([t.render, scene_file, "--seed", "3", "--threads", "1", "-o", out, "--quiet",
         "--json", out + ".json", *flags])
    return read_json(out + ".json"), out


def same_image(t, a, b, what):
    same, text = rgb_equal(a, b, t.work)
    if not same:
        sys.exit(f"FAIL: {what}: the data-parallel image differs from render's\n{text}")


def flags_that_act(t):
    """--proxy-kind, --width, --height, --build, --memory-budget and --q-min act on the
    data-parallel renderer as on the single-process one."""
    render, scene, work = t.render, t.scene, t.work
    # --proxy-kind outside: forwarding relies on the outside proxies alone, so no segment is
    # decided by an inside proxy and more are forwarded; the image stays render's own.
    both, _ = dp_json(t, "both", "--spp", "4")
    outside, outside_exr = dp_json(t, "outside", "--spp", "4", "--proxy-kind", "outside")
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
    _, single_outside = single(t, "single_outside", scene, "--spp", "4", "--proxy-kind",
                               "outside")
    same_image(t, single_outside, outside_exr, "--proxy-kind outside")

    # --width and --height: the image's size.
    small, _ = dp_json(t, "small", "--spp", "1", "--width", "20", "--height", "10")
    if (small["width"], small["height"]) != (20, 10):
        sys.exit(f"FAIL: --width 20 --height 10 rendered {small['width']} x {small['height']}")

    # --build and --memory-budget on an instanced copy of the scene: the data-parallel build is
    # the single-process one for the same flags, and so is the image.
    with open(scene) as f:
        inst = json.load(f)
    lines = []
    for m in inst["meshes"][1:]:
        m["place"] = False
        transform = m.pop("transform")
        lines.append(" ".join([m["name"]] + [repr(float(v)) for v in transform]))
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
        got = read_json(out + ".json")["scene_build"]
        ref, ref_exr = single(t, f"inst_single_{'_'.join(flags)}", inst_scene, "--spp", "2",
                              *flags)
        if got != expect or ref["scene_build"] != expect:
            sys.exit(f"FAIL: {what}: data-parallel build {got}, render's {ref['scene_build']}, "
                     f"expected {expect}")
        same_image(t, ref_exr, out, what)

    # --q-min 1 leaves roulette no choice: it forwards every undecided segment.
    roulette = ["--estimator", "roulette", "--spp", "4", "--forward-cost-us", "200",
                "--local-cost-us", "1", "--passes-per-round", "1"]
    free, _ = dp_json(t, "q_free", *roulette)
    pinned, _ = dp_json(t, "q_pinned", *roulette, "--q-min", "1")
    if not free["mean_q"] < 1 or pinned["mean_q"] != 1:
        sys.exit(f"FAIL: --q-min 1 did not act: mean q {pinned['mean_q']} (without it "
                 f"{free['mean_q']})")


def flags_refused(t):
    """The flags the data-parallel renderer does not take: exit 2 with one line naming them;
    render-compare passes --proxy-kind on. Returns how many refusals were checked."""
    render, scene, work, dp = t.render, t.scene, t.work, t.dp
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
    rows = read_json(os.path.join(report, "report.json"))["rows"]
    if not rows or any(r["blocked_by_inside_proxy"] != 0 for r in rows):
        sys.exit(f"FAIL: render-compare --proxy-kind outside did not act: {rows}")
    return len(cases) + 1


def flags(t):
    """The flags render shares with the single-process renderer act or are refused."""
    flags_that_act(t)
    refusals = flags_refused(t)
    print(f"ok: --proxy-kind, --width, --height, --build, --memory-budget and --q-min act on the "
          f"data-parallel renderer; {refusals} other uses are refused")

def readme(t):
    """README's data-parallel commands run as written."""
    render, work, scenes_dir = t.render, t.work, t.scenes_dir
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
    report = read_json(os.path.join(work, "out", "park-dp", "report.json"))
    policies = {r["forwarding"] for r in report["rows"]}
    if policies != {"domain-bounds", "instance-boxes", "proxies"}:
        sys.exit(f"FAIL: the report's rows cover {policies}")
    print("ok: README's data-parallel commands run and the render equals render's")
