#!/usr/bin/env python3
"""Writes the bundled sculpture park: scenes/park.json, scenes/park-low-sun.json, their shared
instance list scenes/park.instances.txt and the proxies in scenes/park/ (Python 3, stdlib only).

Usage, from the repository root after a build:

    python3 scenes/make_park.py [--proxy-gen build/bin/proxy-gen] [--mesh-info build/bin/mesh-info]
                                [--work out/park-gen] [--no-cache] [--no-proxies]

1. reads each prototype's bounding box with `mesh-info FILE --json` (every prototype is y up and
   stands upright as stored);
2. lays out a 20 x 20 jittered grid (a hash-based RNG with a fixed seed, so every output is
   reproducible byte for byte): per cell one prototype, a yaw about the vertical axis through the
   prototype's box centre, a scale that makes every sculpture about 1.35 units tall (at most
   2.2 units long), times 0.92-1.08, and a height that puts its lowest point 0.001 above the
   ground (y = 0). A sculpture's footprint is the circle around its scaled box, and its jitter
   keeps that circle within (3.0 - 0.1) / 2 of its cell centre, so any two circles are at least
   0.1 apart and no two sculptures touch (checked); both lights must miss every sculpture's
   box (checked; the renderer would treat the proxies as general otherwise);
3. writes the two scenes without proxies and runs proxy-gen's scene mode on park.json twice,
   `--kind outside` and `--kind inside`, with the face budget `--ratio 0.02` (2 % of each
   original; proxy-gen's cache makes a second run fast), into WORK/outside and WORK/inside;
4. copies the proxies (and their .sha256 sidecars) into scenes/park/ and writes both scenes
   again with two proxies per sculpture, outside first, with the class and sha256 proxy-gen
   recorded (checked against the copied file).

--no-proxies writes the scenes with "proxies": [] and stops. Another proxy-gen build may write
other proxy bytes; the scenes then record their new sha256. Then verify:

    build/bin/proxy-check scenes/park.json --rays 100000
    build/bin/render scenes/park.json --estimator culling --spp 16 -o out/park.png
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from proxyvis_tools.meshes import sha256_file  # noqa: E402
from splitmix import rand  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

GRID = 20            # cells per side
SPACING = 3.0        # cell size (scene units): neighbours' shadows overlap at a low sun
JITTER = 0.3         # largest offset of a sculpture from its cell centre, as a fraction of SPACING
HEIGHT = 1.35        # target height of a sculpture
MAX_LENGTH = 2.2     # ... unless its longest horizontal side would exceed this
SCALE_JITTER = 0.08  # scale times 1 +- this
LIFT = 0.001         # lowest point above the ground
GAP = 0.1            # smallest distance between two footprint circles
SEED = 2024
RATIO = 0.02         # proxy face budget: this fraction of each original's faces

# name, file (relative to the repository root), albedo. All closed and y up.
PROTOTYPES = [
    ("bunny", "data/bunny.off", [0.78, 0.75, 0.68]),           # marble
    ("spot", "data/spot_triangulated.obj", [0.82, 0.56, 0.34]),  # terracotta
    ("dragon", "data/dragon.drc", [0.72, 0.5, 0.26]),          # bronze
    ("cow", "data/hard/cow.off", [0.55, 0.52, 0.48]),          # granite
    ("3holes", "data/hard/3holes.off", [0.62, 0.66, 0.72]),    # steel
    ("fandisk", "data/hard/fandisk.off", [0.74, 0.74, 0.7]),   # concrete
]

GROUND = {"name": "ground", "file": "meshes/ground.obj", "albedo": [0.36, 0.46, 0.26],
          "transform": {"scale": [400, 1, 400]}, "make_proxy": False}

# Camera: from the south (+z), 32.5 units up, looking 34 degrees down with a 30 degree vertical
# field of view: the top row looks 19 degrees down and meets the lawn at z = -36, beyond the far
# row of sculptures (z = -28.5); the bottom row (49 degrees down) meets it at z = +30, just beyond
# the near row, whose outer sculptures are out of the frame at the sides. No pixel sees the sky;
# 23 % of them are sculptures (measured: a render with a black lawn and sky light only).
CAMERA = {"eye": [0, 32.5, 58.3], "look_at": [0, 0, 10], "up": [0, 1, 0], "fov_deg": 30,
          "resolution": [160, 120]}

SUN_DISTANCE = 150.0
SUN_SIZE = 2.0
SUN_AZIMUTH = 150.0  # degrees from +x towards +z: the sun is in the west-south-west (left of the
                     # camera, a little behind it), shadows fall to the right, away from it
SKY = {"type": "quad", "corner": [-100, 40, -100], "edge_u": [200, 0, 0], "edge_v": [0, 0, 200],
       "radiance": [0.3, 0.42, 0.65]}
VARIANTS = [
    # file, elevation (degrees), sun radiance, title
    ("park.json", 30.0, [30000, 28500, 26000], "park"),
    ("park-low-sun.json", 10.0, [60000, 48000, 33000], "park-low-sun"),
]


def proxy_entry(kind, name, e, file):
    """The scene's entry for the proxy proxy-gen reported as `e`, stored at `file`."""
    if e.get("class") != kind:
        print(f"warning: {name}: the {kind} proxy is class {e.get('class')}", file=sys.stderr)
    entry = {"kind": kind}
    if "method" in e:
        entry["method"] = e["method"]
    entry.update({"file": file, "class": e.get("class"), "sha256": e["sha256"]})
    return entry


