#!/usr/bin/env python3
"""glTF in and out against tools proxyvis did not write.

gltf_tools.py BIN_DIR DATA_DIR JS_DIR WORK_DIR

Checks, each against facts fixed outside the code under test:
- every file proxyvis writes (mesh-info --save .glb/.gltf, proxy-gen -o .glb/.gltf for the three
  kinds, plain and with --compress draco / meshopt) passes the Khronos glTF-Validator with 0
  errors and 0 warnings, and so do the compressed files decoded by the official decoders
  (decompress.mjs: the validator does not look inside compressed buffers);
- a compressed proxy is the plain one: same triangle count and volume (meshopt and lossless
  Draco keep every position; Draco reorders faces, so the volume's sum may differ in its last
  bits);
- the class survives the file: proxy-check --expect KIND original proxy.glb exits 0, and the
  proof in the node's extras says that class, the exact containment verdict of that kind, zero
  HM' (outside) or MH' (inside) segments, and the input's SHA-256 as hashlib computes it;
- files made by obj2gltf, gltf-pipeline -d (Draco), gltf-transform meshopt / quantize / instance
  from the bundled meshes load as the same mesh as the OBJ they came from: triangle count, and
  bounds and volume within the producer's quantization error. The files are made through the
  tools' libraries, as their command lines call them and with their defaults, in one node run
  (produce.mjs): the 13 command-line runs took 13 s, mostly node loading each tool, and wrote
  the same bytes (compared file by file when the script was written).
"""
import hashlib
import json
import pathlib
import shutil
import struct
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent / "support"))
from gltf_checks import FAILURES, check, glb_json, run  # noqa: E402






def info(bin_dir: pathlib.Path, mesh: pathlib.Path, work: pathlib.Path) -> dict:
    out = work / (mesh.name + ".info.json")
    r = run([bin_dir / "mesh-info", mesh, "--json", out, "--quiet"])
    if r.returncode != 0:
        return {"error": r.stderr.strip()}
    return json.loads(out.read_text())[0]


def validate(js: pathlib.Path, files) -> None:
    r = run(["node", js / "validate.mjs", *files])
    for line in r.stdout.splitlines():
        v = json.loads(line)
        check(v["errors"] == 0 and v["warnings"] == 0,
              f"validator: {pathlib.Path(v['file']).name}: {v['errors']} errors, "
              f"{v['warnings']} warnings {v['messages']}")
    check(r.returncode == 0 and len(r.stdout.splitlines()) == len(files),
          f"validator ran on all {len(files)} files (exit {r.returncode}) {r.stderr.strip()[:200]}")


def decompressed(js, files, work):
    """Each compressed file decoded into a plain one by decompress.mjs (one node run for all)."""
    out = [work / ("decoded_" + f.name) for f in files]
    r = run(["node", js / "decompress.mjs", *(p for pair in zip(files, out) for p in pair)])
    check(r.returncode == 0 and all(p.exists() for p in out),
          f"decompress {len(files)} files: {r.stderr.strip()[:200]}")
    return out


def proxy_output(bin_dir, bunny, kind, out, extra=()) -> bool:
    # A coarse wrap (alpha 1/10 of the diagonal): the files are what is tested, and it is 3x faster.
    coarse = ["--alpha", "0.1"] if kind != "general" else []
    r = run([bin_dir / "proxy-gen", bunny, "--kind", kind, "-o", out, "--quiet",
             "--check-rays", "5000", *coarse, *extra])
    check(r.returncode == 0, f"proxy-gen --kind {kind} -o {out.name} {' '.join(extra)}: "
          f"{r.stderr.strip()}")
    r = run([bin_dir / "proxy-check", bunny, out, "--expect", kind, "--rays", "20000", "--quiet"])
    check(r.returncode == 0, f"proxy-check --expect {kind} {out.name}: exit {r.returncode}")
    return r.returncode == 0


def writers(bin_dir, data, js, work) -> None:
    bunny = data / "bunny.off"
    written, compressed = [], []
    for ext in ("glb", "gltf"):
        for comp in ("none", "draco", "meshopt"):
            out = work / f"bunny_saved_{comp}.{ext}"
            r = run([bin_dir / "mesh-info", bunny, "--save", out, "--compress", comp, "--quiet"])
            check(r.returncode == 0, f"mesh-info --save {out.name}: {r.stderr.strip()}")
            (written if comp == "none" else compressed).append(out)
    source_sha = hashlib.sha256(bunny.read_bytes()).hexdigest()
    for kind, verdict, zero in (("outside", "contains", "HM"), ("inside", "contained", "MH"),
                                ("general", None, None)):
        for ext in ("glb", "gltf"):
            out = work / f"bunny_{kind}.{ext}"
            proxy_output(bin_dir, bunny, kind, out)
            written.append(out)
            doc = glb_json(out) if ext == "glb" else json.loads(out.read_text())
            node = doc["nodes"][0]
            proof = node.get("extras", {}).get("proxyvis", {})
            check(proof.get("class") == kind, f"{out.name}: extras class {proof.get('class')}")
            check(proof.get("source_sha256") == source_sha, f"{out.name}: extras source_sha256")
            if verdict:
                check(proof.get("containment") == verdict,
                      f"{out.name}: extras containment {proof.get('containment')}")
                counts = proof.get("segments", {}).get("counts", {})
                check(counts.get(zero) == 0 and sum(counts.values()) == 5000,
                      f"{out.name}: extras segment counts {counts} ({zero} must be 0)")
            suffix = {"outside": "-occludee", "inside": "-occonly", "general": "-lod"}[kind]
            check(node.get("name") == "bunny" + suffix, f"{out.name}: node name {node.get('name')}")
        plain = info(bin_dir, work / f"bunny_{kind}.glb", work)
        for comp in ("draco", "meshopt"):
            out = work / f"bunny_{kind}_{comp}.glb"
            proxy_output(bin_dir, bunny, kind, out, ("--compress", comp))
            compressed.append(out)
            got = info(bin_dir, out, work)
            # Lossless: the same volume up to the order in which Draco sums the faces.
            check(got.get("faces") == plain["faces"] and
                  abs(got.get("volume", 0) - plain["volume"]) <= 1e-12 * plain["volume"],
                  f"{out.name} is the plain proxy: {got.get('faces')} vs {plain['faces']} faces, "
                  f"volume {got.get('volume')} vs {plain['volume']}")
    validate(js, written + compressed + decompressed(js, compressed, work))


