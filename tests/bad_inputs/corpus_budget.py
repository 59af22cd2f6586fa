"""Meshes for the face-budget cases: a closed mesh of 180 faces (a UV sphere) whose outside wrap
has thousands of faces.

Before the budget was enforced, the sphere's wrap with --max-faces 3 was written with 16 k faces
and exit code 0.
"""
import math
import pathlib


def write_off(path: pathlib.Path, vertices, faces) -> None:
    lines = ["OFF", f"{len(vertices)} {len(faces)} 0"]
    lines += [" ".join(repr(float(c)) for c in v) for v in vertices]
    lines += ["3 " + " ".join(str(i) for i in f) for f in faces]
    path.write_text("\n".join(lines) + "\n")


def uv_sphere(rings: int, segments: int):
    vertices = [(0.0, 0.0, 1.0)]
    for r in range(1, rings):
        theta = math.pi * r / rings
        for s in range(segments):
            phi = 2 * math.pi * s / segments
            vertices.append((math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi),
                             math.cos(theta)))
    vertices.append((0.0, 0.0, -1.0))
    south = len(vertices) - 1
    ring = lambda r, s: 1 + (r - 1) * segments + s % segments
    faces = [(0, ring(1, s), ring(1, s + 1)) for s in range(segments)]
    for r in range(1, rings - 1):
        for s in range(segments):
            a, b, c, d = ring(r, s), ring(r, s + 1), ring(r + 1, s), ring(r + 1, s + 1)
            faces += [(a, c, d), (a, d, b)]
    faces += [(south, ring(rings - 1, s + 1), ring(rings - 1, s)) for s in range(segments)]
    return vertices, faces


def build(out: pathlib.Path, data: pathlib.Path) -> None:
    del data
    vertices, faces = uv_sphere(10, 10)  # 10 + 160 + 10 = 180 faces, outward
    write_off(out / "budget_sphere_180.off", vertices, faces)
