#!/usr/bin/env python3
"""The "unique geometry" sculpture park: every sculpture its own mesh (Python 3, stdlib only).

Usage, from the repository root after a build:

    python3 scenes/make_unique_park.py [--count 400] [--prototypes bunny,spot,dragon]
        [--out out/unique-park] [--proxy-gen build/bin/proxy-gen] [--mesh-info build/bin/mesh-info]
        [--ratio 0.02] [--no-proxies]

    build/bin/render out/unique-park/unique-park.json --spp 16 -o out/unique-park.png

The layout is park.json's (make_park.py): the first --count cells, row by row, of a G x G
jittered grid with G = ceil(sqrt(count)) (400: the 20 x 20 park; 16: a 4 x 4 corner of it,
centred), the same lights, lawn and camera. Each cell's prototype (one of --prototypes, chosen by
the cell's hash as in the park) is deformed by a smooth injective map of its own, in the
prototype's frame (y up, base centre at the origin, h = its height, t = y / h in [0, 1]):

    non-uniform scale   x, y, z times 0.8-1.25, 0.85-1.2, 0.8-1.25
    twist               a rotation about the vertical axis by up to +-35 degrees times t
    bend                a horizontal shift by up to 0.15 h times t^2, in a random direction

Each step is injective (a linear map; a rigid rotation of each horizontal slice; a shift that
depends on y only), so a closed mesh stays closed with the same connectivity, and with triangles
this small against the deformation's curvature no new self-intersection appears (checked with
mesh-info --self-intersections on 16-instance runs: bunny, spot, 3holes and fandisk copies have
none, dragon copies the original's 25 pairs; only the cow, whose original already has 149 pairs
of touching triangles along its non-manifold seams, gets 144-150). make_park.py's layout then scales the
deformed mesh to about 1.35 units tall, yaws it and stands it on the lawn.

Outputs, under --out DIR:
  DIR/meshes/<name>.drc   each deformed mesh: written as a binary PLY, then converted with
                          `mesh-info IN.ply --save OUT.drc --draco-bits 0` (lossless: quantized
                          positions could make a thin part self-intersect); if that conversion
                          fails the PLY is kept and used instead (printed). A manifest records
                          each mesh's parameters and SHA-256 so that an unchanged mesh is not
                          written again.
  DIR/unique-park.instances.txt
                          one line per mesh: every mesh is placed exactly once through the
                          instance list ("place": false), not with "place": true and its own
                          transform, because placed meshes are always flattened into one BVH,
                          while instances leave the choice to the renderer's --build (auto keeps
                          one BVH per mesh above 4 M triangles: these scenes reach 10 M) and the
                          data-parallel renderer treats both alike.
  DIR/unique-park.json    the scene; after proxy-gen's scene mode has run for --kind outside and
                          --kind inside (face budget --ratio, default 2 % of each mesh; proxies in
                          DIR/proxies/outside and DIR/proxies/inside; proxy-gen's cache makes a
                          second run with the same inputs fast), written again with two proxies
                          per mesh, outside first, with the class and sha256 proxy-gen recorded.

Prints the total original triangles and the seconds of each stage.
"""
import argparse
import array
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # no scenes/__pycache__
import make_park  # noqa: E402  (the layout, lights, lawn and camera of park.json)
from proxyvis_tools.meshes import read_ascii_ply, read_obj, read_off, sha256_file  # noqa: E402

SEED = make_park.SEED
PROTO = {name: (path, albedo) for name, path, albedo in make_park.PROTOTYPES}


def load_prototype(name, mesh_info, tmp):
    path = os.path.join(ROOT, PROTO[name][0])
    if path.endswith(".off"):
        return read_off(path)
    if path.endswith(".obj"):
        return read_obj(path)
    ply = os.path.join(tmp, name + ".ply")  # Draco: converted by mesh-info first
    subprocess.run([mesh_info, path, "--quiet", "--save", ply, "--ascii"], check=True,
                   stdout=subprocess.DEVNULL)
    return read_ascii_ply(ply)


