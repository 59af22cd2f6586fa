#!/usr/bin/env python3
"""Seed corpora for the fuzz targets: make_seeds.py OUT_DIR REPO_ROOT [MESH_INFO].

Writes OUT_DIR/<target>/ for every target: small meshes written here in every syntax the loaders
accept (ASCII and binary PLY, OFF, OBJ with its face-corner forms), the small bundled files, and
the first part of the big ones cut down to a consistent smaller mesh (libFuzzer mutates small
inputs much faster). Draco seeds are encoded by MESH_INFO (`mesh-info --save x.drc`) when given,
otherwise the bundled bunny.drc is the only one. The scene seeds are the bundled scenes with every
file reference renamed to the placeholders fuzz_scene_files.h creates.
"""
import json
import pathlib
import shutil
import struct
import subprocess
import sys

TETRA_V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TETRA_F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
QUAD_V = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 0.5, 1)]
QUAD_F = [(0, 1, 2, 3), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)]


def ply_ascii(vs, fs, extra=""):
    head = ["ply", "format ascii 1.0", "comment seed", f"element vertex {len(vs)}",
            "property float x", "property float y", "property float z"]
    if extra:
        head.append("property uchar red")
    head += [f"element face {len(fs)}", "property list uchar int vertex_indices", "end_header"]
    lines = [" ".join(map(str, v)) + (" 200" if extra else "") for v in vs]
    lines += [f"{len(f)} " + " ".join(map(str, f)) for f in fs]
    return ("\n".join(head + lines) + "\n").encode()


def ply_binary(vs, fs, endian, normals=False):
    name = "binary_little_endian" if endian == "<" else "binary_big_endian"
    head = ["ply", f"format {name} 1.0", f"element vertex {len(vs)}",
            "property float x", "property float y", "property float z"]
    if normals:
        head += ["property float nx", "property float ny", "property float nz"]
    head += [f"element face {len(fs)}", "property list uchar int vertex_indices", "end_header"]
    body = b""
    for v in vs:
        body += struct.pack(endian + "3f", *v)
        if normals:
            body += struct.pack(endian + "3f", 0, 0, 1)
    for f in fs:
        body += struct.pack(endian + "B", len(f)) + struct.pack(endian + f"{len(f)}i", *f)
    return ("\n".join(head) + "\n").encode() + body


def off(vs, fs):
    lines = ["OFF", f"{len(vs)} {len(fs)} 0"] + [" ".join(map(str, v)) for v in vs]
    lines += [f"{len(f)} " + " ".join(map(str, f)) for f in fs]
    return ("\n".join(lines) + "\n").encode()


def obj(vs, fs, corner=lambda i: str(i + 1)):
    lines = ["# seed", "o seed"] + ["v " + " ".join(map(str, v)) for v in vs]
    lines += ["vt 0 0", "vt 1 0", "vt 0 1", "vn 0 0 1"]
    lines += ["f " + " ".join(corner(i) for i in f) for f in fs]
    return ("\n".join(lines) + "\n").encode()


def off_head(text, n_vertices):
    """The first n_vertices of an ASCII OFF file with the faces that use only them."""
    lines = [l for l in text.splitlines() if l.strip() and not l.startswith("#")]
    nv, nf = map(int, lines[1].split()[:2])
    vs = lines[2:2 + nv][:n_vertices]
    fs = [l for l in lines[2 + nv:2 + nv + nf]
          if all(int(i) < n_vertices for i in l.split()[1:])]
    return ("\n".join(["OFF", f"{len(vs)} {len(fs)} 0"] + vs + fs) + "\n").encode()


def obj_head(text, n_vertices):
    """The first n_vertices 'v' lines of an OBJ file with the faces that use only them."""
    vs, fs = [], []
    for l in text.splitlines():
        if l.startswith("v ") and len(vs) < n_vertices:
            vs.append(l)
        elif l.startswith("f "):
            idx = [int(c.split("/")[0]) for c in l.split()[1:]]
            if all(0 < i <= n_vertices for i in idx):
                fs.append(" ".join(["f"] + [c.split("/")[0] for c in l.split()[1:]]))
    return ("\n".join(vs + fs) + "\n").encode()


