"""Files for the output-safety cases (cases_io.cmake): small valid meshes and scenes whose outputs
are pointed back at them through links and other spellings, and a scene whose radiance overflows.
"""
import json
import os
import pathlib


def box_off(lo: float, hi: float) -> str:
    corners = [[hi if i & bit else lo for bit in (1, 2, 4)] for i in range(8)]
    tris = ["0 2 3", "0 3 1", "4 5 7", "4 7 6", "0 1 5", "0 5 4", "2 6 7", "2 7 3", "0 4 6",
            "0 6 2", "1 3 7", "1 7 5"]
    lines = ["OFF", "8 12 0"] + [" ".join(str(c) for c in p) for p in corners]
    return "\n".join(lines + ["3 " + t for t in tris]) + "\n"


def scene(radiance: float, size: float = 2) -> str:
    return json.dumps({
        "camera": {"eye": [0, 3, 6], "look_at": [0, 0.5, 0], "fov_deg": 40,
                   "resolution": [16, 12]},
        "lights": [{"type": "quad", "corner": [-size / 2, 4, -size / 2],
                    "edge_u": [size, 0, 0], "edge_v": [0, 0, size],
                    "radiance": [radiance] * 3}],
        "meshes": [
            {"name": "ground", "file": "ground.obj", "transform": {"scale": 10}},
            {"name": "box", "file": "cube.off", "transform": {"translate": [-0.5, 0, -0.5]},
             "proxies": [{"kind": "outside", "method": "box", "file": "around.off",
                          "class": "outside"}]},
        ],
    }, indent=1)


def build(out: pathlib.Path, data: pathlib.Path) -> None:
    io = out / "io"
    io.mkdir()
    (io / "cube.off").write_text(box_off(0, 1))
    (io / "around.off").write_text(box_off(-0.5, 1.5))
    (io / "ground.obj").write_text("v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nf 1 3 2\nf 1 4 3\n")
    os.symlink("cube.off", io / "link_to_cube.off")
    os.link(io / "cube.off", io / "hard_cube.off")
    (io / "scene.json").write_text(scene(8))
    os.symlink("scene.json", io / "link_to_scene.json")
    # 3e38 is a finite float, but a large light of it lights pixels beyond the largest float.
    (io / "huge_radiance.json").write_text(scene(3e38, 100))
    os.symlink("/dev/null", io / "null.ply")  # a device behind a link: written in place
    (io / "a_file").write_text("not a folder\n")
    (io / "a_folder").mkdir()
