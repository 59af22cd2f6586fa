#!/usr/bin/env python3
"""The glTF files proxyvis writes, as a real consumer sees them: three.js's GLTFLoader in headless
Chromium (tests/js/three_consumer, three and its Draco and meshopt decoders from tests/js's npm
packages, no network).

gltf_three.py BIN_DIR DATA_DIR JS_DIR WORK_DIR

Files: mesh-info --save of bunny, spot and teapot, proxy-gen -o of the three kinds on bunny, of
each a Draco copy (gltf-pipeline -d) and a meshopt copy (gltf-transform meshopt), and five bunnies
placed by nodes and as EXT_mesh_gpu_instancing (gltf-transform instance). Checks, each file
against mesh-info --json of the same file:
- three.js loads it without an error and logs no console error;
- the same triangle count (instances and node transforms included);
- the same world-space bounds, within 1e-6 of the diagonal (2e-4 for the compressed copies:
  the decoders dequantize in their own precision).
A checker that finds nothing proves nothing, so defects are planted and must be caught: a
truncated GLB must be rejected, a GLB naming a missing texture must log a console error, and
the comparison must reject a triangle count off by one and bounds off by ten times the tolerance.
"""
import concurrent.futures
import json
import os
import pathlib
import shutil
import struct
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent / "support"))
from gltf_checks import FAILURES, check, glb_json, run  # noqa: E402

PLAIN, COMPRESSED = 1e-6, 2e-4




def info(bin_dir: pathlib.Path, mesh: pathlib.Path) -> dict:
    out = mesh.with_suffix(".info.json")
    r = run([bin_dir / "mesh-info", mesh, "--json", out, "--quiet"])
    if r.returncode != 0:
        return {"error": r.stderr.strip()}
    return json.loads(out.read_text())[0]


def deviation(a: dict, b: dict) -> float:
    """Largest difference of the bounds' corners, as a fraction of a's diagonal."""
    lo_a, hi_a, lo_b, hi_b = a["bounds"]["min"], a["bounds"]["max"], b["bounds"]["min"], b["bounds"]["max"]
    diag = sum((hi_a[i] - lo_a[i]) ** 2 for i in range(3)) ** 0.5
    return max(max(abs(lo_a[i] - lo_b[i]), abs(hi_a[i] - hi_b[i])) for i in range(3)) / diag


def same(expected: dict, seen: dict, tolerance: float) -> bool:
    return ("error" not in expected and "error" not in seen
            and seen["triangles"] == expected["faces"] and deviation(expected, seen) <= tolerance)


def problems(got: dict) -> list:
    """What makes a file fail to load cleanly: the loader's error, any console message above info."""
    return ([got["error"]] if "error" in got else []) + [
        m for m in got.get("console", []) if not m.startswith(("log:", "info:", "debug:"))]


def glb_with_missing_texture(glb: pathlib.Path, out: pathlib.Path) -> None:
    """`glb` with a material whose base colour texture names an image that does not exist."""
    data = glb.read_bytes()
    length = struct.unpack("<I", data[12:16])[0]
    doc = json.loads(data[20:20 + length])
    doc["images"] = [{"uri": "missing.png"}]
    doc["textures"] = [{"source": 0}]
    doc["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
    for mesh in doc["meshes"]:
        for primitive in mesh["primitives"]:
            primitive["material"] = 0
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)  # chunks are 4-byte aligned; JSON pads with spaces
    rest = data[20 + length:]
    out.write_bytes(struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(text) + len(rest))
                    + struct.pack("<II", len(text), 0x4E4F534A) + text + rest)


def make_files(bin_dir, data, js, work) -> dict:
    """Writes the GLBs; returns {path: tolerance}."""
    tools = js / "node_modules" / ".bin"
    jobs = {}
    for name, mesh in (("bunny", data / "bunny.off"), ("spot", data / "spot_triangulated.obj"),
                       ("teapot", data / "teapot.obj")):
        jobs[work / f"{name}.glb"] = [bin_dir / "mesh-info", mesh, "--save", work / f"{name}.glb",
                                      "--quiet"]
    for kind in ("outside", "inside", "general"):
        out = work / f"bunny_{kind}.glb"
        jobs[out] = [bin_dir / "proxy-gen", data / "bunny.off", "--kind", kind, "-o", out,
                     "--quiet", "--gltf-rays", "2000"]
    # Two cores: the producers (each a node start) run side by side.
    with concurrent.futures.ThreadPoolExecutor(os.cpu_count() or 2) as pool:
        def make(out, cmds):
            for cmd in cmds:
                r = run(cmd)
                if r.returncode != 0:
                    break
            check(r.returncode == 0 and out.exists(), f"{out.name} written: {r.stderr.strip()[:200]}")
        list(pool.map(make, jobs, ([cmd] for cmd in jobs.values())))
        copies = {}
        for plain in list(jobs):
            draco, meshopt = (plain.with_name(plain.stem + s) for s in ("_draco.glb", "_meshopt.glb"))
            copies[draco] = [[tools / "gltf-pipeline", "-i", plain, "-o", draco, "-d"]]
            copies[meshopt] = [[tools / "gltf-transform", "meshopt", plain, meshopt]]
        # Five bunnies placed by nodes, then as one InstancedMesh (EXT_mesh_gpu_instancing): node
        # transforms and instances in the count and the bounds.
        placed, instanced = work / "bunny_placed.glb", work / "bunny_instanced.glb"
        more = {instanced: [["node", js / "place_copies.mjs", work / "bunny.glb", placed, 5],
                            [tools / "gltf-transform", "instance", placed, instanced]]}
        list(pool.map(make, {**copies, **more}, {**copies, **more}.values()))
    return {**{f: PLAIN for f in jobs}, **{f: COMPRESSED for f in copies},
            placed: PLAIN, instanced: PLAIN}


