#!/usr/bin/env python3
"""Writes variants of a scanned mesh that stress proxy-gen's mesh building, as binary PLY.

usage: make_scan_variants.py INPUT.ply OUT_DIR

INPUT is a binary little-endian PLY with float x, y, z vertices and uchar/int face lists (the
bundled bun_zipper.ply and dragon.ply). Variants, each named <input>_<variant>.ply:
  soup     every triangle has its own three vertices (unwelded, like the ecosys plant meshes)
  tiles    the faces cut into 4 x 4 x 4 spatial tiles, each tile with its own vertex copies
           (a scanner's tiled export: exact duplicates along the seams)
  shuffled soup with the faces in random order (no locality in vertex or face order)
  fragments the input plus 16 k small loose pieces (four-triangle tents scattered around it):
           many components, as a raw scan has
  fragsoup fragments, unwelded as soup (bun_zipper: 85 k faces, the size of the reported scan)
Pure Python (no numpy); about a second per variant.
"""
import os
import random
import struct
import sys


def read_ply(path):
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    nv = nf = 0
    vprops = []
    current = None
    for line in header:
        w = line.split()
        if w[:1] == ["element"]:
            current = w[1]
            if current == "vertex":
                nv = int(w[2])
            elif current == "face":
                nf = int(w[2])
        elif w[:1] == ["property"] and current == "vertex":
            vprops.append(w[1])
    if "binary_little_endian" not in header[1] or vprops != ["float"] * len(vprops):
        sys.exit(f"{path}: expected binary little-endian float vertices")
    stride = 4 * len(vprops)
    verts = [struct.unpack_from("<3f", data, end + i * stride) for i in range(nv)]
    off = end + nv * stride
    faces = []
    for _ in range(nf):
        n = data[off]
        idx = struct.unpack_from(f"<{n}i", data, off + 1)
        off += 1 + 4 * n
        for k in range(1, n - 1):
            faces.append((idx[0], idx[k], idx[k + 1]))
    return verts, faces


def write_ply(path, verts, faces, comment):
    with open(path, "wb") as f:
        f.write(
            (
                "ply\nformat binary_little_endian 1.0\n"
                f"comment {comment}\n"
                f"element vertex {len(verts)}\nproperty float x\nproperty float y\n"
                f"property float z\nelement face {len(faces)}\n"
                "property list uchar int vertex_indices\nend_header\n"
            ).encode("ascii")
        )
        f.write(b"".join(struct.pack("<3f", *v) for v in verts))
        f.write(b"".join(struct.pack("<B3i", 3, *t) for t in faces))


def soup(verts, faces):
    out_v, out_f = [], []
    for t in faces:
        out_f.append((len(out_v), len(out_v) + 1, len(out_v) + 2))
        out_v.extend(verts[i] for i in t)
    return out_v, out_f


def tiles(verts, faces, n=4):
    lo = [min(v[k] for v in verts) for k in range(3)]
    hi = [max(v[k] for v in verts) for k in range(3)]

    def tile(t):
        c = [sum(verts[i][k] for i in t) / 3 for k in range(3)]
        return tuple(min(n - 1, int(n * (c[k] - lo[k]) / (hi[k] - lo[k] or 1))) for k in range(3))

    out_v, out_f, copies = [], [], {}
    for t in faces:
        key = tile(t)
        tri = []
        for i in t:
            j = copies.get((key, i))
            if j is None:
                j = copies[(key, i)] = len(out_v)
                out_v.append(verts[i])
            tri.append(j)
        out_f.append(tuple(tri))
    return out_v, out_f


def fragments(verts, faces, count=4000, seed=1):
    rng = random.Random(seed)
    lo = [min(v[k] for v in verts) for k in range(3)]
    hi = [max(v[k] for v in verts) for k in range(3)]
    size = max(h - l for l, h in zip(lo, hi)) / 200
    out_v, out_f = list(verts), list(faces)
    for _ in range(count):
        c = [rng.uniform(l, h) for l, h in zip(lo, hi)]
        base = len(out_v)
        # A four-triangle tent: a square base ring around an apex, open underneath.
        out_v.append((c[0], c[1] + size, c[2]))
        for dx, dz in ((1, 1), (1, -1), (-1, -1), (-1, 1)):
            out_v.append((c[0] + dx * size, c[1], c[2] + dz * size))
        for k in range(4):
            out_f.append((base, base + 1 + k, base + 1 + (k + 1) % 4))
    return out_v, out_f


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    src, out_dir = sys.argv[1], sys.argv[2]
    os.makedirs(out_dir, exist_ok=True)
    verts, faces = read_ply(src)
    name = os.path.splitext(os.path.basename(src))[0]
    rng = random.Random(1)
    shuffled = list(faces)
    rng.shuffle(shuffled)
    variants = {
        "soup": soup(verts, faces),
        "tiles": tiles(verts, faces),
        "shuffled": soup(verts, shuffled),
        "fragments": fragments(verts, faces),
        "fragsoup": soup(*fragments(verts, faces)),
    }
    for variant, (v, f) in variants.items():
        path = os.path.join(out_dir, f"{name}_{variant}.ply")
        write_ply(path, v, f, f"{variant} variant of {os.path.basename(src)} (make_scan_variants.py)")
        print(f"{path}: {len(v)} vertices, {len(f)} faces")


if __name__ == "__main__":
    main()
