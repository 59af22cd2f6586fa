#!/usr/bin/env python3
"""Shares one triangle budget over the proxies of a scene's meshes, where proxy-check measures
the most gain, and reports the result on segments it was not chosen on.

A uniform --ratio gives every mesh the same share of its faces. In a scene of many instanced
meshes that is not where the triangles pay: a grass's proxy gets tighter when reduced, a
flower's looser. This script measures each mesh's proxy at several face budgets on the
renderer's segments and picks one budget per mesh so that the proxies' triangles, counted per
instance, stay within --share of the originals' and the rate that matters is least:
P(hit proxy | miss original) for outside proxies (a forward sent for nothing), P(miss proxy |
hit original) for inside ones (a block not found).

Steps, each kept in OUT_DIR so that a second run only does what is missing:
1. options/b<B>/: proxy-gen SCENE --out-dir ... --max-faces B for every B of --budgets, and
   options/b0/ without a budget; options/b<B>.check.json: proxy-check --distribution scene
   --seed SEED on each.
2. allocation.json: the budget of every mesh (budget_choice.py), written into budgets.json,
   the scene with each mesh's "proxy_max_faces".
3. final/: proxy-gen on budgets.json (the proxies come from proxy-gen's cache), final.check.json
   and baseline.check.json (options b0): proxy-check --seed CHECK_SEED, new segments, so the
   printed rate is not the one the choice was made on.

usage: allocate_proxy_budgets.py SCENE --share S --out-dir DIR [--bin DIR] [--kind outside]
           [--budgets 16,32,...] [--rays N] [--seed N] [--check-seed N] [--objective wasted-hits]
           [-- PROXY_GEN_ARGS...]
Exit codes: 0 done, 1 a tool failed or no choice fits the share, 2 bad arguments or scene.
"""
import argparse
import json
import os
import subprocess
import sys

from budget_choice import choose
from proxyvis_tools.scenes import instance_counts, load_scene_absolute

PROG = "allocate_proxy_budgets.py"
RATE_KEY = {"outside": "P_hit_proxy_given_miss_original",
            "inside": "P_miss_proxy_given_hit_original"}
# The counts a rate is a fraction of: outside, segments that miss the original (MH' + MM');
# inside, those that hit it (HH' + HM').
RATE_BASE = {"outside": ("MH", "MM"), "inside": ("HH", "HM")}


def die(code, what, why="", todo=""):
    print(f"{PROG}: error: {what}" + (f": {why}" if why else "") + (f"; {todo}" if todo else ""),
          file=sys.stderr)
    sys.exit(code)


def tool(a, name):
    return os.path.join(a.bin, name)


def run(args, log):
    with open(log, "w") as out:
        p = subprocess.run([str(a) for a in args], stdout=out, stderr=subprocess.STDOUT)
    if p.returncode != 0:
        die(1, f"{' '.join(map(str, args[:2]))} ... exited {p.returncode}", f"see {log}")


def read_checks(path, kind):
    """Per mesh name: proxy faces, original faces, rate (None: no segment it is a fraction of)
    and the misses (or hits) per draw, from a proxy-check --distribution scene JSON."""
    with open(path) as f:
        report = json.load(f)
    out = {}
    for c in report["checks"]:
        name = c["label"].split(" / ")[0]
        base = sum(c["counts"][k] for k in RATE_BASE[kind])
        out[name] = {"faces": c["proxy"]["faces"], "original_faces": c["original"]["faces"],
                     "rate": c[RATE_KEY[kind]], "per_draw": base / max(c["attempts"], 1)}
    return out


def objective_of(name, pick, counts, objective):
    """What a mesh's proxy adds to the objective: its rate times its instances ("rate"), or its
    wasted hits per draw of the renderer's distribution ("wasted-hits": outside, MH', segments
    that hit the proxy and miss the original; inside, HM'). proxy-check maps each segment into
    one instance among those whose box it crosses, so this counts a segment once per mesh, not
    once per instance or per rank it would be forwarded to."""
    if pick["rate"] is None:
        return 0.0
    return pick["rate"] * (counts[name] if objective == "rate" else pick["per_draw"])


def instance_rate(picks, counts):
    """The rate averaged per instance over the meshes that have one."""
    rated = [n for n, p in picks.items() if p["rate"] is not None]
    total = sum(counts[n] for n in rated)
    return sum(objective_of(n, picks[n], counts, "rate") for n in rated) / total if total else None


def summary(label, picks, counts, original):
    triangles = sum(p["faces"] * counts[n] for n, p in picks.items())
    return {"label": label, "triangles": triangles, "share": triangles / original,
            "rate_per_instance": instance_rate(picks, counts),
            "wasted_hits_per_draw": sum(objective_of(n, p, counts, "wasted-hits")
                                     for n, p in picks.items())}