def mesh_info_json(mesh_info, path):
    """mesh-info's JSON report of a mesh file."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "info.json")
        subprocess.run([mesh_info, path, "--quiet", "--json", out], check=True,
                       stdout=subprocess.DEVNULL)
        with open(out) as f:
            return json.load(f)[0]


def mesh_bounds(info):
    """(min, max) of mesh-info's report, rounded to 7 significant digits."""
    r = lambda v: [float(f"{x:.7g}") for x in v]
    return r(info["bounds"]["min"]), r(info["bounds"]["max"])


def fmt(v):
    return f"{v:.6g}"


def layout(protos, grid=GRID, seed=SEED, spacing=SPACING, choose=None, count=None):
    """Instances of a grid x grid park (its first `count` cells, row by row; default all).
    protos: list of (name, bounds). choose(i, j) -> index into protos, default random. Returns
    dicts with name, proto, matrix (row-major 3x4), centre, radius, height, cell."""
    placed = []
    half = (grid - 1) / 2.0
    for i in range(grid):
        for j in range(grid):
            if count is not None and len(placed) >= count:
                return placed
            k = choose(i, j) if choose else min(int(rand(seed, i, j, 0) * len(protos)),
                                                len(protos) - 1)
            name, (lo, hi) = protos[k]
            ext = [hi[a] - lo[a] for a in range(3)]
            s = min(HEIGHT / ext[1], MAX_LENGTH / max(ext[0], ext[2]))
            s *= 1 + SCALE_JITTER * (2 * rand(seed, i, j, 1) - 1)
            yaw = 2 * math.pi * rand(seed, i, j, 2)
            radius = 0.5 * s * math.hypot(ext[0], ext[2])
            cx, cz = (i - half) * spacing, (j - half) * spacing
            jx, jz = 2 * rand(seed, i, j, 3) - 1, 2 * rand(seed, i, j, 4) - 1
            # Each sculpture stays within (spacing - GAP) / 2 of its cell centre, so neighbours
            # never touch; the check below only guards that argument.
            amount = max(0.0, min(JITTER * spacing, (spacing - GAP) / 2 - radius) / math.sqrt(2))
            x, z = cx + amount * jx, cz + amount * jz
            for p in placed:
                if math.hypot(x - p["x"], z - p["z"]) < radius + p["radius"] + GAP:
                    sys.exit(f"cell {i},{j} overlaps cell {p['cell']}; raise spacing")
            c, n = math.cos(yaw), math.sin(yaw)
            # world = T(x, lift, z) * Ry(yaw) * S(s) * T(-box centre xz, -min y)
            bx, bz = 0.5 * (lo[0] + hi[0]), 0.5 * (lo[2] + hi[2])
            ty = LIFT - s * lo[1]
            # Ry: x' = c x + n z, z' = -n x + c z
            tx = x - s * (c * bx + n * bz)
            tz = z - s * (-n * bx + c * bz)
            m = [c * s, 0, n * s, tx,
                 0, s, 0, ty,
                 -n * s, 0, c * s, tz]
            placed.append({"name": name, "proto": k, "matrix": m, "x": x, "z": z,
                           "radius": radius, "height": s * ext[1], "cell": (i, j)})
    return placed