def main() -> int:
    bin_dir, data, js, work = (pathlib.Path(a) for a in sys.argv[1:5])
    chromium = shutil.which("chromium")
    modules = js / "node_modules"
    missing = [m for m in ("three", "playwright-core", "gltf-pipeline", "@gltf-transform/cli")
               if not (modules / m).is_dir()]
    if chromium is None or shutil.which("node") is None or missing:
        print(f"FAIL: chromium, node or {', '.join(missing) or 'nothing'} in {modules} missing: "
              "run ./setup.sh test (it installs them)")
        return 1
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    files = make_files(bin_dir, data, js, work)
    truncated, textured = work / "planted_truncated.glb", work / "planted_missing_texture.glb"
    whole = (work / "bunny.glb").read_bytes()
    truncated.write_bytes(whole[:len(whole) // 2])
    glb_with_missing_texture(work / "bunny.glb", textured)

    names = [f for f in files if f.exists()] + [truncated, textured]
    r = run(["node", js / "three_consumer" / "run.mjs", chromium, *names], timeout=240)
    lines = [json.loads(line) for line in r.stdout.splitlines()]
    check(r.returncode == 0 and len(lines) == len(names) + 1,
          f"three.js inspected all {len(names)} files (exit {r.returncode}) {r.stderr.strip()[-500:]}")
    if not lines:
        return 1
    check(not lines[0]["console"], f"the page starts (WebGL: {lines[0].get('webgl')}) without a "
                                   f"console message: {lines[0]['console']}")
    seen = {pathlib.Path(line["file"]): line for line in lines[1:]}

    for path, tolerance in files.items():
        got = seen.get(path, {"error": "not inspected"})
        expected = info(bin_dir, path)
        check(not problems(got), f"three.js loads {path.name}: {problems(got)}")
        check("error" not in expected and got.get("triangles") == expected["faces"],
              f"{path.name}: {got.get('triangles')} triangles, mesh-info {expected.get('faces')} "
              f"{expected.get('error', '')}")
        if "error" not in got and "error" not in expected:
            d = deviation(expected, got)
            check(d <= tolerance, f"{path.name}: bounds differ by {d:.1e} of the diagonal "
                                  f"(tolerance {tolerance:g})")

    got = seen.get(work / "bunny_instanced.glb", {})
    check(got.get("meshes") == 1 and got.get("instances") == 5,
          f"bunny_instanced.glb is one InstancedMesh of 5 in three.js: {got.get('meshes')} meshes, "
          f"{got.get('instances')} instances")

    # Planted defects: each must be caught.
    got = seen.get(truncated, {})
    check("error" in got and problems(got),
          f"planted: the truncated GLB is rejected: {got.get('error')}")
    got = seen.get(textured, {})
    check("error" not in got
          and any(m.startswith("error:") and "texture" in m for m in problems(got)),
          f"planted: the missing texture loads but logs a console error: {problems(got)}")
    base, got = info(bin_dir, work / "bunny.glb"), seen.get(work / "bunny.glb", {"error": "-"})
    if "error" in base:
        check(False, f"mesh-info bunny.glb: {base['error']}")
        return 1
    check(same(base, got, PLAIN) and same(base, seen.get(textured, {"error": "-"}), PLAIN),
          "planted: the comparison accepts bunny.glb and its textured copy as they are")
    off_by_one = {**base, "faces": base["faces"] + 1}
    lo, hi = base["bounds"]["min"], base["bounds"]["max"]
    shift = 10 * PLAIN * sum((hi[i] - lo[i]) ** 2 for i in range(3)) ** 0.5
    moved = {**base, "bounds": {"min": [lo[0] - shift, lo[1], lo[2]], "max": hi}}
    check(not same(off_by_one, got, PLAIN), "planted: a triangle count off by one is rejected")
    check(not same(moved, got, PLAIN), "planted: bounds off by 1e-5 of the diagonal are rejected")

    print(f"{len(FAILURES)} failures")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
