"""Inputs for the `render` program's bad-input cases (cases_render.cmake): a valid small scene
(for the flag and output cases), a truncated one, and one whose mesh file is not a mesh."""
import json
import pathlib

TRIANGLE_OBJ = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"


def scene(mesh_file: str) -> str:
    return json.dumps({
        "camera": {"eye": [0, 1, 5], "look_at": [0, 0, 0], "fov_deg": 40, "resolution": [8, 8]},
        "lights": [{"type": "quad", "corner": [-1, 4, -1], "edge_u": [2, 0, 0],
                    "edge_v": [0, 0, 2], "radiance": [5, 5, 5]}],
        "meshes": [{"name": "tri", "file": mesh_file}],
    }, indent=1) + "\n"


def build(out: pathlib.Path, data: pathlib.Path) -> None:
    (out / "render_tri.obj").write_text(TRIANGLE_OBJ)
    (out / "render_scene.json").write_text(scene("render_tri.obj"))
    text = scene("render_tri.obj")
    (out / "render_truncated.json").write_text(text[: len(text) // 2])
    # Bytes of no mesh format behind an .obj name.
    (out / "render_garbage.obj").write_bytes(bytes(range(256)) * 4)
    (out / "render_garbage_mesh.json").write_text(scene("render_garbage.obj"))
    (out / "render_a_file").write_text("not a folder\n")