def sun_light(elevation_deg, radiance):
    """A SUN_SIZE square facing the park centre, SUN_DISTANCE away at the given elevation."""
    el, az = math.radians(elevation_deg), math.radians(SUN_AZIMUTH)
    d = [math.cos(el) * math.cos(az), math.sin(el), math.cos(el) * math.sin(az)]
    centre = [SUN_DISTANCE * x for x in d]
    u = [-math.sin(az), 0.0, math.cos(az)]                                   # horizontal
    v = [d[1] * u[2] - d[2] * u[1], d[2] * u[0] - d[0] * u[2], d[0] * u[1] - d[1] * u[0]]
    h = SUN_SIZE / 2
    corner = [centre[a] - h * u[a] - h * v[a] for a in range(3)]
    r4 = lambda w: [round(x, 4) for x in w]
    return {"type": "quad", "corner": r4(corner), "edge_u": r4([SUN_SIZE * x for x in u]),
            "edge_v": r4([SUN_SIZE * x for x in v]), "radiance": radiance}


def luminance(rgb):
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]


def sky_irradiance(sky, point=(0.0, 0.0, 0.0), n=200):
    """Luminance irradiance of the horizontal ground at `point` from the (horizontal) sky quad."""
    e = 0.0
    du, dv = sky["edge_u"][0] / n, sky["edge_v"][2] / n
    h = sky["corner"][1] - point[1]
    for a in range(n):
        for b in range(n):
            x = sky["corner"][0] + (a + 0.5) * du - point[0]
            z = sky["corner"][2] + (b + 0.5) * dv - point[2]
            r2 = x * x + z * z + h * h
            e += h * h / (r2 * r2) * du * dv  # cos at ground * cos at light / r^2
    return luminance(sky["radiance"]) * e


def light_facts(elevation, radiance):
    """(sun irradiance on horizontal ground, sky irradiance, share of light samples to the sun)"""
    e_sun = luminance(radiance) * SUN_SIZE ** 2 / SUN_DISTANCE ** 2 * math.sin(
        math.radians(elevation))
    e_sky = sky_irradiance(SKY)
    p_sun = luminance(radiance) * SUN_SIZE ** 2
    p_sky = luminance(SKY["radiance"]) * SKY["edge_u"][0] * SKY["edge_v"][2]
    return e_sun, e_sky, p_sun / (p_sun + p_sky)


def reach(shadow):
    if shadow < SPACING:
        return f"most of the way to the next sculpture ({SPACING:g} units away)"
    n = int(shadow // SPACING)
    return f"across the next {n} to {n + 1} rows of sculptures ({SPACING:g} units apart)"


def check_lights(instances, lights, protos, margin=0.1):
    """Every light's box must miss every sculpture's world box grown by `margin` times its
    diagonal (room for the outside proxy, which proxy-gen keeps within a few % of it)."""
    for p in instances:
        lo, hi = dict(protos)[p["name"]]
        m = p["matrix"]
        pts = [[m[4 * r] * x + m[4 * r + 1] * y + m[4 * r + 2] * z + m[4 * r + 3] for r in range(3)]
               for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])]
        blo = [min(q[a] for q in pts) for a in range(3)]
        bhi = [max(q[a] for q in pts) for a in range(3)]
        pad = margin * math.dist(blo, bhi)
        for k, light in enumerate(lights):
            c, u, v = light["corner"], light["edge_u"], light["edge_v"]
            corners = [[c[a] + s * u[a] + t * v[a] for a in range(3)] for s in (0, 1) for t in (0, 1)]
            llo = [min(q[a] for q in corners) for a in range(3)]
            lhi = [max(q[a] for q in corners) for a in range(3)]
            if all(llo[a] <= bhi[a] + pad and lhi[a] >= blo[a] - pad for a in range(3)):
                sys.exit(f"light {k} meets the box of instance {p['name']} {p['cell']}")