def close(a: dict, b: dict, tolerance: float) -> bool:
    """Same triangle count, bounds within `tolerance` of the diagonal, volume within 1e-3 when
    closed."""
    if "error" in a or "error" in b or a["faces"] != b["faces"]:
        return False
    lo_a, hi_a, lo_b, hi_b = a["bounds"]["min"], a["bounds"]["max"], b["bounds"]["min"], b["bounds"]["max"]
    diag = sum((hi_a[i] - lo_a[i]) ** 2 for i in range(3)) ** 0.5
    if any(abs(lo_a[i] - lo_b[i]) > tolerance * diag or abs(hi_a[i] - hi_b[i]) > tolerance * diag
           for i in range(3)):
        return False
    if a["closed"] and b["closed"]:
        return abs(a["volume"] - b["volume"]) <= 1e-3 * abs(a["volume"])
    return True


def producers(bin_dir, data, js, work) -> None:
    sources = {"spot": data / "spot_triangulated.obj", "teapot": data / "teapot.obj"}
    bunny_obj = work / "bunny.obj"
    run([bin_dir / "mesh-info", data / "bunny.off", "--save", bunny_obj, "--quiet"])
    sources["bunny"] = bunny_obj
    # Every file in one node run (produce.mjs: each tool's library call with its defaults); the
    # plain file of each mesh is made before the three made from it.
    made = {}  # out: (mesh name, source obj, what made it, tolerance)
    ops = []
    for name, obj in sources.items():
        plain = work / f"{name}_obj2gltf.glb"
        ops += ["obj2gltf", obj, plain]
        made[plain] = (name, obj, "obj2gltf", 0.0)
        for op, tool in (("draco", "gltf-pipeline -d"), ("meshopt", "gltf-transform meshopt"),
                         ("quantize", "gltf-transform quantize")):
            out = work / f"{name}_{op}.glb"
            ops += [op, plain, out]
            made[out] = (name, obj, tool, 2e-4)
    r = run(["node", js / "produce.mjs", *ops])
    check(r.returncode == 0, f"produce.mjs: {r.stderr.strip()[:400]}")
    bases = {name: info(bin_dir, obj, work) for name, obj in sources.items()}
    for out, (name, obj, tool, tolerance) in made.items():
        check(out.exists(), f"{out.name} not made by {tool}")
        got = info(bin_dir, out, work)
        base = bases[name]
        check(close(base, got, tolerance),
              f"{out.name} ({tool}) loads as {obj.name}: {got.get('faces')} vs {base.get('faces')} "
              f"faces, volume {got.get('volume')} vs {base.get('volume')} {got.get('error', '')}")
    # Instancing: five copies placed by nodes, then the same as EXT_mesh_gpu_instancing.
    copies, instanced = work / "copies.glb", work / "instanced.glb"
    r = run(["node", js / "place_copies.mjs", work / "bunny_obj2gltf.glb", copies, 5])
    check(r.returncode == 0, f"place_copies: {r.stderr.strip()[:200]}")
    r = run(["node", js / "produce.mjs", "instance", copies, instanced])
    check(r.returncode == 0, f"gltf-transform instance: {r.stderr.strip()[:200]}")
    check("EXT_mesh_gpu_instancing" in glb_json(instanced).get("extensionsUsed", []),
          "gltf-transform instance used EXT_mesh_gpu_instancing")
    a, b = info(bin_dir, copies, work), info(bin_dir, instanced, work)
    single = info(bin_dir, work / "bunny_obj2gltf.glb", work)
    check(close(a, b, 1e-6) and a["faces"] == 5 * single["faces"],
          f"instanced loads as the five copies: {b.get('faces')} faces, volume {b.get('volume')} "
          f"vs {a.get('volume')} {b.get('error', '')}")


def main() -> int:
    bin_dir, data, js, work = (pathlib.Path(a) for a in sys.argv[1:5])
    if not (js / "node_modules" / "gltf-validator").is_dir() or shutil.which("node") is None:
        print(f"FAIL: node or {js}/node_modules missing: run ./setup.sh (it installs them)")
        return 1
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    writers(bin_dir, data, js, work)
    producers(bin_dir, data, js, work)
    print(f"{len(FAILURES)} failures")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
