"""Helpers for the data-parallel tests: mpirun with the flags this machine needs, and a small
scene whose every object is its own mesh file (so that which rank opens which file is a fact a
test can check), with outside and inside proxies made by proxy-gen."""
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from image_diff import differing_pairs  # noqa: E402
from proxyvis_tools.meshes import bounds, read_mesh, sha256_file  # noqa: E402
from proxyvis_tools.mpi import mpi_env, mpirun_cmd  # noqa: E402,F401  (the cases' mpirun)


def run(cmd, expect=0, env=None):
    p = subprocess.run(cmd, capture_output=True, text=True, env=env or mpi_env())
    if expect is not None and p.returncode != expect:
        sys.exit(f"FAIL: {' '.join(cmd)}\nexit {p.returncode}, expected {expect}\n"
                 f"stdout:\n{p.stdout}\nstderr:\n{p.stderr}")
    return p


def read_json(path):
    with open(path) as f:
        return json.load(f)


def make_unique_scene(folder, data_dir, scenes_dir, proxy_gen, side=3, spacing=1.6,
                      with_inside=True, proxy_cache=None):
    """A side x side grid of sculptures, each its own copy of bunny.off or
    spot_triangulated.obj (distinct files), placed on a ground quad, with a sun at about 30
    degrees and a sky quad. Returns the scene path. With proxy_cache, the proxies are made once
    in that folder and copied (the cases of one test file share them; proxy-gen writes by
    rename, so two cases making the same one at once both see a whole file)."""
    os.makedirs(os.path.join(folder, "meshes"), exist_ok=True)
    made_in = proxy_cache or folder
    os.makedirs(made_in, exist_ok=True)
    protos = {}
    for name, file in (("bunny", "bunny.off"), ("spot", "spot_triangulated.obj")):
        src = os.path.join(data_dir, file)
        proxies = []
        kinds = [("outside", ["--method", "hull"])]
        if with_inside:
            kinds.append(("inside", ["--max-faces", "300"]))
        for kind, flags in kinds:
            out = os.path.join(folder, f"{name}.{kind}.ply")
            made = os.path.join(made_in, f"{name}.{kind}.ply")
            if not os.path.exists(made):
                run([proxy_gen, src, "--kind", kind, *flags, "-o", made, "--quiet"],
                    env=os.environ)
            if made != out:
                shutil.copyfile(made, out)
            proxies.append({"kind": kind, "file": os.path.basename(out), "class": kind,
                            "sha256": sha256_file(out)})
        protos[name] = (src, proxies, bounds(read_mesh(src)[0]))
    meshes = [{"name": "ground", "file": os.path.abspath(os.path.join(scenes_dir, "meshes", "ground.obj")),
               "albedo": [0.7, 0.7, 0.7], "make_proxy": False,
               "transform": {"scale": spacing * side * 1.5}}]
    k = 0
    for i in range(side):
        for j in range(side):
            name = "bunny" if (i + j) % 2 == 0 else "spot"
            src, proxies, (lo, hi) = protos[name]
            ext = os.path.splitext(src)[1]
            copy = os.path.join(folder, "meshes", f"m{k}{ext}")
            shutil.copyfile(src, copy)
            s = 1.0 / (hi[1] - lo[1])
            cx, cz = (lo[0] + hi[0]) / 2, (lo[2] + hi[2]) / 2
            x = (i - (side - 1) / 2) * spacing
            z = (j - (side - 1) / 2) * spacing
            # row-major 3x4: uniform scale, then translate so the model stands on y = 0.
            m = [s, 0, 0, x - s * cx, 0, s, 0, -s * lo[1] + 0.001, 0, 0, s, z - s * cz]
            meshes.append({"name": f"m{k}", "file": os.path.join("meshes", f"m{k}{ext}"),
                           "albedo": [0.8, 0.6, 0.4], "transform": m, "proxies": proxies})
            k += 1
    extent = spacing * side
    scene = {
        "description": "data-parallel test: every sculpture its own mesh file",
        "camera": {"eye": [0, extent * 1.1, extent * 1.4], "look_at": [0, 0.3, 0],
                   "up": [0, 1, 0], "fov_deg": 40, "resolution": [48, 36]},
        "lights": [
            # A sun at about 30 degrees to the side, and a dim sky high above.
            {"type": "quad", "corner": [-60, 35, -2], "edge_u": [0, 0, 4], "edge_v": [0, 4, 0],
             "radiance": [400, 380, 350]},
            {"type": "quad", "corner": [-3 * extent, 20, -3 * extent], "edge_u": [6 * extent, 0, 0],
             "edge_v": [0, 0, 6 * extent], "radiance": [0.3, 0.4, 0.6]},
        ],
        "meshes": meshes,
    }
    path = os.path.join(folder, "unique.json")
    with open(path, "w") as f:
        json.dump(scene, f, indent=1)
    return path


def rgb_equal(exr_a, exr_b, work):
    """True if the R, G, B channels of two EXRs are equal bit for bit, and oiiotool's report."""
    del work  # nothing is written
    try:
        differ = differing_pairs([(exr_a, exr_b)], channels="R,G,B")
    except RuntimeError as e:
        return False, str(e)
    return not differ, differ[0][2] if differ else "PASS"


def rgb_means(exrs):
    """The mean R, G, B of each EXR, from one `oiiotool --stats` over all of them."""
    p = run(["oiiotool", "--stats", *exrs])
    means = [[float(v) for v in line.split(":")[1].split()[:3]]
             for line in p.stdout.splitlines() if "Stats Avg" in line]
    if len(means) != len(exrs):
        sys.exit(f"FAIL: oiiotool --stats gave {len(means)} means for {len(exrs)} images")
    return means