def description(elevation, radiance, n_instances, counts):
    e_sun, e_sky, share = light_facts(elevation, radiance)
    shadow = HEIGHT / math.tan(math.radians(elevation))
    kinds = ", ".join(f"{counts[name]} {name}" for name, _, _ in PROTOTYPES)
    return (
        f"A sculpture park for data-parallel rendering: {n_instances} sculptures on a {GRID} x "
        f"{GRID} jittered grid ({SPACING:g} units apart, {SPACING * GRID:g} x {SPACING * GRID:g}) "
        f"on a 400 x 400 lawn, y up: {kinds} (six closed bundled meshes, each listed once with "
        f"place: false and placed by park.instances.txt, made by make_park.py; "
        f"{counts['triangles'] / 1e6:.1f} M triangles expanded). Each sculpture "
        f"has a random yaw and a scale that makes it about {HEIGHT:g} units tall (at most "
        f"{MAX_LENGTH:g} long), its lowest point {LIFT:g} above the lawn; their footprint "
        f"circles stay {GAP:g} apart. Each mesh has an outside and an inside proxy from "
        f"proxy-gen's scene mode at 2 % of its faces (outside listed first). Camera: from the "
        f"south, 32.5 units up, 34 degrees down with a 30 degree vertical field of view: the park "
        f"fills the frame (a few rows of lawn beyond the far and the near row of sculptures; the "
        f"outer sculptures of the near rows are outside the frame at the sides), so every pixel "
        f"is lawn or sculpture, 23 % of them sculptures. Sun: a {SUN_SIZE:g} x {SUN_SIZE:g} quad {SUN_DISTANCE:g} units away at "
        f"{elevation:g} degrees elevation from the west-south-west (left of the camera, a little "
        f"behind it): a {HEIGHT:g}-unit sculpture casts a {shadow:.1f}-unit shadow to the right "
        f"and away from the camera, "
        f"{reach(shadow)}. "
        f"Sky: a dim 200 x 200 quad 40 units up, the fill light in the shadows. On open lawn the "
        f"sun gives {e_sun / e_sky:.1f}x the sky's irradiance, so sunlit lawn is "
        f"{(e_sun + e_sky) / e_sky:.1f}x as bright as lawn in shadow; lights are chosen by power, "
        f"so the sun gets {100 * share:.0f} % of the light samples. Both lights lie outside "
        f"every sculpture's and proxy's bounding box. 160 x 120; --width 1280 --height 960 "
        f"keeps the framing.")


def dumps_scene(scene):
    """The scene JSON in the bundled scenes' compact style: one line per light, mesh and proxy."""
    one = lambda v: json.dumps(v, separators=(", ", ": "))
    lines = ["{"]
    top = []
    for key in ("name", "description", "camera"):
        top.append(f"  {json.dumps(key)}: {one(scene[key])}")
    top.append('  "lights": [\n' + ",\n".join("    " + one(l) for l in scene["lights"]) +
               "\n  ]")
    meshes = []
    for m in scene["meshes"]:
        head = {k: v for k, v in m.items() if k != "proxies"}
        if "proxies" not in m:
            meshes.append("    " + one(head))
            continue
        text = "    " + one(head)[:-1] + ', "proxies": ['
        if m["proxies"]:
            text += "\n" + ",\n".join("      " + one(p) for p in m["proxies"]) + "]}"
        else:
            text += "]}"
        meshes.append(text)
    top.append('  "meshes": [\n' + ",\n".join(meshes) + "\n  ]")
    top.append(f'  "instances": {one(scene["instances"])}')
    return "{\n" + ",\n".join(top) + "\n}\n"


def scene_dict(title, elevation, radiance, n_instances, counts, proxies, instances_file):
    meshes = [dict(GROUND)]
    for name, path, albedo in PROTOTYPES:
        meshes.append({"name": name, "file": "../" + path, "albedo": albedo, "place": False,
                       "proxies": proxies.get(name, [])})
    return {"name": title, "description": description(elevation, radiance, n_instances, counts),
            "camera": CAMERA, "lights": [sun_light(elevation, radiance), SKY], "meshes": meshes,
            "instances": {"file": instances_file}}


