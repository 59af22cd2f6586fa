"""Shared code of the Blender tests (tests/blender/, docs/blender.md): the arguments after "--",
the add-on installed from the zip the build made, a clean scene, the evaluated world-space
triangles of an object made with Blender's own Apply operators, the programs, assertions.

The scripts run inside Blender:  blender -b --factory-startup --python SCRIPT -- --zip ZIP
--bin build/bin --data data --work DIR  (ctest passes these; see CMakeLists.txt)."""
import argparse
import json
import os
import subprocess
import sys
import time
import traceback

import bpy
import numpy as np
from proxyvis_tools.reports import FILE_KEYS, without

ADDON = "proxyvis_blender"


def arguments():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser()
    p.add_argument("--zip", required=True)
    p.add_argument("--bin", required=True)
    p.add_argument("--data", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("--module", default="", help="build/python: the test's own proxyvis import")
    p.add_argument("--screenshot", default="")
    a = p.parse_args(argv)
    os.makedirs(a.work, exist_ok=True)
    return a


def main(body):
    """Runs body(); any exception or failed assertion exits Blender with code 1."""
    t0 = time.monotonic()
    try:
        body()
    except BaseException:  # noqa: BLE001  (SystemExit too: a test never exits by itself)
        traceback.print_exc()
        sys.stderr.flush()
        os._exit(1)
    print(f"PASS {os.path.basename(sys.argv[sys.argv.index('--python') + 1])} "
          f"in {time.monotonic() - t0:.1f} s", flush=True)


def step(text):
    print(f"-- {text}", flush=True)


def install_addon(zip_path):
    """Preferences > Add-ons > Install... with the zip, then enable it. An add-on left in the
    user folder by an earlier run is removed first, and the installed files must be the zip's."""
    import shutil
    import zipfile
    assert os.path.isfile(zip_path), f"{zip_path}: no such file (build the target all)"
    addons = bpy.utils.user_resource("SCRIPTS", path="addons")
    shutil.rmtree(os.path.join(addons, ADDON), ignore_errors=True)
    assert bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True) == {"FINISHED"}
    with zipfile.ZipFile(zip_path) as z:
        for name in z.namelist():
            with open(os.path.join(addons, name), "rb") as f:
                assert f.read() == z.read(name), f"{name}: not the zip's"
    bpy.ops.preferences.addon_enable(module=ADDON)
    assert ADDON in bpy.context.preferences.addons, "the add-on is not enabled"
    module = sys.modules[ADDON]
    assert os.path.dirname(module.__file__) == os.path.join(addons, ADDON), module.__file__
    assert hasattr(bpy.ops.proxyvis, "make_proxy") and hasattr(bpy.ops.proxyvis, "check")
    return module


def prefs():
    return bpy.context.preferences.addons[ADDON].preferences


def clear_scene():
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    for mesh in list(bpy.data.meshes):
        bpy.data.meshes.remove(mesh)


def select_only(*objects):
    for o in bpy.context.view_layer.objects:
        o.select_set(False)
    for o in objects:
        o.select_set(True)
    bpy.context.view_layer.objects.active = objects[0] if objects else None


def import_one(operator, name, **kwargs):
    """Imports with OPERATOR (one mesh object expected) and names the object NAME."""
    before = set(bpy.data.objects)
    operator(**kwargs)
    new = [o for o in bpy.data.objects if o not in before and o.type == "MESH"]
    assert len(new) == 1, f"{operator}: {len(new)} mesh objects imported"
    new[0].name = name
    return new[0]


def mesh_arrays(mesh):
    """(V float32, F int32) of a mesh's vertices and loop triangles, as stored."""
    mesh.calc_loop_triangles()
    V = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
    mesh.vertices.foreach_get("co", V)
    F = np.empty(len(mesh.loop_triangles) * 3, dtype=np.int32)
    mesh.loop_triangles.foreach_get("vertices", F)
    return V.reshape(-1, 3), F.reshape(-1, 3)


def applied_triangles(obj):
    """The object's triangles the way a user gets them without the add-on: a copy converted to a
    mesh (Object > Convert > Mesh: modifiers applied) with Apply > All Transforms, in world
    space; then its loop triangles."""
    select_only(obj)
    bpy.ops.object.duplicate()
    copy = bpy.context.view_layer.objects.active
    assert copy != obj
    bpy.ops.object.convert(target="MESH")
    bpy.ops.object.transform_apply(location=True, rotation=True, scale=True)
    V, F = mesh_arrays(copy.data)
    mesh = copy.data
    bpy.data.objects.remove(copy)
    bpy.data.meshes.remove(mesh)
    select_only(obj)
    return V, F


def sha256(V, F):
    import hashlib
    h = hashlib.sha256()
    h.update(np.ascontiguousarray(V, dtype="<f4").tobytes())
    h.update(np.ascontiguousarray(F, dtype="<i4").tobytes())
    return h.hexdigest()


