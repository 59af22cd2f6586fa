"""Meshes that load fine but that the proxy generators cannot handle, and scenes around them.

Degenerate geometry (four distinct collinear vertices closed into a tetrahedron, four identical
points), coordinates near the float limit (+-3e38, every y = -1.7e38), and the bunny of data/
scaled or shifted by 1e20 (float then has no resolution left across it). Before the generators
checked their input these crashed CGAL (SIGSEGV, an infinity reaching GMP), aborted OpenMesh, or
spun in the inside wrap's seed search. The scenes: one such mesh beside a good one (the scene is
still written, with the good mesh's proxy), a mesh named ../../../x (its proxy file must stay in
--out-dir), and a scene whose --out-dir is its own folder (scene.json would replace the input).
"""
import json
import pathlib

TETRA_FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def write_off(path: pathlib.Path, vertices, faces) -> None:
    lines = ["OFF", f"{len(vertices)} {len(faces)} 0"]
    lines += [" ".join(repr(float(c)) for c in v) for v in vertices]
    lines += ["3 " + " ".join(str(i) for i in f) for f in faces]
    path.write_text("\n".join(lines) + "\n")


def read_off(path: pathlib.Path):
    tokens = path.read_text().split()
    assert tokens[0] == "OFF"
    nv, nf = int(tokens[1]), int(tokens[2])
    pos = 4
    vertices = []
    for _ in range(nv):
        vertices.append(tuple(float(t) for t in tokens[pos:pos + 3]))
        pos += 3
    faces = []
    for _ in range(nf):
        n = int(tokens[pos])
        faces.append(tuple(int(t) for t in tokens[pos + 1:pos + 1 + n]))
        pos += 1 + n
    return vertices, faces


def scene(meshes) -> str:
    return json.dumps({
        "camera": {"eye": [0, 0, 3], "look_at": [0, 0, 0], "fov_deg": 40,
                   "resolution": [16, 16]},
        "lights": [{"type": "quad", "corner": [-1, 2, -1], "edge_u": [2, 0, 0],
                    "edge_v": [0, 0, 2], "radiance": [5, 5, 5]}],
        "meshes": meshes,
    }, indent=2) + "\n"


def build(out: pathlib.Path, data: pathlib.Path) -> None:
    write_off(out / "gen_collinear_tetra.off", [(0, 0, 0), (1, 0, 0), (2, 0, 0), (3, 0, 0)],
              TETRA_FACES)
    write_off(out / "gen_same_points.off", [(1, 1, 1)] * 4, TETRA_FACES)
    write_off(out / "gen_coords_3e38.off",
              [(3e38, 3e38, 3e38), (-3e38, -3e38, 3e38), (-3e38, 3e38, -3e38),
               (3e38, -3e38, -3e38)], TETRA_FACES)
    vertices, faces = read_off(data / "bunny.off")
    write_off(out / "gen_bunny_scaled_1e20.off", [tuple(c * 1e20 for c in v) for v in vertices],
              faces)
    write_off(out / "gen_bunny_shifted_1e20.off", [tuple(c + 1e20 for c in v) for v in vertices],
              faces)
    write_off(out / "gen_bunny_y_1.7e38.off", [(v[0], -1.7e38, v[2]) for v in vertices], faces)

    bunny = str((data / "bunny.off").resolve())
    mixed = out / "gen_scene_mixed"
    mixed.mkdir()
    (mixed / "scene.json").write_text(scene([
        {"name": "huge", "file": "../gen_coords_3e38.off"},
        {"name": "bunny", "file": bunny},
    ]))
    dotdot = out / "gen_scene_dotdot"
    dotdot.mkdir()
    (dotdot / "scene.json").write_text(scene([{"name": "../../../x", "file": bunny}]))
    own = out / "gen_scene_own_dir"
    own.mkdir()
    write_off(own / "tetra.off", [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)], TETRA_FACES)
    (own / "scene.json").write_text(scene([{"name": "tetra", "file": "tetra.off"}]))