def write_budget_scene(scene, budgets, out):
    """The scene (paths absolute) with each chosen mesh's "proxy_max_faces"."""
    scene = json.loads(json.dumps(scene))
    for m in scene["meshes"]:
        if m["name"] in budgets:
            m["proxy_max_faces"] = budgets[m["name"]]
    tmp = out + ".tmp"
    with open(tmp, "w") as f:
        json.dump(scene, f, indent=1)
    os.replace(tmp, out)


def parse_args(argv):
    extra = []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0])
    ap.add_argument("scene")
    ap.add_argument("--share", type=float, required=True,
                    help="proxy triangles per original triangle, instances counted (e.g. 0.03)")
    ap.add_argument("--out-dir", required=True)
    ap.add_argument("--bin", default="build/bin", help="folder of proxy-gen and proxy-check")
    ap.add_argument("--kind", choices=["outside", "inside"], default="outside")
    ap.add_argument("--budgets", default="16,24,32,48,64,80,96,128,160,200,256",
                    help="face budgets measured per mesh (no budget is always measured too)")
    ap.add_argument("--rays", type=int, default=20000,
                    help="proxy-check segments per mesh (its --rays)")
    ap.add_argument("--seed", type=int, default=0, help="proxy-check seed of the choice")
    ap.add_argument("--check-seed", type=int, default=1,
                    help="proxy-check seed of the printed result (not --seed: new segments)")
    ap.add_argument("--objective", choices=["rate", "wasted-hits"], default="wasted-hits",
                    help="least rate averaged per instance, or least wasted hits per draw of the "
                         "renderer's segments: outside, proxy hits that miss the original; "
                         "inside, original hits the proxy misses")
    a = ap.parse_args(argv)
    try:
        a.budgets = sorted({int(b) for b in a.budgets.split(",")})
    except ValueError:
        die(2, f"--budgets {a.budgets!r}", "expected comma-separated face counts", "e.g. 16,64,256")
    if not a.budgets or a.budgets[0] < 4:
        die(2, f"--budgets {a.budgets}", "a closed proxy has at least 4 faces")
    if not 0 < a.share <= 1:
        die(2, f"--share {a.share}", "expected a fraction in (0, 1]", "e.g. 0.03")
    if a.check_seed == a.seed:
        die(2, "--check-seed equals --seed", "the result would be measured on the segments it was "
            "chosen on", "give another seed")
    a.extra = extra
    return a


def claim_options_dir(a, options_dir):
    """Options kept in OUT/options are reused only by runs that would measure them the same way:
    the settings they were made with are written beside them, and other settings are refused."""
    settings = {"scene": os.path.abspath(a.scene), "kind": a.kind, "rays": a.rays, "seed": a.seed,
                "proxy_gen_args": a.extra}
    path = os.path.join(options_dir, "settings.json")
    if os.path.exists(path):
        with open(path) as f:
            old = json.load(f)
        if old != settings:
            changed = ", ".join(k for k in settings if old.get(k) != settings[k])
            die(2, f"{options_dir} holds options measured with other settings ({changed})",
                "they would be reused as they are", "remove that folder or give another --out-dir")
        return
    with open(path + ".tmp", "w") as f:
        json.dump(settings, f, indent=1)
    os.replace(path + ".tmp", path)


def measure_options(a, options_dir):
    """Step 1: proxies and their checks at every budget (0 = none); returns {budget: checks}."""
    claim_options_dir(a, options_dir)
    gen, check = tool(a, "proxy-gen"), tool(a, "proxy-check")
    measured = {}
    for b in [0] + a.budgets:
        out = os.path.join(options_dir, f"b{b}")
        checks = out + ".check.json"
        if not os.path.exists(checks):
            print(f"{PROG}: budget {b or 'none'}: proxy-gen, proxy-check", file=sys.stderr)
            run([gen, a.scene, "--kind", a.kind, "--out-dir", out, "--json", out + ".gen.json",
                 "-q", *(["--max-faces", b] if b else []), *a.extra], out + ".gen.log")
            run([check, os.path.join(out, "scene.json"), "--distribution", "scene", "--rays",
                 a.rays, "--seed", a.seed, "--json", checks, "-q"], out + ".check.log")
        measured[b] = read_checks(checks, a.kind)
    return measured