def mesh_seeds(out, root):
    ply, offd, objd = out / "fuzz_ply", out / "fuzz_off", out / "fuzz_obj"
    (ply / "tetra_ascii.ply").write_bytes(ply_ascii(TETRA_V, TETRA_F))
    (ply / "quads_color.ply").write_bytes(ply_ascii(QUAD_V, QUAD_F, extra="red"))
    (ply / "tetra_le.ply").write_bytes(ply_binary(TETRA_V, TETRA_F, "<"))
    (ply / "quads_be_normals.ply").write_bytes(ply_binary(QUAD_V, QUAD_F, ">", normals=True))
    shutil.copy(root / "data/foliage/YELLOWFLOWER1.ply", ply / "yellowflower.ply")
    (offd / "tetra.off").write_bytes(off(TETRA_V, TETRA_F))
    (offd / "quads.off").write_bytes(off(QUAD_V, QUAD_F))
    (offd / "bunny_head.off").write_bytes(off_head((root / "data/bunny.off").read_text(), 120))
    (objd / "tetra.obj").write_bytes(obj(TETRA_V, TETRA_F))
    (objd / "quads_slashes.obj").write_bytes(obj(QUAD_V, QUAD_F, lambda i: f"{i + 1}/1/1"))
    (objd / "tetra_negative.obj").write_bytes(obj(TETRA_V, TETRA_F, lambda i: f"{i - 4}//1"))
    (objd / "teapot_head.obj").write_bytes(obj_head((root / "data/teapot.obj").read_text(), 150))
    for f in sorted((root / "scenes/meshes").glob("*.obj")) + [root / "data/scenes/cornell_box.obj"]:
        shutil.copy(f, objd / f.name)


def draco_seeds(out, root, mesh_info):
    drc = out / "fuzz_draco"
    if mesh_info:
        for src in sorted((out / "fuzz_obj").glob("*.obj")) + sorted((out / "fuzz_off").glob("*.off")):
            for bits in (0, 11):
                target = drc / f"{src.stem}_{bits}.drc"
                subprocess.run([mesh_info, str(src), "--save", str(target), "--draco-bits",
                                str(bits), "--quiet"], check=True, stdout=subprocess.DEVNULL)
    else:
        shutil.copy(root / "data/draco/bunny.drc", drc / "bunny.drc")


def gltf_seeds(out, root, mesh_info):
    """Small documents of every kind the loader reads; with mesh-info, the bundled small meshes
    written as .glb and .gltf by it too."""
    sys.path.insert(0, str(root / "tests/bad_inputs"))
    from corpus_loaders import glb, tetra_gltf  # noqa: E402
    import base64
    doc, data = tetra_gltf()
    for mode in (4, 5, 6):
        d, _ = tetra_gltf(mode)
        (out / "fuzz_glb" / f"tetra_mode{mode}.glb").write_bytes(glb(d, data))
        embedded = json.loads(json.dumps(d))
        embedded["buffers"][0]["uri"] = ("data:application/octet-stream;base64," +
                                         base64.b64encode(data).decode())
        (out / "fuzz_gltf" / f"tetra_mode{mode}.gltf").write_text(json.dumps(embedded))
    nodes = json.loads(json.dumps(doc))
    nodes["nodes"] = [{"children": [1], "translation": [1, 2, 3]},
                      {"mesh": 0, "rotation": [0, 0, 0.7071, 0.7071], "scale": [2, 2, 2]}]
    (out / "fuzz_glb" / "tetra_nodes.glb").write_bytes(glb(nodes, data))
    sparse = json.loads(json.dumps(doc))
    sparse["bufferViews"].append({"buffer": 0, "byteOffset": 0, "byteLength": 12})
    sparse["accessors"][0]["sparse"] = {"count": 1,
                                        "indices": {"bufferView": 1, "componentType": 5125},
                                        "values": {"bufferView": 2}}
    (out / "fuzz_glb" / "tetra_sparse.glb").write_bytes(glb(sparse, data))
    if mesh_info:
        for src in sorted((out / "fuzz_off").glob("*.off")):
            for ext, target in ((".glb", "fuzz_glb"), (".gltf", "fuzz_gltf")):
                subprocess.run([mesh_info, str(src), "--save", str(out / target / (src.stem + ext)),
                                "--quiet"], check=True, stdout=subprocess.DEVNULL)
        for sidecar in list((out / "fuzz_glb").glob("*.sha256")) + list((out / "fuzz_gltf").glob("*.sha256")):
            sidecar.unlink()