def bounds(verts):
    lo = [min(verts[a::3]) for a in range(3)]
    hi = [max(verts[a::3]) for a in range(3)]
    return lo, hi


def deform_params(i, j):
    r = lambda k: make_park.rand(SEED, i, j, 100 + k)
    return {
        "scale": [0.8 + 0.45 * r(0), 0.85 + 0.35 * r(1), 0.8 + 0.45 * r(2)],
        "twist_deg": 35.0 * (2 * r(3) - 1),
        "bend": 0.15 * (2 * r(4) - 1),
        "bend_dir_deg": 360.0 * r(5),
    }


def deform(verts, box, p):
    """The deformed copy of verts (flat list x0 y0 z0 x1 ...), in the prototype's units."""
    lo, hi = box
    cx, y0, cz = 0.5 * (lo[0] + hi[0]), lo[1], 0.5 * (lo[2] + hi[2])
    h = hi[1] - lo[1]
    sx, sy, sz = p["scale"]
    tw = math.radians(p["twist_deg"])
    bend = p["bend"] * h * sy
    bd = math.radians(p["bend_dir_deg"])
    bx, bz = bend * math.cos(bd), bend * math.sin(bd)
    out = array.array("f", bytes(4 * len(verts)))
    cos, sin = math.cos, math.sin
    for k in range(0, len(verts), 3):
        x = (verts[k] - cx) * sx
        t = (verts[k + 1] - y0) / h
        z = (verts[k + 2] - cz) * sz
        a = tw * t
        c, s = cos(a), sin(a)
        t2 = t * t
        out[k] = c * x + s * z + bx * t2
        out[k + 1] = t * h * sy
        out[k + 2] = -s * x + c * z + bz * t2
    return out


def face_block(faces):
    """The binary PLY face element of a triangle list (the same for every copy of a prototype)."""
    out = bytearray()
    idx = array.array("i", faces)
    if sys.byteorder != "little":
        idx.byteswap()
    raw = idx.tobytes()
    for k in range(0, len(raw), 12):
        out += b"\x03" + raw[k:k + 12]
    return bytes(out)


def write_ply(path, verts, faces_bytes, nfaces):
    head = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(verts) // 3}\n"
            "property float x\nproperty float y\nproperty float z\n"
            f"element face {nfaces}\nproperty list uchar int vertex_indices\nend_header\n")
    v = array.array("f", verts)
    if sys.byteorder != "little":
        v.byteswap()
    with open(path, "wb") as f:
        f.write(head.encode())
        f.write(v.tobytes())
        f.write(faces_bytes)


