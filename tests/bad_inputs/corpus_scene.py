"""Scenes whose values the renderer's float arithmetic cannot take, and scene text that would
reach the terminal raw. Each must be refused at load with one error line naming the scene file
(or the instance list's file:line), and nothing written."""
import json
import pathlib

TRIANGLE_OBJ = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"


def scene(**changes):
    """A valid small scene around scene_tri.obj, with top-level or camera/light/mesh changes."""
    s = {
        "camera": {"eye": [0, 1, 5], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 40,
                   "resolution": [16, 16]},
        "lights": [{"type": "quad", "corner": [-1, 4, -1], "edge_u": [2, 0, 0],
                    "edge_v": [0, 0, 2], "radiance": [5, 5, 5]}],
        "meshes": [{"name": "tri", "file": "scene_tri.obj"}],
    }
    for key, value in changes.items():
        part, _, field = key.partition("__")
        target = {"camera": s["camera"], "light": s["lights"][0], "mesh": s["meshes"][0]}.get(part)
        if target is None:
            s[key] = value
        else:
            target[field] = value
    return json.dumps(s, indent=1) + "\n"


def build(out: pathlib.Path, data: pathlib.Path) -> None:
    (out / "scene_tri.obj").write_text(TRIANGLE_OBJ)
    # A valid scene: the flag cases (--memory-budget) must fail on the flag alone.
    (out / "scene_ok.json").write_text(scene())
    cases = {
        # Rendered inf/NaN tables with exit code 0.
        "scene_radiance_1e38.json": scene(light__radiance=[1e38, 1e38, 1e38]),
        # Was reported as "up is zero or parallel to the view direction".
        "scene_eye_1e30.json": scene(camera__eye=[0, 1, 1e30]),
        "scene_eye_is_look_at.json": scene(camera__eye=[0, 0, 0]),
        "scene_up_zero.json": scene(camera__up=[0, 0, 0]),
        "scene_up_parallel.json": scene(camera__up=[0, 2, 10]),
        "scene_fov_179_9.json": scene(camera__fov_deg=179.9),
        "scene_resolution_20000.json": scene(camera__resolution=[20000, 16]),
        "scene_scale_1e30.json": scene(mesh__transform={"scale": 1e30}),
        "scene_scale_1e-20.json": scene(mesh__transform={"scale": [1, 1e-20, 1]}),
        "scene_light_1e-8.json": scene(light__edge_u=[1e-8, 0, 0], light__edge_v=[0, 0, 1e-8]),
        "scene_instances_1e7.json": scene(instances={"file": "scene_1e7.instances.txt"}),
    }
    for name, text in cases.items():
        (out / name).write_text(text)
    (out / "scene_1e7.instances.txt").write_text("tri 1 2 3\ntri 1e7 0 0 0  0 1 0 0  0 0 1 0\n")
    # An unknown key that is an escape sequence (clear screen): the message must escape it.
    (out / "scene_escape_key.json").write_text(
        scene().replace('"fov_deg": 40', '"fov_deg": 40, "\\u001b[2J\\u0007": 1'))