def write_ply(path, V, F):
    """Binary little-endian PLY of float32 vertices, the programs' own layout."""
    V = np.ascontiguousarray(V, dtype="<f4")
    faces = np.empty(len(F), dtype=[("n", "u1"), ("i", "<i4", (3,))])
    faces["n"], faces["i"] = 3, F
    with open(path, "wb") as f:
        f.write((f"ply\nformat binary_little_endian 1.0\nelement vertex {len(V)}\n"
                 "property float x\nproperty float y\nproperty float z\n"
                 f"element face {len(F)}\nproperty list uchar int vertex_indices\n"
                 "end_header\n").encode())
        f.write(V.tobytes())
        f.write(faces.tobytes())


def run(bin_dir, program, *args, expect_code=0):
    """build/bin/PROGRAM ARGS: (exit code, stderr); the exit code must be expect_code."""
    t0 = time.monotonic()
    p = subprocess.run([os.path.join(bin_dir, program), *map(str, args)], capture_output=True,
                       text=True, timeout=600)
    step(f"{program} {' '.join(map(str, args))}: exit {p.returncode}, "
         f"{time.monotonic() - t0:.1f} s")
    assert p.returncode == expect_code, f"{program}: exit {p.returncode}\n{p.stderr}"
    return p.returncode, p.stderr


def error_text(stderr, program, path):
    """What PROGRAM printed after "PROGRAM: error: PATH: "."""
    prefix = f"{program}: error: {path}: "
    lines = [ln for ln in stderr.splitlines() if ln.startswith(prefix)]
    assert lines, f"no '{prefix}' line in:\n{stderr}"
    return lines[-1][len(prefix):]


def read_ply_arrays(path):
    """(V float32, F int32) of a binary PLY written by the programs (the add-on's reader)."""
    backend = sys.modules[ADDON + ".backend"]
    V, F = backend.read_ply(path)
    return V.astype(np.float32), F


def expect_equal(a, b, what):
    assert a == b, f"{what}: {a!r} != {b!r}"


def compare_with_programs(proxy, original_V, original_F, work, bin_dir, stem, flags):
    """Runs proxy-gen FLAGS and proxy-check on ORIGINAL (written as binary PLY) and asserts that
    the add-on's proxy object equals proxy-gen's output: the same file bytes when written the
    same way, the same report but for timings and file names, the same custom properties."""
    src = os.path.join(work, f"{stem}.ply")
    out = os.path.join(work, f"{stem}.proxy-gen.ply")
    rep = os.path.join(work, f"{stem}.proxy-gen.json")
    chk = os.path.join(work, f"{stem}.proxy-check.json")
    write_ply(src, original_V, original_F)
    run(bin_dir, "proxy-gen", src, *flags, "-o", out, "--json", rep, "-q")
    with open(rep) as f:
        expected = json.load(f)
    cls = expected["class"] or "general"
    expect_args = ["--expect", cls] if cls in ("outside", "inside") else []
    run(bin_dir, "proxy-check", src, out, "--rays", 100000, "--json", chk, "-q", *expect_args)
    with open(chk) as f:
        expected_check = json.load(f)

    # The proxy object: its vertices and triangles are proxy-gen's, byte for byte.
    Vb, Fb = mesh_arrays(proxy.data)
    Vg, Fg = read_ply_arrays(out)
    assert np.array_equal(Vb, Vg) and np.array_equal(Fb, Fg), f"{proxy.name}: not proxy-gen's"
    mine = os.path.join(work, f"{stem}.blender.ply")
    write_ply(mine, Vb, Fb)
    with open(mine, "rb") as a, open(out, "rb") as b:
        assert a.read() == b.read(), f"{mine} and {out} differ"

    g = lambda key: proxy.get("proxyvis_" + key)  # noqa: E731
    expect_equal(g("class"), cls, "class")
    expect_equal(g("kind"), expected["kind"], "kind")
    expect_equal(g("method"), expected["method"], "method")
    expect_equal(g("faces"), expected["faces"], "faces")
    expect_equal(len(proxy.data.polygons), expected["faces"], "polygons")
    expect_equal(g("verified"), expected["verified"], "verified")
    expect_equal(g("volume_ratio"), expected["volume_ratio"], "volume ratio")
    expect_equal(g("hausdorff_original_to_proxy"),
                 expected["hausdorff"]["original_to_proxy"], "Hausdorff original->proxy")
    expect_equal(g("hausdorff_proxy_to_original"),
                 expected["hausdorff"]["proxy_to_original"], "Hausdorff proxy->original")
    expect_equal(g("containment"), expected["checks"].get("containment"), "containment")
    for c in ("HH", "HM", "MH", "MM"):
        expect_equal(g(c), expected_check["counts"][c], f"{c}' count")
    expect_equal(g("HM_rate_upper_95"), expected_check["intervals"]["HM"]["hi"], "HM' bound")
    expect_equal(g("MH_rate_upper_95"), expected_check["intervals"]["MH"]["hi"], "MH' bound")
    expect_equal(g("check_holds"), True, "check holds")
    expect_equal(g("source_sha256"), sha256(original_V, original_F), "source sha256")
    # The whole reports, but for timings and file names.
    expect_equal(without(json.loads(g("report")), FILE_KEYS), without(expected, FILE_KEYS),
                 "proxy-gen report")
    expect_equal(without(json.loads(g("check_report")), FILE_KEYS),
                 without(expected_check, FILE_KEYS), "proxy-check report")
    return expected, expected_check
