"""Files for the cases of cases_proxygen.cmake: a plain file where proxy-gen's --cache folder
should be, and scenes whose new "make_proxy" key has a wrong type.
"""
import json
import pathlib


def build(out: pathlib.Path, data: pathlib.Path) -> None:
    d = out / "proxygen"
    d.mkdir()
    (d / "a_file").write_text("not a folder\n")
    (d / "tri.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n")
    head = {"camera": {"eye": [0, 0, 3], "look_at": [0, 0, 0]},
            "lights": [{"type": "quad", "corner": [-1, 2, -1], "edge_u": [2, 0, 0],
                        "edge_v": [0, 0, 2], "radiance": [5, 5, 5]}]}
    for name, value in (("string", "no"), ("number", 0), ("null", None)):
        scene = dict(head, meshes=[{"name": "tet", "file": "tri.obj", "make_proxy": value}])
        (d / f"make_proxy_{name}.json").write_text(json.dumps(scene))