def allocate(a, measured, counts):
    """Step 2: one budget per mesh; returns ({name: budget}, {name: pick}, original triangles).
    A mesh without a proxy at some budget (proxy-gen found none cheaper than the original) keeps
    the run's settings, and its proxy's triangles at no budget come off the share."""
    everywhere = set.intersection(*(set(m) for m in measured.values()))
    if not everywhere:
        die(1, f"no mesh of {a.scene} got a {a.kind} proxy at every budget",
            f"see the proxy-gen reports in {os.path.join(a.out_dir, 'options')}",
            "an open mesh has no inside proxy; a mesh with \"make_proxy\": false gets none")
    names = sorted(everywhere)
    fixed = {n: p for n, p in measured[0].items() if n not in everywhere}
    for n in sorted(set.union(*(set(m) for m in measured.values())) - everywhere):
        print(f"{PROG}: note: {n} has no proxy at some budgets: left at the run's settings",
              file=sys.stderr)
    original = sum(p["original_faces"] * counts[n] for n, p in
                   {**fixed, **{n: measured[0][n] for n in names}}.items())
    cap = a.share * original - sum(p["faces"] * counts[n] for n, p in fixed.items())
    items = [[(m[n]["faces"] * counts[n], objective_of(n, m[n], counts, a.objective))
              for m in measured.values()] for n in names]
    got = choose(items, cap) if cap >= 0 else None
    if got is None:
        least = sum(min(c for c, _ in opts) for opts in items)
        die(1, f"no budget per mesh keeps the proxies within --share {a.share}",
            f"the smallest measured take {least / original:.2%} of the original triangles",
            "add smaller --budgets or raise --share")
    budgets_list = list(measured)
    budgets = {n: budgets_list[k] for n, k in zip(names, got[0])}
    picks = {n: measured[budgets[n]][n] for n in names}
    picks.update(fixed)
    return budgets, picks, original


def measure_result(a, budget_scene, final, options_dir):
    """Step 3: the chosen proxies (from proxy-gen's cache) and both checks on --check-seed."""
    run([tool(a, "proxy-gen"), budget_scene, "--kind", a.kind, "--out-dir", final,
         "--json", final + ".gen.json", "-q", *a.extra], final + ".gen.log")
    held_out = {}
    for label, scene_json in (("final", os.path.join(final, "scene.json")),
                              ("baseline", os.path.join(options_dir, "b0", "scene.json"))):
        path = os.path.join(a.out_dir, f"{label}.check.json")
        run([tool(a, "proxy-check"), scene_json, "--distribution", "scene", "--rays",
             a.rays, "--seed", a.check_seed, "--json", path, "-q"], path[:-5] + ".log")
        held_out[label] = read_checks(path, a.kind)
    return held_out


def print_table(rows, kind):
    print(f"| proxies | triangles | share | {RATE_KEY[kind]} per instance | wasted hits per draw |")
    print("|---|---:|---:|---:|---:|")
    for r in rows:
        fmt = lambda x: "-" if x is None else f"{x:.4f}"  # noqa: E731
        print(f"| {r['label']} | {r['triangles']:,} | {100 * r['share']:.2f} % | "
              f"{fmt(r['rate_per_instance'])} | {fmt(r['wasted_hits_per_draw'])} |")


def main():
    a = parse_args(sys.argv[1:])
    try:
        scene = load_scene_absolute(a.scene)
        counts = instance_counts(scene)
    except (OSError, ValueError, KeyError) as e:
        die(2, a.scene, f"cannot read the scene or its instance list ({e})", "give a scene JSON")
    options_dir = os.path.join(a.out_dir, "options")
    os.makedirs(options_dir, exist_ok=True)
    measured = measure_options(a, options_dir)
    budgets, picks, original = allocate(a, measured, counts)
    budget_scene = os.path.join(a.out_dir, "budgets.json")
    write_budget_scene(scene, budgets, budget_scene)

    final = os.path.join(a.out_dir, "final")
    held_out = measure_result(a, budget_scene, final, options_dir)

    rows = [summary(f"budget {b or 'none'} (seed {a.seed})", m, counts, original)
            for b, m in measured.items()]
    rows.append(summary(f"chosen (seed {a.seed}, the segments it was chosen on)", picks, counts,
                        original))
    rows.append(summary(f"no budget (seed {a.check_seed})", held_out["baseline"], counts, original))
    rows.append(summary(f"chosen (seed {a.check_seed})", held_out["final"], counts, original))
    report = {"scene": os.path.abspath(a.scene), "kind": a.kind, "share": a.share,
              "objective": a.objective, "original_triangles": original, "rows": rows,
              "meshes": {n: {"instances": counts[n], "budget": budgets[n],
                             "faces": held_out["final"][n]["faces"],
                             "rate": held_out["final"][n]["rate"]} for n in sorted(budgets)},
              "budget_scene": os.path.abspath(budget_scene),
              "scene_with_proxies": os.path.abspath(os.path.join(final, "scene.json"))}
    tmp = os.path.join(a.out_dir, "allocation.json.tmp")
    with open(tmp, "w") as f:
        json.dump(report, f, indent=1)
    os.replace(tmp, os.path.join(a.out_dir, "allocation.json"))
    print_table(rows, a.kind)
    print(f"scene with proxies: {report['scene_with_proxies']}")

if __name__ == "__main__":
    main()
