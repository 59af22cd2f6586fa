"""Files for the cases of cases_shard.cmake: a scene of three meshes (a, c in shard 0 of 2 and b
in shard 1 by FNV-1a 64 of their names) sharing the bunny, and another scene.

Run as a script (`corpus_shard.py PROXY_GEN CORPUS_DIR`, the bad_inputs.shard_corpus test) it
makes the shards the cases merge with this build's proxy-gen, and the damaged copies: a manifest
of another build, a truncated manifest, a truncated proxy.
"""
import json
import pathlib
import shutil
import subprocess
import sys

SETTINGS = ["--kind", "outside", "--method", "hull", "--no-cache", "-q"]


def scene(meshes, albedo):
    return {
        "camera": {"eye": [0, 0.1, 0.5], "look_at": [0, 0.1, 0], "fov_deg": 40,
                   "resolution": [16, 16]},
        "lights": [{"type": "quad", "corner": [-1, 2, -1], "edge_u": [2, 0, 0],
                    "edge_v": [0, 0, 2], "radiance": [4, 4, 4]}],
        "meshes": [{"name": n, "file": "bunny.off", "albedo": albedo} for n in meshes],
    }


def build(out: pathlib.Path, data: pathlib.Path) -> None:
    d = out / "shard"
    d.mkdir()
    shutil.copyfile(data / "bunny.off", d / "bunny.off")
    (d / "scene.json").write_text(json.dumps(scene(["a", "b", "c"], [0.7, 0.7, 0.7]), indent=1))
    # A plan folder with a finished unit: a new plan there would mix two runs' units.
    (d / "plan_done" / "units").mkdir(parents=True)
    (d / "plan_done" / "units" / "0.done").write_text("shard 0/2\n")
    # The same meshes, another albedo: another content hash.
    (d / "other_scene.json").write_text(
        json.dumps(scene(["a", "b", "c"], [0.5, 0.7, 0.7]), indent=1))


def make_shards(proxy_gen: str, corpus: pathlib.Path) -> None:
    d = corpus / "shard"

    def shard(scene_file, spec, folder, *extra):
        shutil.rmtree(d / folder, ignore_errors=True)
        subprocess.run([proxy_gen, d / scene_file, *SETTINGS, "--shard", spec, "--out-dir",
                        d / folder, *extra], check=True, timeout=120)

    shard("scene.json", "0/2", "s2_0")
    shard("scene.json", "1/2", "s2_1")
    shard("scene.json", "1/3", "s3_1")
    shard("other_scene.json", "1/2", "other_1")
    shard("scene.json", "1/2", "seed_1", "--seed", "5")
    for copy in ("build_1", "trunc_manifest_1", "trunc_proxy_1"):
        shutil.rmtree(d / copy, ignore_errors=True)
        shutil.copytree(d / "s2_1", d / copy)
    manifest = json.loads((d / "build_1" / "shard.json").read_text())
    manifest["build"] = "exe-sha256:" + "0" * 64
    (d / "build_1" / "shard.json").write_text(json.dumps(manifest, indent=1))
    text = (d / "trunc_manifest_1" / "shard.json").read_bytes()
    (d / "trunc_manifest_1" / "shard.json").write_bytes(text[: len(text) // 2])
    ply = d / "trunc_proxy_1" / "b.outside.ply"
    ply.write_bytes(ply.read_bytes()[:-100])


if __name__ == "__main__":
    make_shards(sys.argv[1], pathlib.Path(sys.argv[2]))