def write_text(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def instance_lines(instances, header):
    lines = [f"# {h}" for h in header]
    for p in instances:
        lines.append(p["name"] + " " + " ".join(fmt(v) for v in p["matrix"]))
    return "\n".join(lines) + "\n"


def run_proxy_gen(proxy_gen, scene, kind, out_dir, ratio=RATIO, extra=()):
    """proxy-gen's scene mode; returns {mesh name: proxy entry with file relative to out_dir},
    the report (JSON) and the scene it wrote."""
    os.makedirs(os.path.dirname(out_dir) or ".", exist_ok=True)
    report = out_dir + ".json"
    cmd = [proxy_gen, scene, "--kind", kind, "--ratio", str(ratio), "--out-dir", out_dir,
           "--quiet", "--json", report, *extra]
    print("+", " ".join(cmd), flush=True)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out_dir, "scene.json")) as f:
        written = json.load(f)
    with open(report) as f:
        rep = json.load(f)
    entries = {}
    for m in written["meshes"]:
        for p in m.get("proxies", []):
            if p.get("kind") == kind:
                entries[m["name"]] = p
    return entries, rep


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--proxy-gen", default=os.path.join(ROOT, "build/bin/proxy-gen"))
    ap.add_argument("--mesh-info", default=os.path.join(ROOT, "build/bin/mesh-info"))
    ap.add_argument("--work", default=os.path.join(ROOT, "out/park-gen"),
                    help="proxy-gen's output folders (default out/park-gen)")
    ap.add_argument("--no-cache", action="store_true",
                    help="pass --no-cache to proxy-gen (generate every proxy again)")
    ap.add_argument("--no-proxies", action="store_true",
                    help="only write the instance list and the scenes without proxies")
    args = ap.parse_args()
    start = time.time()

    infos = {name: mesh_info_json(args.mesh_info, os.path.join(ROOT, path))
             for name, path, _ in PROTOTYPES}
    protos = [(name, mesh_bounds(infos[name])) for name, _, _ in PROTOTYPES]
    instances = layout(protos)
    counts = {name: sum(p["name"] == name for p in instances) for name, _, _ in PROTOTYPES}
    counts["triangles"] = sum(infos[p["name"]]["faces"] for p in instances)
    write_text(os.path.join(HERE, "park.instances.txt"), instance_lines(instances, [
        "park.json / park-low-sun.json instances: NAME m00 m01 m02 m03 m10 ... m23 (row-major "
        "3x4, y up)",
        f"generated by make_park.py: {GRID} x {GRID} jittered grid, seed {SEED}, yaw, scale to "
        f"about {HEIGHT:g} units tall, lowest point {LIFT:g} above y = 0",
    ]))
    heights = [p["height"] for p in instances]
    print(f"{len(instances)} instances ({', '.join(f'{counts[n]} {n}' for n in infos)}; "
          f"{counts['triangles']:,} triangles expanded), "
          f"heights {min(heights):.3f}..{max(heights):.3f}, footprint radius "
          f"{min(p['radius'] for p in instances):.3f}..{max(p['radius'] for p in instances):.3f}")

    for _, elevation, radiance, _ in VARIANTS:
        check_lights(instances, [sun_light(elevation, radiance), SKY], protos)

    def write_scenes(proxies):
        for file, elevation, radiance, title in VARIANTS:
            scene = scene_dict(title, elevation, radiance, len(instances), counts, proxies,
                               "park.instances.txt")
            write_text(os.path.join(HERE, file), dumps_scene(scene))

    write_scenes({})
    if args.no_proxies:
        return 0

    proxy_dir = os.path.join(HERE, "park")
    os.makedirs(proxy_dir, exist_ok=True)
    proxies = {name: [] for name, _, _ in PROTOTYPES}
    summary = {}
    for kind in ("outside", "inside"):
        out_dir = os.path.join(args.work, kind)
        entries, rep = run_proxy_gen(args.proxy_gen, os.path.join(HERE, "park.json"), kind,
                                     out_dir, extra=["--no-cache"] if args.no_cache else [])
        for m in rep.get("meshes", []):
            summary[(m.get("name"), kind)] = m
        for name, _, _ in PROTOTYPES:
            e = entries.get(name)
            if e is None:
                sys.exit(f"proxy-gen wrote no {kind} proxy for {name}")
            src = os.path.join(out_dir, e["file"])
            dst = os.path.join(proxy_dir, os.path.basename(e["file"]))
            shutil.copyfile(src, dst)
            if os.path.exists(src + ".sha256"):
                shutil.copyfile(src + ".sha256", dst + ".sha256")
            if e.get("sha256") != sha256_file(dst):
                sys.exit(f"{dst}: sha256 differs from the one proxy-gen recorded")
            proxies[name].append(proxy_entry(kind, name, e, "park/" + os.path.basename(dst)))
    write_scenes(proxies)
    print("wrote scenes/park.json, scenes/park-low-sun.json, scenes/park.instances.txt, "
          f"scenes/park/ ({2 * len(PROTOTYPES)} proxies) in {time.time() - start:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
