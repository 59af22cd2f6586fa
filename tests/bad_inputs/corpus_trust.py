"""Scenes whose proxies claim a class they do not have (the trust of a proxy's class)."""
import json
import pathlib

# The box [-1, 1]^3 with a fan of 4 triangles per face: 24 triangles, so a 12-triangle box proxy
# is cheaper and the renderer uses it.
CORNERS = [(x, y, z) for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)]
CENTRES = [(0, 0, -1), (0, 0, 1), (0, -1, 0), (0, 1, 0), (-1, 0, 0), (1, 0, 0)]
QUADS = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
BOX_TRIANGLES = [(a, b, c) for q in QUADS for (a, b, c) in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]


def off(vertices, triangles) -> str:
    lines = ["OFF", f"{len(vertices)} {len(triangles)} 0"]
    lines += [" ".join(f"{c:g}" for c in v) for v in vertices]
    lines += ["3 " + " ".join(map(str, t)) for t in triangles]
    return "\n".join(lines) + "\n"


def fan_box() -> str:
    tris = []
    for i, q in enumerate(QUADS):
        centre = 8 + i
        tris += [(q[k], q[(k + 1) % 4], centre) for k in range(4)]
    return off(CORNERS + CENTRES, tris)


def box(scale: float, drop_last: bool = False) -> str:
    tris = BOX_TRIANGLES[:-1] if drop_last else BOX_TRIANGLES
    return off([tuple(scale * c for c in v) for v in CORNERS], tris)


def scene(proxy: str, extra: dict) -> str:
    ref = {"kind": "outside", "file": proxy, "class": "outside", **extra}
    return json.dumps({
        "camera": {"eye": [0, 4, 7], "look_at": [0, 0, 0], "fov_deg": 40, "resolution": [8, 8]},
        "lights": [{"type": "quad", "corner": [-1, 5, -1], "edge_u": [2, 0, 0],
                    "edge_v": [0, 0, 2], "radiance": [8, 8, 8]}],
        "meshes": [{"name": "fanbox", "file": "fanbox.off", "proxies": [ref]}],
    }, indent=1) + "\n"


def build(out: pathlib.Path, data: pathlib.Path) -> None:
    d = out / "trust"
    d.mkdir()
    (d / "fanbox.off").write_text(fan_box())
    (d / "shrunk.off").write_text(box(0.5))  # the original shrunk by 50%: inside, not outside
    (d / "open.off").write_text(box(1.2, drop_last=True))  # a hole: containment undecidable
    (d / "corrupt.off").write_text("OFF\n8 12 0\n1 2\n")  # truncated
    (d / "mislabelled.json").write_text(scene("shrunk.off", {}))
    (d / "open_proxy.json").write_text(scene("open.off", {}))
    (d / "corrupt_proxy.json").write_text(scene("corrupt.off", {}))
    (d / "bad_hash.json").write_text(scene("shrunk.off", {"sha256": "ABC123"}))