PLACEHOLDERS = {".obj": "a.obj", ".ply": "b.ply", ".off": "c.off", ".drc": "d.drc"}


def placeholder_scene(scene):
    """The scene with every file reference renamed to a placeholder of fuzz_scene_files.h."""
    for m in scene.get("meshes", []):
        m["file"] = PLACEHOLDERS[pathlib.Path(m["file"]).suffix.lower()]
        for p in m.get("proxies", []):
            p["file"] = "p.ply"
    if "instances" in scene:
        scene["instances"]["file"] = "i.txt"
    return scene


def scene_seeds(out, root):
    sj, il = out / "fuzz_scene_json", out / "fuzz_instance_list"
    for f in sorted((root / "scenes").glob("*.json")):
        scene = placeholder_scene(json.loads(f.read_text()))
        (sj / f.name).write_text(json.dumps(scene) + "\n")
    (sj / "minimal.json").write_text(json.dumps({
        "camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 40,
                   "resolution": [8, 8]},
        "lights": [{"type": "triangle", "vertices": [[0, 3, 0], [1, 3, 0], [0, 3, 1]],
                    "radiance": [1, 1, 1]},
                   {"type": "triangles", "triangles": [[[0, 4, 0], [1, 4, 0], [0, 4, 1]]],
                    "radiance": [2, 2, 2]}],
        "meshes": [{"name": "m", "file": "a.obj", "albedo": [0.5, 0.5, 0.5],
                    "transform": {"translate": [1, 2, 3], "rotate": [0, 1, 0, 30], "scale": [1, 2, 1]},
                    "place": False,
                    "proxies": [{"kind": "outside", "method": "wrap", "file": "p.ply",
                                 "class": "outside"}]},
                   {"name": "n", "file": "c.off", "transform": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0]}],
        "instances": {"file": "i.txt"}}) + "\n")
    lines = (root / "scenes/foliage.instances.txt").read_text().splitlines()
    (il / "foliage_head.txt").write_text("\n".join(lines[:12]) + "\n")
    (il / "forms.txt").write_text(
        "# translation, 3x4 and 4x4 forms\nground 1 2 3\n"
        "GRASS1 1 0 0 0 0 1 0 0 0 0 1 0  # 3x4\n"
        "BUSH11 2 0 0 1 0 2 0 1 0 0 2 1 0 0 0 1\n\n")


def main() -> int:
    out, root = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    mesh_info = sys.argv[3] if len(sys.argv) > 3 else None
    if out.exists():
        shutil.rmtree(out)
    for t in ("fuzz_ply", "fuzz_obj", "fuzz_off", "fuzz_draco", "fuzz_glb", "fuzz_gltf",
              "fuzz_scene_json", "fuzz_instance_list"):
        (out / t).mkdir(parents=True)
    mesh_seeds(out, root)
    draco_seeds(out, root, mesh_info)
    gltf_seeds(out, root, mesh_info)
    scene_seeds(out, root)
    for d in sorted(out.iterdir()):
        print(f"seeds: {d.name}: {sum(1 for _ in d.iterdir())} files")
    return 0


if __name__ == "__main__":
    sys.exit(main())
