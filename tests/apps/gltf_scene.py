#!/usr/bin/env python3
"""glTF scenes, both ways, on the bundled dragon-plane scene.

gltf_scene.py BIN_DIR SOURCE_DIR JS_DIR WORK_DIR

Checks, each against facts fixed outside the code under test:
- proxy-gen SCENE --out-dir D --gltf D/scene.glb writes a GLB that the Khronos validator passes
  with 0 errors and 0 warnings; its default scene holds the original triangles only (100,000
  dragon + 2 ground + 2 light), the proxy is a hidden child node named "dragon-occludee" whose
  mesh extras carry the proof (class outside, containment "contains"), that node, picked by
  name, is the very proxy written beside it (same triangle count and volume as the PLY), and
  proxy-check --node dragon --proxy-node dragon-occludee --expect outside holds within the file;
- the GLB read back as a scene renders the image of the JSON scene (same seed and samples) up to
  float rounding: no pixel value differs by more than 1e-4 (OpenImageIO's idiff; the camera
  comes back through a matrix, so its rays differ in their last bits: 1.2e-6 seen);
- with --kind general the proxy is the dragon node's MSFT_lod level instead (a node outside the
  scene's root list, with the dragon's transform), and that file validates as well;
- proxy-gen on the GLB as a scene (--out-dir) builds the dragon's proxy again, its scene.json
  refers to the GLB's meshes by "gltf_mesh", proxy-check --expect outside holds for it, two
  shards merged give the same files, and
  render-compare runs on the GLB scene itself and writes its report.
"""
import json
import pathlib
import shutil
import struct
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent / "support"))
from gltf_checks import FAILURES, check, glb_json, run  # noqa: E402





def mesh_info(bin_dir, path, work, *extra) -> dict:
    out = work / "info.json"
    r = run([bin_dir / "mesh-info", path, "--json", out, "--quiet", *extra])
    return json.loads(out.read_text())[0] if r.returncode == 0 else {"error": r.stderr.strip()}



# The dragon's outside proxies with a coarse wrap (alpha 1/20 of the diagonal): what is tested is
# the scene's files, not the proxy's tightness, and it halves each run.
COARSE = ["--alpha", "0.05"]


