"""The data-parallel route choice under --forwarding proxies (label mpi):
  - images: exact renders with --proxy-route measured (on a fabric of dear forwards and on one of
    free forwards) and with --proxy-route always all equal the single-process exact render bit
    for bit (R, G, B);
  - counts: `always` routes no segment by the instance boxes; `measured` on a fabric whose
    forwards cost milliseconds routes most through the proxies (the cheaper there), and on any
    fabric explores the boxes' route with a share of the segments; roulette with both costs
    fixed stays bit-reproducible under the default, `always`;
  - refusals: an unknown --proxy-route, or one without --forwarding proxies, exits 2 with one
    line and writes nothing.
usage: route_choice_test.py RENDER_EXE PROXY_GEN_EXE DATA_DIR SCENES_DIR WORK_DIR"""
import json
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(__file__))
from mpi_support import make_unique_scene, mpirun_cmd, run  # noqa: E402
from image_diff import differing_pairs  # noqa: E402

render, proxy_gen, data_dir, scenes_dir, work = sys.argv[1:6]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
scene = make_unique_scene(work, data_dir, scenes_dir, proxy_gen, side=3,
                          proxy_cache=os.path.join(os.path.dirname(work), "proxies"))
COMMON = ["--spp", "8", "--seed", "5", "--threads", "1", "--quiet"]


def fail(text):
    sys.exit(f"FAIL: {text}")


def dp(name, *flags, expect=0, forwarding="proxies"):
    out = os.path.join(work, name + ".exr")
    p = run(mpirun_cmd(2) + [render, scene, "--data-parallel", "--forwarding", forwarding, "-o",
                             out, "--json", out + ".json", "--passes-per-round", "2", *COMMON,
                             *flags], expect=expect)
    if expect != 0:
        return out, p
    with open(out + ".json") as f:
        return out, json.load(f)


single = os.path.join(work, "single.exr")
run([render, scene, "--estimator", "exact", "-o", single, *COMMON])

always, s_always = dp("always", "--proxy-route", "always")
dear, s_dear = dp("dear", "--proxy-route", "measured", "--network", "ib-hdr",
                  "--network-alpha-us", "20000")
free, s_free = dp("free", "--proxy-route", "measured", "--network", "ib-hdr",
                  "--network-alpha-us", "0", "--network-beta-gbps", "1000000")

for what, s, route in (("always", s_always, "always"), ("dear", s_dear, "measured"),
                       ("free", s_free, "measured")):
    if s.get("proxy_route") != route:
        fail(f"{what}: proxy_route is {s.get('proxy_route')!r}, expected {route!r}")
    if s["routed_by_proxies"] + s["routed_by_instance_boxes"] == 0:
        fail(f"{what}: no segment was routed; the scene does not exercise the choice")
if s_always["routed_by_instance_boxes"] != 0:
    fail(f"always: {s_always['routed_by_instance_boxes']} segments routed by the boxes")
# Dear forwards: proxies route half of the first round (of 4) and all but a sixteenth of the
# later ones: about 0.83 of the segments; at least 0.7 unless the choice is wrong.
share = s_dear["routed_by_proxies"] / (s_dear["routed_by_proxies"] +
                                       s_dear["routed_by_instance_boxes"])
if share < 0.7:
    fail(f"dear forwards: only {share:.3f} of the segments went through the proxies")
for what, s in (("dear", s_dear), ("free", s_free)):
    if s["routed_by_instance_boxes"] == 0:
        fail(f"{what}: the boxes' route was never explored")
# Counts that do not depend on the route: every segment is decided the same way in the end.
for key in ("shadow_segments", "blocked_locally"):
    if not s_always[key] == s_dear[key] == s_free[key]:
        fail(f"'{key}' differs between routes: {s_always[key]}, {s_dear[key]}, {s_free[key]}")
for _, out, text in differing_pairs(((single, o) for o in (always, dear, free)), channels="R,G,B"):
    fail(f"{out} differs from the single-process exact render\n{text}")

_, s_default = dp("default", "--estimator", "roulette", "--forward-cost-us", "200",
                  "--local-cost-us", "1")
if s_default["proxy_route"] != "always" or s_default["routed_by_instance_boxes"] != 0:
    fail(f"the default route sent {s_default['routed_by_instance_boxes']} segments by the boxes "
         f"under proxy_route {s_default['proxy_route']!r}")

for name, forwarding, route, needle in (
        ("unknown", "proxies", "sometimes", "--proxy-route"),
        ("boxes", "instance-boxes", "always", "--proxy-route does not act")):
    out, p = dp("bad_" + name, "--proxy-route", route, expect=2, forwarding=forwarding)
    lines = [line for line in p.stderr.splitlines() if line.strip()]
    if len(lines) != 1 or needle not in lines[0]:
        fail(f"{name}: expected one line naming {needle!r}, got:\n{p.stderr}")
    if os.path.exists(out) or os.path.exists(out + ".json"):
        fail(f"{name}: a refused render left {out}")
print(f"ok: proxies' share {share:.3f} on dear forwards, "
      f"{s_free['routed_by_proxies']}/{s_free['routed_by_instance_boxes']} on free ones; "
      "every exact image equals the single-process render; refusals exit 2")