def write_meshes(cells, kinds, protos, mesh_dir, mesh_info):
    """Each cell's deformed mesh in mesh_dir (Draco, PLY when the conversion fails), reusing the
    files of an earlier run whose key and SHA-256 match (meshes/manifest.json). Returns the
    instances' (name, bounds), their files, the triangle count, the reused count and the names
    kept as PLY."""
    manifest_path = os.path.join(mesh_dir, "manifest.json")
    manifest = {}
    if os.path.exists(manifest_path):
        with open(manifest_path) as f:
            manifest = json.load(f)
    inst_protos, files, triangles, reused, as_ply = [], [], 0, 0, []
    for c, ((i, j), kind) in enumerate(zip(cells, kinds)):
        name = f"{kind}-{c:04d}"
        verts, faces, box, fblock, src_sha = protos[kind]
        params = deform_params(i, j)
        key = {"prototype": kind, "source_sha256": src_sha, "params": params}
        old = manifest.get(name)
        path = None
        if old and old.get("key") == key and os.path.exists(os.path.join(mesh_dir, old["file"])) \
                and sha256_file(os.path.join(mesh_dir, old["file"])) == old["sha256"]:
            path = os.path.join(mesh_dir, old["file"])
            dbox = (old["bounds"][0], old["bounds"][1])
            reused += 1
        else:
            dverts = deform(verts, box, params)
            dbox = bounds(dverts)
            ply = os.path.join(mesh_dir, name + ".tmp.ply")
            write_ply(ply, dverts, fblock, len(faces) // 3)
            drc = os.path.join(mesh_dir, name + ".drc")
            r = subprocess.run([mesh_info, ply, "--quiet", "--save", drc, "--draco-bits",
                                "0"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                               text=True)
            if r.returncode == 0:
                os.remove(ply)
                path = drc
            else:
                path = os.path.join(mesh_dir, name + ".ply")
                os.replace(ply, path)
                as_ply.append(name)
                print(f"note: {name}: Draco conversion failed ({r.stderr.strip()}); kept the "
                      "PLY", file=sys.stderr)
            manifest[name] = {"key": key, "file": os.path.basename(path),
                              "sha256": sha256_file(path), "bounds": [list(dbox[0]), list(dbox[1])],
                              "triangles": len(faces) // 3}
        inst_protos.append((name, dbox))
        files.append(path)
        triangles += len(faces) // 3
    with open(manifest_path + ".tmp", "w") as f:
        json.dump(manifest, f, indent=1, sort_keys=True)
    os.replace(manifest_path + ".tmp", manifest_path)
    return inst_protos, files, triangles, reused, as_ply


def make_proxies(proxy_gen, scene_path, out, inst_protos, ratio, stages):
    """Outside and inside proxies of every mesh by proxy-gen: each mesh's scene entries."""
    proxies = {name: [] for name, _ in inst_protos}
    for kind in ("outside", "inside"):
        t0 = time.time()
        out_dir = os.path.join(out, "proxies", kind)
        entries, rep = make_park.run_proxy_gen(proxy_gen, scene_path, kind, out_dir,
                                               ratio=ratio)
        cache = rep.get("cache", {})
        stages[f"proxy-gen {kind} ({cache.get('cached', '?')} cached, "
               f"{cache.get('generated', '?')} generated)"] = time.time() - t0
        faces = 0
        for name, _ in inst_protos:
            e = entries.get(name)
            if e is None:
                sys.exit(f"proxy-gen wrote no {kind} proxy for {name}")
            entry = make_park.proxy_entry(
                kind, name, e, os.path.relpath(os.path.join(out_dir, e["file"]), out))
            proxies[name].append(entry)
        for m in rep.get("meshes", []):
            faces += m.get("faces", 0) if "skipped" not in m else 0
        print(f"{kind} proxies: {faces:,} triangles in all")
    return proxies


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--count", type=int, default=400, help="instances (default 400)")
    ap.add_argument("--prototypes", default="bunny,spot,dragon",
                    help="comma list of " + ",".join(PROTO) + " (default bunny,spot,dragon)")
    ap.add_argument("--out", default="out/unique-park", help="output folder")
    ap.add_argument("--proxy-gen", default=os.path.join(ROOT, "build/bin/proxy-gen"))
    ap.add_argument("--mesh-info", default=os.path.join(ROOT, "build/bin/mesh-info"))
    ap.add_argument("--ratio", type=float, default=make_park.RATIO,
                    help="proxy face budget as a fraction of each mesh (default 0.02)")
    ap.add_argument("--no-proxies", action="store_true", help="stop before proxy-gen")
    args = ap.parse_args()
    start = time.time()
    stages = {}

    names = [n.strip() for n in args.prototypes.split(",") if n.strip()]
    for n in names:
        if n not in PROTO:
            ap.error(f"--prototypes: unknown {n!r} (known: {', '.join(PROTO)})")
    if args.count < 1 or args.count > 40000:
        ap.error("--count must be in 1..40000")
    grid = math.ceil(math.sqrt(args.count))
    out = os.path.abspath(args.out)
    mesh_dir = os.path.join(out, "meshes")
    os.makedirs(mesh_dir, exist_ok=True)

    # The cells and their prototypes, as make_park.layout will visit them.
    cells = [divmod(c, grid) for c in range(args.count)]
    kinds = [names[min(int(make_park.rand(SEED, i, j, 0) * len(names)), len(names) - 1)]
             for i, j in cells]

    t0 = time.time()
    protos = {}
    with tempfile.TemporaryDirectory() as tmp:
        for n in sorted(set(kinds)):
            verts, faces = load_prototype(n, args.mesh_info, tmp)
            protos[n] = (verts, faces, bounds(verts), face_block(faces),
                         sha256_file(os.path.join(ROOT, PROTO[n][0])))
    stages["load prototypes"] = time.time() - t0

    t0 = time.time()
    inst_protos, files, triangles, reused, as_ply = write_meshes(cells, kinds, protos, mesh_dir,
                                                                 args.mesh_info)
    stages["deform + write meshes"] = time.time() - t0

    placed = make_park.layout(inst_protos, grid=grid, choose=lambda i, j: i * grid + j,
                              count=args.count)
    assert len(placed) == args.count
    lines = make_park.instance_lines(placed, [
        "unique-park.json instances: one line per mesh (each deformed mesh placed once)",
        f"generated by make_unique_park.py --count {args.count} --prototypes "
        f"{','.join(names)}: make_park.py's layout on a {grid} x {grid} grid",
    ])
    make_park.write_text(os.path.join(out, "unique-park.instances.txt"), lines)
    elevation, radiance = make_park.VARIANTS[0][1], make_park.VARIANTS[0][2]
    lights = [make_park.sun_light(elevation, radiance), make_park.SKY]
    make_park.check_lights(placed, lights, inst_protos)
    ground = dict(make_park.GROUND)
    ground["file"] = os.path.relpath(os.path.join(HERE, ground["file"]), out)
    counts = {n: kinds.count(n) for n in names}

    def scene(proxies):
        meshes = [ground]
        for (name, _), path in zip(inst_protos, files):
            meshes.append({"name": name, "file": os.path.relpath(path, out),
                           "albedo": PROTO[name.rsplit("-", 1)[0]][1], "place": False,
                           "proxies": proxies.get(name, [])})
        return {
            "name": "unique-park",
            "description": (
                f"The unique-geometry sculpture park (make_unique_park.py): {args.count} "
                f"sculptures ({', '.join(f'{counts[n]} {n}' for n in names)}), each its own mesh "
                f"(a per-instance non-uniform scale, twist and bend of a bundled closed mesh), "
                f"{triangles:,} original triangles in all, each mesh placed once by "
                f"unique-park.instances.txt on the first {args.count} cells of a {grid} x {grid} "
                f"grid laid out as park.json, with park.json's lawn, sun, sky and camera."),
            "camera": make_park.CAMERA, "lights": lights, "meshes": meshes,
            "instances": {"file": "unique-park.instances.txt"}}

    scene_path = os.path.join(out, "unique-park.json")
    make_park.write_text(scene_path, make_park.dumps_scene(scene({})))
    print(f"{args.count} meshes ({', '.join(f'{counts[n]} {n}' for n in names)}; "
          f"{reused} unchanged, {len(as_ply)} kept as PLY), {triangles:,} original triangles; "
          f"{'PLY' if len(as_ply) == args.count else 'Draco'} files in {mesh_dir}")

    if not args.no_proxies:
        proxies = make_proxies(args.proxy_gen, scene_path, out, inst_protos, args.ratio, stages)
        make_park.write_text(scene_path, make_park.dumps_scene(scene(proxies)))
    print(f"wrote {scene_path}")
    for k, v in stages.items():
        print(f"  {k:<45} {v:8.1f} s")
    print(f"  {'total':<45} {time.time() - start:8.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