def main() -> int:
    bin_dir, src, js, work = (pathlib.Path(a) for a in sys.argv[1:5])
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    out = work / "proxies"
    glb = out / "scene.glb"
    r = run([bin_dir / "proxy-gen", src / "scenes/dragon-plane.json", "--kind", "outside", *COARSE,
             "--out-dir", out, "--gltf", glb, "--no-cache", "--quiet"])
    check(r.returncode == 0 and glb.exists(), f"proxy-gen --gltf: exit {r.returncode} {r.stderr.strip()[-300:]}")
    if r.returncode != 0:
        return 1
    v = run(["node", js / "validate.mjs", glb])
    line = json.loads(v.stdout.splitlines()[0]) if v.stdout else {}
    check(v.returncode == 0, f"validator: {line.get('errors')} errors, {line.get('warnings')} warnings "
          f"{line.get('messages')}")

    whole = mesh_info(bin_dir, glb, work)
    check(whole.get("faces") == 100004, f"default scene: {whole.get('faces')} triangles (100004 expected)")
    doc = glb_json(glb)
    proxy_nodes = [n for n in doc["nodes"] if n.get("name") == "dragon-occludee"]
    check(len(proxy_nodes) == 1 and proxy_nodes[0].get("extensions", {}).get(
        "KHR_node_visibility", {}).get("visible") is False, "dragon-occludee is one hidden node")
    if proxy_nodes:
        proof = doc["meshes"][proxy_nodes[0]["mesh"]].get("extras", {}).get("proxyvis", {})
        check(proof.get("class") == "outside" and proof.get("containment") == "contains",
              f"the proxy mesh's proof: class {proof.get('class')}, containment {proof.get('containment')}")
    r = run([bin_dir / "proxy-check", glb, glb, "--node", "dragon", "--proxy-node",
             "dragon-occludee", "--expect", "outside", "--rays", "20000", "--quiet"])
    check(r.returncode == 0, f"proxy-check GLB GLB --node dragon --proxy-node dragon-occludee "
          f"--expect outside: exit {r.returncode} {r.stderr.strip()[-200:]}")
    picked = mesh_info(bin_dir, glb, work, "--node", "dragon-occludee")
    ply = mesh_info(bin_dir, out / "dragon.outside.ply", work)
    check(picked.get("faces") == ply.get("faces") and
          abs(picked.get("volume", 0) - ply.get("volume", 1)) <= 1e-9 * abs(ply.get("volume", 1)),
          f"--node dragon-occludee is the written proxy: {picked.get('faces')} vs {ply.get('faces')} faces")

    general = work / "general"
    lod_glb = general / "scene.glb"
    r = run([bin_dir / "proxy-gen", src / "scenes/dragon-plane.json", "--kind", "general",
             "--out-dir", general, "--gltf", lod_glb, "--no-cache", "--quiet"])
    check(r.returncode == 0, f"proxy-gen --kind general --gltf: {r.stderr.strip()[-200:]}")
    if r.returncode == 0:
        doc = glb_json(lod_glb)
        dragon = [n for n in doc["nodes"] if n.get("name") == "dragon"]
        ids = dragon[0].get("extensions", {}).get("MSFT_lod", {}).get("ids", []) if dragon else []
        lod_ok = len(ids) == 1 and doc["nodes"][ids[0]].get("name") == "dragon-lod" and \
            ids[0] not in doc["scenes"][0]["nodes"]
        check(lod_ok, f"the general proxy is the dragon's MSFT_lod level: ids {ids}")
        v = run(["node", js / "validate.mjs", lod_glb])
        check(v.returncode == 0, f"validator on the LOD scene: {v.stdout.strip()[:300]}")

    images = []
    for scene in (src / "scenes/dragon-plane.json", glb):
        image = work / (scene.name + ".exr")
        r = run([bin_dir / "render", scene, "--spp", "8", "--seed", "5", "-o", image, "--quiet"])
        check(r.returncode == 0, f"render {scene.name}: {r.stderr.strip()[-200:]}")
        images.append(image)
    r = run(["idiff", "-fail", "1e-4", "-warn", "1e-4", *images])
    check(r.returncode == 0, f"the GLB scene renders the JSON scene's image: idiff exit {r.returncode} "
          f"{r.stdout.strip()[-200:]}")

    again = work / "again"
    r = run([bin_dir / "proxy-gen", glb, "--kind", "outside", *COARSE, "--out-dir", again,
             "--no-cache", "--quiet"])
    check(r.returncode == 0, f"proxy-gen on the GLB as a scene: {r.stderr.strip()[-300:]}")
    scene = json.loads((again / "scene.json").read_text()) if r.returncode == 0 else {"meshes": []}
    dragon = [m for m in scene["meshes"] if m["name"] == "dragon"]
    check(len(dragon) == 1 and "gltf_mesh" in dragon[0] and dragon[0]["proxies"],
          "its scene.json names the dragon by gltf_mesh, with a proxy")
    if dragon and dragon[0]["proxies"]:
        original = work / "dragon_from_glb.ply"
        run([bin_dir / "mesh-info", glb, "--node", "dragon", "--save", original, "--quiet"])
        r = run([bin_dir / "proxy-check", original, again / dragon[0]["proxies"][0]["file"],
                 "--expect", "outside", "--rays", "20000", "--quiet"])
        check(r.returncode == 0, f"proxy-check --expect outside on it: exit {r.returncode}")
    # In two shards merged, the same proxy and scene as the whole run.
    shards = [work / f"shard{k}" for k in range(2)]
    for k, folder in enumerate(shards):
        run([bin_dir / "proxy-gen", glb, "--kind", "outside", *COARSE, "--out-dir", folder,
             "--shard", f"{k}/2", "--no-cache", "--quiet"])
    merged = work / "merged"
    r = run([bin_dir / "proxy-gen", glb, "--kind", "outside", *COARSE, "--out-dir", merged,
             "--merge-shards", *shards, "--no-cache", "--quiet"])
    same = r.returncode == 0 and all(
        (merged / f).exists() and (merged / f).read_bytes() == (again / f).read_bytes()
        for f in ("dragon.outside.ply", "scene.json"))
    check(same, f"two shards merged give the whole run's proxy and scene.json: exit {r.returncode}")
    r = run([bin_dir / "render-compare", glb, "--out", work / "report", "--spp", "2",
             "--equal-time", "0", "--reference-spp", "32", "--seeds", "1", "--estimators",
             "exact,roulette", "--quiet"])
    check(r.returncode == 0 and (work / "report/report.html").exists(),
          f"render-compare on the GLB scene: exit {r.returncode} {r.stderr.strip()[-200:]}")
    print(f"{len(FAILURES)} failures")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
